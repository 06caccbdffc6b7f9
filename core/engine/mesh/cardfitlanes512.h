#pragma once

// The card fits' AVX-512 kernels (cardfitlanes.cpp chooses them at run time): eight groups a zmm
// register of doubles, each lane bit for bit the scalar fits'. Only on x86-64, only where
// simd::useAvx512(); cardfitlanes.h says what each computes.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/mesh/cardfitlanes.h"

namespace sylva::mesh::lanes512 {

/// prepareCardFitLanes with eight lanes (lanes.width 8).
void prepareAvx512(const std::vector<skel::Leaf>& leaves,
                   const std::span<const std::uint32_t>* groups, std::size_t n, float aspect,
                   float scale, CardFitInput* in, CardFitLanes& lanes);
/// cardExtentLanes of prepareAvx512's lanes.
void extentAvx512(const CardFitLanes& lanes, const CardFitInput* in, const glm::dvec3* along,
                  const glm::dvec3* across, std::size_t n, double (*extent)[4]);
/// finishCardFitLanes.
bool finishAvx512(const CardFitLanes& lanes, const CardFitInput* in,
                  const std::span<const std::uint32_t>* group, const glm::dvec3* e1p,
                  const glm::dvec3* e2p, std::size_t n, glm::vec3* const* out);
/// secondMatrixLanes.
bool secondAvx512(const CardFitInput* in, const glm::dvec3* e1p, std::size_t n, glm::dmat3* rest,
                  glm::dvec3* seed2);

} // namespace sylva::mesh::lanes512
