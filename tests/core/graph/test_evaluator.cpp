#include "engine/graph/graph.h"
#include "engine/util/error.h"

#include <gtest/gtest.h>

#include <atomic>

using namespace sylva::graph;
using sylva::Value;

namespace {

std::atomic<int> gSourceRuns{0};

/// Test node types: "test_source" makes a chain of `length` nodes; "test_double" doubles every
/// position of its input. Simple enough to check results by hand.
void registerTestTypes() {
    static bool done = false;
    if (done) return;
    done = true;
    registerBuiltinNodeTypes();
    NodeRegistry::instance().add(
        NodeType{"test_source",
                 0,
                 0,
                 [](const NodeContext& ctx) {
                     ++gSourceRuns;
                     auto s = std::make_shared<sylva::skel::Skeleton>();
                     const auto n = ctx.params.integer("length", 1);
                     sylva::requireRange("length", static_cast<double>(n), 1, 1000);
                     std::int32_t parent = -1;
                     const float y0 = ctx.seedOverridden ? static_cast<float>(ctx.seed) : 0.0f;
                     for (std::int64_t i = 0; i <= n; ++i)
                         parent = s->addNode({0, y0 + static_cast<float>(i), 0}, parent, 0.1f, 0,
                                             {1, 0, 0, 0});
                     NodeOutput out;
                     out.skeleton = s;
                     out.stats["segments"] = static_cast<double>(n);
                     return out;
                 },
                 {"length"},
                 {},
                 {},
                 {}});
    NodeRegistry::instance().add(NodeType{"test_double",
                                          1,
                                          1,
                                          [](const NodeContext& ctx) {
                                              auto s = std::make_shared<sylva::skel::Skeleton>(
                                                  *ctx.inputs[0]->skeleton);
                                              for (auto& p : s->position)
                                                  p *= 2.0f;
                                              NodeOutput out;
                                              out.skeleton = s;
                                              out.timingsMs["double"] = 0.0;
                                              return out;
                                          },
                                          {},
                                          {},
                                          {},
                                          {}});
}

SpeciesGraph chainGraph() {
    SpeciesGraph g;
    g.name = "chain";
    g.nodes = {NodeDesc{"src", "test_source", Value::Object{{"length", 3}}, {}},
               NodeDesc{"dbl", "test_double", Value::Object{}, {"src"}}};
    g.output = "dbl";
    return g;
}

} // namespace

TEST(Evaluator, EvaluatesInputsFirstAndAccumulatesStats) {
    registerTestTypes();
    Evaluator e(chainGraph());
    const NodeOutput& out = e.evaluate();
    ASSERT_TRUE(out.skeleton);
    ASSERT_EQ(out.skeleton->size(), 4u);
    EXPECT_FLOAT_EQ(out.skeleton->position[3].y, 6.0f);
    EXPECT_EQ(out.stats.at("segments"), 3.0); // from the input node
    EXPECT_TRUE(out.timingsMs.count("double"));
}

TEST(Evaluator, CachesUntilSomethingChanges) {
    registerTestTypes();
    Evaluator e(chainGraph());
    e.evaluate();
    EXPECT_EQ(e.evaluations(), 2u);
    e.evaluate();
    EXPECT_EQ(e.evaluations(), 2u);        // nothing changed: nothing re-runs
    e.setParam("dbl", "unused", Value(1)); // test_double has no known-param list → accepted
    e.evaluate();
    EXPECT_EQ(e.evaluations(), 3u); // only the edited node re-ran
    e.setParam("src", "length", Value(5));
    const NodeOutput& out = e.evaluate();
    EXPECT_EQ(e.evaluations(), 5u); // source and everything downstream
    EXPECT_EQ(out.skeleton->size(), 6u);
    e.evaluate(7);
    EXPECT_EQ(e.evaluations(), 7u); // a seed change re-runs the generators
    EXPECT_FLOAT_EQ(e.evaluate(7).skeleton->position[0].y, 14.0f);
}

TEST(Evaluator, RejectsBadGraphsWithMessages) {
    registerTestTypes();
    auto expectError = [](SpeciesGraph g, const std::string& fragment) {
        try {
            Evaluator e(std::move(g));
            FAIL() << "accepted a graph that should fail with: " << fragment;
        } catch (const sylva::InvalidInput& ex) {
            EXPECT_NE(std::string(ex.what()).find(fragment), std::string::npos) << ex.what();
        }
    };
    SpeciesGraph g = chainGraph();
    g.nodes[1].type = "no_such_type";
    expectError(g, "unknown type 'no_such_type'");
    g = chainGraph();
    g.nodes[1].inputs = {"ghost"};
    expectError(g, "unknown node 'ghost'");
    g = chainGraph();
    g.output = "nowhere";
    expectError(g, "output node 'nowhere'");
    g = chainGraph();
    g.nodes[0].params = Value::Object{{"lenght", 3}};
    expectError(g, "no parameter 'lenght'");
    g = chainGraph();
    g.nodes[1].inputs = {};
    expectError(g, "takes 1..1 inputs");
    g = chainGraph();
    g.nodes.push_back(NodeDesc{"src", "test_source", Value::Object{}, {}});
    expectError(g, "duplicate node id 'src'");
    g = chainGraph();
    g.nodes[0].type = "test_double";
    g.nodes[0].inputs = {"dbl"};
    expectError(g, "cycle");
}

TEST(Evaluator, RejectedEditLosesNothing) {
    registerTestTypes();
    Evaluator e(chainGraph());
    EXPECT_THROW(e.setParam("ghost", "x", Value(1)), sylva::InvalidInput);
    EXPECT_THROW(e.setParam("src", "bogus", Value(1)), sylva::InvalidInput);
    EXPECT_EQ(e.graph().findNode("src")->params.toJson(), R"({"length":3})");
    // A node that throws while evaluating leaves the evaluator usable.
    e.setParam("src", "length", Value(0));
    EXPECT_THROW(e.evaluate(), sylva::InvalidInput);
    e.setParam("src", "length", Value(2));
    EXPECT_EQ(e.evaluate().skeleton->size(), 3u);
}

TEST(BuiltinNodes, SelfOrganizingTreesCarryTheirGrowthRecords) {
    registerBuiltinNodeTypes();
    SpeciesGraph g;
    g.name = "so";
    g.nodes = {NodeDesc{"grow", "self_organizing", Value::Object{{"cycles", 5}}, {}}};
    g.output = "grow";
    Evaluator e(std::move(g));
    const auto& s = *e.evaluate(3).skeleton;
    ASSERT_GT(s.size(), 1u);
    EXPECT_EQ(s.light.size(), s.size());
    EXPECT_EQ(s.vigour.size(), s.size());
    EXPECT_EQ(s.age.size(), s.size());
    EXPECT_NO_THROW(s.validate());
    // The root has lived through every cycle; light is non-negative everywhere.
    EXPECT_GE(s.age[0], s.age.back());
    for (float l : s.light)
        EXPECT_GE(l, 0.0f);
}

TEST(Evaluator, TracedSourcesReachTheMesherThroughAdapt) {
    registerBuiltinNodeTypes();
    SpeciesGraph g;
    g.name = "traced";
    g.nodes = {
        NodeDesc{"grow",
                 "lsystem",
                 Value::Object{{"grammar", "axiom: A\nA -> F[+F]B\nB -> F\n"}, {"generations", 2}},
                 {}},
        NodeDesc{"adapt", "adapt", Value::Object{}, {"grow"}},
        NodeDesc{"mesh", "tube_mesh", Value::Object{}, {"adapt"}}};
    g.output = "mesh";
    Evaluator e(std::move(g));
    EXPECT_TRUE(e.evaluate(1).skeleton->sourceLine.empty()); // off by default
    const std::size_t before = e.evaluations();
    e.setTraceSources(true);
    const auto& s = *e.evaluate(1).skeleton;
    EXPECT_EQ(e.evaluations(), before + 3); // the cache was dropped: every node ran again
    EXPECT_EQ(s.sourceLine, (std::vector<std::int32_t>{2, 2, 2, 3}));
}

TEST(Evaluator, SharedGraphIsCopiedOnceAChange) {
    registerTestTypes();
    Evaluator e(chainGraph());
    const std::shared_ptr<const SpeciesGraph> first = e.sharedGraph();
    EXPECT_EQ(e.sharedGraph(), first); // unchanged graph: the same copy again
    EXPECT_EQ(first->findNode("src")->params.toJson(), R"({"length":3})");
    EXPECT_THROW(e.setParam("src", "bogus", Value(1)), sylva::InvalidInput);
    EXPECT_EQ(e.sharedGraph(), first); // a rejected edit changes nothing
    e.setParam("src", "length", Value(5));
    const std::shared_ptr<const SpeciesGraph> second = e.sharedGraph();
    EXPECT_NE(second, first);
    EXPECT_EQ(second->findNode("src")->params.toJson(), R"({"length":5})");
    EXPECT_EQ(first->findNode("src")->params.toJson(), R"({"length":3})"); // kept as it was
}

TEST(Evaluator, ParameterHashesFollowEveryKindOfEdit) {
    // The cache keys use the parameters' hashes computed when the graph is set: a rejected edit
    // keeps the old ones, setGraph and setParam make new ones.
    registerTestTypes();
    Evaluator e(chainGraph());
    e.evaluate();
    EXPECT_EQ(e.evaluations(), 2u);
    EXPECT_THROW(e.setParam("src", "bogus", Value(1)), sylva::InvalidInput);
    e.evaluate();
    EXPECT_EQ(e.evaluations(), 2u); // the rejected edit left the keys as they were
    SpeciesGraph g = chainGraph();
    g.nodes[0].params = Value::Object{{"length", 4}};
    e.setGraph(g);
    EXPECT_EQ(e.evaluate().skeleton->size(), 5u);
    EXPECT_EQ(e.evaluations(), 4u);
    e.setGraph(g); // the same graph again: the same keys, nothing re-runs
    e.evaluate();
    EXPECT_EQ(e.evaluations(), 4u);
    e.setParam("src", "length", Value(3)); // back to the first graph's parameters
    EXPECT_EQ(e.evaluate().skeleton->size(), 4u);
    EXPECT_EQ(e.evaluations(), 6u);
}

TEST(Evaluator, MesherReadsEachSpeciesOwnParameters) {
    // tube_mesh keeps the settings it read last (per thread) while its parameters stay the same:
    // species alternating on one thread, and edits, must each get their own mesh.
    registerBuiltinNodeTypes();
    auto graphWith = [](int resolution) {
        SpeciesGraph g;
        g.name = "tubes";
        g.nodes = {
            NodeDesc{"grow",
                     "lsystem",
                     Value::Object{{"grammar", "axiom: A\nA -> F[+F]B\nB -> F[-F]A\n"},
                                   {"generations", 4}},
                     {}},
            NodeDesc{"mesh", "tube_mesh", Value::Object{{"resolution", resolution}}, {"grow"}}};
        g.output = "mesh";
        return g;
    };
    auto meshOf = [](Evaluator& e, std::uint64_t seed) {
        const NodeOutput& out = e.evaluate(seed);
        EXPECT_TRUE(out.mesh);
        return std::make_pair(out.mesh->positions.size(), out.mesh->indices);
    };
    Evaluator six(graphWith(6));
    Evaluator eight(graphWith(8));
    const auto sixMesh = meshOf(six, 1);
    const auto eightMesh = meshOf(eight, 1);
    EXPECT_NE(sixMesh.first, eightMesh.first);
    EXPECT_EQ(meshOf(six, 2), sixMesh); // after the other species: read again
    EXPECT_EQ(meshOf(eight, 2), eightMesh);
    six.setParam("mesh", "resolution", Value(8));
    EXPECT_EQ(meshOf(six, 3), eightMesh); // an edit is read
    six.setParam("mesh", "resolution", Value(6));
    EXPECT_EQ(meshOf(six, 4), sixMesh);
    EXPECT_THROW(six.setParam("mesh", "resolution", Value(65)), sylva::InvalidInput);
    EXPECT_EQ(meshOf(six, 5), sixMesh);
}
