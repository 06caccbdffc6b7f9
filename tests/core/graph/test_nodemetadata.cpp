// The node metadata is the one description of every parameter: these tests tie it to what the
// node types really do (names, defaults, ranges) and to the graph's port kinds.
#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/util/error.h"

#include <gtest/gtest.h>

#include <set>

using namespace sylva::graph;
using sylva::Value;

namespace {

const char* kGrammar = "axiom: F\nF -> F[+F][-F]F\ngenerations: 3\nangle: 25\n";

SpeciesGraph graphOf(std::vector<NodeDesc> nodes, std::string output) {
    SpeciesGraph g;
    g.name = "t";
    g.nodes = std::move(nodes);
    g.output = std::move(output);
    return g;
}

/// Evaluates a generator → tube_mesh graph and returns a fingerprint of the tree.
std::string fingerprint(const SpeciesGraph& g) {
    Evaluator e(g);
    const NodeOutput& out = e.evaluate(7);
    std::string f =
        std::to_string(out.skeleton->size()) + "/" + std::to_string(out.skeleton->leaves.size());
    if (out.mesh) {
        double sum = 0;
        for (const auto& p : out.mesh->positions)
            sum += p.x * 1.0 + p.y * 3.0 + p.z * 7.0;
        f += "/" + std::to_string(out.mesh->vertexCount()) + "/" + std::to_string(sum);
    }
    return f;
}

/// The node's parameters set explicitly to the defaults the metadata states, except \p keep
/// (the test's own values) and parameters without a default.
Value defaultsOf(const std::string& type, Value::Object keep) {
    const NodeType* t = NodeRegistry::instance().find(type);
    for (const ParamSpec& p : t->params)
        if (!p.defaultValue.isNull() && !keep.count(p.name)) keep[p.name] = p.defaultValue;
    return Value(std::move(keep));
}

class NodeMetadata : public ::testing::Test {
protected:
    void SetUp() override { registerBuiltinNodeTypes(); }
};

TEST_F(NodeMetadata, EveryBuiltinTypeDescribesEveryParameter) {
    const NodeRegistry& r = NodeRegistry::instance();
    for (const char* name :
         {"lsystem", "space_colonization", "self_organizing", "adapt", "tube_mesh", "leaves"}) {
        SCOPED_TRACE(name);
        const NodeType* t = r.find(name);
        ASSERT_NE(t, nullptr);
        EXPECT_FALSE(t->doc.empty());
        EXPECT_FALSE(t->category.empty());
        std::set<std::string> specs, known(t->knownParams.begin(), t->knownParams.end());
        for (const ParamSpec& p : t->params) {
            SCOPED_TRACE(p.name);
            EXPECT_TRUE(specs.insert(p.name).second) << "described twice";
            EXPECT_FALSE(p.doc.empty());
            EXPECT_FALSE(p.group.empty());
            // A stated default is a valid value.
            EXPECT_NO_THROW(checkParam(p, p.defaultValue));
            if (p.kind == ParamKind::Enum) {
                EXPECT_FALSE(p.choices.empty());
            }
        }
        EXPECT_EQ(specs, known) << "knownParams and the metadata disagree";
    }
}

// Panels and undo steps show a parameter in words; Python and files keep its name.
TEST_F(NodeMetadata, ParametersReadAsWords) {
    EXPECT_EQ(paramWords("leaf_scale"), "leaf scale");
    EXPECT_EQ(paramWords("lod_leaf_cluster_pixels"), "LOD leaf cluster pixels");
    EXPECT_EQ(paramWords("node_ids"), "node IDs");
    EXPECT_EQ(paramWords("w_max"), "w max");
    EXPECT_EQ(paramWords("seed"), "seed");
    EXPECT_EQ(paramWords("_odd__name_"), "odd name");
    EXPECT_EQ(paramWords(""), "");
    ParamSpec spec;
    spec.name = "lod_fov";
    EXPECT_EQ(spec.label(), "LOD FOV");
    spec.name = "max_bend";
    EXPECT_EQ(spec.label(), "Max bend");
    // Every built-in parameter has a label, and no label keeps an underscore.
    for (const std::string& type : NodeRegistry::instance().names())
        for (const ParamSpec& p : NodeRegistry::instance().find(type)->params) {
            EXPECT_FALSE(p.label().empty()) << type << "." << p.name;
            EXPECT_EQ(p.label().find('_'), std::string::npos) << type << "." << p.name;
        }
}

TEST_F(NodeMetadata, PaperSymbolsAreNamed) {
    const NodeRegistry& r = NodeRegistry::instance();
    auto doc = [&](const char* type, const char* param) {
        return r.find(type)->findParam(param)->doc;
    };
    EXPECT_NE(doc("space_colonization", "influence_distance").find("d_i"), std::string::npos);
    EXPECT_NE(doc("space_colonization", "kill_distance").find("d_k"), std::string::npos);
    EXPECT_NE(doc("space_colonization", "segment_length").find("D:"), std::string::npos);
    EXPECT_NE(doc("self_organizing", "lambda").find("λ"), std::string::npos);
    EXPECT_NE(doc("self_organizing", "alpha").find("α"), std::string::npos);
    EXPECT_NE(doc("self_organizing", "shadow_a").find("a:"), std::string::npos);
    EXPECT_NE(doc("self_organizing", "shadow_b").find("b:"), std::string::npos);
    EXPECT_NE(doc("adapt", "max_bend").find("Maximum bend"), std::string::npos);
    EXPECT_NE(doc("adapt", "bend_multiplier").find("multiplier"), std::string::npos);
}

TEST_F(NodeMetadata, ValidationRefusesOutOfRangeWithTheRange) {
    const NodeRegistry& r = NodeRegistry::instance();
    for (const std::string& name : r.names()) {
        const NodeType* t = r.find(name);
        for (const ParamSpec& p : t->params) {
            if (p.kind != ParamKind::Number && p.kind != ParamKind::Integer) continue;
            if (p.max >= 1e300) continue;
            SCOPED_TRACE(name + "." + p.name);
            const double bad = p.max + std::max(1.0, std::abs(p.max));
            try {
                checkParam(p, Value(bad));
                ADD_FAILURE() << "accepted " << bad;
            } catch (const sylva::InvalidInput& e) {
                EXPECT_NE(std::string(e.what()).find(p.rangeText()), std::string::npos) << e.what();
            }
            EXPECT_NO_THROW(checkParam(p, Value(p.max)));
        }
    }
    // Through a whole graph: the node and the range are named, nothing is evaluated.
    const SpeciesGraph g =
        graphOf({{"grow", "lsystem", Value::Object{{"grammar", kGrammar}}, {}},
                 {"mesh", "tube_mesh", Value::Object{{"resolution", 65}}, {"grow"}}},
                "mesh");
    try {
        Evaluator e(g);
        FAIL() << "accepted resolution 65";
    } catch (const sylva::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("node 'mesh' (tube_mesh): resolution must be in "
                                             "[3, 64], got 65"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_THROW(checkParam(*r.find("tube_mesh")->findParam("resolution"), Value(8.5)),
                 sylva::InvalidInput);
    EXPECT_THROW(checkParam(*r.find("tube_mesh")->findParam("thickness"), Value("bogus")),
                 sylva::InvalidInput);
    EXPECT_THROW(checkParam(*r.find("space_colonization")->findParam("segment_length"), Value(0)),
                 sylva::InvalidInput); // (0, 100]: zero is out
}

// Fuzz finding 13: an integer parameter far beyond any integer type (5e105 attractors) is refused
// with its range, without converting it to an integer first (undefined behaviour under UBSan).
TEST_F(NodeMetadata, HugeIntegersAreRefusedWithTheirRange) {
    const ParamSpec& attractors =
        *NodeRegistry::instance().find("space_colonization")->findParam("attractors");
    for (const double huge : {5.00444e105, -1e300, 1e19}) {
        try {
            checkParam(attractors, Value(huge));
            ADD_FAILURE() << "accepted " << huge;
        } catch (const sylva::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("[1, 2000000]"), std::string::npos) << e.what();
        }
    }
    EXPECT_THROW(checkParam(attractors, Value(1.5)), sylva::InvalidInput); // in range, not whole
    EXPECT_NO_THROW(checkParam(attractors, Value(2000000.0)));
}

// The defaults the metadata states are the ones the code uses: a graph with every parameter
// set to its stated default grows the same tree as one that leaves them unset.
TEST_F(NodeMetadata, StatedDefaultsAreTheCodesDefaults) {
    const Value::Object lsys{{"grammar", kGrammar}};
    const Value::Object sc{{"attractors", 400}, {"max_iterations", 60}};
    const Value::Object so{{"cycles", 5}, {"markers", 3000}, {"leaf_size", 0.1}};
    for (const auto& [type, own] : std::vector<std::pair<std::string, Value::Object>>{
             {"lsystem", lsys}, {"space_colonization", sc}, {"self_organizing", so}}) {
        SCOPED_TRACE(type);
        const SpeciesGraph unset = graphOf({{"grow", type, Value(own), {}},
                                            {"leaves", "leaves", Value::Object{}, {"grow"}},
                                            {"adapt", "adapt", Value::Object{}, {"leaves"}},
                                            {"mesh", "tube_mesh", Value::Object{}, {"adapt"}}},
                                           "mesh");
        const SpeciesGraph stated =
            graphOf({{"grow", type, defaultsOf(type, own), {}},
                     {"leaves", "leaves", defaultsOf("leaves", {}), {"grow"}},
                     {"adapt", "adapt", defaultsOf("adapt", {}), {"leaves"}},
                     {"mesh", "tube_mesh", defaultsOf("tube_mesh", {}), {"adapt"}}},
                    "mesh");
        EXPECT_EQ(fingerprint(unset), fingerprint(stated));
    }
}

TEST_F(NodeMetadata, ConnectionsAreTypeChecked) {
    const SpeciesGraph g = graphOf({{"grow", "lsystem", Value::Object{{"grammar", kGrammar}}, {}},
                                    {"sc", "space_colonization", Value::Object{}, {}},
                                    {"mesh", "tube_mesh", Value::Object{}, {"grow"}},
                                    {"mesh2", "tube_mesh", Value::Object{}, {}},
                                    {"adapt", "adapt", Value::Object{}, {}},
                                    {"leaves", "leaves", Value::Object{}, {}}},
                                   "mesh");
    EXPECT_EQ(outputKind(g, "grow"), PortKind::Skeleton);
    EXPECT_EQ(outputKind(g, "mesh"), PortKind::Mesh);
    EXPECT_EQ(connectionError(g, "grow", "mesh2"), "");
    EXPECT_EQ(connectionError(g, "mesh", "leaves"), ""); // leaves take a mesh too
    EXPECT_EQ(connectionError(g, "grow", "sc"), "");     // an initial skeleton
    EXPECT_NE(connectionError(g, "mesh", "adapt")
                  .find("takes a skeleton, but 'mesh' "
                        "(tube_mesh) gives a mesh"),
              std::string::npos);
    EXPECT_NE(connectionError(g, "grow", "mesh").find("already has its input"), std::string::npos);
    EXPECT_NE(connectionError(g, "mesh", "grow").find("takes no input"), std::string::npos);
    EXPECT_NE(connectionError(g, "nope", "mesh2").find("no node 'nope'"), std::string::npos);

    // A cycle: adapt → leaves → adapt.
    SpeciesGraph c = g;
    c.findNode("leaves")->inputs = {"adapt"};
    EXPECT_NE(connectionError(c, "leaves", "adapt").find("cycle"), std::string::npos);

    // leaves pass their input's kind on: after a mesh they give a mesh.
    SpeciesGraph m = g;
    m.findNode("leaves")->inputs = {"mesh"};
    EXPECT_EQ(outputKind(m, "leaves"), PortKind::Mesh);
    EXPECT_NE(connectionError(m, "leaves", "adapt").find("gives a mesh"), std::string::npos);
}

} // namespace
