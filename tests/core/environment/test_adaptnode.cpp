#include <gtest/gtest.h>

#include <filesystem>

#include "engine/graph/graph.h"
#include "engine/nodes/adaptnode.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::graph;

namespace {

/// A trunk of 12 half-metre segments with a branch at 2 m reaching 1.1 m toward +x.
NodeOutput testTree(const NodeContext&) {
    auto s = std::make_shared<skel::Skeleton>();
    s->addNode(glm::vec3(0.0f), -1, 0.2f, 0, glm::quat(1, 0, 0, 0));
    for (int i = 1; i <= 12; ++i)
        s->addNode(glm::vec3(0, 0.5f * static_cast<float>(i), 0), i - 1, 0.15f, 0,
                   glm::quat(1, 0, 0, 0));
    std::int32_t last = 4;
    for (int j = 1; j <= 5; ++j)
        last = s->addNode(
            glm::vec3(0.22f * static_cast<float>(j), 2.0f + 0.1f * static_cast<float>(j), 0), last,
            0.05f, 1, glm::quat(1, 0, 0, 0));
    NodeOutput out;
    out.skeleton = std::move(s);
    out.stats["segments"] = 17;
    return out;
}

SpeciesGraph graphWith(Value adaptParams) {
    registerBuiltinNodeTypes();
    NodeRegistry::instance().add(NodeType{"test_tree", 0, 0, testTree, {}, {}, {}, {}});
    SpeciesGraph g;
    g.name = "test";
    g.nodes.push_back(NodeDesc{"gen", "test_tree", Value::Object{}, {}});
    g.nodes.push_back(NodeDesc{"adapt", "adapt", std::move(adaptParams), {"gen"}});
    g.output = "adapt";
    g.baseDir = std::filesystem::path(SYLVA_TEST_DATA_DIR) / "obstacles";
    return g;
}

Value wallAt(double x) {
    Value::Object wall;
    wall["file"] = "wall.obj"; // 0.2 m thick, centred on x = 0
    wall["translate"] = Value::Array{x, 0.0, 0.0};
    return Value::Object{{"obstacles", Value::Array{Value(wall)}}};
}

} // namespace

TEST(AdaptNode, BendsTheInputAwayFromItsObstacles) {
    Evaluator ev(graphWith(wallAt(1.1)));
    const NodeOutput& out = ev.evaluate();
    ASSERT_TRUE(out.skeleton);
    EXPECT_LT(out.skeleton->position[12].x, -0.2f);
    EXPECT_GE(out.stats.at("adapt_colliding_before"), 1.0);
    EXPECT_EQ(out.stats.at("adapt_hidden_nodes"), 0.0);
    EXPECT_EQ(out.stats.at("adapt_obstacle_triangles"), 12.0);
    EXPECT_EQ(out.stats.at("segments"), 17.0); // the generator's stats pass through
    EXPECT_TRUE(out.timingsMs.count("adapt"));

    // The tree's own placement: moved 5 m to -x, the wall no longer touches it.
    Value moved = wallAt(1.1);
    moved.objectRef()["position"] = Value::Array{-5.0, 0.0, 0.0};
    Evaluator far(graphWith(moved));
    EXPECT_EQ(far.evaluate().skeleton->position[12], glm::vec3(0, 6, 0));

    // Switches reach the algorithm: no pruning and no bending leaves the collision in place.
    Value still = wallAt(1.1);
    still.objectRef()["max_bend"] = 0.0;
    still.objectRef()["prune"] = false;
    Evaluator none(graphWith(still));
    EXPECT_GE(none.evaluate().stats.at("adapt_colliding_after"), 1.0);
}

TEST(AdaptNode, BadParametersAndFilesGetTheirMessages) {
    Value missing =
        Value::Object{{"obstacles", Value::Array{Value(Value::Object{{"file", "nowhere.obj"}})}}};
    Evaluator ev(graphWith(missing));
    try {
        ev.evaluate();
        ADD_FAILURE() << "a missing obstacle file was accepted";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find("nowhere.obj"), std::string::npos) << e.what();
    }
    Value bend = wallAt(1.1);
    bend.objectRef()["max_bend"] = 3.0;
    EXPECT_THROW(Evaluator(graphWith(bend)), InvalidInput); // refused by the node metadata
    Value key = Value::Object{
        {"obstacles", Value::Array{Value(Value::Object{{"file", "wall.obj"}, {"offset", 1.0}})}}};
    Evaluator badKey(graphWith(key));
    try {
        badKey.evaluate();
        ADD_FAILURE();
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("offset"), std::string::npos) << e.what();
    }
}

TEST(AdaptNode, ObstacleScenesAreCachedByFileAndTransform) {
    const std::filesystem::path wall =
        std::filesystem::path(SYLVA_TEST_DATA_DIR) / "obstacles" / "wall.obj";
    const auto a = env::loadObstacleScene({{wall, {}}});
    const auto b = env::loadObstacleScene({{wall, {}}});
    EXPECT_EQ(a.get(), b.get());
    env::MeshTransform t;
    t.translate = glm::vec3(1, 0, 0);
    const auto c = env::loadObstacleScene({{wall, t}});
    EXPECT_NE(a.get(), c.get());
    EXPECT_NEAR(c->lo().x, 0.9f, 1e-6f);
    EXPECT_NE(env::loadObstacleScene({{wall, {}}}, false).get(), a.get());
    // The same file spelled through another folder (a project saved elsewhere names it by
    // another relative path) is the same scene.
    const std::filesystem::path roundabout =
        std::filesystem::path(SYLVA_TEST_DATA_DIR) / "obstacles" / ".." / "obstacles" / "wall.obj";
    EXPECT_EQ(env::loadObstacleScene({{roundabout, {}}}).get(), a.get());
}
