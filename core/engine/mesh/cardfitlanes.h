#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/mesh/cardfit.h"
#include "engine/util/rawvector.h"

namespace sylva::mesh {

/// Four groups' card fits side by side, a group a lane (the fits' double sums in one AVX
/// register, four groups' chains in step): perf record of the English oak had prepareCardFit
/// and cardExtent at ~10 % of the tree, each group's chains of double additions one corner after
/// the other (a group's mean, covariance and extent wait on the addition before). Each lane is
/// its group's arithmetic in prepareCardFitPlain's and cardExtentPlain's order, bit for bit.
/// With AVX-512, eight groups side by side (one zmm register of doubles: half the instructions
/// a group of the four-lane path's sums, a mask for the ended lanes instead of an and).
/// The corners, a step (leaf j's corner c, step 4j + c) width lanes of x, y and z.
struct CardFitLanes {
    RawVector<float> x, y, z;  ///< step s, lane k at [width * s + k]
    std::size_t steps = 0;     ///< 4 x the largest group's leaves
    std::size_t width = 4;     ///< lanes a step: 4 (AVX) or 8 (AVX-512)
    std::size_t sizes[8] = {}; ///< each lane's leaves (a lane past the groups: the first's)
};

/// Whether prepareCardFitLanes and cardExtentLanes run here: x86-64 with AVX (chosen at run
/// time), not with SYLVA_NO_AVX=1 set.
bool cardFitLanesAvailable();

/// How many groups prepareCardFitLanes and cardExtentLanes take a call here: 8 with AVX-512
/// (not with SYLVA_NO_AVX512=1 set), 4 with AVX only, 0 where !cardFitLanesAvailable().
std::size_t cardFitLanesWidth();

/// prepareCardFit of \p groups[k] into \p in[k] for k < n (1 to cardFitLanesWidth(), every
/// group of one leaf or more), each lane bit for bit prepareCardFitPlain's heading, up, left, m
/// and cov; the corners kept in \p lanes (in[k].corners untouched). Only where
/// cardFitLanesAvailable().
void prepareCardFitLanes(const std::vector<skel::Leaf>& leaves,
                         const std::span<const std::uint32_t>* groups, std::size_t n, float aspect,
                         float scale, CardFitInput* in, CardFitLanes& lanes);

/// cardExtent of each lane k < n of \p lanes about in[k].m along along[k] and across[k]:
/// extent[k] = {a0, a1, c0, c1}, bit for bit cardExtentPlain's. Only where
/// cardFitLanesAvailable().
void cardExtentLanes(const CardFitLanes& lanes, const CardFitInput* in, const glm::dvec3* along,
                     const glm::dvec3* across, std::size_t n, double (*extent)[4]);

/// cardAxes, cardExtentLanes, cardRect and cardCorners of the eight lanes k < n of \p lanes
/// (prepareCardFitLanes' with AVX-512: lanes.width 8) in one zmm register a coordinate, each
/// lane bit for bit the scalar functions': out[k][0..3] the corners, out[k][4] the normal.
/// \p e1, \p e2 the covariances' two largest eigenvectors (e2 not yet made perpendicular).
/// \return false, nothing written, where a lane's e2 runs along its e1 (cardAxes then takes
/// anyPerpendicular: the caller takes the scalar functions for those lanes).
bool finishCardFitLanes(const CardFitLanes& lanes, const CardFitInput* in,
                        const std::span<const std::uint32_t>* group, const glm::dvec3* e1,
                        const glm::dvec3* e2, std::size_t n, glm::vec3* const* out);

/// secondMatrix of in[k] and e1[k] for k < n (1 to 8, where cardFitLanesWidth() is 8) in one
/// zmm register a coordinate, each lane bit for bit the scalar function's rest[k] and seed2[k].
/// \return false, nothing written, where a lane's seed vanishes (secondMatrix then takes
/// anyPerpendicular: the caller takes the scalar function for those lanes).
bool secondMatrixLanes(const CardFitInput* in, const glm::dvec3* e1, std::size_t n,
                       glm::dmat3* rest, glm::dvec3* seed2);

} // namespace sylva::mesh
