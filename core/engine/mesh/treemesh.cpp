#include "engine/mesh/treemesh.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "engine/mesh/leafclusters.h"
#include "engine/mesh/leaflight.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

namespace sylva::mesh {

namespace {

/// How much wider a ring of \p res sides must be to cover, seen from a random direction, as
/// much as one of \p base sides: their mean widths are perimeter / pi = 2 n r sin(pi/n) / pi.
double ringWidthCompensation(int base, int res) {
    if (res >= base) return 1.0;
    const auto width = [](int n) { return n * std::sin(std::numbers::pi / n); };
    return width(base) / width(res);
}

} // namespace

namespace {
LeafClusterSettings clusterSettings(const TreeMeshSettings& settings) {
    LeafClusterSettings clusters;
    clusters.leavesPerCard = settings.leafClusterSize;
    clusters.seed = settings.seed;
    clusters.crossed = settings.leafClusterCrossed;
    return clusters;
}

// One card a leaf, or cluster cards when the species has a cluster atlas (from \p plan where
// the caller planned them).
void appendLeaves(Mesh& mesh, const std::vector<skel::Leaf>& leaves,
                  const TreeMeshSettings& settings, const skel::Skeleton* skeleton,
                  const LeafClusterPlan* plan = nullptr) {
    const std::size_t firstVertex = mesh.positions.size();
    if (settings.leafClusterSize > 1) {
        if (plan)
            appendLeafClusterCards(mesh, leaves, clusterSettings(settings), skeleton, *plan);
        else
            appendLeafClusterCards(mesh, leaves, settings.leafCards, clusterSettings(settings),
                                   skeleton, settings.acceptLeafCard);
    } else {
        appendLeafCards(mesh, leaves, settings.leafCards, skeleton);
    }
    std::vector<float> light;
    if (settings.leafTint.lightShading > 0.0 && skeleton != nullptr)
        light = leafCardLight(mesh, firstVertex, leaves, *skeleton);
    tintLeafCards(mesh, firstVertex,
                  leafVariationFor(settings.leafTint, settings.season, settings.deciduous),
                  leafReferenceColor(settings.leafTint, settings.season, settings.deciduous),
                  settings.leafTint.patchSize, mixSeed(settings.seed, salt::kLeafTint), light,
                  settings.leafTint.lightShading);
}

Mesh withTextures(Mesh mesh, const TreeMeshSettings& settings) {
    for (Submesh& s : mesh.submeshes) {
        if (s.material == "bark") s.texture = settings.barkTexture;
        if (s.material == "leaf") {
            // A cluster card shows the species' cluster atlas; a deciduous tree's the season's
            // version of its atlas or leaf (the summer one where none was drawn).
            const std::string& summer =
                settings.leafClusterSize > 1 ? settings.leafClusterTexture : settings.leafTexture;
            s.texture = settings.deciduous ? seasonTextureFile(summer, settings.season) : summer;
        }
    }
    return mesh;
}

Mesh buildUntexturedTreeMesh(const skel::Skeleton& skeleton, const TreeMeshSettings& settings,
                             Progress& progress) {
    TubeSettings tubes = settings.tubes;
    double leafFraction = 1.0;
    Mesh mesh;
    if (!settings.useLod) {
        // The leaves shown (the season's) and their cluster cards, planned before the bark so
        // that its arrays are made with room for the cards: growing them afterwards moved the
        // bark's ~2 MB (the English oak; perf record: memmove ~2 % of its samples).
        std::vector<skel::Leaf> seasonal;
        const std::vector<skel::Leaf>* shown = nullptr;
        if (settings.leaves && !skeleton.leaves.empty()) {
            if (settings.deciduous && settings.season != Season::Summer) {
                seasonal = seasonLeaves(skeleton.leaves, settings.season, true, settings.seed);
                if (!seasonal.empty()) shown = &seasonal;
            } else {
                shown = &skeleton.leaves;
            }
        }
        std::optional<LeafClusterPlan> plan;
        if (shown && settings.leafClusterSize > 1) {
            plan = planLeafClusterCards(*shown, settings.leafCards, clusterSettings(settings),
                                        settings.acceptLeafCard);
            tubes.reserveVertices = 4 * plan->cards();
            tubes.reserveIndices = 6 * plan->cards();
        }
        appendTubes(mesh, skeleton, tubes, progress);
        if (shown) appendLeaves(mesh, *shown, settings, &skeleton, plan ? &*plan : nullptr);
        return mesh;
    }
    const LodLevel level = selectLod(settings.lod, settings.cameraDistance);
    const double compensation = ringWidthCompensation(tubes.resolution, level.resolution);
    if (level.band > 0) {
        tubes.caps = false;     // a cap is a disc across a branch end: a pixel or less out here
        tubes.barkRelief = 0.0; // bark as geometry is the nearest level's only
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
    tubes.twigResolution = std::min(tubes.twigResolution, level.resolution);
    tubes.simplifyTolerance = std::max(tubes.simplifyTolerance, level.simplifyTolerance);
    leafFraction = level.leafFraction;
    const skel::Skeleton kept = dropSmallSubtrees(
        skeleton, level.minSubtreeExtent, settings.leafCards.sizeScale, level.leafyTwigExtent);
    appendTubes(mesh, kept, tubes, progress);
    // The season's leaves first, so that clusters and thinning work on what the tree shows.
    const std::vector<skel::Leaf> seasonal =
        settings.deciduous && settings.season != Season::Summer
            ? seasonLeaves(kept.leaves, settings.season, true, settings.seed)
            : std::vector<skel::Leaf>();
    const std::vector<skel::Leaf>& shown =
        settings.deciduous && settings.season != Season::Summer ? seasonal : kept.leaves;
    if (settings.leaves && !shown.empty()) {
        std::vector<skel::Leaf> leaves = clusterLeaves(
            shown, level.leafCell, settings.leafCards.sizeScale, settings.acceptLeafCard);
        if (leafFraction < 1.0) {
            leaves = thinLeaves(leaves, leafFraction, settings.seed);
            // Enlarged survivors that would reach into an obstacle are left out.
            if (settings.acceptLeafCard)
                std::erase_if(leaves, std::not_fn(settings.acceptLeafCard));
        }
        appendLeaves(mesh, leaves, settings, &kept);
    }
    return mesh;
}
} // namespace

Mesh buildTreeMesh(const skel::Skeleton& skeleton, const TreeMeshSettings& settings,
                   Progress& progress) {
    Mesh mesh = buildUntexturedTreeMesh(skeleton, settings, progress);
    if (settings.barkTexture.empty() && settings.leafTexture.empty() &&
        settings.leafClusterTexture.empty())
        return mesh;
    return withTextures(std::move(mesh), settings);
}

} // namespace sylva::mesh
