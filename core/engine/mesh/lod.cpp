#include "engine/mesh/lod.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>

#include "engine/util/error.h"
#include "engine/util/random.h"

namespace sylva::mesh {

void validateLod(const LodSettings& settings) {
    if (settings.bands.empty()) throw InvalidInput("lod_bands must not be empty");
    for (std::size_t i = 0; i < settings.bands.size(); ++i) {
        const LodBand& b = settings.bands[i];
        const std::string where = "lod band " + std::to_string(i);
        if (i == 0 && b.distance != 0.0)
            throw InvalidInput(where + ": the first band must start at distance 0");
        if (i > 0 && !(b.distance > settings.bands[i - 1].distance))
            throw InvalidInput(where + ": distances must increase");
        requireRange((where + " resolution").c_str(), b.resolution, 3, 64);
        requireRange((where + " leaf fraction").c_str(), b.leafFraction, 1e-3, 1.0);
    }
    requireRange("lod screen height", settings.screenHeightPx, 1.0, 1e5);
    requireRange("lod fov", settings.fovYDegrees, 1.0, 179.0);
    requireRange("lod min twig pixels", settings.minTwigPixels, 0.0, 1e3);
    requireRange("lod simplify pixels", settings.simplifyPixels, 0.0, 1e3);
    requireRange("lod leaf cluster pixels", settings.leafClusterPixels, 0.0, 1e3);
    requireRange("lod ribbon pixels", settings.ribbonPixels, 0.0, 1e3);
}

LodLevel selectLod(const LodSettings& settings, double distance) {
    validateLod(settings);
    LodLevel level;
    for (std::size_t i = 0; i < settings.bands.size(); ++i)
        if (settings.bands[i].distance <= distance) level.band = i;
    const LodBand& b = settings.bands[level.band];
    level.resolution = b.resolution;
    level.leafFraction = b.leafFraction;
    if (level.band > 0) {
        // A length L at distance d covers L / (2 d tan(fov/2)) of the screen height.
        const double halfFov = settings.fovYDegrees * std::numbers::pi / 360.0;
        level.metresPerPixel = 2.0 * distance * std::tan(halfFov) / settings.screenHeightPx;
        level.minSubtreeExtent = settings.minTwigPixels * level.metresPerPixel;
        level.simplifyTolerance = settings.simplifyPixels * level.metresPerPixel;
        level.leafCell = settings.leafClusterPixels * level.metresPerPixel;
        level.ribbonRadius = 0.5 * settings.ribbonPixels * level.metresPerPixel;
    }
    return level;
}

skel::Skeleton dropSmallSubtrees(const skel::Skeleton& s, double minExtent, double leafScale) {
    skel::Skeleton out = s;
    const std::size_t n = s.size();
    if (minExtent <= 0.0 || n == 0) return out;
    // Bounds of every subtree (node positions and leaf cards), children before parents.
    std::vector<glm::vec3> lo(s.position), hi(s.position);
    for (const skel::Leaf& leaf : s.leaves) {
        if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) continue;
        const auto k = static_cast<std::size_t>(leaf.node);
        const glm::vec3 r(leaf.size * static_cast<float>(leafScale));
        lo[k] = glm::min(lo[k], leaf.position - r);
        hi[k] = glm::max(hi[k], leaf.position + r);
    }
    for (std::size_t i = n; i-- > 1;) {
        const std::int32_t p = s.parent[i];
        if (p < 0) continue;
        lo[static_cast<std::size_t>(p)] = glm::min(lo[static_cast<std::size_t>(p)], lo[i]);
        hi[static_cast<std::size_t>(p)] = glm::max(hi[static_cast<std::size_t>(p)], hi[i]);
    }
    // A lateral (a child of another branch order, as the tube mesher starts one) goes when its
    // subtree, together with the fork it grows from, is smaller than minExtent.
    std::vector<std::uint8_t> drop(n, 0);
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t pi = s.parent[i];
        if (pi < 0) continue;
        const auto p = static_cast<std::size_t>(pi);
        if (drop[p]) {
            drop[i] = 1;
            continue;
        }
        if (s.order[i] == s.order[p]) continue;
        const glm::vec3 l = glm::min(lo[i], s.position[p]), h = glm::max(hi[i], s.position[p]);
        if (static_cast<double>(glm::length(h - l)) < minExtent) {
            drop[i] = 1;
            any = true;
        }
    }
    if (!any) return out;
    for (std::size_t i = 0; i < n; ++i)
        if (drop[i]) out.flags[i] |= skel::kHidden;
    std::erase_if(out.leaves, [&](const skel::Leaf& leaf) {
        return leaf.node >= 0 && static_cast<std::size_t>(leaf.node) < n &&
               drop[static_cast<std::size_t>(leaf.node)];
    });
    return out;
}

std::vector<skel::Leaf> clusterLeaves(const std::vector<skel::Leaf>& leaves, double cell,
                                      double leafScale) {
    if (cell <= 0.0 || leaves.size() < 2) return leaves;
    struct Entry {
        std::int64_t x, y, z;
        std::size_t leaf;
    };
    std::vector<Entry> entries(leaves.size());
    std::vector<glm::dvec3> centre(leaves.size());
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        const skel::Leaf& l = leaves[i];
        centre[i] = glm::dvec3(l.position) +
                    glm::dvec3(skel::headingOf(l.orientation)) * (0.5 * l.size * leafScale);
        entries[i] = {static_cast<std::int64_t>(std::floor(centre[i].x / cell)),
                      static_cast<std::int64_t>(std::floor(centre[i].y / cell)),
                      static_cast<std::int64_t>(std::floor(centre[i].z / cell)), i};
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        return std::tie(a.x, a.y, a.z, a.leaf) < std::tie(b.x, b.y, b.z, b.leaf);
    });
    std::vector<skel::Leaf> out;
    out.reserve(leaves.size());
    for (std::size_t a = 0; a < entries.size();) {
        std::size_t b = a + 1;
        while (b < entries.size() && entries[b].x == entries[a].x && entries[b].y == entries[a].y &&
               entries[b].z == entries[a].z)
            ++b;
        if (b - a == 1) {
            out.push_back(leaves[entries[a].leaf]);
        } else {
            double area = 0.0;
            glm::dvec3 c(0.0);
            std::size_t largest = entries[a].leaf;
            for (std::size_t k = a; k < b; ++k) {
                const skel::Leaf& l = leaves[entries[k].leaf];
                const double w = static_cast<double>(l.size) * l.size;
                area += w;
                c += w * centre[entries[k].leaf];
                if (l.size > leaves[largest].size) largest = entries[k].leaf;
            }
            skel::Leaf merged = leaves[largest];
            if (area > 0.0) {
                c /= area;
                merged.size = static_cast<float>(std::sqrt(area));
            } else {
                c = centre[largest];
            }
            merged.position = glm::vec3(c - glm::dvec3(skel::headingOf(merged.orientation)) *
                                                (0.5 * merged.size * leafScale));
            out.push_back(merged);
        }
        a = b;
    }
    return out;
}

std::vector<skel::Leaf> thinLeaves(const std::vector<skel::Leaf>& leaves, double fraction,
                                   std::uint64_t seed) {
    if (fraction >= 1.0 || leaves.empty()) return leaves;
    std::vector<skel::Leaf> kept;
    kept.reserve(static_cast<std::size_t>(static_cast<double>(leaves.size()) * fraction) + 1);
    double total = 0.0, keptArea = 0.0;
    std::size_t largest = 0;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        const double a = static_cast<double>(leaves[i].size) * leaves[i].size;
        total += a;
        if (leaves[i].size > leaves[largest].size) largest = i;
        // Per-leaf decisions (not one stream) keep the choice stable when leaves are added.
        Rng rng(mixSeed(seed, i));
        if (rng.uniform() < fraction) {
            kept.push_back(leaves[i]);
            keptArea += a;
        }
    }
    if (kept.empty()) {
        kept.push_back(leaves[largest]);
        keptArea = static_cast<double>(leaves[largest].size) * leaves[largest].size;
    }
    if (keptArea > 0.0) {
        const auto s = static_cast<float>(std::sqrt(total / keptArea));
        for (skel::Leaf& l : kept)
            l.size *= s;
    }
    return kept;
}

namespace {

/// How much wider a ring of \p res sides must be to cover, seen from a random direction, as
/// much as one of \p base sides: their mean widths are perimeter / pi = 2 n r sin(pi/n) / pi.
double ringWidthCompensation(int base, int res) {
    if (res >= base) return 1.0;
    const auto width = [](int n) { return n * std::sin(std::numbers::pi / n); };
    return width(base) / width(res);
}

} // namespace

Mesh buildTreeMesh(const skel::Skeleton& skeleton, const TreeMeshSettings& settings,
                   Progress& progress) {
    TubeSettings tubes = settings.tubes;
    double leafFraction = 1.0;
    Mesh mesh;
    if (!settings.useLod) {
        appendTubes(mesh, skeleton, tubes, progress);
        if (settings.leaves && !skeleton.leaves.empty())
            appendLeafCards(mesh, skeleton.leaves, settings.leafCards, &skeleton);
        return mesh;
    }
    const LodLevel level = selectLod(settings.lod, settings.cameraDistance);
    const double compensation = ringWidthCompensation(tubes.resolution, level.resolution);
    if (level.band > 0) {
        tubes.caps = false; // a cap is a disc across a branch end: a pixel or less out here
        if (settings.hasCamera && level.ribbonRadius > 0.0) {
            tubes.ribbonBelowRadius = level.ribbonRadius;
            tubes.ribbonCamera = settings.cameraLocal;
            // A ribbon facing the camera is as wide as the full-detail ring's mean width.
            const int n = tubes.resolution;
            tubes.ribbonWidthScale =
                n * std::sin(std::numbers::pi / n) / std::numbers::pi / compensation;
        }
    }
    tubes.radiusScale *= compensation;
    tubes.resolution = level.resolution;
    tubes.simplifyTolerance = std::max(tubes.simplifyTolerance, level.simplifyTolerance);
    leafFraction = level.leafFraction;
    const skel::Skeleton kept =
        dropSmallSubtrees(skeleton, level.minSubtreeExtent, settings.leafCards.sizeScale);
    appendTubes(mesh, kept, tubes, progress);
    if (settings.leaves && !kept.leaves.empty()) {
        std::vector<skel::Leaf> leaves =
            clusterLeaves(kept.leaves, level.leafCell, settings.leafCards.sizeScale);
        if (leafFraction < 1.0) leaves = thinLeaves(leaves, leafFraction, settings.seed);
        appendLeafCards(mesh, leaves, settings.leafCards, &kept);
    }
    return mesh;
}

std::vector<LodChainLevel> buildLodChain(const skel::Skeleton& skeleton,
                                         const TreeMeshSettings& settings, Progress& progress) {
    validateLod(settings.lod);
    std::vector<LodChainLevel> chain;
    for (const LodBand& band : settings.lod.bands) {
        TreeMeshSettings s = settings;
        s.useLod = true;
        s.cameraDistance = band.distance;
        chain.push_back({band.distance, buildTreeMesh(skeleton, s, progress)});
    }
    return chain;
}

} // namespace sylva::mesh
