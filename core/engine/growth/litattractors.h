#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::growth {

/// Which attraction points of a crown envelope the light reaches (issue #33). A crown
/// colonizing a uniformly filled envelope fills it evenly and reads as a blob; a real crown
/// is foliage where the light was: sunlit clusters at the ends of the limbs, gaps between them,
/// and a shaded inside that sheds its leaves. All lengths in metres.
struct LightParams {
    /// K: sunlit foliage clusters; 0 keeps every point (no light model); [0, 1000].
    int clusters = 0;
    /// Radius of a cluster as a fraction of the envelope's mean half-extent; (0, 2].
    float clusterRadius = 0.35f;
    /// Spread of the clusters' radii: each is clusterRadius · (1 ± spread/2); [0, 1].
    float clusterSpread = 0.5f;
    /// The most shaded fraction of the points is dropped (their shadow: Palubicki et al. 2009's
    /// pyramids cast by the points above, a = 1, b = 2, four voxels down), as a crown sheds the
    /// shoots inside it that get too little light; 0 keeps them all; [0, 1).
    float shadedFraction = 0.0f;
    /// Edge of a shadow voxel; (0, 100].
    float voxelSize = 0.6f;
    /// Clusters inside the crown, among the points more shaded than their height band's median
    /// (but not shed): the foliage a real crown carries on its main limbs under the lit shell.
    /// Without them a crown of lit clusters is a thin shell that reads from the side as a ring
    /// with an empty middle; [0, 1000].
    int innerClusters = 0;
    /// Radius of an inner cluster as a fraction of clusterRadius; (0, 2].
    float innerRadius = 0.7f;
};

/// Throws InvalidInput with the allowed range for the first bad value.
void validate(const LightParams& params);

/// The attraction points light reaches, in their input order (a subset of \p points).
///
/// Shadow: every point casts a pyramid of shadow down a ShadowGrid; a point's exposure is the
/// full light less the shadow of the others at its voxel. Clusters: the K centres are picked
/// one by one among the points, each the one that maximises √exposure × distance to the centres
/// already chosen (× a seeded jitter in [0.75, 1]), among the points at most as shaded as the
/// median of their height band (one of eight), so they sit on the lit outside of the crown and
/// spread over it (the most exposed first); a point is kept when it lies within some cluster's
/// radius and it is not among the shadedFraction most shaded. The innerClusters are
/// picked the same way after them among the inside points (more shaded than their band's median,
/// not shed), spread by distance alone. Deterministic for a seed.
std::vector<glm::vec3> litAttractors(const std::vector<glm::vec3>& points,
                                     const LightParams& params, std::uint64_t seed);

} // namespace sylva::growth
