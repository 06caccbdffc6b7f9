// Issue #44: bark as geometry at the nearest level. The oak's and the pine's trunks stand out in
// ridges and plates around their rings (radial deviation of the LOD-0 surface where a plane cuts
// the trunk), the beech's stays smooth; past the first LOD band the tubes are as without relief.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../forest/presetfile.h"
#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/mesh/treemesh.h"
#include "engine/nodes/meshnodes.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/image.h"

using namespace sylva;

namespace {

const std::filesystem::path kPresets = SYLVA_PRESETS_DIR;

struct Grown {
    std::shared_ptr<const skel::Skeleton> skeleton;
    std::shared_ptr<const mesh::Mesh> mesh;
};

Grown grow(const std::string& species, std::uint64_t seed, const Value::Object& extra = {}) {
    graph::registerBuiltinNodeTypes();
    graph::SpeciesGraph g = sylva::testing::loadPreset(kPresets / (species + ".json"));
    for (graph::NodeDesc& n : g.nodes)
        if (n.type == "tube_mesh") {
            Value::Object params = n.params.toObject();
            params["node_ids"] = Value(true);
            for (const auto& [key, value] : extra)
                params[key] = value;
            n.params = Value(std::move(params));
        }
    graph::Evaluator evaluator(std::move(g));
    const graph::NodeOutput& out = evaluator.evaluate(seed);
    return {out.skeleton, out.mesh};
}

/// Mean over planes y = 1.2 .. 1.8 m (above every flare and buttress) of the spread of the
/// trunk's cut outline around its centre: the largest distance from the centre less the
/// smallest, metres. Only bark triangles whose vertices all belong to the trunk's own nodes.
double trunkRelief(const Grown& g) {
    const skel::Skeleton& s = *g.skeleton;
    const mesh::Mesh& m = *g.mesh;
    std::vector<std::uint8_t> onTrunk(s.size(), 0);
    for (std::int32_t x = 0; x >= 0 && !s.empty();) {
        onTrunk[static_cast<std::size_t>(x)] = 1;
        std::int32_t next = -1;
        for (std::size_t c = 0; c < s.size() && next < 0; ++c)
            if (s.parent[c] == x && s.order[c] == s.order[static_cast<std::size_t>(x)] &&
                !(s.flags[c] & skel::kHidden))
                next = static_cast<std::int32_t>(c);
        x = next;
    }
    double sum = 0.0;
    int planes = 0;
    for (double h = 1.2; h <= 1.8001; h += 0.05) {
        std::vector<glm::dvec2> pts;
        for (const mesh::Submesh& sm : m.submeshes) {
            if (sm.material != "bark") continue;
            for (std::size_t t = sm.firstIndex; t + 2 < sm.firstIndex + sm.indexCount; t += 3) {
                const std::uint32_t v[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
                if (!onTrunk[m.node[v[0]]] || !onTrunk[m.node[v[1]]] || !onTrunk[m.node[v[2]]])
                    continue;
                for (int e = 0; e < 3; ++e) {
                    const glm::dvec3 a(m.positions[v[e]]), b(m.positions[v[(e + 1) % 3]]);
                    if ((a.y - h) * (b.y - h) >= 0.0 || a.y == b.y) continue;
                    const glm::dvec3 p = a + (h - a.y) / (b.y - a.y) * (b - a);
                    pts.emplace_back(p.x, p.z);
                }
            }
        }
        if (pts.size() < 6) continue;
        glm::dvec2 c(0.0);
        for (const glm::dvec2& p : pts)
            c += p;
        c /= static_cast<double>(pts.size());
        double lo = 1e9, hi = 0.0;
        for (const glm::dvec2& p : pts) {
            lo = std::min(lo, glm::length(p - c));
            hi = std::max(hi, glm::length(p - c));
        }
        sum += hi - lo;
        ++planes;
    }
    return planes > 0 ? sum / planes : 0.0;
}

} // namespace

TEST(BarkRelief, OakRidgedPinePlatedBeechSmooth) {
    for (std::uint64_t seed : {11u, 47u}) {
        const double oak = trunkRelief(grow("english-oak", seed));
        const double oakFlat =
            trunkRelief(grow("english-oak", seed, {{"bark_relief", Value(0.0)}}));
        const double pine = trunkRelief(grow("scots-pine", seed));
        const double beech = trunkRelief(grow("european-beech", seed));
        std::printf("seed %llu: trunk relief at 1.2-1.8 m: oak %.1f mm (without relief %.1f), "
                    "Scots pine %.1f mm, beech %.1f mm\n",
                    static_cast<unsigned long long>(seed), 1e3 * oak, 1e3 * oakFlat, 1e3 * pine,
                    1e3 * beech);
        EXPECT_GE(oak, 0.025) << seed;
        EXPECT_LE(oakFlat, 0.010) << seed; // a polygon's facets, the taper across a plane
        EXPECT_GE(pine, 0.015) << seed;
        EXPECT_LE(beech, 0.010) << seed;
    }
}

TEST(BarkRelief, DeterministicAndOnlyAtTheNearestLevel) {
    const Grown a = grow("english-oak", 11), b = grow("english-oak", 11);
    ASSERT_EQ(a.mesh->positions, b.mesh->positions);
    ASSERT_EQ(a.mesh->normals, b.mesh->normals);
    for (const glm::vec3& n : a.mesh->normals)
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-3f);

    // Past the first band the tubes are those of the same tree without relief.
    graph::registerBuiltinNodeTypes();
    mesh::TreeMeshSettings settings = mesh::treeMeshSettingsFromParams(
        sylva::testing::loadPreset(kPresets / "english-oak.json").nodes.back().params, 1, {});
    ASSERT_GT(settings.tubes.barkRelief, 0.0);
    settings.useLod = true;
    settings.cameraDistance = 30.0; // the second band
    mesh::TreeMeshSettings flat = settings;
    flat.tubes.barkRelief = 0.0;
    const mesh::Mesh far = mesh::buildTreeMesh(*a.skeleton, settings);
    const mesh::Mesh farFlat = mesh::buildTreeMesh(*a.skeleton, flat);
    EXPECT_EQ(far.positions, farFlat.positions);
    EXPECT_EQ(far.indices, farFlat.indices);
    // The first band keeps it: more triangles than without.
    settings.cameraDistance = flat.cameraDistance = 5.0;
    EXPECT_GT(mesh::buildTreeMesh(*a.skeleton, settings).triangleCount(),
              mesh::buildTreeMesh(*a.skeleton, flat).triangleCount());
}

TEST(BarkRelief, BadParametersNameTheirRange) {
    Value::Object p;
    p["bark_relief"] = Value(0.9);
    EXPECT_THROW(mesh::treeMeshSettingsFromParams(Value(p), 1, {}), InvalidInput);
    p["bark_relief"] = Value(0.1);
    p["bark_relief_pattern"] = Value(std::string("scales"));
    try {
        mesh::treeMeshSettingsFromParams(Value(p), 1, {});
        FAIL() << "no error for an unknown pattern";
    } catch (const InvalidInput& e) {
        // The choices from tube_mesh's table, as the parameter panel and docs show them.
        EXPECT_NE(std::string(e.what()).find("bark_relief_pattern must be one of ridges | plates"),
                  std::string::npos)
            << e.what();
    }
}

// The pine's bark vertex colours, averaged below 2 m and above 9 m (seed 11).
struct LowHigh {
    glm::dvec3 low{0.0}, high{0.0};
};

LowHigh pineBarkColours() {
    const Grown g = grow("scots-pine", 11);
    const mesh::Mesh& m = *g.mesh;
    EXPECT_EQ(m.colors.size(), m.positions.size());
    LowHigh r;
    int nLow = 0, nHigh = 0;
    for (const mesh::Submesh& sm : m.submeshes) {
        if (sm.material != "bark") continue;
        for (std::size_t t = sm.firstIndex; t < sm.firstIndex + sm.indexCount; ++t) {
            const std::uint32_t v = m.indices[t];
            if (v >= m.colors.size()) continue;
            const glm::dvec3 c = glm::dvec3(m.colors[v]) / 255.0;
            if (m.positions[v].y < 2.0f) {
                r.low += c;
                ++nLow;
            } else if (m.positions[v].y > 9.0f) {
                r.high += c;
                ++nHigh;
            }
        }
    }
    EXPECT_GT(nLow, 0);
    EXPECT_GT(nHigh, 0);
    r.low /= std::max(nLow, 1);
    r.high /= std::max(nHigh, 1);
    return r;
}

TEST(BarkRelief, PineBarkGreyLowOrangeHigh) {
    const LowHigh c = pineBarkColours();
    // Low: grey (channels within a few percent); high: orange (red well above blue).
    EXPECT_LT(c.low.x - c.low.z, 0.06);
    EXPECT_GT(c.high.x - c.high.z, 0.35);
    EXPECT_GT(c.high.x, c.low.x);
}

// The orange comes from the height tint, not the texture: the pine's bark texture is grey-brown
// plates (its orange patches showed low on the stem too), and tinted it reads grey-brown low and
// orange high (its mean times the vertex colours, as the viewport and the exporters multiply).
TEST(BarkRelief, PineBarkTextureGreyBrownTintedOrangeHigh) {
    const Image tex = readPng(kPresets / "textures" / "scots-pine_bark.png");
    ASSERT_FALSE(tex.empty());
    glm::dvec3 mean(0.0);
    std::size_t orange = 0;
    for (int y = 0; y < tex.height; ++y)
        for (int x = 0; x < tex.width; ++x) {
            const std::uint8_t* p = tex.at(x, y);
            const glm::dvec3 c(p[0] / 255.0, p[1] / 255.0, p[2] / 255.0);
            mean += c;
            orange += c.x - c.z > 0.3 ? 1 : 0;
        }
    const double texels = static_cast<double>(tex.width) * tex.height;
    mean /= texels;
    const LowHigh c = pineBarkColours();
    const glm::dvec3 low = mean * c.low, high = mean * c.high;
    std::printf("pine bark texture: mean %.3f %.3f %.3f, orange texels %.2f %%; tinted low %.3f "
                "%.3f %.3f, high %.3f %.3f %.3f\n",
                mean.x, mean.y, mean.z, 100.0 * static_cast<double>(orange) / texels, low.x, low.y,
                low.z, high.x, high.y, high.z);
    // The texture drawn with orange patches had 10.7 % of its texels this orange.
    EXPECT_LT(static_cast<double>(orange) / texels, 0.01);
    EXPECT_LT(low.x - low.z, 0.07);
    EXPECT_GT(high.x - high.z, 0.3);
}
