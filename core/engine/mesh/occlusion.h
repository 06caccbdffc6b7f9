#pragma once

#include <vector>

#include "engine/mesh/mesh.h"

namespace sylva::mesh {

/// A cheap ambient occlusion per vertex from the crown, for viewers: 1 = open sky, lower deeper
/// inside the foliage. The crown is the box of the leaf cards' vertices (Submesh "leaf"); a
/// vertex's depth is its ellipsoidal distance from the crown's centre (1 at the box's inscribed
/// ellipsoid), so inner leaves and the branches among them darken while the outer shell and a
/// bare trunk below the crown stay lit; the lower half of the crown is a little darker than
/// the top, where the sky reaches. Values lie in [\p minimum, 1]. A mesh without leaves gets
/// all ones. O(vertices).
/// \param minimum the darkest value, at the crown's centre, in [0, 1].
std::vector<float> crownOcclusion(const Mesh& mesh, float minimum = 0.45f);

} // namespace sylva::mesh
