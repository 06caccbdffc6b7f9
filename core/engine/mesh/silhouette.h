#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/mesh/mesh.h"

namespace sylva::mesh {

/// The pixels of an orthographic view of \p mesh that any of its triangles overlaps at all
/// (conservative rasterisation, geometry only: a twig thinner than a pixel still covers the
/// pixels it crosses, as it shows in an antialiased frame). The view looks along
/// -cross(right, up) with \p right and \p up its axes; a point p lands at
/// (dot(p - centre, right) · scale + pixels / 2, pixels / 2 - dot(p - centre, up) · scale):
/// \p scale pixels a metre, \p centre at the middle of the square. \p covered gets pixels²
/// entries, row by row from the top, 1 where covered.
void coverageMask(const Mesh& mesh, const glm::vec3& centre, const glm::vec3& right,
                  const glm::vec3& up, double scale, int pixels,
                  std::vector<std::uint8_t>& covered);

/// \p mask (width × height, 1 = covered) closed by a disc of \p radius pixels (dilated, then
/// eroded; a pixel covered before stays covered): the gaps between leaves narrower than the
/// disc count as crown, as they do for an eye at that size; wider holes stay open.
std::vector<std::uint8_t> closeMask(const std::vector<std::uint8_t>& mask, int width, int height,
                                    int radius = 1);

/// View \p k of \p views that the silhouette checks take (silhouetteIoU, impostorfit): around
/// the tree, every other one 20 degrees above the horizon; a unit direction toward the viewer.
glm::vec3 silhouetteView(int k, int views);

/// Intersection over union of two masks of the same size (1 when both are empty).
double maskIoU(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b);

} // namespace sylva::mesh
