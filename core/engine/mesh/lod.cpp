#include "engine/mesh/lod.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

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
    requireRange("lod leafy twig pixels", settings.leafyTwigPixels, 0.0, 1e3);
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
        level.leafyTwigExtent = settings.leafyTwigPixels * level.metresPerPixel;
        level.simplifyTolerance = settings.simplifyPixels * level.metresPerPixel;
        level.leafCell = settings.leafClusterPixels * level.metresPerPixel;
        level.ribbonRadius = 0.5 * settings.ribbonPixels * level.metresPerPixel;
    }
    return level;
}

skel::Skeleton dropSmallSubtrees(const skel::Skeleton& s, double minExtent, double leafScale,
                                 double leafyExtent) {
    skel::Skeleton out = s;
    const std::size_t n = s.size();
    if ((minExtent <= 0.0 && leafyExtent <= 0.0) || n == 0) return out;
    // Bounds of every subtree (node positions and leaf cards) and whether it carries leaves,
    // children before parents.
    std::vector<glm::vec3> lo(s.position), hi(s.position);
    std::vector<std::uint8_t> leafy(n, 0);
    for (const skel::Leaf& leaf : s.leaves) {
        if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) continue;
        const auto k = static_cast<std::size_t>(leaf.node);
        const glm::vec3 r(leaf.size * static_cast<float>(leafScale));
        lo[k] = glm::min(lo[k], leaf.position - r);
        hi[k] = glm::max(hi[k], leaf.position + r);
        leafy[k] = 1;
    }
    for (std::size_t i = n; i-- > 1;) {
        const std::int32_t p = s.parent[i];
        if (p < 0) continue;
        lo[static_cast<std::size_t>(p)] = glm::min(lo[static_cast<std::size_t>(p)], lo[i]);
        hi[static_cast<std::size_t>(p)] = glm::max(hi[static_cast<std::size_t>(p)], hi[i]);
        leafy[static_cast<std::size_t>(p)] |= leafy[i];
    }
    // A lateral (a child of another branch order, as the tube mesher starts one) goes when its
    // subtree, together with the fork it grows from, is smaller than minExtent; a leafy one
    // smaller than leafyExtent loses its bark (2) but keeps its leaves.
    std::vector<std::uint8_t> drop(n, 0);
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t pi = s.parent[i];
        if (pi < 0) continue;
        const auto p = static_cast<std::size_t>(pi);
        if (drop[p]) {
            drop[i] = drop[p];
            continue;
        }
        if (s.order[i] == s.order[p]) continue;
        const glm::vec3 l = glm::min(lo[i], s.position[p]), h = glm::max(hi[i], s.position[p]);
        const auto extent = static_cast<double>(glm::length(h - l));
        if (extent < minExtent)
            drop[i] = 1;
        else if (leafy[i] && extent < leafyExtent)
            drop[i] = 2;
        any = any || drop[i] != 0;
    }
    if (!any) return out;
    for (std::size_t i = 0; i < n; ++i)
        if (drop[i]) out.flags[i] |= skel::kHidden;
    std::erase_if(out.leaves, [&](const skel::Leaf& leaf) {
        return leaf.node >= 0 && static_cast<std::size_t>(leaf.node) < n &&
               drop[static_cast<std::size_t>(leaf.node)] == 1;
    });
    return out;
}

std::vector<skel::Leaf> clusterLeaves(const std::vector<skel::Leaf>& leaves, double cell,
                                      double leafScale,
                                      const std::function<bool(const skel::Leaf&)>& accept) {
    if (cell <= 0.0 || leaves.size() < 2) return leaves;
    // Clusters in the order of their first leaf (a hash table from cube to cluster, no sort: the
    // order only depends on the input's). Open addressing in one flat array: a node-based map
    // made this the LOD's most expensive step.
    struct Cube {
        std::int64_t x, y, z;
        bool operator==(const Cube&) const = default;
    };
    struct Slot {
        Cube cube;
        std::uint32_t cluster = 0xffffffffu;
    };
    struct Cluster {
        std::size_t count = 0, largest = 0;
        double area = 0.0;
        glm::dvec3 centre{0.0};
    };
    std::size_t capacity = 16;
    while (capacity < 2 * leaves.size())
        capacity *= 2;
    std::vector<Slot> table(capacity);
    std::vector<Cluster> clusters;
    std::vector<std::uint32_t> clusterOf(leaves.size());
    const double inv = 1.0 / cell;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        const skel::Leaf& l = leaves[i];
        const glm::dvec3 c = glm::dvec3(l.position) + glm::dvec3(skel::headingOf(l.orientation)) *
                                                          (0.5 * l.size * leafScale);
        const Cube key{static_cast<std::int64_t>(std::floor(c.x * inv)),
                       static_cast<std::int64_t>(std::floor(c.y * inv)),
                       static_cast<std::int64_t>(std::floor(c.z * inv))};
        std::size_t h = static_cast<std::size_t>(mixSeed(mixSeed(static_cast<std::uint64_t>(key.x),
                                                                 static_cast<std::uint64_t>(key.y)),
                                                         static_cast<std::uint64_t>(key.z))) &
                        (capacity - 1);
        while (table[h].cluster != 0xffffffffu && !(table[h].cube == key))
            h = (h + 1) & (capacity - 1);
        if (table[h].cluster == 0xffffffffu) {
            table[h] = {key, static_cast<std::uint32_t>(clusters.size())};
            clusters.push_back({0, i, 0.0, glm::dvec3(0.0)});
        }
        clusterOf[i] = table[h].cluster;
        Cluster& k = clusters[table[h].cluster];
        const double w = static_cast<double>(l.size) * l.size;
        ++k.count;
        k.area += w;
        k.centre += w * c;
        if (l.size > leaves[k.largest].size) k.largest = i;
    }
    std::vector<skel::Leaf> out;
    out.reserve(clusters.size());
    for (std::size_t ci = 0; ci < clusters.size(); ++ci) {
        const Cluster& k = clusters[ci];
        if (k.count == 1) {
            out.push_back(leaves[k.largest]);
            continue;
        }
        skel::Leaf merged = leaves[k.largest];
        if (k.area > 0.0) {
            merged.size = static_cast<float>(std::sqrt(k.area));
            const glm::dvec3 c = k.centre / k.area;
            merged.position = glm::vec3(c - glm::dvec3(skel::headingOf(merged.orientation)) *
                                                (0.5 * merged.size * leafScale));
        }
        if (accept && !accept(merged)) {
            for (std::size_t i = 0; i < leaves.size(); ++i)
                if (clusterOf[i] == ci) out.push_back(leaves[i]);
            continue;
        }
        out.push_back(merged);
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

} // namespace sylva::mesh
