#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/skeleton/skeleton.h"
#include "engine/util/rawvector.h"

namespace sylva::mesh {

/// The corners appendLeafCards gives \p leaf (stem left, stem right, tip right, tip left),
/// from its heading and left axes; \p aspect and \p scale as LeafCardSettings'.
inline void leafCorners(const skel::Leaf& leaf, const glm::vec3& heading, const glm::vec3& left,
                        float aspect, float scale, glm::vec3 out[4]) {
    const float len = leaf.size * scale;
    const glm::vec3 h = heading * len;
    const glm::vec3 l = left * (0.5f * aspect * len);
    out[0] = leaf.position + l;
    out[1] = leaf.position - l;
    out[2] = leaf.position - l + h;
    out[3] = leaf.position + l + h;
}
/// The same from the leaf's orientation.
inline void leafCorners(const skel::Leaf& leaf, float aspect, float scale, glm::vec3 out[4]) {
    leafCorners(leaf, skel::headingOf(leaf.orientation), skel::leftOf(leaf.orientation), aspect,
                scale, out);
}

/// Each leaf's middle, position + 0.5 * size * heading in double (where a leaf belongs when
/// leaves are grouped in cells): four leaves at a time on SSE2 (the heading as prepareCardFit
/// makes it), bit for bit leafMiddlesPlain for finite quaternions.
/// \return the sum of leaf.size x sizeScale in leaf order (the groups' mean leaf), made in the
/// same pass (a pass of its own read the ~690 KB of the English oak's leaves once more).
/// \p mids a RawVector: every middle is written, and the zero fill of a std::vector's resize
/// (the oak's ~460 KB a tree, a fresh vector each) was ~0.4 % of the tree's samples.
double leafMiddles(const std::vector<skel::Leaf>& leaves, double sizeScale,
                   RawVector<glm::dvec3>& mids);

/// What a cluster card (leafclusters.h) is fitted from: its leaves' card corners (four a leaf,
/// in leaf order), their mean and covariance (made in double from the float corners, summed in
/// that order), and the sums of the leaves' heading, up and left axes. The corners a RawVector:
/// each fit resizes them to its group and writes every one, and std::vector's resize() inside
/// the capacity (the lanes' inputs are reused, group after group) value-initialised each new
/// vec3 through a stack temporary written in parts and read back whole (docs/perf/geometry.md,
/// eighth pass).
struct CardFitInput {
    RawVector<glm::vec3> corners;
    glm::dvec3 heading{0.0}, up{0.0}, left{0.0}, m{0.0};
    glm::dmat3 cov{0.0};
};

/// \p in for the leaves of \p group: four leaves at a time on SSE2, their quaternions turned
/// into their axes and corners four lanes to a register, each lane the float operations of
/// leafCorners in order and the axes from the nine products of a quaternion's components the
/// three share (glm's quaternion product less its products by 0 and 1: its bits for every
/// finite quaternion); the mean summed as the corners are made,
/// the covariance each point's coordinates two to a register: bit for bit
/// prepareCardFitPlain's (perf record of the English oak: prepareCardFit 17 % of the cards'
/// stage, three quaternion products and a card a leaf, one float at a time).
void prepareCardFit(const std::vector<skel::Leaf>& leaves, std::span<const std::uint32_t> group,
                    float aspect, float scale, CardFitInput& in);

/// The smallest and largest dot products of (corner - in.m) with \p along (a0, a1) and with
/// \p across (c0, c1): a corner's two products in one SSE2 register, each lane the scalar
/// operations in order, bit for bit cardExtentPlain's (perf record of the English oak: the
/// fits' last pass over the corners, 0.15 -> 0.14 ms a tree; with the corners kept as floats,
/// 0.25 ms without it).
void cardExtent(const CardFitInput& in, const glm::dvec3& along, const glm::dvec3& across,
                double& a0, double& a1, double& c0, double& c1);

/// A cluster card's plane and axes (leafclusters): n (toward the leaves' up), along (the stem
/// edge toward where the leaves start: their mean heading in the plane, e1 when they point every
/// way) and across.
struct CardAxes {
    glm::dvec3 n, along, across;
};

/// A unit vector perpendicular to \p v.
glm::dvec3 anyPerpendicular(const glm::dvec3& v);

/// The covariance of \p in without its part along its largest eigenvector \p e1, and in \p seed2
/// the start of the second power iteration: in.left made perpendicular to e1, normalised.
glm::dmat3 secondMatrix(const CardFitInput& in, const glm::dvec3& e1, glm::dvec3& seed2);

/// The axes of \p n cards from their inputs, their groups (for the leaves' count) and their
/// covariances' two largest eigenvectors \p e1 and \p e2 (e2 made perpendicular to e1 and
/// normalised in place), each stage for every card before the next: a card's chain of four
/// normalisations (a square root and a division each) waited on the one before; cards side by
/// side overlap theirs (perf record of the English oak: finishFit 4.6 %, on those chains). Each
/// card's arithmetic is its own, in its order: the same axes as one card at a time.
void cardAxes(const CardFitInput* in, const std::span<const std::uint32_t>* group,
              const glm::dvec3* e1, glm::dvec3* e2, CardAxes* out, std::size_t n);

/// Measured on the broadleaf library (test_leafclusters): 0.9 covers what one card a leaf
/// covers within 3% from the side and from the camera.
inline constexpr double kCardShrink = 0.9;

/// A card's rectangle from its extent (cardExtent's a0, a1, c0, c1): the corners' box is larger
/// than the leaves it holds (their outlines are not a rectangle), so it is shrunk about its
/// middle by kCardShrink; lo and hi the stem and tip edges' points on along, cm the middle across.
struct CardRect {
    double a0, a1, c0, c1, cm;
    glm::dvec3 lo, hi;
};
CardRect cardRect(const CardFitInput& in, const CardAxes& axes, const double (&extent)[4]);
/// The rectangle's corners (stem, stem, tip, tip: lo + c1, lo + c0, hi + c0, hi + c1 across) and
/// the card's normal, as floats.
void cardCorners(const CardRect& r, const CardAxes& axes, glm::vec3 corners[4], glm::vec3& normal);

/// prepareCardFit, leafMiddles and cardExtent the straightforward way (glm, one operation after the
/// other), for tests.
void prepareCardFitPlain(const std::vector<skel::Leaf>& leaves,
                         std::span<const std::uint32_t> group, float aspect, float scale,
                         CardFitInput& in);
double leafMiddlesPlain(const std::vector<skel::Leaf>& leaves, double sizeScale,
                        std::vector<glm::dvec3>& mids);
void cardExtentPlain(const CardFitInput& in, const glm::dvec3& along, const glm::dvec3& across,
                     double& a0, double& a1, double& c0, double& c1);

} // namespace sylva::mesh
