#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "engine/skeleton/skeleton.h"

namespace sylva::mesh {

/// One distance band: from \p distance (metres to the camera) on, rings get \p resolution
/// vertices and a fraction \p leafFraction of the leaves survives (enlarged to keep the area).
struct LodBand {
    double distance = 0.0;
    int resolution = 8;
    double leafFraction = 1.0; ///< (0, 1]
};

/// Camera-driven level of detail (reference 000: resolution 8 near, 3 far). What goes is
/// decided by what the camera can see of it (issue 20): sizes are measured in pixels of a
/// screenHeightPx-high viewport with a fovYDegrees vertical field of view at the tree's distance.
struct LodSettings {
    std::vector<LodBand> bands{{0.0, 8, 1.0}, {25.0, 5, 1.0}, {60.0, 3, 1.0}};
    double screenHeightPx = 1080.0; ///< viewport height the pixel thresholds refer to
    double fovYDegrees = 60.0;      ///< vertical field of view
    /// In every band but the first, a lateral branch is dropped (with its leaves) only when its
    /// whole subtree, leaf cards included, spans fewer pixels than this (the diagonal of its
    /// bounds): a twig is thinner than a pixel long before its crown is.
    double minTwigPixels = 1.0;
    /// In every band but the first, a lateral subtree that carries leaves and spans fewer
    /// pixels than this keeps its leaves but loses its bark: out here a leafy shoot's stem is
    /// hidden by its own leaves (the leaves then merge into clusters like the others).
    double leafyTwigPixels = 4.0;
    /// In every band but the first, axes are simplified within this many pixels (nodes whose
    /// position and radius the straight tube between their neighbours matches that closely).
    double simplifyPixels = 0.5;
    /// In every band but the first, leaves whose card centres fall in the same cube of this many
    /// pixels are merged into one card of the same total area (a leaf cluster), 0 = off.
    double leafClusterPixels = 2.0;
    /// In every band but the first, and when the camera's position is known, axes thinner than
    /// this many pixels become flat ribbons facing the camera (caps are left out too).
    double ribbonPixels = 2.0;
};

/// What selectLod() chose.
struct LodLevel {
    std::size_t band = 0;
    int resolution = 8;
    double leafFraction = 1.0;
    double metresPerPixel = 0.0;    ///< a pixel's footprint at the distance; 0 in the first band
    double minSubtreeExtent = 0.0;  ///< metres: smaller lateral subtrees are dropped
    double leafyTwigExtent = 0.0;   ///< metres: smaller leafy lateral subtrees lose their bark
    double simplifyTolerance = 0.0; ///< metres
    double leafCell = 0.0;          ///< metres: leaf cluster cube edge, 0 = no clustering
    double ribbonRadius = 0.0;      ///< metres: thinner axes become ribbons (with a camera)
};

/// Checks bands (non-empty, distances strictly increasing from 0, resolution 3..64, fraction in
/// (0, 1]); throws InvalidInput naming the offending band.
void validateLod(const LodSettings& settings);

/// The band whose distance is the largest one <= \p distance (metres), and the pixel-based
/// thresholds of LodSettings turned into metres at that distance.
LodLevel selectLod(const LodSettings& settings, double distance);

/// The skeleton as the LOD keeps it: lateral subtrees (with their leaves) whose bounds' diagonal
/// is below \p minExtent metres are flagged kHidden and their leaves removed; leafy ones below
/// \p leafyExtent are flagged kHidden but keep their leaves (bark only goes). Leaf cards count
/// with their length Leaf::size · \p leafScale. Returns a copy; nothing is dropped when both
/// extents are 0.
skel::Skeleton dropSmallSubtrees(const skel::Skeleton& skeleton, double minExtent,
                                 double leafScale = 1.0, double leafyExtent = 0.0);

/// Merges the leaves whose card centres (anchor + heading · size · leafScale / 2) fall in the
/// same cube of edge \p cell metres into one card: the largest leaf's orientation and node,
/// centred on the area-weighted centre of the cluster, with the total area (size² summed).
/// Deterministic (clusters in the order of their first leaf); a leaf alone in its cube is kept
/// as it is.
/// A cluster card that \p accept (when given) refuses is not made: its leaves stay as they are.
std::vector<skel::Leaf> clusterLeaves(const std::vector<skel::Leaf>& leaves, double cell,
                                      double leafScale = 1.0,
                                      const std::function<bool(const skel::Leaf&)>& accept = {});

/// Keeps about \p fraction of the leaves (a deterministic choice from \p seed) and scales the
/// survivors so that the total card area (∝ size²) is exactly conserved. At least one leaf
/// survives when there was one.
std::vector<skel::Leaf> thinLeaves(const std::vector<skel::Leaf>& leaves, double fraction,
                                   std::uint64_t seed);

} // namespace sylva::mesh
