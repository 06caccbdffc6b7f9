// Issue #44: one continuous tree. Every species file in presets/ (globbed, so a new species is
// covered), grown at seeds 11 and 47, has a flared base, a trunk that tapers under its crown,
// no branch thicker than the branch it grows from and no radius step along its trunk; the oak
// keeps its lower trunk bare of leaves. Radii near the ground are measured on the mesh (the
// flare is the mesher's); the others on the skeleton every exporter, LOD and the wind read.

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
#include "engine/skeleton/skeleton.h"

using namespace sylva;

namespace {

const std::filesystem::path kPresets = SYLVA_PRESETS_DIR;

// The thresholds the issue states.
constexpr double kMinFlare = 1.25;     ///< ground radius / radius 1 m up
constexpr double kMaxTaper = 0.92;     ///< radius under the crown / radius 1 m up
constexpr double kMinClearTrunk = 1.0; ///< taper checked where the clear trunk is this long (m)
/// Along the trunk's axis the radius falls by at most this much per metre between consecutive
/// nodes (a cone of about 6°): a fall faster than that reads as a step or a collar.
constexpr double kMaxStepSlope = 0.1;
/// Where the trunk's axis ends at a fork, its thickest child keeps at least this share of the
/// trunk's radius there (no trunk much wider than the fork above it).
constexpr double kMinForkShare = 0.75;
constexpr double kMaxLowLeafShare = 0.005; ///< oak: leaf triangles in the lowest quarter

std::vector<std::filesystem::path> speciesFiles() {
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(kPresets))
        if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

struct Measured {
    double flare = 0.0;     ///< mesh radius at 3 mm / at 1 m; 0: the trunk is lower
    double rootFlare = 0.0; ///< mesh radius at 3 mm / the root node's radius
    double taper = 0.0;     ///< skeleton radius under the crown / at 1 m; 0: crown at 1 m or lower
    double crownBase = 0.0; ///< height of the trunk's first fork (m)
    double childParent = 0.0;
    double stepSlope = 0.0;
    double forkShare = 1.0;
    double lowLeafShare = 0.0;
    double breastRadius = 0.0; ///< skeleton radius 1.3 m up (half the DBH), for the record
    bool hasTrunk = false;
};

// Mean distance of the trunk tube's surface from its centre where the plane y = h cuts it:
// the bark triangles of the trunk's nodes only (laterals' base rings carry their own node).
double meshRadiusAt(const mesh::Mesh& m, const std::vector<std::uint8_t>& onTrunk, double h) {
    std::vector<glm::dvec2> pts;
    std::vector<mesh::Submesh> runs = m.submeshes;
    if (runs.empty()) runs.push_back({"bark", 0, static_cast<std::uint32_t>(m.indices.size())});
    for (const mesh::Submesh& sm : runs) {
        if (sm.material != "bark") continue;
        for (std::size_t t = sm.firstIndex; t + 2 < sm.firstIndex + sm.indexCount; t += 3) {
            const std::uint32_t v[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
            bool trunk = true;
            for (std::uint32_t k : v)
                trunk = trunk && m.node[k] < onTrunk.size() && onTrunk[m.node[k]];
            if (!trunk) continue;
            for (int e = 0; e < 3; ++e) {
                const glm::dvec3 a(m.positions[v[e]]), b(m.positions[v[(e + 1) % 3]]);
                if ((a.y - h) * (b.y - h) >= 0.0 || a.y == b.y) continue;
                const double u = (h - a.y) / (b.y - a.y);
                const glm::dvec3 p = a + u * (b - a);
                pts.emplace_back(p.x, p.z);
            }
        }
    }
    if (pts.empty()) return 0.0;
    glm::dvec2 c(0.0);
    for (const glm::dvec2& p : pts)
        c += p;
    c /= static_cast<double>(pts.size());
    double r = 0.0;
    for (const glm::dvec2& p : pts)
        r += glm::length(p - c);
    return r / static_cast<double>(pts.size());
}

Measured measure(const std::filesystem::path& file, std::uint64_t seed) {
    graph::registerBuiltinNodeTypes();
    graph::SpeciesGraph g = sylva::testing::loadPreset(file);
    for (graph::NodeDesc& n : g.nodes)
        if (n.type == "tube_mesh") {
            Value::Object params = n.params.toObject();
            params["node_ids"] = Value(true);
            n.params = Value(std::move(params));
        }
    graph::Evaluator evaluator(std::move(g));
    const graph::NodeOutput& out = evaluator.evaluate(seed);
    Measured r;
    if (!out.mesh || !out.skeleton) return r;
    const skel::Skeleton& s = *out.skeleton;
    const mesh::Mesh& m = *out.mesh;
    auto visible = [&](std::size_t i) { return (s.flags[i] & skel::kHidden) == 0; };

    // Every branch no thicker than the one it grows from, at the junction.
    for (std::size_t i = 0; i < s.size(); ++i) {
        const std::int32_t p = s.parent[i];
        if (p < 0 || !visible(i)) continue;
        r.childParent = std::max(r.childParent, static_cast<double>(s.radius[i]) /
                                                    s.radius[static_cast<std::size_t>(p)]);
    }

    // The trunk: the first root's axis (children of its own order), as the mesher draws it.
    std::vector<std::vector<std::int32_t>> children(s.size());
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.parent[i] >= 0 && visible(i))
            children[static_cast<std::size_t>(s.parent[i])].push_back(static_cast<std::int32_t>(i));
    std::vector<std::int32_t> trunk;
    std::vector<std::uint8_t> onTrunk(s.size(), 0);
    for (std::int32_t x = 0; x >= 0 && !s.empty();) {
        trunk.push_back(x);
        onTrunk[static_cast<std::size_t>(x)] = 1;
        std::int32_t next = -1;
        for (std::int32_t c : children[static_cast<std::size_t>(x)])
            if (s.order[static_cast<std::size_t>(c)] == s.order[static_cast<std::size_t>(x)]) {
                next = c;
                break;
            }
        x = next;
    }
    r.hasTrunk = trunk.size() >= 2;
    if (!r.hasTrunk) return r;
    auto R = [&](std::int32_t i) {
        return static_cast<double>(s.radius[static_cast<std::size_t>(i)]);
    };
    auto Y = [&](std::int32_t i) {
        return static_cast<double>(s.position[static_cast<std::size_t>(i)].y);
    };
    for (std::size_t k = 0; k + 1 < trunk.size(); ++k) {
        const double len = glm::length(s.position[static_cast<std::size_t>(trunk[k + 1])] -
                                       s.position[static_cast<std::size_t>(trunk[k])]);
        if (len > 1e-6) r.stepSlope = std::max(r.stepSlope, (R(trunk[k]) - R(trunk[k + 1])) / len);
    }
    const std::int32_t top = trunk.back();
    double thickest = 0.0;
    for (std::int32_t c : children[static_cast<std::size_t>(top)])
        thickest = std::max(thickest, R(c));
    if (!children[static_cast<std::size_t>(top)].empty()) r.forkShare = thickest / R(top);

    // The crown base: the trunk's first node with a visible lateral.
    std::size_t fork = trunk.size() - 1;
    for (std::size_t k = 0; k < trunk.size(); ++k)
        if (children[static_cast<std::size_t>(trunk[k])].size() >
            (k + 1 < trunk.size() ? 1u : 0u)) {
            fork = k;
            break;
        }
    r.crownBase = Y(trunk[fork]);
    // Skeleton radius at height h along the trunk (linear between nodes, as the tubes).
    auto radiusAt = [&](double h) {
        for (std::size_t k = 0; k + 1 < trunk.size(); ++k) {
            const double y0 = Y(trunk[k]), y1 = Y(trunk[k + 1]);
            if (h >= y0 && h <= y1 && y1 > y0)
                return R(trunk[k]) + (h - y0) / (y1 - y0) * (R(trunk[k + 1]) - R(trunk[k]));
        }
        return 0.0;
    };
    r.breastRadius = radiusAt(Y(trunk[0]) + 1.3);
    // Printed wherever the crown starts above 1 m, checked from kMinClearTrunk up.
    if (r.crownBase > 1.05 && radiusAt(1.0) > 0.0) r.taper = R(trunk[fork]) / radiusAt(1.0);

    const double ground = meshRadiusAt(m, onTrunk, Y(trunk[0]) + 0.003);
    // 1 m up (a hair above, where rings lie exactly at 1 m).
    const double up = Y(trunk.back()) >= Y(trunk[0]) + 1.2 ? meshRadiusAt(m, onTrunk, 1.0001) : 0.0;
    r.flare = up > 0.0 ? ground / up : 0.0;
    r.rootFlare = ground / R(trunk[0]);

    // Leaf triangles in the lowest quarter of the tree's height.
    double height = 0.0;
    for (const glm::vec3& p : m.positions)
        height = std::max(height, static_cast<double>(p.y));
    std::size_t leafTris = 0, low = 0;
    for (const mesh::Submesh& sm : m.submeshes) {
        if (sm.material != "leaf") continue;
        for (std::size_t t = sm.firstIndex; t + 2 < sm.firstIndex + sm.indexCount; t += 3) {
            const double y = (m.positions[m.indices[t]].y + m.positions[m.indices[t + 1]].y +
                              m.positions[m.indices[t + 2]].y) /
                             3.0;
            ++leafTris;
            low += y < 0.25 * height ? 1 : 0;
        }
    }
    r.lowLeafShare = leafTris > 0 ? static_cast<double>(low) / static_cast<double>(leafTris) : 0.0;
    return r;
}

} // namespace

TEST(TrunkJunctions, EverySpeciesIsOneContinuousTree) {
    const std::vector<std::filesystem::path> files = speciesFiles();
    ASSERT_GE(files.size(), 12u);
    for (const std::filesystem::path& file : files) {
        const std::string name = file.stem().string();
        for (std::uint64_t seed : {11u, 47u}) {
            SCOPED_TRACE(name + " seed " + std::to_string(seed));
            const Measured m = measure(file, seed);
            std::printf("%-22s seed %2llu: flare %.3f (at the root %.3f) taper %.3f (crown base "
                        "%.2f m) child/parent "
                        "%.3f step slope %.3f fork share %.3f low leaves %.4f r(1.3 m) %.3f\n",
                        name.c_str(), static_cast<unsigned long long>(seed), m.flare, m.rootFlare,
                        m.taper, m.crownBase, m.childParent, m.stepSlope, m.forkShare,
                        m.lowLeafShare, m.breastRadius);
            if (!m.hasTrunk) continue;
            if (m.flare > 0.0) {
                EXPECT_GE(m.flare, kMinFlare);
            }
            EXPECT_GE(m.rootFlare, kMinFlare);
            if (m.taper > 0.0 && m.crownBase >= kMinClearTrunk) {
                EXPECT_LE(m.taper, kMaxTaper);
            }
            EXPECT_LE(m.childParent, 1.0 + 1e-5);
            EXPECT_LE(m.stepSlope, kMaxStepSlope);
            EXPECT_GE(m.forkShare, kMinForkShare);
            if (name == "english-oak") {
                EXPECT_LE(m.lowLeafShare, kMaxLowLeafShare);
            }
        }
    }
}
