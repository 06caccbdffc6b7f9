#include "engine/mesh/lod.h"

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
        // A diameter 2r at distance d covers 2r / (2 d tan(fov/2)) of the screen height.
        const double halfFov = settings.fovYDegrees * std::numbers::pi / 360.0;
        level.minBranchRadius =
            settings.minTwigPixels * distance * std::tan(halfFov) / settings.screenHeightPx;
    }
    return level;
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

Mesh buildTreeMesh(const skel::Skeleton& skeleton, const TreeMeshSettings& settings,
                   Progress& progress) {
    TubeSettings tubes = settings.tubes;
    double leafFraction = 1.0;
    if (settings.useLod) {
        const LodLevel level = selectLod(settings.lod, settings.cameraDistance);
        tubes.resolution = level.resolution;
        tubes.minBranchRadius = std::max(tubes.minBranchRadius, level.minBranchRadius);
        leafFraction = level.leafFraction;
    }
    Mesh mesh;
    appendTubes(mesh, skeleton, tubes, progress);
    if (settings.leaves && !skeleton.leaves.empty()) {
        if (leafFraction < 1.0)
            appendLeafCards(mesh, thinLeaves(skeleton.leaves, leafFraction, settings.seed),
                            settings.leafCards, &skeleton);
        else
            appendLeafCards(mesh, skeleton.leaves, settings.leafCards, &skeleton);
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
