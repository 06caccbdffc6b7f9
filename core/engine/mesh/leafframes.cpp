#include "engine/mesh/leafframes.h"

#if defined(__SSE2__)
#include <emmintrin.h>

#include <cstdint>

namespace sylva::mesh {

namespace {

// Sixteen floats as four SSE2 registers, each operation made on all four in turn: blocks of four
// leaves whose chains of square roots and divisions interleave in the instruction stream. A
// block's chain (three square roots and divisions, the quaternion's pick through memory, its
// normalisation: roughly 250 cycles by the latencies) is too long for the processor to overlap the
// next iteration's, so the work was bound by the chain's latency (the oak: ~8 ns a leaf with two
// registers, ~6.5 with four; eight registers spill: slower). Each lane's operations are the scalar
// ones in order.
struct Pack {
    static constexpr int kRegs = 4;
    static constexpr int kLanes = 4 * kRegs;
    __m128 r[kRegs];
    static Pack all(float v) {
        Pack p;
        for (__m128& x : p.r)
            x = _mm_set1_ps(v);
        return p;
    }
    static Pack load(const float* f) {
        Pack p;
        for (int i = 0; i < kRegs; ++i)
            p.r[i] = _mm_loadu_ps(f + 4 * i);
        return p;
    }
    void store(float* f) const {
        for (int i = 0; i < kRegs; ++i)
            _mm_store_ps(f + 4 * i, r[i]);
    }
    template <class Op> static Pack map(Pack x, Pack y, Op op) {
        Pack p;
        for (int i = 0; i < kRegs; ++i)
            p.r[i] = op(x.r[i], y.r[i]);
        return p;
    }
};
inline Pack operator+(Pack x, Pack y) {
    return Pack::map(x, y, [](__m128 a, __m128 b) { return _mm_add_ps(a, b); });
}
inline Pack operator-(Pack x, Pack y) {
    return Pack::map(x, y, [](__m128 a, __m128 b) { return _mm_sub_ps(a, b); });
}
inline Pack operator*(Pack x, Pack y) {
    return Pack::map(x, y, [](__m128 a, __m128 b) { return _mm_mul_ps(a, b); });
}
inline Pack operator/(Pack x, Pack y) {
    return Pack::map(x, y, [](__m128 a, __m128 b) { return _mm_div_ps(a, b); });
}
inline Pack operator-(Pack x) { // the sign bit flipped, as glm's unary minus on floats
    return Pack::map(x, x, [](__m128 a, __m128) { return _mm_xor_ps(a, _mm_set1_ps(-0.0f)); });
}
inline Pack sqrt(Pack x) {
    return Pack::map(x, x, [](__m128 a, __m128) { return _mm_sqrt_ps(a); });
}
inline unsigned lessMask(Pack x, Pack y) {
    unsigned m = 0;
    for (int i = 0; i < Pack::kRegs; ++i)
        m |= static_cast<unsigned>(_mm_movemask_ps(_mm_cmplt_ps(x.r[i], y.r[i]))) << (4 * i);
    return m;
}
inline unsigned lessEqualMask(Pack x, Pack y) {
    unsigned m = 0;
    for (int i = 0; i < Pack::kRegs; ++i)
        m |= static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(x.r[i], y.r[i]))) << (4 * i);
    return m;
}
struct PackIndex {
    __m128i r[Pack::kRegs] = {};
};
// Each lane's a_i for its index i (0..3) in a PackIndex, by masks: the value's bits unchanged.
struct PackPick {
    __m128 is[4][Pack::kRegs];
    explicit PackPick(const PackIndex& index) {
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < Pack::kRegs; ++k)
                is[i][k] = _mm_castsi128_ps(_mm_cmpeq_epi32(index.r[k], _mm_set1_epi32(i)));
    }
    Pack operator()(const Pack& a0, const Pack& a1, const Pack& a2, const Pack& a3) const {
        Pack p;
        for (int k = 0; k < Pack::kRegs; ++k)
            p.r[k] =
                _mm_or_ps(_mm_or_ps(_mm_and_ps(is[0][k], a0.r[k]), _mm_and_ps(is[1][k], a1.r[k])),
                          _mm_or_ps(_mm_and_ps(is[2][k], a2.r[k]), _mm_and_ps(is[3][k], a3.r[k])));
        return p;
    }
};
// quatOfFrame's running choice: where f is larger than big, big becomes f and index i.
inline void take(Pack f, int i, Pack& big, PackIndex& index) {
    const __m128i ii = _mm_set1_epi32(i);
    for (int k = 0; k < Pack::kRegs; ++k) {
        const __m128 more = _mm_cmpgt_ps(f.r[k], big.r[k]);
        big.r[k] = _mm_or_ps(_mm_and_ps(more, f.r[k]), _mm_andnot_ps(more, big.r[k]));
        const __m128i mi = _mm_castps_si128(more);
        index.r[k] = _mm_or_si128(_mm_and_si128(mi, ii), _mm_andnot_si128(mi, index.r[k]));
    }
}

} // namespace

unsigned leafFramesSse16(const LeafFrameWeights& w, const float* const in[7], float q[4][16]) {
    using P = Pack;
    const P sp = P::all(w.sinPetiole), cp = P::all(w.cosPetiole);
    const P nw = P::all(w.normal);
    const P uw = P::all(w.up);
    const P lw = P::all(w.light);
    const P zero = P::all(0.0f), one = P::all(1.0f);
    const P upX = uw * zero, upY = uw * one, upZ = upX;
    const P lwX = lw * P::all(w.lightX), lwY = lw * P::all(w.lightY), lwZ = lw * P::all(w.lightZ);
    auto dot = [](P ax, P ay, P az, P bx, P by, P bz) { return ax * bx + ay * by + az * bz; };
    const P tx = P::load(in[0]), ty = P::load(in[1]), tz = P::load(in[2]);
    const P rx = P::load(in[3]), ry = P::load(in[4]), rz = P::load(in[5]);
    const P fw = P::load(in[6]);
    P hx = sp * rx + cp * tx + fw * tx;
    P hy = sp * ry + cp * ty + fw * ty;
    P hz = sp * rz + cp * tz + fw * tz;
    P inv = one / sqrt(dot(hx, hy, hz, hx, hy, hz));
    hx = hx * inv;
    hy = hy * inv;
    hz = hz * inv;
    P nx = nw * rx + upX + lwX;
    P ny = nw * ry + upY + lwY;
    P nz = nw * rz + upZ + lwZ;
    const P nh = dot(nx, ny, nz, hx, hy, hz);
    nx = nx - nh * hx;
    ny = ny - nh * hy;
    nz = nz - nh * hz;
    const P nn = dot(nx, ny, nz, nx, ny, nz);
    // A lane whose normal is (nearly) along its heading takes frame()'s other branch.
    const unsigned odd = lessMask(nn, P::all(1e-8f));
    inv = one / sqrt(nn);
    nx = nx * inv;
    ny = ny * inv;
    nz = nz * inv;
    // l = cross(n, h); the frame's matrix is (-l, h, n) by columns.
    const P lx = ny * hz - hy * nz;
    const P ly = nz * hx - hz * nx;
    const P lz = nx * hy - hx * ny;
    const P m00 = -lx, m01 = -ly, m02 = -lz; // -l as glm negates: the sign flipped
    const P m10 = hx, m11 = hy, m12 = hz, m20 = nx, m21 = ny, m22 = nz;
    // quatOfFrame, a pack at a time.
    const P fx = m00 - m11 - m22;
    const P fy = m11 - m00 - m22;
    const P fz = m22 - m00 - m11;
    P big = m00 + m11 + m22;
    PackIndex index{};
    take(fx, 1, big, index);
    take(fy, 2, big, index);
    take(fz, 3, big, index);
    const P bv = sqrt(big + one) * P::all(0.5f);
    const P mult = P::all(0.25f) / bv;
    const P v1 = (m12 - m21) * mult, v2 = (m20 - m02) * mult, v3 = (m01 - m10) * mult;
    const P v4 = (m01 + m10) * mult, v5 = (m20 + m02) * mult, v6 = (m12 + m21) * mult;
    // w, x, y, z: each lane's pick (placeLeaves' kFramePick, by its index) of {bv, v1, ..., v6},
    // chosen by masks (the same bits; through memory, a store and reload a lane, the pick was part
    // of the chain the iteration waits on).
    const PackPick pick(index);
    const P qw = pick(bv, v1, v2, v3), qx = pick(v1, bv, v4, v5);
    const P qy = pick(v2, v4, bv, v6), qz = pick(v3, v5, v6, bv);
    // glm::normalize(quat): (w w + x x) + (y y + z z), one over its root.
    const P len = sqrt((qw * qw + qx * qx) + (qy * qy + qz * qz));
    const unsigned flat = lessEqualMask(len, zero);
    const P over = one / len;
    (qw * over).store(q[0]);
    (qx * over).store(q[1]);
    (qy * over).store(q[2]);
    (qz * over).store(q[3]);
    return odd | flat;
}

} // namespace sylva::mesh
#endif
