// buildForest in stages (issue 42): each species' growth policy is decided once, in the plan,
// from the traits its node types declare, never from a type's name; a generator that declares
// a stand growth is grown by the stand stage whatever it is called.
#include <gtest/gtest.h>

#include <atomic>

#include "engine/forest/forestbuild.h"
#include "engine/forest/speciesplan.h"
#include "engine/nodes/builtinnodes.h"

using namespace sylva;

namespace {

graph::SpeciesGraph chain(std::vector<graph::NodeDesc> nodes) {
    graph::SpeciesGraph g;
    g.name = "s";
    for (graph::NodeDesc& n : nodes)
        if (n.params.isNull()) n.params = Value::Object{}; // `{}` above is JSON null
    g.nodes = std::move(nodes);
    g.output = g.nodes.back().id;
    return g;
}

const Value kGrammar =
    Value::Object{{"grammar", "angle: 30\naxiom: F[+F][-F]\n"}, {"generations", 0}};

forest::ForestScene sceneOf(const graph::SpeciesGraph& g, int trees) {
    forest::ForestScene s;
    s.seed = 3;
    s.species.push_back({"s", g, -1});
    placement::Domain d;
    d.min = {-30.0f, -30.0f};
    d.max = {30.0f, 30.0f};
    d.counts = {{"s", trees}};
    s.domains.push_back(d);
    return s;
}

std::atomic<int> gStandCalls{0};

/// A generator named nothing the forest knows, whose trees grow together: each skeleton is a
/// stalk as many metres high as the stand has trees.
void registerStandType() {
    static bool done = false;
    if (done) return;
    done = true;
    graph::registerBuiltinNodeTypes();
    graph::NodeType type;
    type.name = "test_thicket";
    type.role = graph::NodeRole::Generator;
    type.evaluate = [](const graph::NodeContext&) {
        graph::NodeOutput out;
        auto s = std::make_shared<skel::Skeleton>();
        const std::int32_t root = s->addNode({0, 0, 0}, -1, 0.1f, 0, {1, 0, 0, 0});
        s->addNode({0, 1, 0}, root, 0.05f, 0, {1, 0, 0, 0});
        out.skeleton = s;
        return out;
    };
    auto stand = std::make_shared<graph::StandGrowth>();
    stand->standOf = [](const Value&) { return 0; };
    stand->grow = [](const std::vector<graph::StandMember>& members, const std::vector<glm::vec3>&,
                     Progress&) {
        ++gStandCalls;
        std::vector<skel::Skeleton> out(members.size());
        for (skel::Skeleton& s : out) {
            const std::int32_t root = s.addNode({0, 0, 0}, -1, 0.1f, 0, {1, 0, 0, 0});
            s.addNode({0, static_cast<float>(members.size()), 0}, root, 0.05f, 0, {1, 0, 0, 0});
        }
        return out;
    };
    type.stand = std::move(stand);
    graph::NodeRegistry::instance().add(std::move(type));
}

} // namespace

TEST(ForestStages, EachSpeciesGrowthPolicyComesFromItsNodeTypesTraits) {
    graph::registerBuiltinNodeTypes();
    forest::ForestScene scene;
    scene.species.push_back(
        {"plain", chain({{"grow", "lsystem", kGrammar, {}}, {"mesh", "tube_mesh", {}, {"grow"}}}),
         -1});
    scene.species.push_back({"adapting",
                             chain({{"grow", "lsystem", kGrammar, {}},
                                    {"fit", "adapt", {}, {"grow"}},
                                    {"mesh", "tube_mesh", {}, {"fit"}}}),
                             -1});
    scene.species.push_back(
        {"stand",
         chain({{"grow", "self_organizing", Value::Object{{"cycles", 3}, {"markers", 200}}, {}},
                {"mesh", "tube_mesh", {}, {"grow"}}}),
         -1});
    const std::vector<forest::build::SpeciesPlan> plans =
        forest::build::planSpecies(scene, forest::ForestOptions{});
    ASSERT_EQ(plans.size(), 3u);

    const forest::build::SpeciesPlan& plain = plans[0];
    EXPECT_EQ(plain.stand, nullptr);
    EXPECT_TRUE(plain.instanced && plain.cached && plain.seedOnly && plain.forestAdapts &&
                plain.adaptsToNeighbours);
    EXPECT_EQ(plain.skeletonNode, "grow");
    EXPECT_EQ(plain.meshNode->id, "mesh");

    // Its own adapt node sees the place: no variant's skeleton stands in, the forest does not
    // adapt it again.
    const forest::build::SpeciesPlan& adapting = plans[1];
    EXPECT_TRUE(adapting.instanced && adapting.cached);
    EXPECT_FALSE(adapting.seedOnly);
    EXPECT_FALSE(adapting.forestAdapts);
    EXPECT_EQ(adapting.skeletonNode, "fit");

    const forest::build::SpeciesPlan& stand = plans[2];
    EXPECT_EQ(stand.stand, graph::standGrowthOf("self_organizing"));
    EXPECT_NE(stand.stand, nullptr);
    EXPECT_FALSE(stand.instanced || stand.cached || stand.seedOnly || stand.adaptsToNeighbours);
    EXPECT_TRUE(stand.forestAdapts);
}

TEST(ForestStages, AGeneratorWithAStandGrowthGrowsInTheStandStageWhateverItsName) {
    registerStandType();
    const forest::ForestScene scene =
        sceneOf(chain({{"grow", "test_thicket", {}, {}}, {"mesh", "tube_mesh", {}, {"grow"}}}), 3);
    const int before = gStandCalls;
    std::vector<forest::ForestTree> trees;
    const forest::ForestStats stats = forest::buildForest(
        scene, forest::ForestOptions{}, [&](const std::vector<forest::ForestTree>& batch) {
            trees.insert(trees.end(), batch.begin(), batch.end());
        });
    EXPECT_EQ(gStandCalls - before, 1); // one stand, all three trees together
    ASSERT_EQ(trees.size(), 3u);
    EXPECT_EQ(stats.variants, 0u); // never instanced
    for (const forest::ForestTree& tree : trees) {
        EXPECT_EQ(tree.variant, -1);
        ASSERT_TRUE(tree.skeleton);
        ASSERT_EQ(tree.skeleton->size(), 2u);
        // The stand's skeleton (3 m: three trees), not the node's own (1 m).
        EXPECT_FLOAT_EQ(tree.skeleton->position[1].y, 3.0f);
        // Upright at scale 1: its size comes from the stand.
        EXPECT_EQ(tree.instance.scale, 1.0f);
        EXPECT_EQ(tree.instance.rotation, 0.0f);
    }
}

TEST(ForestStages, ABareGrammarIsWrappedIntoTheBuiltinGeneratorAndMesher) {
    const graph::SpeciesGraph g = nodes::grammarSpecies("tree.lsys");
    const graph::NodeDesc* mesh = graph::meshOutput(g);
    ASSERT_NE(mesh, nullptr);
    EXPECT_EQ(g.skeletonSource(), "grow");
    EXPECT_EQ(graph::roleOf(g.findNode("grow")->type), graph::NodeRole::Generator);
    EXPECT_EQ(g.findNode("grow")->params.string("grammar_file", ""), "tree.lsys");
    EXPECT_EQ(graph::standGrowthOf(g.findNode("grow")->type), nullptr);
}
