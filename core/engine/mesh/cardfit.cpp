#include "engine/mesh/cardfit.h"
#include "engine/mesh/cardaxes4.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#if defined(__SSE2__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

namespace sylva::mesh {

void prepareCardFitPlain(const std::vector<skel::Leaf>& leaves,
                         std::span<const std::uint32_t> group, float aspect, float scale,
                         CardFitInput& in) {
    RawVector<glm::vec3>& pts = in.corners;
    pts.resize(4 * group.size());
    glm::dvec3 heading(0.0), up(0.0), left(0.0);
    glm::vec3* out = pts.data();
    for (std::uint32_t i : group) {
        // Each axis made once a leaf (the corners and the sums both need them).
        const glm::vec3 h = skel::headingOf(leaves[i].orientation);
        const glm::vec3 l = skel::leftOf(leaves[i].orientation);
        leafCorners(leaves[i], h, l, aspect, scale, out);
        out += 4;
        heading += glm::dvec3(h);
        up += glm::dvec3(skel::upOf(leaves[i].orientation));
        left += glm::dvec3(l);
    }
    glm::dvec3 m(0.0);
    for (const glm::vec3& q : pts)
        m += glm::dvec3(q);
    m /= static_cast<double>(pts.size());
    glm::dmat3 cov(0.0);
    for (const glm::vec3& q : pts) {
        const glm::dvec3 d = glm::dvec3(q) - m;
        cov += glm::outerProduct(d, d);
    }
    in.heading = heading;
    in.up = up;
    in.left = left;
    in.m = m;
    in.cov = cov;
}

double leafMiddlesPlain(const std::vector<skel::Leaf>& leaves, double sizeScale,
                        std::vector<glm::dvec3>& mids) {
    mids.resize(leaves.size());
    double sizes = 0.0;
    for (const skel::Leaf& leaf : leaves)
        sizes += leaf.size * sizeScale;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
        const skel::Leaf& leaf = leaves[i];
        mids[i] = glm::dvec3(leaf.position) + 0.5 * glm::dvec3(skel::headingOf(leaf.orientation)) *
                                                  static_cast<double>(leaf.size);
    }
    return sizes;
}

void cardExtentPlain(const CardFitInput& in, const glm::dvec3& along, const glm::dvec3& across,
                     double& a0, double& a1, double& c0, double& c1) {
    a0 = 1e300, a1 = -1e300, c0 = 1e300, c1 = -1e300;
    for (const glm::vec3& p : in.corners) {
        const glm::dvec3 q(p);
        const double a = glm::dot(q - in.m, along), c = glm::dot(q - in.m, across);
        a0 = std::min(a0, a);
        a1 = std::max(a1, a);
        c0 = std::min(c0, c);
        c1 = std::max(c1, c);
    }
}

#if defined(__SSE2__)

namespace {

// A float corner's x and y as two doubles, its z as the low double.
__m128d xyOf(const glm::vec3& p) {
    // __m128i may alias any type: the two floats as one 64-bit load.
    return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(&p.x))));
}
__m128d zOf(const glm::vec3& p) {
    return _mm_cvtss_sd(_mm_setzero_pd(), _mm_load_ss(&p.z));
}

// Four lanes' (x, y, z) as four (x, y, z, 0) vectors, one a lane.
void toPoints(const Vec4x3& v, __m128 out[4]) {
    out[0] = v.x;
    out[1] = v.y;
    out[2] = v.z;
    out[3] = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(out[0], out[1], out[2], out[3]);
}

// A point (x, y, z, 0)'s x and y as doubles, and its z (and 0).
__m128d xyOf(__m128 p) {
    return _mm_cvtps_pd(p);
}
__m128d zOf(__m128 p) {
    return _mm_cvtps_pd(_mm_movehl_ps(p, p));
}

} // namespace

void prepareCardFit(const std::vector<skel::Leaf>& leaves, std::span<const std::uint32_t> group,
                    float aspect, float scale, CardFitInput& in) {
    static_assert(offsetof(glm::quat, w) == 3 * sizeof(float), "a quaternion is x, y, z, w");
    RawVector<glm::vec3>& pts = in.corners;
    const std::size_t n = group.size();
    pts.resize(4 * n);
    const float halfAspect = 0.5f * aspect; // leafCorners' 0.5f * aspect * len
    const __m128 scale4 = _mm_set1_ps(scale);
    __m128d headingXY = _mm_setzero_pd(), headingZ = _mm_setzero_pd();
    __m128d upXY = _mm_setzero_pd(), upZ = _mm_setzero_pd();
    __m128d leftXY = _mm_setzero_pd(), leftZ = _mm_setzero_pd();
    __m128d sumXY = _mm_setzero_pd(), sumZ = _mm_setzero_pd();
    // Four leaves at a time (the last ones repeated to fill a four): their axes and corners
    // as leafCorners and skel::headingOf, leftOf, upOf make them, lane by lane.
    for (std::size_t b = 0; b < n; b += 4) {
        const std::size_t r = std::min<std::size_t>(4, n - b);
        const skel::Leaf* leaf[4];
        for (std::size_t j = 0; j < 4; ++j)
            leaf[j] = &leaves[group[b + std::min(j, r - 1)]];
        const LeafCards4 cards = leafCards4(leaf, halfAspect, scale4);
        const Vec4x3 &h = cards.axes.h, &l = cards.axes.l, &u = cards.axes.u;
        __m128 corner[4][4], heading[4], left[4], up[4];
        for (int c = 0; c < 4; ++c)
            toPoints(cards.corner[c], corner[c]);
        toPoints(h, heading);
        toPoints(l, left);
        toPoints(u, up);
        for (std::size_t j = 0; j < r; ++j) {
            glm::vec3* out = &pts[4 * (b + j)];
            for (int c = 0; c < 4; ++c) {
                const __m128 p = corner[c][j];
                _mm_storel_pi(reinterpret_cast<__m64*>(&out[c].x), p);
                _mm_store_ss(&out[c].z, _mm_movehl_ps(p, p));
                sumXY = _mm_add_pd(sumXY, xyOf(p));
                sumZ = _mm_add_pd(sumZ, zOf(p));
            }
            headingXY = _mm_add_pd(headingXY, xyOf(heading[j]));
            headingZ = _mm_add_pd(headingZ, zOf(heading[j]));
            upXY = _mm_add_pd(upXY, xyOf(up[j]));
            upZ = _mm_add_pd(upZ, zOf(up[j]));
            leftXY = _mm_add_pd(leftXY, xyOf(left[j]));
            leftZ = _mm_add_pd(leftZ, zOf(left[j]));
        }
    }
    const double count = static_cast<double>(pts.size());
    const __m128d mXY = _mm_div_pd(sumXY, _mm_set1_pd(count));
    const __m128d mZ = _mm_div_sd(sumZ, _mm_set_sd(count));
    // cov[i][j] += d[j] * d[i], the six distinct sums of the nine (a product is the same double
    // either way round, and each is summed in corner order from +0 in both of its places): xx
    // and yy as dXY * dXY, xz and yz as dXY * dz, xy and zz as (dx, dz) * (dy, dz). Three
    // products and three sums a corner where the four columns' and rows' took five and five
    // (perf annotate of the English oak: the covariance pass a third of prepareCardFit).
    __m128d sq = _mm_setzero_pd(), xzyz = _mm_setzero_pd(), xyzz = _mm_setzero_pd();
    for (const glm::vec3& q : pts) {
        const __m128d dXY = _mm_sub_pd(xyOf(q), mXY);
        const __m128d dZ = _mm_sub_sd(zOf(q), mZ);
        const __m128d dz = _mm_unpacklo_pd(dZ, dZ);
        sq = _mm_add_pd(sq, _mm_mul_pd(dXY, dXY));
        xzyz = _mm_add_pd(xzyz, _mm_mul_pd(dXY, dz));
        xyzz = _mm_add_pd(xyzz, _mm_mul_pd(_mm_unpacklo_pd(dXY, dz), _mm_unpackhi_pd(dXY, dz)));
    }
    alignas(16) double xxYy[2], xzYz[2], xyZz[2], v[6];
    _mm_store_pd(xxYy, sq);
    _mm_store_pd(xzYz, xzyz);
    _mm_store_pd(xyZz, xyzz);
    in.cov =
        glm::dmat3(xxYy[0], xyZz[0], xzYz[0], xyZz[0], xxYy[1], xzYz[1], xzYz[0], xzYz[1], xyZz[1]);
    _mm_store_pd(v, mXY);
    in.m = glm::dvec3(v[0], v[1], _mm_cvtsd_f64(mZ));
    _mm_store_pd(v, headingXY);
    in.heading = glm::dvec3(v[0], v[1], _mm_cvtsd_f64(headingZ));
    _mm_store_pd(v, upXY);
    in.up = glm::dvec3(v[0], v[1], _mm_cvtsd_f64(upZ));
    _mm_store_pd(v, leftXY);
    in.left = glm::dvec3(v[0], v[1], _mm_cvtsd_f64(leftZ));
}

double leafMiddles(const std::vector<skel::Leaf>& leaves, double sizeScale,
                   RawVector<glm::dvec3>& mids) {
    const std::size_t n = leaves.size();
    mids.resize(n);
    double sizes = 0.0;
    const __m128d half = _mm_set1_pd(0.5);
    for (std::size_t b = 0; b < n; b += 4) {
        const std::size_t r = std::min<std::size_t>(4, n - b);
        const skel::Leaf* leaf[4];
        for (std::size_t j = 0; j < 4; ++j)
            leaf[j] = &leaves[b + std::min(j, r - 1)];
        __m128 qx = _mm_loadu_ps(&leaf[0]->orientation.x);
        __m128 qy = _mm_loadu_ps(&leaf[1]->orientation.x);
        __m128 qz = _mm_loadu_ps(&leaf[2]->orientation.x);
        __m128 qw = _mm_loadu_ps(&leaf[3]->orientation.x);
        _MM_TRANSPOSE4_PS(qx, qy, qz, qw);
        __m128 heading[4];
        toPoints(headingAxis(qx, qy, qz, qw), heading);
        for (std::size_t j = 0; j < r; ++j) {
            // position + (0.5 * heading) * size, in double, as leafMiddlesPlain.
            const glm::vec3& p = leaf[j]->position;
            const __m128d size = _mm_set1_pd(static_cast<double>(leaf[j]->size));
            const __m128d xy =
                _mm_add_pd(xyOf(p), _mm_mul_pd(_mm_mul_pd(half, xyOf(heading[j])), size));
            const __m128d z =
                _mm_add_sd(zOf(p), _mm_mul_sd(_mm_mul_sd(half, zOf(heading[j])), size));
            alignas(16) double v[2];
            _mm_store_pd(v, xy);
            mids[b + j] = glm::dvec3(v[0], v[1], _mm_cvtsd_f64(z));
            sizes += leaf[j]->size * sizeScale;
        }
    }
    return sizes;
}

void cardExtent(const CardFitInput& in, const glm::dvec3& along, const glm::dvec3& across,
                double& a0, double& a1, double& c0, double& c1) {
    // Lane 0 the along products, lane 1 the across ones: dot = (x + y) + z, as glm::dot.
    const __m128d mXY = _mm_set_pd(in.m.y, in.m.x), mZ = _mm_set_sd(in.m.z);
    const __m128d alongXY = _mm_set_pd(along.y, along.x);
    const __m128d acrossXY = _mm_set_pd(across.y, across.x);
    const __m128d axesZ = _mm_set_pd(across.z, along.z);
    __m128d lo = _mm_set1_pd(1e300), hi = _mm_set1_pd(-1e300);
    for (const glm::vec3& q : in.corners) {
        const __m128d dXY = _mm_sub_pd(xyOf(q), mXY);
        const __m128d dZ = _mm_sub_sd(zOf(q), mZ);
        const __m128d ta = _mm_mul_pd(dXY, alongXY), tc = _mm_mul_pd(dXY, acrossXY);
        const __m128d xs = _mm_unpacklo_pd(ta, tc), ys = _mm_unpackhi_pd(ta, tc);
        const __m128d zs = _mm_mul_pd(_mm_unpacklo_pd(dZ, dZ), axesZ);
        const __m128d dot = _mm_add_pd(_mm_add_pd(xs, ys), zs);
        // std::min(lo, dot) is dot < lo ? dot : lo, as minpd(dot, lo); max alike.
        lo = _mm_min_pd(dot, lo);
        hi = _mm_max_pd(dot, hi);
    }
    alignas(16) double l[2], h[2];
    _mm_store_pd(l, lo);
    _mm_store_pd(h, hi);
    a0 = l[0];
    c0 = l[1];
    a1 = h[0];
    c1 = h[1];
}

#else

double leafMiddles(const std::vector<skel::Leaf>& leaves, double sizeScale,
                   RawVector<glm::dvec3>& mids) {
    std::vector<glm::dvec3> plain;
    const double sizes = leafMiddlesPlain(leaves, sizeScale, plain);
    mids.assign(plain.begin(), plain.end());
    return sizes;
}

void prepareCardFit(const std::vector<skel::Leaf>& leaves, std::span<const std::uint32_t> group,
                    float aspect, float scale, CardFitInput& in) {
    prepareCardFitPlain(leaves, group, aspect, scale, in);
}

void cardExtent(const CardFitInput& in, const glm::dvec3& along, const glm::dvec3& across,
                double& a0, double& a1, double& c0, double& c1) {
    cardExtentPlain(in, along, across, a0, a1, c0, c1);
}

#endif

glm::dvec3 anyPerpendicular(const glm::dvec3& v) {
    const glm::dvec3 a = std::abs(v.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    return glm::normalize(glm::cross(v, a));
}

namespace {
// glm::normalize(v) given glm::length(v): v * (1 / sqrt(dot(v, v))), glm's own arithmetic, the
// square root taken once where a length test comes first (the same doubles as glm::normalize).
glm::dvec3 scaledBy(const glm::dvec3& v, double length) {
    return v * (1.0 / length);
}
} // namespace

void cardAxes(const CardFitInput* in, const std::span<const std::uint32_t>* group,
              const glm::dvec3* e1, glm::dvec3* e2, CardAxes* out, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
        e2[k] = e2[k] - glm::dot(e2[k], e1[k]) * e1[k];
        const double length = glm::length(e2[k]);
        e2[k] = length < 1e-9 ? glm::normalize(anyPerpendicular(e1[k])) : scaledBy(e2[k], length);
    }
    for (std::size_t k = 0; k < n; ++k) {
        glm::dvec3 c = glm::normalize(glm::cross(e1[k], e2[k]));
        if (glm::dot(c, in[k].up) < 0.0) c = -c;
        out[k].n = c;
    }
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dvec3& heading = in[k].heading;
        const glm::dvec3& c = out[k].n;
        const glm::dvec3 along = heading - glm::dot(heading, c) * c;
        const double length = glm::length(along);
        out[k].along = length > 0.2 * static_cast<double>(group[k].size())
                           ? scaledBy(along, length)
                           : (glm::dot(e1[k], heading) < 0.0 ? -e1[k] : e1[k]);
    }
    for (std::size_t k = 0; k < n; ++k)
        out[k].across = glm::normalize(glm::cross(out[k].n, out[k].along));
}

glm::dmat3 secondMatrix(const CardFitInput& in, const glm::dvec3& e1, glm::dvec3& seed2) {
    const double l1 = glm::dot(e1, in.cov * e1);
    const glm::dmat3 rest = in.cov - l1 * glm::outerProduct(e1, e1);
    const glm::dvec3 s2 = in.left - glm::dot(in.left, e1) * e1;
    const double length = glm::length(s2);
    seed2 = length < 1e-9 ? glm::normalize(anyPerpendicular(e1)) : scaledBy(s2, length);
    return rest;
}

CardRect cardRect(const CardFitInput& in, const CardAxes& axes, const double (&extent)[4]) {
    CardRect r{};
    const double shrink = kCardShrink;
    const double a0 = extent[0], a1 = extent[1], c0 = extent[2], c1 = extent[3];
    const double am = 0.5 * (a0 + a1);
    r.cm = 0.5 * (c0 + c1);
    r.a0 = am + shrink * (a0 - am);
    r.a1 = am + shrink * (a1 - am);
    r.c0 = r.cm + shrink * (c0 - r.cm);
    r.c1 = r.cm + shrink * (c1 - r.cm);
    r.lo = in.m + r.a0 * axes.along;
    r.hi = in.m + r.a1 * axes.along;
    return r;
}

void cardCorners(const CardRect& r, const CardAxes& axes, glm::vec3 corners[4], glm::vec3& normal) {
    corners[0] = glm::vec3(r.lo + r.c1 * axes.across);
    corners[1] = glm::vec3(r.lo + r.c0 * axes.across);
    corners[2] = glm::vec3(r.hi + r.c0 * axes.across);
    corners[3] = glm::vec3(r.hi + r.c1 * axes.across);
    normal = glm::vec3(axes.n);
}

} // namespace sylva::mesh
