#include "engine/mesh/barkrelief.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "engine/util/error.h"
#include "engine/util/safenormalize.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace sylva::mesh {

namespace {

std::uint32_t hash3(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint32_t h = a * 0x9E3779B1u ^ (b + 0x7F4A7C15u) * 0x85EBCA77u ^ c * 0xC2B2AE3Du;
    h ^= h >> 15;
    h *= 0x2C1B3C6Du;
    h ^= h >> 12;
    h *= 0x297A2D39u;
    h ^= h >> 15;
    return h;
}

/// Uniform in [0, 1) from a lattice point.
float unit(std::int32_t i, std::int32_t j, std::uint32_t seed) {
    return static_cast<float>(
               hash3(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j), seed) >> 8) *
           (1.0f / 16777216.0f);
}

std::int32_t wrap(std::int32_t i, int period) {
    const std::int32_t m = i % period;
    return m < 0 ? m + period : m;
}

float smooth(float t) {
    return t * t * (3.0f - 2.0f * t);
}

float smoothstep(float a, float b, float x) {
    return smooth(std::clamp((x - a) / (b - a), 0.0f, 1.0f));
}

/// Value noise in [0, 1), lattice spacing 1, periodic in x with \p period lattice cells.
float noise(float x, float y, int period, std::uint32_t seed) {
    const float fx = std::floor(x), fy = std::floor(y);
    const auto ix = static_cast<std::int32_t>(fx), iy = static_cast<std::int32_t>(fy);
    const float tx = smooth(x - fx), ty = smooth(y - fy);
    const std::int32_t x0 = wrap(ix, period), x1 = wrap(ix + 1, period);
    const float a = unit(x0, iy, seed), b = unit(x1, iy, seed);
    const float c = unit(x0, iy + 1, seed), d = unit(x1, iy + 1, seed);
    return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

float ridges(float x, float y, int columns, std::uint32_t seed) {
    // (ridgesRow makes the same numbers a ring at a time: change both together.)
    // The ridges meander over a few of their widths along the axis.
    // (Its lattice is two columns wide where the columns are even, so that it closes the ring.)
    const bool even = columns % 2 == 0;
    const float warp =
        0.9f * (noise(even ? x * 0.5f : x, y * 0.25f, even ? columns / 2 : columns, seed) - 0.5f);
    const float xs = x + warp;
    const float fx = std::floor(xs);
    const std::int32_t col = wrap(static_cast<std::int32_t>(fx), columns);
    const float f = xs - fx;
    // Flat-topped ridge, V furrow at the column's edges.
    const float ridge = std::sqrt(std::max(std::sin(std::numbers::pi_v<float> * f), 0.0f));
    // Each ridge is broken across into segments of 2-4 widths, each its own height.
    const float along = y / 3.0f + unit(col, -1, seed);
    const float fa = std::floor(along);
    const float u = along - fa;
    const float height = 0.55f + 0.45f * unit(col, static_cast<std::int32_t>(fa), seed ^ 0x51u);
    const float brk =
        0.35f + 0.65f * smoothstep(0.0f, 0.15f, u) * smoothstep(0.0f, 0.15f, 1.0f - u);
    return ridge * height * brk;
}

float plates(float x, float y, int columns, std::uint32_t seed) {
    const float warp = 0.5f * (noise(x, y * 0.5f, columns, seed) - 0.5f);
    const float xs = x + warp;
    const float fx = std::floor(xs);
    const std::int32_t col = wrap(static_cast<std::int32_t>(fx), columns);
    const float f = xs - fx;
    // Plates about 1.6 widths long, each column's cracks across at its own offsets.
    const float along = y / 1.6f + unit(col, -7, seed);
    const float fa = std::floor(along);
    const float u = along - fa;
    const auto row = static_cast<std::int32_t>(fa);
    const float edge = smoothstep(0.0f, 0.2f, f) * smoothstep(0.0f, 0.2f, 1.0f - f);
    const float edgeAlong = smoothstep(0.0f, 0.12f, u) * smoothstep(0.0f, 0.12f, 1.0f - u);
    const float height = 0.45f + 0.55f * unit(col, row, seed ^ 0xA7u);
    // A plate's upper end stands out a little more than its lower (scales lie on each other).
    const float tilt = 0.85f + 0.15f * u;
    return std::min(edge, edgeAlong) * height * tilt;
}

/// ridges(x_j, y, columns, seed) scaled by \p amplitude for a whole ring, the same operations
/// in the same order; what does not change along the ring (the warp noise's row of lattice
/// values, each column's height and break) is made once, what depends on j alone (x_j and its
/// warp lattice columns and blend) is \p ring's.
void ridgesRow(BarkRing& ring, float y, std::uint32_t seed, float amplitude, float* row) {
    const int columns = std::max(ring.columns, 1);
    const bool even = columns % 2 == 0;
    const int period = even ? columns / 2 : columns;
    // The warp noise's lattice rows iy and iy + 1 (noise's y is constant along the ring).
    const float ny = y * 0.25f;
    const float fy = std::floor(ny);
    const auto iy = static_cast<std::int32_t>(fy);
    const float ty = smooth(ny - fy);
    const auto cols = static_cast<std::size_t>(columns);
    ring.scratch.resize(2 * static_cast<std::size_t>(period) + 2 * cols);
    float* low = ring.scratch.data();
    float* high = low + period;
    float* height = high + period;
    float* brk = height + cols;
    for (std::int32_t i = 0; i < period; ++i) {
        low[i] = unit(i, iy, seed);
        high[i] = unit(i, iy + 1, seed);
    }
    for (std::int32_t col = 0; col < columns; ++col) {
        const float along = y / 3.0f + unit(col, -1, seed);
        const float fa = std::floor(along);
        const float u = along - fa;
        height[col] = 0.55f + 0.45f * unit(col, static_cast<std::int32_t>(fa), seed ^ 0x51u);
        brk[col] = 0.35f + 0.65f * smoothstep(0.0f, 0.15f, u) * smoothstep(0.0f, 0.15f, 1.0f - u);
    }
    const float* xs0 = ring.x.data();
    const float* blend = ring.blend.data();
    const std::int32_t* lower = ring.lower.data();
    for (int j = 0; j < ring.sides; ++j) {
        const float x = xs0[j];
        const float tx = blend[j];
        const std::int32_t x0 = lower[j];
        const std::int32_t x1 = x0 + 1 == period ? 0 : x0 + 1;
        const float a = low[x0], b = low[x1], c = high[x0], d = high[x1];
        const float n = (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
        const float warp = 0.9f * (n - 0.5f);
        const float xs = x + warp;
        const float fx = std::floor(xs);
        const std::int32_t col = wrap(static_cast<std::int32_t>(fx), columns);
        const float f = xs - fx;
        const float ridge = std::sqrt(std::max(std::sin(std::numbers::pi_v<float> * f), 0.0f));
        row[j] = amplitude * (ridge * height[col] * brk[col]);
    }
}

} // namespace

BarkPattern parseBarkPattern(const std::string& name) {
    if (name == "ridges") return BarkPattern::Ridges;
    if (name == "plates") return BarkPattern::Plates;
    throw InvalidInput("bark_relief_pattern must be \"ridges\" or \"plates\", got \"" + name +
                       "\"");
}

double barkRingSpacing(BarkPattern pattern) {
    return pattern == BarkPattern::Ridges ? 1.5 : 0.4;
}

float barkReliefShape(BarkPattern pattern, float x, float y, int columns, std::uint32_t seed) {
    columns = std::max(columns, 1);
    return pattern == BarkPattern::Ridges ? ridges(x, y, columns, seed)
                                          : plates(x, y, columns, seed);
}

BarkRing::BarkRing(BarkPattern pattern_, int columns_, int sides_)
    : pattern(pattern_), columns(columns_), sides(std::max(sides_, 0)) {
    if (pattern != BarkPattern::Ridges) return;
    // ridges()'s x and its warp noise's lattice column and blend (nx, floor, smooth, wrap).
    const int cols = std::max(columns, 1);
    const bool even = cols % 2 == 0;
    const int period = even ? cols / 2 : cols;
    const auto n = static_cast<std::size_t>(sides);
    x.resize(n);
    blend.resize(n);
    lower.resize(n);
    for (int j = 0; j < sides; ++j) {
        const auto k = static_cast<std::size_t>(j);
        x[k] = static_cast<float>(j * cols) / static_cast<float>(sides);
        const float nx = even ? x[k] * 0.5f : x[k];
        const float fx0 = std::floor(nx);
        blend[k] = smooth(nx - fx0);
        lower[k] = wrap(static_cast<std::int32_t>(fx0), period);
    }
}

void barkReliefRow(BarkRing& ring, float y, std::uint32_t seed, float amplitude, float* row) {
    if (ring.pattern == BarkPattern::Ridges) {
        ridgesRow(ring, y, seed, amplitude, row);
        return;
    }
    for (int j = 0; j < ring.sides; ++j)
        row[j] = amplitude * barkReliefShape(ring.pattern,
                                             static_cast<float>(j * ring.columns) /
                                                 static_cast<float>(ring.sides),
                                             y, ring.columns, seed);
}

void barkReliefRow(BarkPattern pattern, int columns, int sides, float y, std::uint32_t seed,
                   float amplitude, float* row) {
    BarkRing ring(pattern, columns, sides);
    barkReliefRow(ring, y, seed, amplitude, row);
}

// (four quotients to a division on SSE2, each the scalar one: IEEE division rounds alike
// packed or not)
void barkSlopeRow(const float* row, const float* a, const float* b, int res, float twoDTheta,
                  float ds, float* dTh, float* dS) {
    const auto n = static_cast<std::size_t>(res) + 1;
    for (std::size_t j = 0; j < n; ++j) {
        const std::size_t prev = j == 0 ? static_cast<std::size_t>(res) - 1 : j - 1;
        const std::size_t next = j == static_cast<std::size_t>(res) ? 1 : j + 1;
        dTh[j] = row[next] - row[prev];
        dS[j] = b[j] - a[j];
    }
    const bool along = ds > 1e-12f;
#if defined(__SSE2__)
    for (std::size_t j = n; j % 4 != 0; ++j)
        dTh[j] = dS[j] = 0.0f;
    const __m128 d = _mm_set1_ps(twoDTheta), e = _mm_set1_ps(along ? ds : 1.0f);
    for (std::size_t j = 0; j < n; j += 4) {
        _mm_storeu_ps(dTh + j, _mm_div_ps(_mm_loadu_ps(dTh + j), d));
        _mm_storeu_ps(dS + j, _mm_div_ps(_mm_loadu_ps(dS + j), e));
    }
#else
    for (std::size_t j = 0; j < n; ++j) {
        dTh[j] /= twoDTheta;
        dS[j] /= along ? ds : 1.0f;
    }
#endif
    if (!along)
        for (std::size_t j = 0; j < n; ++j)
            dS[j] = 0.0f;
}

void barkReliefVertices(const float* ax, const float* ay, std::size_t count, const glm::vec3& p,
                        const glm::vec3& n, const glm::vec3& b, const glm::vec3& t,
                        const float* rho, const float* dTheta, const float* dS, float minLength,
                        float* out, std::size_t stride) {
#if defined(__SSE2__)
    const __m128 nX = _mm_set1_ps(n.x), nY = _mm_set1_ps(n.y), nZ = _mm_set1_ps(n.z);
    const __m128 bX = _mm_set1_ps(b.x), bY = _mm_set1_ps(b.y), bZ = _mm_set1_ps(b.z);
    const __m128 tX = _mm_set1_ps(t.x), tY = _mm_set1_ps(t.y), tZ = _mm_set1_ps(t.z);
    const __m128 pX = _mm_set1_ps(p.x), pY = _mm_set1_ps(p.y), pZ = _mm_set1_ps(p.z);
    const __m128 sign = _mm_set1_ps(-0.0f), least = _mm_set1_ps(minLength);
    for (std::size_t j = 0; j < count; j += 4) {
        const __m128 x = _mm_loadu_ps(ax + j), y = _mm_loadu_ps(ay + j);
        const __m128 minusY = _mm_xor_ps(y, sign); // -a.y (a sign flip, as glm's negation)
        // radial = a.x n + a.y b, around = -a.y n + a.x b
        const __m128 rx = _mm_add_ps(_mm_mul_ps(x, nX), _mm_mul_ps(y, bX));
        const __m128 ry = _mm_add_ps(_mm_mul_ps(x, nY), _mm_mul_ps(y, bY));
        const __m128 rz = _mm_add_ps(_mm_mul_ps(x, nZ), _mm_mul_ps(y, bZ));
        const __m128 ux = _mm_add_ps(_mm_mul_ps(minusY, nX), _mm_mul_ps(x, bX));
        const __m128 uy = _mm_add_ps(_mm_mul_ps(minusY, nY), _mm_mul_ps(x, bY));
        const __m128 uz = _mm_add_ps(_mm_mul_ps(minusY, nZ), _mm_mul_ps(x, bZ));
        const __m128 rr = _mm_loadu_ps(rho + j);
        const __m128 dT = _mm_loadu_ps(dTheta + j);
        const __m128 rrd = _mm_mul_ps(rr, _mm_loadu_ps(dS + j));
        // (rr radial - dTheta around) - (rr dS) t
        const __m128 vx =
            _mm_sub_ps(_mm_sub_ps(_mm_mul_ps(rr, rx), _mm_mul_ps(dT, ux)), _mm_mul_ps(rrd, tX));
        const __m128 vy =
            _mm_sub_ps(_mm_sub_ps(_mm_mul_ps(rr, ry), _mm_mul_ps(dT, uy)), _mm_mul_ps(rrd, tY));
        const __m128 vz =
            _mm_sub_ps(_mm_sub_ps(_mm_mul_ps(rr, rz), _mm_mul_ps(dT, uz)), _mm_mul_ps(rrd, tZ));
        // safeNormalize: glm::length's dot ((x x + y y) + z z) and its square root, v / l where
        // l is above minLength, else radial (also where l is NaN)
        const __m128 l = _mm_sqrt_ps(
            _mm_add_ps(_mm_add_ps(_mm_mul_ps(vx, vx), _mm_mul_ps(vy, vy)), _mm_mul_ps(vz, vz)));
        const __m128 longer = _mm_cmpgt_ps(l, least);
        auto pick = [&](__m128 q, __m128 fallback) {
            return _mm_or_ps(_mm_and_ps(longer, q), _mm_andnot_ps(longer, fallback));
        };
        _mm_storeu_ps(out + j, _mm_add_ps(pX, _mm_mul_ps(rr, rx)));
        _mm_storeu_ps(out + stride + j, _mm_add_ps(pY, _mm_mul_ps(rr, ry)));
        _mm_storeu_ps(out + 2 * stride + j, _mm_add_ps(pZ, _mm_mul_ps(rr, rz)));
        _mm_storeu_ps(out + 3 * stride + j, pick(_mm_div_ps(vx, l), rx));
        _mm_storeu_ps(out + 4 * stride + j, pick(_mm_div_ps(vy, l), ry));
        _mm_storeu_ps(out + 5 * stride + j, pick(_mm_div_ps(vz, l), rz));
    }
#else
    for (std::size_t j = 0; j < count; ++j) {
        const glm::vec3 radial = ax[j] * n + ay[j] * b;
        const glm::vec3 around = -ay[j] * n + ax[j] * b;
        const float rr = rho[j];
        const glm::vec3 position = p + rr * radial;
        const glm::vec3 normal =
            safeNormalize(rr * radial - dTheta[j] * around - rr * dS[j] * t, radial, minLength);
        for (int k = 0; k < 3; ++k) {
            out[static_cast<std::size_t>(k) * stride + j] = position[k];
            out[static_cast<std::size_t>(3 + k) * stride + j] = normal[k];
        }
    }
#endif
}

void barkReliefInterleave(const float* lanes, std::size_t stride, std::size_t count, const float* u,
                          float uTiles, float v, glm::vec3* pos, glm::vec3* nrm, glm::vec2* uv) {
    std::size_t j = 0;
#if defined(__SSE2__)
    // Four x, y, z lanes to x0 y0 z0 x1 | y1 z1 x2 y2 | z2 x3 y3 z3.
    auto triples = [](__m128 x, __m128 y, __m128 z, float* out) {
        const __m128 xy = _mm_unpacklo_ps(x, y);                          // x0 y0 x1 y1
        const __m128 zx = _mm_shuffle_ps(z, x, _MM_SHUFFLE(1, 1, 0, 0));  // z0 z0 x1 x1
        const __m128 yz = _mm_shuffle_ps(y, z, _MM_SHUFFLE(1, 1, 1, 1));  // y1 y1 z1 z1
        const __m128 xy2 = _mm_unpackhi_ps(x, y);                         // x2 y2 x3 y3
        const __m128 zx2 = _mm_shuffle_ps(z, x, _MM_SHUFFLE(3, 3, 2, 2)); // z2 z2 x3 x3
        const __m128 yz3 = _mm_shuffle_ps(y, z, _MM_SHUFFLE(3, 3, 3, 3)); // y3 y3 z3 z3
        _mm_storeu_ps(out, _mm_shuffle_ps(xy, zx, _MM_SHUFFLE(2, 0, 1, 0)));
        _mm_storeu_ps(out + 4, _mm_shuffle_ps(yz, xy2, _MM_SHUFFLE(1, 0, 2, 0)));
        _mm_storeu_ps(out + 8, _mm_shuffle_ps(zx2, yz3, _MM_SHUFFLE(2, 0, 2, 0)));
    };
    const __m128 tiles = _mm_set1_ps(uTiles), vv = _mm_set1_ps(v);
    for (; j + 4 <= count; j += 4) {
        triples(_mm_loadu_ps(lanes + j), _mm_loadu_ps(lanes + stride + j),
                _mm_loadu_ps(lanes + 2 * stride + j), &pos[j].x);
        triples(_mm_loadu_ps(lanes + 3 * stride + j), _mm_loadu_ps(lanes + 4 * stride + j),
                _mm_loadu_ps(lanes + 5 * stride + j), &nrm[j].x);
        const __m128 us = _mm_mul_ps(tiles, _mm_loadu_ps(u + j));
        _mm_storeu_ps(&uv[j].x, _mm_unpacklo_ps(us, vv));
        _mm_storeu_ps(&uv[j + 2].x, _mm_unpackhi_ps(us, vv));
    }
#endif
    for (; j < count; ++j) {
        pos[j] = {lanes[j], lanes[stride + j], lanes[2 * stride + j]};
        nrm[j] = {lanes[3 * stride + j], lanes[4 * stride + j], lanes[5 * stride + j]};
        uv[j] = {uTiles * u[j], v};
    }
}

} // namespace sylva::mesh
