#include <gtest/gtest.h>

#include "engine/graph/graph.h"
#include "engine/nodes/meshnodes.h"
#include "engine/util/error.h"

using namespace sylva;
using sylva::Value;

namespace {

graph::SpeciesGraph species(Value::Object meshParams, bool withLeaves = false) {
    graph::SpeciesGraph g;
    g.name = "test";
    Value::Object grow{{"grammar", Value("generations: 3\nangle: 30\nwidth: 0.2\naxiom: X\n"
                                         "X -> F[&!XJ]/(120)[&!XJ]/(120)!FX\n")}};
    g.nodes.push_back({"grow", "lsystem", Value(grow), {}});
    std::string meshInput = "grow";
    if (withLeaves) {
        g.nodes.push_back({"leaves",
                           "leaves",
                           Value(Value::Object{{"phyllotaxis", Value("opposite")},
                                               {"max_branch_radius", Value(0.05)}}),
                           {"grow"}});
        meshInput = "leaves";
    }
    g.nodes.push_back({"mesh", "tube_mesh", Value(std::move(meshParams)), {meshInput}});
    g.output = "mesh";
    return g;
}

} // namespace

TEST(MeshNodes, TubeMeshStatsAndPassThrough) {
    graph::Evaluator ev(species({{"resolution", Value(6)}}));
    const graph::NodeOutput& out = ev.evaluate();
    ASSERT_TRUE(out.mesh);
    ASSERT_TRUE(out.skeleton);
    EXPECT_EQ(out.stats.at("vertices"), static_cast<double>(out.mesh->vertexCount()));
    EXPECT_EQ(out.stats.at("triangles"), static_cast<double>(out.mesh->triangleCount()));
    EXPECT_TRUE(out.timingsMs.count("mesh"));
    EXPECT_EQ(out.skeleton, ev.evaluateNode("grow", false, 0).skeleton);
    // Grammar leaves (J) become cards.
    EXPECT_EQ(out.mesh->submeshes.back().material, "leaf");
    EXPECT_EQ(out.mesh->submeshes.back().indexCount, 6u * out.skeleton->leaves.size());
}

TEST(MeshNodes, ResolutionOutOfRangeNamesTheRange) {
    // Refused when the graph is built (the node metadata's range), before anything runs.
    try {
        graph::Evaluator ev(species({{"resolution", Value(65)}}));
        FAIL();
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("resolution must be in [3, 64]"), std::string::npos)
            << e.what();
    }
}

TEST(MeshNodes, LeavesNodeAndLod) {
    graph::Evaluator near(species({{"lod_distance", Value(0)}}, true));
    graph::Evaluator far(species({{"lod_distance", Value(100)}}, true));
    const auto& a = near.evaluate();
    const auto& b = far.evaluate();
    EXPECT_GT(a.stats.at("leaves"), 0.0);
    EXPECT_LT(b.stats.at("triangles"), a.stats.at("triangles"));
    EXPECT_EQ(b.stats.at("lod_band"), 2.0);
    EXPECT_THROW(graph::Evaluator(species({{"thickness", Value("pipe")}})), InvalidInput);
}

TEST(MeshNodes, SettingsFromParams) {
    const Value params(Value::Object{
        {"resolution", Value(5)},
        {"thickness", Value("branching")},
        {"lod_bands", Value(Value::Array{Value(Value::Array{Value(0), Value(7)}),
                                         Value(Value::Array{Value(30), Value(4), Value(0.5)})})},
        {"lod_distance", Value(31)}});
    const mesh::TreeMeshSettings s = mesh::treeMeshSettingsFromParams(params, 1);
    EXPECT_EQ(s.tubes.resolution, 5);
    EXPECT_EQ(s.tubes.thickness, mesh::ThicknessMode::Branching);
    ASSERT_EQ(s.lod.bands.size(), 2u);
    EXPECT_EQ(s.lod.bands[1].resolution, 4);
    EXPECT_TRUE(s.useLod);
    EXPECT_EQ(mesh::selectLod(s.lod, s.cameraDistance).resolution, 4);
}

// The default LOD bands (8, 5, 3 sides) were finer than a species of 6 sides near the camera:
// the bench species' tree had 393,652 triangles at the camera LOD for 5 to 20 m against
// 301,800 without it. They are capped at the species' resolution; explicit bands are kept.
TEST(MeshNodes, DefaultLodIsNeverFinerThanTheSpecies) {
    const mesh::TreeMeshSettings six =
        mesh::treeMeshSettingsFromParams(Value(Value::Object{{"resolution", Value(6)}}), 1);
    ASSERT_EQ(six.lod.bands.size(), 3u);
    EXPECT_EQ(six.lod.bands[0].resolution, 6);
    EXPECT_EQ(six.lod.bands[1].resolution, 5);
    EXPECT_EQ(six.lod.bands[2].resolution, 3);
    for (const int resolution : {3, 4, 6, 8, 12}) {
        graph::Evaluator full(species({{"resolution", Value(resolution)}}, true));
        graph::Evaluator near(
            species({{"resolution", Value(resolution)}, {"lod_distance", Value(1)}}, true));
        EXPECT_LE(near.evaluate().stats.at("triangles"), full.evaluate().stats.at("triangles"))
            << resolution;
    }
    // Bands given explicitly are the artist's: kept even when finer.
    const mesh::TreeMeshSettings explicitBands = mesh::treeMeshSettingsFromParams(
        Value(Value::Object{
            {"resolution", Value(4)},
            {"lod_bands", Value(Value::Array{Value(Value::Array{Value(0), Value(9)})})}}),
        1);
    EXPECT_EQ(explicitBands.lod.bands[0].resolution, 9);
}
