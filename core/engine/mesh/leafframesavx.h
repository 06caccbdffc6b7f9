#pragma once

#include <cstdint>

namespace sylva::mesh {

/// The constants of a leaf's frame (placeLeaves): the petiole angle's sine and cosine, the
/// weights of the branch normal, world up and the light, and the light's direction.
struct LeafFrameWeights {
    float sinPetiole = 0.0f, cosPetiole = 1.0f;
    float normal = 0.0f, up = 0.0f, light = 0.0f;
    float lightX = 0.0f, lightY = 1.0f, lightZ = 0.0f;
};

/// Whether leafFramesAvx16 runs here: the processor has AVX and SYLVA_NO_AVX is unset.
bool leafFramesAvx();

/// The frames of sixteen leaves, placeLeaves' SSE2 orientations eight lanes to a register (the
/// same operations in each lane, in the same order: the same bits). \p in: the leaves' tangents
/// (x, y, z), radial directions (x, y, z) and forward weights, seven arrays from the first of the
/// sixteen. Writes each lane's normalised quaternion to q (w, x, y, z by lane) and returns the
/// lanes (bit i: lane i) whose frame the scalar path must make instead (the normal along the
/// heading, or a quaternion of no length). Call only where leafFramesAvx() is true.
unsigned leafFramesAvx16(const LeafFrameWeights& w, const float* const in[7], float q[4][16]);

/// Whether leafFramesAvx512x64 runs here: the processor has AVX-512 and neither SYLVA_NO_AVX
/// nor SYLVA_NO_AVX512 is set.
bool leafFramesAvx512();

/// leafFramesAvx16 for sixty-four leaves, sixteen lanes to a register (the same operations in
/// each lane, in the same order: the same bits); bit i of the result is lane i. Call only where
/// leafFramesAvx512() is true.
std::uint64_t leafFramesAvx512x64(const LeafFrameWeights& w, const float* const in[7],
                                  float q[4][64]);

} // namespace sylva::mesh
