#pragma once

#include "engine/skeleton/skeleton.h"

namespace sylva::growth {

/// Fills Skeleton::light of a grown tree from its own shade (issue #44: the leaves' tint reads
/// it, outer sun-facing foliage lighter, inner darker): every node casts a shadow pyramid down a
/// voxel grid of edge \p voxelSize (Palubicki et al. 2009, the pyramids litAttractors and the
/// self-organizing growth use, reaching about 4 m down so the crown's sides see the sky past its
/// edge), each node (its internode's leaves) gathers the exposure 1 / (1 + shadow of the others)
/// at its voxel, in (0, 1], and a node's record is what its subtree gathered (the
/// self-organizing records' units); a record less its children's is the node's own exposure.
/// Replaces any light already there; leaves vigour and age as they are. O(nodes + voxels).
/// \param voxelSize metres, > 0 (space_colonization's `light_voxel_size`).
/// Reads the shadow only at the nodes' voxels: each node counts the nodes in the square above it
/// at each depth (a summed-area table of the counts per layer) instead of every pyramid being
/// spread over a grid, the same integers as recordLightByShadowGrid.
void recordLight(skel::Skeleton& skeleton, float voxelSize);

/// The same records from a ShadowGrid that every node's pyramid is added to (applyBatch): the
/// reference recordLight is tested against bit for bit, and what it takes for a crown whose
/// grid could reach the ShadowGrid's limit (so the same LimitExceeded) or whose box passes 2^24
/// voxels.
void recordLightByShadowGrid(skel::Skeleton& skeleton, float voxelSize);

} // namespace sylva::growth
