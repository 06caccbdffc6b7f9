#pragma once
// A leaf's frame sixteen leaves at a time for placeLeaves: the SSE2 path here, the AVX one in
// leafframesavx. Each lane makes the scalar frame's operations in the same order (packed square
// roots and divisions round as the scalar ones do), so the same quaternions bit for bit.

namespace sylva::mesh {

/// The constants of a leaf's frame (placeLeaves): the petiole angle's sine and cosine, the
/// weights of the branch normal, world up and the light, and the light's direction.
struct LeafFrameWeights {
    float sinPetiole = 0.0f, cosPetiole = 1.0f;
    float normal = 0.0f, up = 0.0f, light = 0.0f;
    float lightX = 0.0f, lightY = 1.0f, lightZ = 0.0f;
};

#if defined(__SSE2__)
/// The frames of sixteen leaves, four SSE2 registers at a time. \p in: the leaves' tangents
/// (x, y, z), radial directions (x, y, z) and forward weights, seven arrays from the first of
/// the sixteen. Writes each lane's normalised quaternion to q (w, x, y, z by lane) and returns
/// the lanes (bit i: lane i) whose frame the scalar path must make instead (the normal along
/// the heading, or a quaternion of no length).
unsigned leafFramesSse16(const LeafFrameWeights& w, const float* const in[7], float q[4][16]);
#endif

} // namespace sylva::mesh
