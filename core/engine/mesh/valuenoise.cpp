#include "engine/mesh/valuenoise.h"

#include <cmath>

#if defined(__SSE2__) && defined(__x86_64__)
#include <emmintrin.h>
#endif

#include "engine/util/exactround.h"
#include "engine/util/random.h"

namespace sylva::mesh {

namespace {

// A value in [-1, 1) from a hash.
double signedUnit(std::uint64_t h) {
    return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0;
}

double smooth(double t) {
    return t * t * (3.0 - 2.0 * t);
}

// floorExact(x) for |x| < 2^52 (the caller's test), without floorExact's branch on x's sign
// (the cards' noise points are either side of the crown's axis, a mispredicted branch a sign
// change): the truncation less 1 where it is above x, and -0 kept as -0 (the only x below +0
// whose floor is a zero).
double floorNear(double x) {
#if defined(__SSE2__) && defined(__x86_64__)
    const __m128d X = _mm_set_sd(x);
    const __m128d t = _mm_cvtsi64_sd(_mm_setzero_pd(), _mm_cvttsd_si64(X));
    __m128d r = _mm_sub_sd(t, _mm_and_pd(_mm_cmpgt_sd(t, X), _mm_set_sd(1.0)));
    const __m128d sign = _mm_and_pd(X, _mm_set_sd(-0.0));
    r = _mm_or_pd(r, _mm_and_pd(_mm_cmpeq_sd(r, _mm_setzero_pd()), sign));
    return _mm_cvtsd_f64(r);
#else
    return floorExact(x);
#endif
}

} // namespace

void ValueNoise::cover(const glm::dvec3& lo, const glm::dvec3& hi, std::size_t maxPoints) {
    mGrid.clear();
    mMade.clear();
    mCellMade.clear();
    std::int64_t origin[3], size[3];
    std::size_t points = 1;
    for (int k = 0; k < 3; ++k) {
        // A box too far out for 64-bit cells (or not finite) keeps no grid.
        if (!(std::abs(lo[k]) < 0x1p52 && std::abs(hi[k]) < 0x1p52 && lo[k] <= hi[k])) return;
        origin[k] = static_cast<std::int64_t>(floorExact(lo[k])) - 1;
        size[k] = static_cast<std::int64_t>(floorExact(hi[k])) + 2 - origin[k] + 1;
        const auto n = static_cast<std::size_t>(size[k]);
        if (n > maxPoints || points * n > maxPoints) return;
        points *= n;
    }
    for (int k = 0; k < 3; ++k) {
        mOrigin[k] = origin[k];
        mSize[k] = size[k];
    }
    mGrid.resize(points);
    mMade.assign(points, 0);
    mCellMade.assign(points, 0);
}

glm::dvec3 ValueNoise::lattice(std::int64_t x, std::int64_t y, std::int64_t z) const {
    const std::uint64_t h = mixSeed(
        mixSeed(mixSeed(mSeed, static_cast<std::uint64_t>(x)), static_cast<std::uint64_t>(y)),
        static_cast<std::uint64_t>(z));
    return glm::dvec3(signedUnit(mixSeed(h, 1)), signedUnit(mixSeed(h, 2)),
                      signedUnit(mixSeed(h, 3)));
}

const glm::dvec3& ValueNoise::kept(std::int64_t x, std::int64_t y, std::int64_t z) {
    const std::int64_t gx = x - mOrigin[0], gy = y - mOrigin[1], gz = z - mOrigin[2];
    if (gx < 0 || gy < 0 || gz < 0 || gx >= mSize[0] || gy >= mSize[1] || gz >= mSize[2]) {
        mScratch = lattice(x, y, z);
        return mScratch;
    }
    const auto i = static_cast<std::size_t>((gz * mSize[1] + gy) * mSize[0] + gx);
    if (!mMade[i]) {
        mGrid[i] = lattice(x, y, z);
        mMade[i] = 1;
    }
    return mGrid[i];
}

glm::dvec3 ValueNoise::operator()(const glm::dvec3& p) {
    const bool near = std::abs(p.x) < 0x1p52 && std::abs(p.y) < 0x1p52 && std::abs(p.z) < 0x1p52;
    const glm::dvec3 f = near ? glm::dvec3(floorNear(p.x), floorNear(p.y), floorNear(p.z))
                              : glm::dvec3(floorExact(p.x), floorExact(p.y), floorExact(p.z));
    const glm::dvec3 t = p - f;
    const auto ix = static_cast<std::int64_t>(f.x), iy = static_cast<std::int64_t>(f.y),
               iz = static_cast<std::int64_t>(f.z);
    const double sx = smooth(t.x), sy = smooth(t.y), sz = smooth(t.z);
    const std::int64_t gx = ix - mOrigin[0], gy = iy - mOrigin[1], gz = iz - mOrigin[2];
    if (gx >= 0 && gy >= 0 && gz >= 0 && gx + 1 < mSize[0] && gy + 1 < mSize[1] &&
        gz + 1 < mSize[2]) {
        // A cell inside the grid reads its eight points there, made the first time a cell
        // needs them (one test a cell: the cards change cell about every other card, and a
        // branch on the cell being the last one's was mispredicted about as often).
        const auto sx1 = static_cast<std::size_t>(mSize[0]);
        const std::size_t sxy = sx1 * static_cast<std::size_t>(mSize[1]);
        const auto base = static_cast<std::size_t>((gz * mSize[1] + gy) * mSize[0] + gx);
        if (!mCellMade[base]) makeCell(ix, iy, iz, base);
        const glm::dvec3* row[2][2] = {{&mGrid[base], &mGrid[base + sx1]},
                                       {&mGrid[base + sxy], &mGrid[base + sxy + sx1]}};
        return interpolate(row, sx, sy, sz);
    }
    if (!mValid || ix != mCell[0] || iy != mCell[1] || iz != mCell[2]) {
        for (int dz = 0; dz < 2; ++dz)
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx)
                    mCorner[dz][dy][dx] = kept(ix + dx, iy + dy, iz + dz);
        mCell[0] = ix;
        mCell[1] = iy;
        mCell[2] = iz;
        mValid = true;
    }
    const glm::dvec3* row[2][2] = {{mCorner[0][0], mCorner[0][1]}, {mCorner[1][0], mCorner[1][1]}};
    return interpolate(row, sx, sy, sz);
}

void ValueNoise::makeCell(std::int64_t ix, std::int64_t iy, std::int64_t iz, std::size_t base) {
    const auto sx = static_cast<std::size_t>(mSize[0]);
    const std::size_t sxy = sx * static_cast<std::size_t>(mSize[1]);
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const std::size_t i = base + static_cast<std::size_t>(dz) * sxy +
                                      static_cast<std::size_t>(dy) * sx +
                                      static_cast<std::size_t>(dx);
                if (!mMade[i]) {
                    mGrid[i] = lattice(ix + dx, iy + dy, iz + dz);
                    mMade[i] = 1;
                }
            }
    mCellMade[base] = 1;
}

glm::dvec3 ValueNoise::interpolate(const glm::dvec3* const row[2][2], double sx, double sy,
                                   double sz) {
    glm::dvec3 c[2][2];
    for (int dz = 0; dz < 2; ++dz)
        for (int dy = 0; dy < 2; ++dy) {
            const glm::dvec3& a = row[dz][dy][0];
            const glm::dvec3& b = row[dz][dy][1];
            c[dz][dy] = a + (b - a) * sx;
        }
    const glm::dvec3 y0 = c[0][0] + (c[0][1] - c[0][0]) * sy;
    const glm::dvec3 y1 = c[1][0] + (c[1][1] - c[1][0]) * sy;
    return y0 + (y1 - y0) * sz;
}

} // namespace sylva::mesh
