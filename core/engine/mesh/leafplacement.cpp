#include "engine/mesh/leafplacement.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <span>

#include <glm/gtc/quaternion.hpp>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "engine/mesh/leafframesavx.h"
#include "engine/util/error.h"
#include "engine/util/random.h"

namespace sylva::mesh {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

glm::vec3 perpendicular(const glm::vec3& t, const glm::vec3& hint) {
    glm::vec3 p = hint - glm::dot(hint, t) * t;
    if (glm::dot(p, p) < 1e-8f) {
        const glm::vec3 a = std::abs(t.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        p = glm::cross(t, a);
    }
    return glm::normalize(p);
}

// glm::quat_cast of a rotation matrix without its branches: the same four candidates, the same
// comparisons in the same order and the same arithmetic, so the same quaternion bit for bit. A
// leaf's frame turns every way, so which candidate is the largest was mispredicted about every
// other leaf (perf record of the English oak: Placer::leaf 10 % of the tree, its samples on
// quat_cast's branches).
// w, x, y, z of each of glm::quat_cast's four cases, from {biggest, (m12 - m21), (m20 - m02),
// (m01 - m10), (m01 + m10), (m20 + m02), (m12 + m21)}, each times mult.
constexpr int kFramePick[4][4] = {{0, 1, 2, 3}, {1, 0, 4, 5}, {2, 4, 0, 6}, {3, 5, 6, 0}};

glm::quat quatOfFrame(const glm::mat3& m) {
    const float fx = m[0][0] - m[1][1] - m[2][2];
    const float fy = m[1][1] - m[0][0] - m[2][2];
    const float fz = m[2][2] - m[0][0] - m[1][1];
    const float fw = m[0][0] + m[1][1] + m[2][2];
    int index = 0;
    float biggest = fw;
    index = fx > biggest ? 1 : index;
    biggest = fx > biggest ? fx : biggest;
    index = fy > biggest ? 2 : index;
    biggest = fy > biggest ? fy : biggest;
    index = fz > biggest ? 3 : index;
    biggest = fz > biggest ? fz : biggest;
    const float big = std::sqrt(biggest + 1.0f) * 0.5f;
    const float mult = 0.25f / big;
    const float v[7] = {big,
                        (m[1][2] - m[2][1]) * mult,
                        (m[2][0] - m[0][2]) * mult,
                        (m[0][1] - m[1][0]) * mult,
                        (m[0][1] + m[1][0]) * mult,
                        (m[2][0] + m[0][2]) * mult,
                        (m[1][2] + m[2][1]) * mult};
    const int* pick = kFramePick[index];
    return {v[pick[0]], v[pick[1]], v[pick[2]], v[pick[3]]};
}

#if defined(__SSE2__)
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
#endif

// The cosine and sine of an angle in radians, as floats.
glm::vec2 angleTrig(double ang) {
    return {static_cast<float>(std::cos(ang)), static_cast<float>(std::sin(ang))};
}

// The spiral's angles of its first kSharedSpiral positions, made once for the process (they
// depend on the position only: every tree made them again, ~200 std::cos and std::sin of a
// double a tree for the English oak); Placer's own table goes on past them.
constexpr std::uint64_t kSharedSpiral = 512;
const glm::vec2* sharedSpiral() {
    static const std::vector<glm::vec2> table = [] {
        std::vector<glm::vec2> t(kSharedSpiral);
        for (std::uint64_t q = 0; q < kSharedSpiral; ++q)
            t[q] = angleTrig(137.5 * kDeg * static_cast<double>(q));
        return t;
    }();
    return table.data();
}

struct Placer {
    const LeafPlacement& p;
    glm::vec3 light;
    std::vector<skel::Leaf>& out;
    // The petiole angle's sine and cosine, made once (they were made again for every leaf).
    float sinPetiole = std::sin(static_cast<float>(p.petioleAngle * kDeg));
    float cosPetiole = std::cos(static_cast<float>(p.petioleAngle * kDeg));

    // The frame of a leaf on a branch with tangent \p t, radial direction \p radial, one at
    // a time (orientAll's lanes do the same arithmetic four at a time).
    glm::quat frame(const glm::vec3& t, const glm::vec3& radial, float forward) const {
        glm::vec3 h = glm::normalize(sinPetiole * radial + cosPetiole * t + forward * t);
        glm::vec3 n = static_cast<float>(p.normalWeight) * radial +
                      static_cast<float>(p.upWeight) * glm::vec3(0, 1, 0) +
                      static_cast<float>(p.lightWeight) * light;
        // The card must not contain its own normal: keep n perpendicular to the heading.
        n -= glm::dot(n, h) * h;
        if (glm::dot(n, n) < 1e-8f) n = perpendicular(h, glm::cross(h, t) + radial);
        n = glm::normalize(n);
        const glm::vec3 l = glm::cross(n, h); // U × H = L for a right-handed H, L, U frame
        return glm::normalize(quatOfFrame(glm::mat3(-l, h, n)));
    }

    // A leaf at \p base on a branch with tangent \p t, radial direction \p radial: its
    // position, size (drawn from rng, in leaf order) and node now, its orientation and the
    // leaf itself by orientAll. Written through raw pointers into room made once: a push_back
    // here (its growth a call) kept the leaf loop's values on the stack.
    void leaf(const glm::vec3& base, const glm::vec3& t, const glm::vec3& radial, float forward,
              Rng& rng, std::int32_t node) {
        float* const in = inputs.get() + count;
        for (int a = 0; a < 3; ++a)
            in[a * stride] = t[a];
        in[6 * stride] = forward;
        leafAround(base, radial, rng, node);
    }

    // leaf() without the tangent and forward weight, which fill() writes for a run of leaves
    // after (a segment's run shares them; seven values a leaf kept the loop's values on the
    // stack).
    void leafAround(const glm::vec3& base, const glm::vec3& radial, Rng& rng, std::int32_t node) {
        float* const in = inputs.get() + count;
        const double v = p.sizeVariation * rng.uniform(-1.0, 1.0);
        for (int a = 0; a < 3; ++a) {
            in[(3 + a) * stride] = radial[a];
            in[(7 + a) * stride] = base[a];
        }
        in[10 * stride] = static_cast<float>(p.size * (1.0 + v));
        nodes[count] = node;
        ++count;
    }
    // \p n spiral leaves along a segment from \p a0 (radius \p r0) to \p a1 (radius \p r1),
    // leaf c at its middle fraction f = (c + 0.5) / n and angle run[c]: leafAround()'s values in
    // two loops, the sizes first (the generator's draws, in leaf order) and then the positions
    // and radial directions, the same products and sums of the same floats a leaf, four leaves
    // a step (n < 2^31).
    void spiralLeaves(const glm::vec2* run, std::uint32_t n, const glm::vec3& a0,
                      const glm::vec3& a1, float r0, float r1, const glm::vec3& e1,
                      const glm::vec3& e2, Rng& rng, std::int32_t node) {
        float* const in = inputs.get() + count;
        float* __restrict const size = in + 10 * stride;
        std::int32_t* __restrict const nodeOut = nodes.get() + count;
        const double sizeVariation = p.sizeVariation, leafSize = p.size;
        for (std::uint32_t c = 0; c < n; ++c) {
            const double v = sizeVariation * rng.uniform(-1.0, 1.0);
            size[c] = static_cast<float>(leafSize * (1.0 + v));
            nodeOut[c] = node;
        }
        float* __restrict const rx = in + 3 * stride;
        float* __restrict const ry = in + 4 * stride;
        float* __restrict const rz = in + 5 * stride;
        float* __restrict const bx = in + 7 * stride;
        float* __restrict const by = in + 8 * stride;
        float* __restrict const bz = in + 9 * stride;
        const glm::vec3 d = a1 - a0;
        const float dr = r1 - r0;
        const auto fn = static_cast<float>(n);
        // The angles as floats (cosine, sine); four leaves a step on SSE2, each lane the
        // scalar loop's operations in its order (no product is fused: the same bits).
        const float* const trig = &run[0].x;
        std::int32_t c = 0;
        const auto last = static_cast<std::int32_t>(n);
#if defined(__SSE2__)
        const __m128 half = _mm_set1_ps(0.5f), fv = _mm_set1_ps(fn);
        const __m128 r0v = _mm_set1_ps(r0), drv = _mm_set1_ps(dr);
        const __m128 e1x = _mm_set1_ps(e1.x), e1y = _mm_set1_ps(e1.y), e1z = _mm_set1_ps(e1.z);
        const __m128 e2x = _mm_set1_ps(e2.x), e2y = _mm_set1_ps(e2.y), e2z = _mm_set1_ps(e2.z);
        const __m128 ax = _mm_set1_ps(a0.x), ay = _mm_set1_ps(a0.y), az = _mm_set1_ps(a0.z);
        const __m128 dx = _mm_set1_ps(d.x), dy = _mm_set1_ps(d.y), dz = _mm_set1_ps(d.z);
        for (; c + 4 <= last; c += 4) {
            const __m128 cf = _mm_cvtepi32_ps(_mm_setr_epi32(c, c + 1, c + 2, c + 3));
            const __m128 f = _mm_div_ps(_mm_add_ps(cf, half), fv);
            const __m128 r = _mm_add_ps(r0v, _mm_mul_ps(f, drv));
            const __m128 lo = _mm_loadu_ps(trig + 2 * c), hi = _mm_loadu_ps(trig + 2 * c + 4);
            const __m128 cx = _mm_shuffle_ps(lo, hi, _MM_SHUFFLE(2, 0, 2, 0));
            const __m128 cy = _mm_shuffle_ps(lo, hi, _MM_SHUFFLE(3, 1, 3, 1));
            const __m128 x = _mm_add_ps(_mm_mul_ps(cx, e1x), _mm_mul_ps(cy, e2x));
            const __m128 y = _mm_add_ps(_mm_mul_ps(cx, e1y), _mm_mul_ps(cy, e2y));
            const __m128 z = _mm_add_ps(_mm_mul_ps(cx, e1z), _mm_mul_ps(cy, e2z));
            _mm_storeu_ps(rx + c, x);
            _mm_storeu_ps(ry + c, y);
            _mm_storeu_ps(rz + c, z);
            _mm_storeu_ps(bx + c, _mm_add_ps(_mm_add_ps(ax, _mm_mul_ps(f, dx)), _mm_mul_ps(r, x)));
            _mm_storeu_ps(by + c, _mm_add_ps(_mm_add_ps(ay, _mm_mul_ps(f, dy)), _mm_mul_ps(r, y)));
            _mm_storeu_ps(bz + c, _mm_add_ps(_mm_add_ps(az, _mm_mul_ps(f, dz)), _mm_mul_ps(r, z)));
        }
#endif
        for (; c < last; ++c) {
            const float f = (static_cast<float>(c) + 0.5f) / fn;
            const float r = r0 + f * dr;
            const float cx = trig[2 * c], cy = trig[2 * c + 1];
            const float x = cx * e1.x + cy * e2.x;
            const float y = cx * e1.y + cy * e2.y;
            const float z = cx * e1.z + cy * e2.z;
            rx[c] = x;
            ry[c] = y;
            rz[c] = z;
            bx[c] = (a0.x + f * d.x) + r * x;
            by[c] = (a0.y + f * d.y) + r * y;
            bz[c] = (a0.z + f * d.z) + r * z;
        }
        count += n;
    }

    /// Leaf k (leaf() call k) with its orientation \p q, appended to out.
    void emit(std::size_t k, const glm::quat& q) {
        out.push_back({{input(7)[k], input(8)[k], input(9)[k]}, q, input(10)[k], nodes[k]});
    }
    /// The tangent \p t and forward weight of the leaves from leaf() call \p from to the last.
    void fill(std::size_t from, const glm::vec3& t, float forward) {
        float* const in = inputs.get();
        for (int a = 0; a < 3; ++a)
            std::fill(in + a * stride + from, in + a * stride + count, t[a]);
        std::fill(in + 6 * stride + from, in + 6 * stride + count, forward);
    }

    // The orientations of the leaves (leaf() calls, in order), each leaf then appended to out:
    // frame()'s arithmetic four leaves at a time on SSE2 (each lane's operations are the scalar
    // ones, in the same order, and packed square roots and divisions round as the scalar ones do:
    // the same quaternions, bit for bit). One leaf's frame is four square roots and divisions in a
    // chain; perf record of the English oak: Placer::leaf 10 % of the tree.
    void orientAll() {
        const std::size_t n = count;
        std::size_t k = 0;
        if (leafFramesAvx()) {
            // The same lanes eight to a register (leafFramesAvx16), or sixteen, four registers
            // a call (leafFramesAvx512x64).
            const LeafFrameWeights w{sinPetiole,
                                     cosPetiole,
                                     static_cast<float>(p.normalWeight),
                                     static_cast<float>(p.upWeight),
                                     static_cast<float>(p.lightWeight),
                                     light.x,
                                     light.y,
                                     light.z};
            if (leafFramesAvx512()) {
                alignas(64) float q[4][64];
                for (; k + 64 <= n; k += 64) {
                    const float* const in[7] = {input(0) + k, input(1) + k, input(2) + k,
                                                input(3) + k, input(4) + k, input(5) + k,
                                                input(6) + k};
                    const std::uint64_t scalar = leafFramesAvx512x64(w, in, q);
                    for (int lane = 0; lane < 64; ++lane) {
                        const std::size_t kk = k + static_cast<std::size_t>(lane);
                        emit(kk, scalar >> lane & 1
                                     ? scalarFrame(kk)
                                     : glm::quat(q[0][lane], q[1][lane], q[2][lane], q[3][lane]));
                    }
                }
            }
            alignas(32) float q[4][16];
            for (; k + 16 <= n; k += 16) {
                const float* const in[7] = {input(0) + k, input(1) + k, input(2) + k, input(3) + k,
                                            input(4) + k, input(5) + k, input(6) + k};
                const unsigned scalar = leafFramesAvx16(w, in, q);
                for (int lane = 0; lane < 16; ++lane) {
                    const std::size_t kk = k + static_cast<std::size_t>(lane);
                    emit(kk, scalar >> lane & 1
                                 ? scalarFrame(kk)
                                 : glm::quat(q[0][lane], q[1][lane], q[2][lane], q[3][lane]));
                }
            }
        }
#if defined(__SSE2__)
        using P = Pack;
        const P sp = P::all(sinPetiole), cp = P::all(cosPetiole);
        const P nw = P::all(static_cast<float>(p.normalWeight));
        const P uw = P::all(static_cast<float>(p.upWeight));
        const P lw = P::all(static_cast<float>(p.lightWeight));
        const P zero = P::all(0.0f), one = P::all(1.0f);
        const P upX = uw * zero, upY = uw * one, upZ = upX;
        const P lwX = lw * P::all(light.x), lwY = lw * P::all(light.y), lwZ = lw * P::all(light.z);
        auto dot = [](P ax, P ay, P az, P bx, P by, P bz) { return ax * bx + ay * by + az * bz; };
        for (; k + Pack::kLanes <= n; k += Pack::kLanes) {
            const P tx = P::load(&input(0)[k]), ty = P::load(&input(1)[k]),
                    tz = P::load(&input(2)[k]);
            const P rx = P::load(&input(3)[k]), ry = P::load(&input(4)[k]),
                    rz = P::load(&input(5)[k]);
            const P fw = P::load(&input(6)[k]);
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
            // w, x, y, z: each lane's kFramePick[index] of {bv, v1, ..., v6}, chosen by masks
            // (the same bits; through memory, a store and reload a lane, the pick was part of
            // the chain the iteration waits on).
            const PackPick pick(index);
            const P qw = pick(bv, v1, v2, v3), qx = pick(v1, bv, v4, v5);
            const P qy = pick(v2, v4, bv, v6), qz = pick(v3, v5, v6, bv);
            // glm::normalize(quat): (w w + x x) + (y y + z z), one over its root.
            const P len = sqrt((qw * qw + qx * qx) + (qy * qy + qz * qz));
            const unsigned flat = lessEqualMask(len, zero);
            const P over = one / len;
            alignas(16) float r[4][Pack::kLanes];
            (qw * over).store(r[0]);
            (qx * over).store(r[1]);
            (qy * over).store(r[2]);
            (qz * over).store(r[3]);
            for (int lane = 0; lane < Pack::kLanes; ++lane) {
                const std::size_t kk = k + static_cast<std::size_t>(lane);
                emit(kk, (odd | flat) >> lane & 1
                             ? scalarFrame(kk)
                             : glm::quat(r[0][lane], r[1][lane], r[2][lane], r[3][lane]));
            }
        }
#endif
        for (; k < n; ++k)
            emit(k, scalarFrame(k));
        count = 0;
    }

    glm::quat scalarFrame(std::size_t k) const {
        return frame({input(0)[k], input(1)[k], input(2)[k]},
                     {input(3)[k], input(4)[k], input(5)[k]}, input(6)[k]);
    }

    /// Room for \p leaves leaf() calls.
    void reserve(std::size_t leaves) {
        stride = leaves;
        inputs = std::make_unique_for_overwrite<float[]>(11 * leaves);
        nodes = std::make_unique_for_overwrite<std::int32_t[]>(leaves);
        count = 0;
    }
    const float* input(int a) const {
        return inputs.get() + static_cast<std::size_t>(a) * stride;
    }

    /// leaf()'s tangents (x, y, z), radial directions (x, y, z), forward weights, positions
    /// (x, y, z) and sizes: eleven arrays of stride floats, count leaves in each; and nodes.
    std::unique_ptr<float[]> inputs{};
    std::unique_ptr<std::int32_t[]> nodes{};
    std::size_t stride = 0;
    std::size_t count = 0;

    // The cosines and sines of the leaves' angles at position index k (radians), as floats.
    // They depend on k only (spiral) or on its parity: made once each, from the same double
    // angle as before (std::sincos of a double was a tenth of the placement).
    // Returned as a view of the tables (copying them into a vector at every position was a
    // clear and a push_back a leaf).
    std::span<const glm::vec2> angles(std::uint64_t k) {
        if (p.phyllotaxis == Phyllotaxis::Spiral) {
            const std::uint64_t j = k % 100000;
            if (j < kSharedSpiral) return {sharedSpiral() + j, 1};
            if (j >= spiral.size() && j < kSpiralTable)
                for (std::uint64_t q = spiral.size(); q <= j; ++q)
                    spiral.push_back(trig(137.5 * kDeg * static_cast<double>(q)));
            if (j < spiral.size()) return {&spiral[j], 1};
            far = trig(137.5 * kDeg * static_cast<double>(j));
            return {&far, 1};
        }
        std::vector<glm::vec2>& cached = parity[k % 2];
        if (cached.empty()) {
            switch (p.phyllotaxis) {
            case Phyllotaxis::Alternate:
                cached.push_back(trig(std::numbers::pi * static_cast<double>(k % 2)));
                break;
            case Phyllotaxis::Opposite: {
                const double base = 0.5 * std::numbers::pi * static_cast<double>(k % 2);
                cached.push_back(trig(base));
                cached.push_back(trig(base + std::numbers::pi));
                break;
            }
            case Phyllotaxis::Whorled: {
                const double gap = 2.0 * std::numbers::pi / p.whorlCount;
                const double base = 0.5 * gap * static_cast<double>(k % 2);
                for (int i = 0; i < p.whorlCount; ++i)
                    cached.push_back(trig(base + gap * i));
                break;
            }
            case Phyllotaxis::Spiral:
                break;
            }
        }
        return cached;
    }

    /// The angles of positions k .. k + count - 1 where they are one a position (spiral) and
    /// lie in a row of the table (filled as far as needed); null otherwise (angles() then).
    const glm::vec2* spiralRun(std::uint64_t k, std::uint64_t count) {
        if (p.phyllotaxis != Phyllotaxis::Spiral || count == 0) return nullptr;
        const std::uint64_t j = k % 100000;
        if (j + count <= kSharedSpiral) return sharedSpiral() + j;
        if (j + count > kSpiralTable || j + count > 100000) return nullptr;
        for (std::uint64_t q = spiral.size(); q < j + count; ++q)
            spiral.push_back(trig(137.5 * kDeg * static_cast<double>(q)));
        return spiral.data() + j;
    }

    static glm::vec2 trig(double ang) {
        return angleTrig(ang);
    }
    static constexpr std::uint64_t kSpiralTable = 1u << 16;
    std::vector<glm::vec2> spiral{};    ///< by k % 100000, filled as far as asked
    glm::vec2 far{};                    ///< the angle of a spiral position past the table
    std::vector<glm::vec2> parity[2]{}; ///< the other arrangements, by k % 2
};

// A segment's length, tangent and the two radial axes its leaves turn about.
// Left uninitialised where made (placeLeaves writes the leafy segments' and reads no other).
struct SegmentFrame {
    float len;
    glm::vec3 t, e1, e2;
};

// At least as many leaves as placeLeaves makes (one more a segment than its density gives):
// the output reserved once, not grown by copying.
std::size_t leafBound(const skel::Skeleton& s, const LeafPlacement& p,
                      const std::vector<std::uint8_t>& hidden,
                      const std::vector<std::uint32_t>& children, const SegmentFrame* frames) {
    const std::size_t perPosition = p.phyllotaxis == Phyllotaxis::Opposite  ? 2
                                    : p.phyllotaxis == Phyllotaxis::Whorled ? p.whorlCount
                                                                            : 1;
    std::size_t bound = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const std::int32_t par = s.parent[i];
        if (par < 0 || hidden[i]) continue;
        if (p.alongBranches && s.radius[i] <= p.maxBranchRadius) {
            const float len = frames[i].len;
            bound += perPosition * (static_cast<std::size_t>(p.density * len) + 1);
        }
        if (p.atTips && children[i] == 0) bound += static_cast<std::size_t>(p.tipCount);
    }
    return bound;
}

} // namespace

std::vector<skel::Leaf> placeLeaves(const skel::Skeleton& s, const LeafPlacement& p) {
    requireRange("whorl_count", p.whorlCount, 2, 12);
    requireRange("size", p.size, 1e-6, 100.0);
    requireRange("size_variation", p.sizeVariation, 0.0, 1.0);
    requireRange("density", p.density, 0.0, 1000.0);
    requireRange("tip_count", p.tipCount, 0, 32);
    requireRange("max_branch_radius", p.maxBranchRadius, 0.0, 1e3);
    requireRange("petiole_angle", p.petioleAngle, 0.0, 90.0);
    requireRange("normal_weight", p.normalWeight, 0.0, 1e3);
    requireRange("up_weight", p.upWeight, 0.0, 1e3);
    requireRange("light_weight", p.lightWeight, 0.0, 1e3);
    s.validate();

    std::vector<skel::Leaf> out;
    if (p.keepGrammarLeaves) out = s.leaves;
    const float ll = glm::length(p.lightDirection);
    Placer placer{p, ll > 0.0f ? p.lightDirection / ll : glm::vec3(0, 1, 0), out};

    const std::size_t n = s.size();
    std::vector<std::uint32_t> children(n, 0);
    std::vector<std::uint8_t> hidden(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t par = s.parent[i];
        hidden[i] =
            (s.flags[i] & skel::kHidden) || (par >= 0 && hidden[static_cast<std::size_t>(par)]);
        if (par >= 0 && !hidden[i]) ++children[static_cast<std::size_t>(par)];
    }
    // Each segment's frame first, in a loop of their own: a frame is a chain of two square
    // roots and divisions, which the segments' loops of leaves kept from overlapping.
    // Only the segments that bear leaves (along it or at its tip) need theirs: the thick ones
    // below the leafy twigs are skipped (their frame is left unwritten and never read).
    const auto frameRoom = std::make_unique_for_overwrite<SegmentFrame[]>(n);
    SegmentFrame* const frames = frameRoom.get();
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t par = s.parent[i];
        if (par < 0 || hidden[i]) continue;
        if (!(p.alongBranches && s.radius[i] <= p.maxBranchRadius) &&
            !(p.atTips && children[i] == 0))
            continue;
        const glm::vec3 a0 = s.position[static_cast<std::size_t>(par)], a1 = s.position[i];
        SegmentFrame& f = frames[i];
        f.len = glm::length(a1 - a0);
        f.t = f.len > 1e-9f ? (a1 - a0) / f.len : skel::headingOf(s.orientation[i]);
        f.e1 = perpendicular(f.t, skel::upOf(s.orientation[i]));
        f.e2 = glm::cross(f.t, f.e1);
    }
    // Running position index along each axis so phyllotaxis continues across segments.
    std::vector<std::uint64_t> index(n, 0);
    const std::size_t bound = leafBound(s, p, hidden, children, frames);
    const std::size_t first = out.size();
    out.reserve(first + bound);
    placer.reserve(bound);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t par = s.parent[i];
        if (par < 0 || hidden[i]) continue;
        const auto pi = static_cast<std::size_t>(par);
        std::uint64_t k = s.order[i] == s.order[pi] ? index[pi] : 0;
        // A segment without leaves passes its axis's position index on (no generator seeded).
        if (!(p.alongBranches && s.radius[i] <= p.maxBranchRadius) &&
            !(p.atTips && children[i] == 0)) {
            index[i] = k;
            continue;
        }
        Rng rng(mixSeed(p.seed, i));
        const glm::vec3 a0 = s.position[pi], a1 = s.position[i];
        const SegmentFrame& frame = frames[i];
        const float len = frame.len;
        const glm::vec3 t = frame.t, e1 = frame.e1, e2 = frame.e2;
        if (p.alongBranches && s.radius[i] <= p.maxBranchRadius && len > 0.0f) {
            const auto count = static_cast<std::uint64_t>(p.density * len + rng.uniform());
            // The spiral's one angle a position, from its table without a call a leaf.
            const glm::vec2* run = count < (1u << 31) ? placer.spiralRun(k, count) : nullptr;
            if (run != nullptr) {
                const std::size_t from = placer.count;
                placer.spiralLeaves(run, static_cast<std::uint32_t>(count), a0, a1, s.radius[pi],
                                    s.radius[i], e1, e2, rng, static_cast<std::int32_t>(i));
                placer.fill(from, t, 0.0f);
                k += count;
            } else {
                for (std::uint64_t c = 0; c < count; ++c, ++k) {
                    const float f = (static_cast<float>(c) + 0.5f) / static_cast<float>(count);
                    const glm::vec3 axis = a0 + f * (a1 - a0);
                    const float r = s.radius[pi] + f * (s.radius[i] - s.radius[pi]);
                    for (const glm::vec2& cs : placer.angles(k)) {
                        const glm::vec3 radial = cs.x * e1 + cs.y * e2;
                        placer.leaf(axis + r * radial, t, radial, 0.0f, rng,
                                    static_cast<std::int32_t>(i));
                    }
                }
            }
        }
        index[i] = k;
        if (p.atTips && children[i] == 0) {
            for (int c = 0; c < p.tipCount; ++c) {
                const double ang = 2.0 * std::numbers::pi * c / p.tipCount + rng.uniform(0.0, 0.5);
                const glm::vec3 radial =
                    static_cast<float>(std::cos(ang)) * e1 + static_cast<float>(std::sin(ang)) * e2;
                placer.leaf(a1, t, radial, 1.0f, rng, static_cast<std::int32_t>(i));
            }
        }
    }
    placer.orientAll();
    return out;
}

} // namespace sylva::mesh
