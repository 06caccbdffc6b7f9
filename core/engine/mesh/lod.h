#pragma once

#include <cstdint>
#include <vector>

#include "engine/mesh/leafcards.h"
#include "engine/mesh/mesh.h"
#include "engine/mesh/tubemesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"

namespace sylva::mesh {

/// One distance band: from \p distance (metres to the camera) on, rings get \p resolution
/// vertices and a fraction \p leafFraction of the leaves survives (enlarged to keep the area).
struct LodBand {
    double distance = 0.0;
    int resolution = 8;
    double leafFraction = 1.0; ///< (0, 1]
};

/// Camera-driven level of detail (reference 000: resolution 8 near, 3 far).
struct LodSettings {
    std::vector<LodBand> bands{{0.0, 8, 1.0}, {25.0, 5, 0.5}, {60.0, 3, 0.25}};
    double screenHeightPx = 1080.0; ///< viewport height the twig threshold refers to
    double fovYDegrees = 60.0;      ///< vertical field of view
    /// In every band but the first, lateral branches whose projected diameter is below this
    /// many pixels are dropped.
    double minTwigPixels = 1.5;
};

/// What selectLod() chose.
struct LodLevel {
    std::size_t band = 0;
    int resolution = 8;
    double minBranchRadius = 0.0; ///< metres
    double leafFraction = 1.0;
};

/// Checks bands (non-empty, distances strictly increasing from 0, resolution 3..64, fraction in
/// (0, 1]); throws InvalidInput naming the offending band.
void validateLod(const LodSettings& settings);

/// The band whose distance is the largest one <= \p distance (metres), and the radius under
/// which a twig is thinner than minTwigPixels at that distance.
LodLevel selectLod(const LodSettings& settings, double distance);

/// Keeps about \p fraction of the leaves (a deterministic choice from \p seed) and scales the
/// survivors so that the total card area (∝ size²) is exactly conserved. At least one leaf
/// survives when there was one.
std::vector<skel::Leaf> thinLeaves(const std::vector<skel::Leaf>& leaves, double fraction,
                                   std::uint64_t seed);

/// Everything that makes a tree's mesh.
struct TreeMeshSettings {
    TubeSettings tubes;
    LeafCardSettings leafCards;
    bool leaves = true;          ///< cards for the skeleton's leaves ("leaf" submesh)
    bool useLod = false;         ///< choose resolution/twigs/leaves from cameraDistance
    double cameraDistance = 0.0; ///< metres, with useLod
    LodSettings lod;
    std::uint64_t seed = 0; ///< leaf thinning
};

/// Bark tubes plus leaf cards, at the level of detail the settings ask for.
Mesh buildTreeMesh(const skel::Skeleton& skeleton, const TreeMeshSettings& settings,
                   Progress& progress = noProgress());

/// One level of a LOD chain.
struct LodChainLevel {
    double distance = 0.0; ///< where the band starts
    Mesh mesh;
};

/// A LOD chain for game engines: one mesh per band of settings.lod (LOD0 = nearest).
std::vector<LodChainLevel> buildLodChain(const skel::Skeleton& skeleton,
                                         const TreeMeshSettings& settings,
                                         Progress& progress = noProgress());

} // namespace sylva::mesh
