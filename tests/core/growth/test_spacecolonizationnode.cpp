// The space_colonization node: parameters, seeds, mesh envelopes from files, the initial-skeleton
// input, and the shipped presets (loaded as the species format describes, without Qt).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "engine/graph/graph.h"
#include "engine/growth/envelope.h"
#include "engine/growth/spacecolonization.h"
#include "engine/skeleton/radii.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::graph;

namespace {

const std::string kData = std::string(SYLVA_TEST_DATA_DIR) + "/growth";

SpeciesGraph crownGraph(Value::Object params, std::string base = kData) {
    SpeciesGraph g;
    g.name = "test";
    g.baseDir = base;
    g.sourceFile = base + "/test.json";
    g.nodes.push_back({"crown", "space_colonization", Value(std::move(params)), {}});
    g.output = "crown";
    return g;
}

Value::Object smallCrown() {
    return Value::Object{{"attractors", 600},
                         {"envelope", Value::Object{{"shape", "sphere"},
                                                    {"center", Value::Array{0.0, 6.0, 0.0}},
                                                    {"radius", 4.5}}},
                         {"influence_distance", 3.0},
                         {"kill_distance", 0.6},
                         {"segment_length", 0.2},
                         {"randomness", 0.147},
                         {"trunk_height", 2.0},
                         {"pipe_exponent", 2.41},
                         {"tip_radius", 0.01},
                         {"seed", 5}};
}

std::string errorOf(SpeciesGraph g) {
    try {
        Evaluator e(std::move(g));
        e.evaluate();
    } catch (const std::exception& ex) {
        return ex.what();
    }
    return "";
}

// Minimal species-file reader (the Qt-side loader lives in core/document).
SpeciesGraph loadPreset(const std::string& name) {
    const std::string path = std::string(SYLVA_PRESETS_DIR) + "/" + name;
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << path;
    std::stringstream text;
    text << in.rdbuf();
    const Value root = Value::parseJson(text.str(), path);
    EXPECT_EQ(root.string("format", ""), "sylva-species");
    SpeciesGraph g;
    g.name = root.string("name", name);
    g.baseDir = SYLVA_PRESETS_DIR;
    g.sourceFile = path;
    const Value& graph = *root.find("graph");
    for (const Value& n : graph.find("nodes")->toArray()) {
        NodeDesc d;
        d.id = n.string("id", "");
        d.type = n.string("type", "");
        if (const Value* p = n.find("params")) d.params = *p;
        if (const Value* ins = n.find("inputs"))
            for (const Value& i : ins->toArray())
                d.inputs.push_back(i.toString());
        g.nodes.push_back(std::move(d));
    }
    g.output = graph.string("output", g.nodes.back().id);
    return g;
}

} // namespace

class SpaceColonizationNode : public ::testing::Test {
protected:
    void SetUp() override { registerBuiltinNodeTypes(); }
};

TEST_F(SpaceColonizationNode, MatchesTheLibraryCallAndReportsStats) {
    Evaluator e(crownGraph(smallCrown()));
    const NodeOutput& out = e.evaluate();
    ASSERT_TRUE(out.skeleton);
    // The same tree straight from the library.
    growth::ColonizationParams p;
    p.trunkHeight = 2.0f;
    p.seed = 5;
    const auto points = growth::Envelope::sphere({0, 6, 0}, 4.5f).sample(600, 5);
    growth::ColonizationResult r = growth::colonize(points, p);
    // The node ends with the final radius pass (its defaults: taper 0.1, junction_slope 0.08).
    skel::shapeRadii(r.skeleton);
    EXPECT_EQ(out.skeleton->position, r.skeleton.position);
    EXPECT_EQ(out.skeleton->radius, r.skeleton.radius);
    EXPECT_EQ(out.skeleton->order, r.skeleton.order);
    EXPECT_EQ(out.stats.at("segments"), double(r.skeleton.segmentCount()));
    EXPECT_EQ(out.stats.at("attractors"), 600.0);
    EXPECT_EQ(out.stats.at("attractors_killed") + out.stats.at("attractors_left"), 600.0);
    EXPECT_EQ(out.stats.at("iterations"), double(r.iterations));
    EXPECT_TRUE(out.timingsMs.count("grow"));
}

TEST_F(SpaceColonizationNode, SeedOverrideWins) {
    Evaluator e(crownGraph(smallCrown()));
    const auto own = e.evaluate().skeleton;
    const auto same = e.evaluate(5).skeleton;
    const auto other = e.evaluate(6).skeleton;
    EXPECT_EQ(own->position, same->position);
    EXPECT_NE(own->position, other->position);
}

TEST_F(SpaceColonizationNode, MeshEnvelopeResolvesAgainstTheSpeciesFolder) {
    Value::Object params = smallCrown();
    params["envelope"] = Value::Object{{"shape", "mesh"},
                                       {"file", "cube.obj"},
                                       {"scale", 2.0},
                                       {"offset", Value::Array{0.0, 3.0, 0.0}}};
    Evaluator e(crownGraph(params));
    const NodeOutput& out = e.evaluate();
    glm::vec3 lo, hi;
    out.skeleton->bounds(lo, hi);
    // The cube spans [-2,2] x [3,7] x [-2,2]; the crown fills it to within one segment.
    EXPECT_GT(hi.y, 6.0f);
    EXPECT_LE(hi.y, 7.0f + 0.2f + 1e-4f);
    EXPECT_LE(hi.x, 2.0f + 0.2f + 1e-4f);
    EXPECT_GE(lo.x, -2.0f - 0.2f - 1e-4f);

    params["envelope"] = Value::Object{{"shape", "mesh"}, {"file", "no-such-crown.obj"}};
    const std::string msg = errorOf(crownGraph(params));
    EXPECT_NE(msg.find("no-such-crown.obj"), std::string::npos) << msg;
}

TEST_F(SpaceColonizationNode, BadParametersGiveClearMessages) {
    Value::Object p = smallCrown();
    p["kill_distance"] = 4.0;
    EXPECT_NE(errorOf(crownGraph(p)).find("kill_distance must be smaller than influence_distance"),
              std::string::npos);
    p = smallCrown();
    p["kill_distance"] = 0.1;
    EXPECT_NE(errorOf(crownGraph(p)).find("larger than segment_length"), std::string::npos);
    p = smallCrown();
    p["attractors"] = 0;
    EXPECT_NE(errorOf(crownGraph(p)).find("attractors must be in [1, 2000000]"), std::string::npos);
    p = smallCrown();
    p["envelope"] = Value::Object{{"shape", "sphere"}, {"radius", 2.0}, {"radii", 3.0}};
    EXPECT_NE(errorOf(crownGraph(p)).find("unknown key 'radii'"), std::string::npos);
    p = smallCrown();
    p["envelope"] = Value::Object{{"shape", "torus"}};
    EXPECT_NE(errorOf(crownGraph(p)).find("envelope shape must be one of"), std::string::npos);
    p = smallCrown();
    p["pipe_exponent"] = 9.0;
    EXPECT_NE(errorOf(crownGraph(p)).find("pipe_exponent must be in [1, 4]"), std::string::npos);
    // Messages name the node.
    EXPECT_NE(errorOf(crownGraph(p)).find("crown"), std::string::npos);
}

TEST_F(SpaceColonizationNode, GrowsOnAnUpstreamSkeleton) {
    SpeciesGraph g = crownGraph(smallCrown());
    g.nodes.insert(
        g.nodes.begin(),
        NodeDesc{"trunk",
                 "lsystem",
                 Value::Object{{"grammar", "generations: 0\nstep: 0.5\naxiom: FFFF/F\n"}},
                 {}});
    g.nodes.back().inputs = {"trunk"};
    Evaluator e(g);
    const NodeOutput& trunkOut = e.evaluateNode("trunk", false, 0);
    const auto trunk = trunkOut.skeleton;
    const NodeOutput& out = e.evaluate();
    ASSERT_GT(out.skeleton->size(), trunk->size() + 50);
    for (std::size_t i = 0; i < trunk->size(); ++i)
        EXPECT_EQ(out.skeleton->position[i], trunk->position[i]);
    EXPECT_TRUE(out.stats.count("symbols")); // accumulated from the input
}

TEST_F(SpaceColonizationNode, PresetsGrow) {
    for (const char* name :
         {"sc-round.json", "sc-columnar.json", "sc-umbrella.json", "sc-lsystem-trunk.json"}) {
        SCOPED_TRACE(name);
        Evaluator e(loadPreset(name));
        const NodeOutput& out = e.evaluate();
        ASSERT_TRUE(out.skeleton);
        ASSERT_TRUE(out.mesh);
        EXPECT_GT(out.skeleton->size(), 500u);
        EXPECT_GT(out.mesh->triangleCount(), 1000u);
        EXPECT_NE(out.stats.at("stop_reason"), 2.0) << "hit the iteration cap";
    }
}
