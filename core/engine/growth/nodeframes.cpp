#include "engine/growth/nodeframes.h"

#include <algorithm>
#include <cstdlib>
#include <limits>

#include <glm/gtx/quaternion.hpp>

#include "engine/skeleton/skeleton.h"
#include "engine/util/x86intrinsics.h"

namespace sylva::growth {

glm::quat transportFrame(const glm::quat& parent, const glm::vec3& dir) {
    return glm::normalize(glm::rotation(skel::headingOf(parent), dir) * parent);
}

namespace {

#if defined(SYLVA_X86_INTRINSICS)
// Read once (util/x86intrinsics).
const bool kHasAvx512 = simd::useAvx512();

using simd::add; // unfused: glm's bits
using simd::mul;
using simd::sub;

/// Sixteen lanes of transportFrame: parents (w, x, y, z) and directions (x, y, z) by component,
/// the frames written to q (w, x, y, z). Returns the lanes transportFrame must make instead.
__attribute__((target("avx512f"))) std::uint32_t
transport16(const float* pw, const float* px, const float* py, const float* pz, const float* dx,
            const float* dy, const float* dz, float* qw, float* qx, float* qy, float* qz) {
    const __m512 zero = _mm512_setzero_ps(), one = _mm512_set1_ps(1.0f);
    const __m512 two = _mm512_set1_ps(2.0f);
    const __m512 w = _mm512_loadu_ps(pw), x = _mm512_loadu_ps(px), y = _mm512_loadu_ps(py),
                 z = _mm512_loadu_ps(pz);
    // headingOf(parent) = parent * (0, 1, 0): glm's q * v with v = (0, 1, 0), every product
    // made (a product by 0 or 1 is not folded away without -ffast-math).
    const __m512 uvx = sub(mul(y, zero), mul(one, z));
    const __m512 uvy = sub(mul(z, zero), mul(zero, x));
    const __m512 uvz = sub(mul(x, one), mul(zero, y));
    const __m512 uuvx = sub(mul(y, uvz), mul(uvy, z));
    const __m512 uuvy = sub(mul(z, uvx), mul(uvz, x));
    const __m512 uuvz = sub(mul(x, uvy), mul(uvx, y));
    const __m512 hx = add(zero, mul(add(mul(uvx, w), uuvx), two));
    const __m512 hy = add(one, mul(add(mul(uvy, w), uuvy), two));
    const __m512 hz = add(zero, mul(add(mul(uvz, w), uuvz), two));
    // glm::rotation(h, dir).
    const __m512 ex = _mm512_loadu_ps(dx), ey = _mm512_loadu_ps(dy), ez = _mm512_loadu_ps(dz);
    const __m512 cosTheta = add(add(mul(hx, ex), mul(hy, ey)), mul(hz, ez));
    const float eps = std::numeric_limits<float>::epsilon();
    const __mmask16 same = _mm512_cmp_ps_mask(cosTheta, _mm512_set1_ps(1.0f - eps), _CMP_GE_OQ);
    const __mmask16 opposite =
        _mm512_cmp_ps_mask(cosTheta, _mm512_set1_ps(-1.0f + eps), _CMP_LT_OQ);
    const __m512 ax = sub(mul(hy, ez), mul(ey, hz));
    const __m512 ay = sub(mul(hz, ex), mul(ez, hx));
    const __m512 az = sub(mul(hx, ey), mul(ex, hy));
    const __m512 s = _mm512_sqrt_ps(mul(add(one, cosTheta), two));
    const __m512 invs = _mm512_div_ps(one, s);
    // The same direction: the identity rotation.
    const __m512 rw = _mm512_mask_mov_ps(mul(s, _mm512_set1_ps(0.5f)), same, one);
    const __m512 rx = _mm512_mask_mov_ps(mul(ax, invs), same, zero);
    const __m512 ry = _mm512_mask_mov_ps(mul(ay, invs), same, zero);
    const __m512 rz = _mm512_mask_mov_ps(mul(az, invs), same, zero);
    // rotation * parent (glm's operator*=, left to right).
    const __m512 mw = sub(sub(sub(mul(rw, w), mul(rx, x)), mul(ry, y)), mul(rz, z));
    const __m512 mx = sub(add(add(mul(rw, x), mul(rx, w)), mul(ry, z)), mul(rz, y));
    const __m512 my = sub(add(add(mul(rw, y), mul(ry, w)), mul(rz, x)), mul(rx, z));
    const __m512 mz = sub(add(add(mul(rw, z), mul(rz, w)), mul(rx, y)), mul(ry, x));
    // glm::normalize(quat): (w w + x x) + (y y + z z), one over its root.
    const __m512 len =
        _mm512_sqrt_ps(add(add(mul(mw, mw), mul(mx, mx)), add(mul(my, my), mul(mz, mz))));
    const __mmask16 flat = _mm512_cmp_ps_mask(len, zero, _CMP_LE_OQ);
    const __m512 over = _mm512_div_ps(one, len);
    _mm512_storeu_ps(qw, mul(mw, over));
    _mm512_storeu_ps(qx, mul(mx, over));
    _mm512_storeu_ps(qy, mul(my, over));
    _mm512_storeu_ps(qz, mul(mz, over));
    return static_cast<std::uint32_t>(opposite | flat);
}
#else
const bool kHasAvx512 = false;
#endif

} // namespace

bool transportFramesAvx512() {
    return kHasAvx512;
}

void transportFrames(std::span<const glm::quat> frames, std::span<const std::uint32_t> nodes,
                     std::span<const glm::vec3> dirs, std::vector<glm::quat>& out) {
    const std::size_t n = nodes.size();
    out.resize(n);
    std::size_t k = 0;
#if defined(SYLVA_X86_INTRINSICS)
    if (kHasAvx512) {
        // A block's inputs by component (the lanes past the last node: the identity and a
        // direction along its heading, made and dropped), its frames likewise.
        alignas(64) float in[7][16];
        alignas(64) float q[4][16];
        for (; k < n; k += 16) {
            const std::size_t lanes = std::min<std::size_t>(16, n - k);
            for (std::size_t l = 0; l < 16; ++l) {
                const bool real = l < lanes;
                const glm::quat p = real ? frames[nodes[k + l]] : glm::quat(1, 0, 0, 0);
                const glm::vec3 d = real ? dirs[k + l] : glm::vec3(0, 1, 0);
                in[0][l] = p.w;
                in[1][l] = p.x;
                in[2][l] = p.y;
                in[3][l] = p.z;
                in[4][l] = d.x;
                in[5][l] = d.y;
                in[6][l] = d.z;
            }
            const std::uint32_t scalar = transport16(in[0], in[1], in[2], in[3], in[4], in[5],
                                                     in[6], q[0], q[1], q[2], q[3]);
            for (std::size_t l = 0; l < lanes; ++l)
                out[k + l] = scalar >> l & 1u ? transportFrame(frames[nodes[k + l]], dirs[k + l])
                                              : glm::quat(q[0][l], q[1][l], q[2][l], q[3][l]);
        }
        return;
    }
#endif
    for (; k < n; ++k)
        out[k] = transportFrame(frames[nodes[k]], dirs[k]);
}

} // namespace sylva::growth
