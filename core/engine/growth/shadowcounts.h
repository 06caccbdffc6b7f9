#pragma once
// The shadow a ShadowGrid would hold at its own sources' voxels, made by counting the sources
// above each one instead of spreading every pyramid over a grid: recordLight and litAttractors
// read the grid only there.
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/growth/shadowgrid.h"

namespace sylva::growth {

/// raw[i] = the raw value a ShadowGrid whose floor is below every voxel holds at voxels[i]
/// after a pyramid of \p kernel (weight 1) at each of \p voxels: each voxel counts the sources
/// in the square of half-width q, q layers above it (a summed-area table of the counts, layer by
/// layer) and adds Δs(q) times the count, in the grid's 32-bit wrap-around, so the same
/// integers bit for bit. Returns false, leaving \p raw as it was, where the grid must decide:
/// its box could reach kMaxShadowVoxels (where the grid throws LimitExceeded), or the box of
/// voxels is over 2^24 (the table and the per-voxel sums, 12 bytes a voxel, would outgrow the
/// grid's five).
bool shadowAtSources(std::span<const glm::ivec3> voxels, const ShadowKernel& kernel,
                     std::vector<std::int32_t>& raw);

} // namespace sylva::growth
