#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace sylva::growth {

/// Shadow propagation's optimal growth direction (Palubicki et al. 2009, §4.2): the least
/// shadowed of the 26 neighbours of a bud's voxel that lie inside its perception cone.
///
/// \param shadow raw shadow values of the 3×3×3 voxels around the bud, index
///        (dy+1)·9 + (dx+1)·3 + (dz+1) (ShadowGrid::neighbourhood()); ShadowGrid::kOpaque
///        for voxels no bud may grow into. The centre (index 13) is ignored.
/// \param dir the bud's unit direction (the cone's axis).
/// \param cosHalf cosine of half the cone's apex angle; a neighbour is inside when the unit
///        vector towards it, n, has n·dir ≥ cosHalf.
/// \return the unit sum of the unit vectors towards every neighbour inside the cone that ties
///        for the least shadow, or \p dir when no neighbour is inside (or the sum is ~0).
///
/// The neighbours are summed per distance class (6 faces at 1, 12 edges at √2, 8 corners at
/// √3) as exact integer offsets, scaled by 1/|offset| at the end, so the result does not depend
/// on the order in which they are visited.
glm::vec3 leastShadowedDirection(const std::int32_t (&shadow)[27], const glm::vec3& dir,
                                 float cosHalf);

} // namespace sylva::growth
