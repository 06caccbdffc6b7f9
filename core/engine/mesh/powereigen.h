#pragma once

#include <cstddef>

#include <glm/glm.hpp>

namespace sylva::mesh {

/// The most eigenvectors largestEigenvectors takes at once.
inline constexpr std::size_t kPowerLanes = 16;

/// Largest eigenvectors of \p n (at most kPowerLanes) symmetric 3x3 matrices by power iteration,
/// each from its \p v (replaced by the result): 24 steps, a matrix whose product vanishes keeps its
/// vector. The direction after 24 products does not depend on how they are grouped or where the
/// vector is scaled, so (after the matrix is scaled to unit absolute sum, so that four products
/// neither overflow nor underflow) the matrix's fourth power is made once, by two squarings, and
/// each block of kBlock products is one product with it; between blocks the vector is brought
/// back to about unit length by a power of two (exact: no square root or division), and only
/// the last block's is normalised (perf record of the English oak: principal 6.6 % of the tree,
/// all of it waiting on the divider, with three divisions and a square root a step; then 0.30 ms
/// a tree with 24 products and a normalisation every four). The result is the same up to
/// rounding. The n chains are independent and advance in step, two to an SSE2 register; the
/// squarings make the six entries of a symmetric matrix (\p c must be symmetric, bit for bit,
/// as a covariance is), and the vectors are blended with their kept ones only where a lane's
/// product vanished (0.19 -> 0.17 ms a tree). Where there is AVX-512 (and neither SYLVA_NO_AVX512
/// nor SYLVA_NO_AVX is set) eight lanes take one register, sixteen two side by side (each
/// register's chain of products waits on every operation before it; two overlap): the same
/// operations in each lane's order, the same bits as largestEigenvectorsPairs (which takes
/// eight at a time).
/// Used by the leaf cluster cards' fits (appendLeafClusterCards).
void largestEigenvectors(const glm::dmat3* c, glm::dvec3* v, std::size_t n);

/// largestEigenvectors two lanes an SSE2 register (one matrix at a time without SSE2), whatever
/// the processor: what it takes without AVX-512; for tests.
void largestEigenvectorsPairs(const glm::dmat3* c, glm::dvec3* v, std::size_t n);

/// The same power iteration done the straightforward way, one matrix after the other: each of
/// the 24 products normalised (a matrix whose product falls under 1e-18 keeps its vector). The
/// same directions as largestEigenvectors up to rounding; for tests.
void largestEigenvectorsStepwise(const glm::dmat3* c, glm::dvec3* v, std::size_t n);

} // namespace sylva::mesh
