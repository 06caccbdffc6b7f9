#pragma once

#include "engine/mesh/leafframes.h"

namespace sylva::mesh {

/// Whether leafFramesAvx16 runs here: the processor has AVX and SYLVA_NO_AVX is unset.
bool leafFramesAvx();

/// The frames of sixteen leaves, leafFramesSse16's lanes eight to a register (the
/// same operations in each lane, in the same order: the same bits). \p in: the leaves' tangents
/// (x, y, z), radial directions (x, y, z) and forward weights, seven arrays from the first of the
/// sixteen. Writes each lane's normalised quaternion to q (w, x, y, z by lane) and returns the
/// lanes (bit i: lane i) whose frame the scalar path must make instead (the normal along the
/// heading, or a quaternion of no length). Call only where leafFramesAvx() is true.
unsigned leafFramesAvx16(const LeafFrameWeights& w, const float* const in[7], float q[4][16]);

} // namespace sylva::mesh
