#pragma once

#include <cstddef>
#include <vector>

#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"

namespace sylva::mesh {

/// How lit each leaf card is, from the growth's own light records (Skeleton::light, issue #44):
/// a leaf sees its node's own light (its record less its children's; where that is nothing, the
/// record per tip of the node's subtree);
/// a card (four vertices from \p firstVertex on, as appendLeafCards and appendLeafClusterCards
/// make them) sees the mean of the leaves in the 0.5 m cell of its centre (or of the 27 cells
/// around it when its own holds none). Values are spread over [0, 1] between the cards' 5th
/// and 50th percentiles: 0 the most shaded, 1 the lit half. Empty when the skeleton carries no
/// light records or no leaf hangs on a node. Deterministic, O(cards + leaves).
std::vector<float> leafCardLight(const Mesh& mesh, std::size_t firstVertex,
                                 const std::vector<skel::Leaf>& leaves,
                                 const skel::Skeleton& skeleton);

/// The box of the 0.5 m cells of the leaves on a node below \p n (into \p lo and \p hi, each
/// axis' least and greatest cell; INT_MAX and INT_MIN where no leaf counts), and how many leaves
/// count: leafCardLight's grid. leafCellBox takes the box of the positions and their cells'
/// floors; leafCellBoxOfCells (its reference and its fallback for NaN and far coordinates) the
/// box of every leaf's cell. The same boxes and counts.
std::size_t leafCellBox(const std::vector<skel::Leaf>& leaves, std::size_t n, glm::ivec3& lo,
                        glm::ivec3& hi);
std::size_t leafCellBoxOfCells(const std::vector<skel::Leaf>& leaves, std::size_t n, glm::ivec3& lo,
                               glm::ivec3& hi);

} // namespace sylva::mesh
