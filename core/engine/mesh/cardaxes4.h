#pragma once

// The axes and card corners of four leaves, four lanes to an SSE2 register (cardfit's and
// cardfitlanes' shared arithmetic; x86-64 only).

#if defined(__SSE2__)
#include <xmmintrin.h>

#include "engine/skeleton/skeleton.h"

namespace sylva::mesh {

// Four lanes' x, y and z.
struct Vec4x3 {
    __m128 x, y, z;
};

// glm's q * v (v + ((uv * w) + uuv) * 2, uv = cross(q.xyz, v), uuv = cross(q.xyz, uv), cross(a,
// b) = (a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y)) for four
// quaternions and v the heading (0, 1, 0), the left (-1, 0, 0) and the up (0, 0, 1) axes,
// bit for bit for finite quaternions, from the nine products of q's components the three
// share: q * v's products by 0 and 1 dropped (a product by 1 is exact; one by 0 a zero, and a zero
// added to or taken from a value leaves it as it is, so only the sign of a zero can differ on the
// way, and the last addition of v's +0, 1 or -1 makes every zero +0 as q * v's does), each
// remaining sum the one q * v adds, -a - b as -(a) - b (negation is exact). 39 operations for the
// three axes where three whole products took 90 (perf annotate of the English oak: the rotations
// were the larger part of prepareCardFit's ~140 operations a leaf).
struct Axes4 {
    Vec4x3 h, l, u;
};
inline Vec4x3 headingAxis(__m128 qx, __m128 qy, __m128 qz, __m128 qw) {
    const __m128 sign = _mm_set1_ps(-0.0f), two = _mm_set1_ps(2.0f);
    const __m128 xx = _mm_mul_ps(qx, qx), zz = _mm_mul_ps(qz, qz);
    const __m128 xy = _mm_mul_ps(qy, qx), yz = _mm_mul_ps(qz, qy);
    const __m128 xw = _mm_mul_ps(qx, qw), zw = _mm_mul_ps(qz, qw);
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
    return {_mm_add_ps(zero, _mm_mul_ps(_mm_sub_ps(xy, zw), two)),
            _mm_add_ps(one, _mm_mul_ps(_mm_sub_ps(_mm_xor_ps(zz, sign), xx), two)),
            _mm_add_ps(zero, _mm_mul_ps(_mm_add_ps(xw, yz), two))};
}
inline Axes4 basisAxes(__m128 qx, __m128 qy, __m128 qz, __m128 qw) {
    const __m128 sign = _mm_set1_ps(-0.0f), two = _mm_set1_ps(2.0f);
    const __m128 xx = _mm_mul_ps(qx, qx), yy = _mm_mul_ps(qy, qy), zz = _mm_mul_ps(qz, qz);
    const __m128 xy = _mm_mul_ps(qy, qx), xz = _mm_mul_ps(qx, qz), yz = _mm_mul_ps(qz, qy);
    const __m128 xw = _mm_mul_ps(qx, qw), yw = _mm_mul_ps(qy, qw), zw = _mm_mul_ps(qz, qw);
    const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f), minusOne = _mm_set1_ps(-1.0f);
    const auto axis = [&](__m128 v, __m128 sum) { return _mm_add_ps(v, _mm_mul_ps(sum, two)); };
    return {{axis(zero, _mm_sub_ps(xy, zw)), axis(one, _mm_sub_ps(_mm_xor_ps(zz, sign), xx)),
             axis(zero, _mm_add_ps(xw, yz))},
            {axis(minusOne, _mm_add_ps(yy, zz)), axis(zero, _mm_sub_ps(_mm_xor_ps(zw, sign), xy)),
             axis(zero, _mm_sub_ps(yw, xz))},
            {axis(zero, _mm_add_ps(yw, xz)), axis(zero, _mm_sub_ps(yz, xw)),
             axis(one, _mm_sub_ps(_mm_xor_ps(xx, sign), yy))}};
}

// Four leaves' axes and their cards' corners (leafCorners' float operations lane by lane:
// stem left, stem right, tip right, tip left), \p halfAspect leafCorners' 0.5f * aspect and
// \p scale4 its scale in every lane.
struct LeafCards4 {
    Axes4 axes;
    Vec4x3 corner[4];
};
inline LeafCards4 leafCards4(const skel::Leaf* const leaf[4], float halfAspect, __m128 scale4) {
    __m128 qx = _mm_loadu_ps(&leaf[0]->orientation.x);
    __m128 qy = _mm_loadu_ps(&leaf[1]->orientation.x);
    __m128 qz = _mm_loadu_ps(&leaf[2]->orientation.x);
    __m128 qw = _mm_loadu_ps(&leaf[3]->orientation.x);
    _MM_TRANSPOSE4_PS(qx, qy, qz, qw);
    __m128 px = _mm_loadu_ps(&leaf[0]->position.x); // x, y, z and the orientation's x
    __m128 py = _mm_loadu_ps(&leaf[1]->position.x);
    __m128 pz = _mm_loadu_ps(&leaf[2]->position.x);
    __m128 pw = _mm_loadu_ps(&leaf[3]->position.x);
    _MM_TRANSPOSE4_PS(px, py, pz, pw);
    LeafCards4 out{basisAxes(qx, qy, qz, qw), {}};
    const Vec4x3 &h = out.axes.h, &l = out.axes.l;
    const __m128 len =
        _mm_mul_ps(_mm_set_ps(leaf[3]->size, leaf[2]->size, leaf[1]->size, leaf[0]->size), scale4);
    const __m128 across = _mm_mul_ps(_mm_set1_ps(halfAspect), len);
    const Vec4x3 hl{_mm_mul_ps(h.x, len), _mm_mul_ps(h.y, len), _mm_mul_ps(h.z, len)};
    const Vec4x3 ll{_mm_mul_ps(l.x, across), _mm_mul_ps(l.y, across), _mm_mul_ps(l.z, across)};
    const Vec4x3 plus{_mm_add_ps(px, ll.x), _mm_add_ps(py, ll.y), _mm_add_ps(pz, ll.z)};
    const Vec4x3 minus{_mm_sub_ps(px, ll.x), _mm_sub_ps(py, ll.y), _mm_sub_ps(pz, ll.z)};
    out.corner[0] = plus;
    out.corner[1] = minus;
    out.corner[2] = {_mm_add_ps(minus.x, hl.x), _mm_add_ps(minus.y, hl.y),
                     _mm_add_ps(minus.z, hl.z)};
    out.corner[3] = {_mm_add_ps(plus.x, hl.x), _mm_add_ps(plus.y, hl.y), _mm_add_ps(plus.z, hl.z)};
    return out;
}

} // namespace sylva::mesh

#endif
