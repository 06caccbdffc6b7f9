#pragma once

#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/mesh/leafcell.h"

namespace sylva::mesh {

/// The leaf grouping's hash of a cell (leafclusters' cell table and cell count).
inline std::uint64_t leafCellHash(const LeafCell& k) {
    std::uint64_t h = static_cast<std::uint64_t>(k.x) * 0x9E3779B97F4A7C15ull;
    h ^= static_cast<std::uint64_t>(k.y) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
    h ^= static_cast<std::uint64_t>(k.z) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
    return h;
}

/// The cells of \p n middles at edge \p cell and their hashes' low bits (hash & \p mask, mask
/// below 2^32), one leaf at a time: what leafCellsHashed gives.
void leafCellsHashedPlain(const glm::dvec3* mids, std::size_t n, double cell, std::uint64_t mask,
                          LeafCell* cells, std::uint32_t* hashes);

/// leafCellsHashedPlain, eight leaves a register with AVX-512 (avx512f and avx512dq, not with
/// SYLVA_NO_AVX512 or SYLVA_NO_AVX): the same quotients (divisions), floors (toward -infinity,
/// exact) and 64-bit hashes; a block of eight with a quotient of 2^51 or more (or NaN) takes
/// leafCell, as the tail of fewer than eight does.
void leafCellsHashed(const glm::dvec3* mids, std::size_t n, double cell, std::uint64_t mask,
                     LeafCell* cells, std::uint32_t* hashes);

} // namespace sylva::mesh
