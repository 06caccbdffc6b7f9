#include "engine/mesh/leaftint.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "engine/mesh/valuenoise.h"
#include "engine/util/exactround.h"
#include "engine/util/random.h"
#include "engine/util/x86intrinsics.h"

namespace sylva::mesh {

namespace {

// The summer green of make_textures.py's leaves (their mean, sRGB), and spring's lighter one.
constexpr glm::vec3 kSummerGreen{0.26f, 0.40f, 0.12f};
constexpr glm::vec3 kSpringGreen{0.42f, 0.58f, 0.18f};

glm::vec3 rgbToHsv(const glm::vec3& c) {
    const float mx = std::max({c.x, c.y, c.z}), mn = std::min({c.x, c.y, c.z});
    const float d = mx - mn;
    float h = 0.0f;
    if (d > 1e-6f) {
        if (mx == c.x)
            h = (c.y - c.z) / d;
        else if (mx == c.y)
            h = 2.0f + (c.z - c.x) / d;
        else
            h = 4.0f + (c.x - c.y) / d;
        h /= 6.0f;
        if (h < 0.0f) h += 1.0f;
    }
    return {h, mx > 0.0f ? d / mx : 0.0f, mx};
}

glm::vec3 hsvToRgb(const glm::vec3& hsv) {
    const float h = (hsv.x - floorExact(hsv.x)) * 6.0f, s = hsv.y, v = hsv.z;
    const int i = static_cast<int>(floorExact(h)) % 6;
    const float f = h - floorExact(h);
    const float p = v * (1.0f - s), q = v * (1.0f - s * f), t = v * (1.0f - s * (1.0f - f));
    switch (i) {
    case 0:
        return {v, t, p};
    case 1:
        return {q, v, p};
    case 2:
        return {p, v, t};
    case 3:
        return {p, q, v};
    case 4:
        return {t, p, v};
    default:
        return {v, p, q};
    }
}

// A value in [-1, 1) from a hash.
double signedUnit(std::uint64_t h) {
    return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0;
}

std::uint8_t toByte(double v) {
    return static_cast<std::uint8_t>(llroundExact(std::clamp(v, 0.0, 1.0) * 255.0));
}

// A card's own share of its variation; the rest follows the crown's patches. Patches are
// what makes a crown read as lit branches and shaded ones; cards of their own alone read as
// confetti (measured by eye on the gallery's oak, beech and maple: 0.4).
constexpr double kOwnShare = 0.4;

} // namespace

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float c) {
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

const LeafColorVariation& leafVariationFor(const LeafTintSettings& settings, Season season,
                                           bool deciduous) {
    return deciduous && season == Season::Autumn ? settings.autumn : settings.summer;
}

glm::vec3 leafReferenceColor(const LeafTintSettings& settings, Season season, bool deciduous) {
    if (!deciduous) return kSummerGreen;
    if (season == Season::Autumn) return settings.autumnColor;
    return season == Season::Spring ? kSpringGreen : kSummerGreen;
}

namespace {

// What a multiplier needs of its reference colour, worked out once for all cards.
struct Reference {
    glm::vec3 hsv;
    double lin[3];
    bool strong[3]; ///< carries a quarter of the strongest channel or more (see multiplier())
};

Reference reference(const glm::vec3& referenceSrgb) {
    const glm::vec3 ref = glm::clamp(referenceSrgb, glm::vec3(0.02f), glm::vec3(1.0f));
    Reference r;
    r.hsv = rgbToHsv(ref);
    double strongest = 0.0;
    for (int k = 0; k < 3; ++k) {
        r.lin[k] = srgbToLinear(ref[k]);
        strongest = std::max(strongest, r.lin[k]);
    }
    for (int k = 0; k < 3; ++k)
        r.strong[k] = r.lin[k] >= 0.25 * strongest;
    return r;
}

// The most multipliers made together.
constexpr std::size_t kTintLanes = 8;

// The multipliers of \p n (at most kTintLanes) cards' variations, each stage for every card
// before the next: a card's multiplier is one long chain (divisions, the HSV turn, three
// powf, three more divisions) and the cards' chains side by side overlap (perf record of the
// English oak: multiplier and powf half of tintLeafCards' time). Each card's arithmetic its
// own, in its order: the same bytes as one card at a time.
//
// Where SSE2 is there, the block's divisions, conversions, clamps and roundings are made two
// cards (doubles) or four (floats) to an instruction: ten divisions a card (the hue's, three in
// srgbToLinear, six ratios), which waited on the divider one by one. Each lane is the scalar
// operation on the same operands (IEEE division, products, sums and conversions round alike
// packed or not; the clamps and the maximum are written as the same comparisons, NaN kept where
// std::clamp and std::max keep it); without SSE2, card by card.
#if defined(__SSE2__)

// std::clamp(v, lo, hi) lane by lane: (v < lo) ? lo : (hi < v) ? hi : v (a NaN stays).
__m128d clampPd(__m128d v, __m128d lo, __m128d hi) {
    const __m128d below = _mm_cmplt_pd(v, lo), above = _mm_cmplt_pd(hi, v);
    const __m128d r = _mm_or_pd(_mm_and_pd(above, hi), _mm_andnot_pd(above, v));
    return _mm_or_pd(_mm_and_pd(below, lo), _mm_andnot_pd(below, r));
}

__m128 clampPs(__m128 v, __m128 lo, __m128 hi) {
    const __m128 below = _mm_cmplt_ps(v, lo), above = _mm_cmplt_ps(hi, v);
    const __m128 r = _mm_or_ps(_mm_and_ps(above, hi), _mm_andnot_ps(above, v));
    return _mm_or_ps(_mm_and_ps(below, lo), _mm_andnot_ps(below, r));
}

// Four floats from two pairs of doubles, each static_cast<float>.
__m128 toFloats(__m128d a, __m128d b) {
    return _mm_movelh_ps(_mm_cvtpd_ps(a), _mm_cvtpd_ps(b));
}

#if defined(SYLVA_X86_INTRINSICS)
// x^2.4f (the float 2.4f) for doubles x in [2^-4, 1], eight lanes: ln x from x = 2^e m (m in
// [sqrt(1/2), sqrt(2)]) as 2 atanh((m - 1) / (m + 1)) to its s^13 term, then exp of 2.4f ln x
// as 2^k exp(f), |f| <= ln(2) / 2, to its f^10 term: within ~1e-12 of x^2.4f (the series'
// remainders ~5e-13, the roundings ~30 ulps of a double), whatever the roundings or fused
// products; powfBoundsAvx512 takes it to 2^-21 either side.
__attribute__((target("avx512f"))) inline __m512d pow24Avx512(__m512d x) {
    __m512d e = _mm512_getexp_pd(x);
    __m512d m = _mm512_getmant_pd(x, _MM_MANT_NORM_1_2, _MM_MANT_SIGN_src);
    const __mmask8 big = _mm512_cmp_pd_mask(m, _mm512_set1_pd(1.4142135623730951), _CMP_GT_OQ);
    m = _mm512_mask_mul_pd(m, big, m, _mm512_set1_pd(0.5));
    e = _mm512_mask_add_pd(e, big, e, _mm512_set1_pd(1.0));
    const __m512d one = _mm512_set1_pd(1.0);
    const __m512d s = _mm512_div_pd(_mm512_sub_pd(m, one), _mm512_add_pd(m, one));
    const __m512d s2 = _mm512_mul_pd(s, s);
    __m512d p = _mm512_set1_pd(1.0 / 13.0);
    for (const double c : {1.0 / 11.0, 1.0 / 9.0, 1.0 / 7.0, 1.0 / 5.0, 1.0 / 3.0, 1.0})
        p = _mm512_fmadd_pd(p, s2, _mm512_set1_pd(c));
    const __m512d ln2 = _mm512_set1_pd(0.6931471805599453);
    const __m512d lnx =
        _mm512_fmadd_pd(e, ln2, _mm512_mul_pd(_mm512_add_pd(s, s), p)); // e ln 2 + ln m
    const __m512d t = _mm512_mul_pd(_mm512_set1_pd(static_cast<double>(2.4f)), lnx);
    const __m512d k = _mm512_roundscale_pd(_mm512_mul_pd(t, _mm512_set1_pd(1.4426950408889634)),
                                           _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    const __m512d f = _mm512_fnmadd_pd(k, ln2, t);
    __m512d q = _mm512_set1_pd(1.0 / 3628800.0);
    for (const double c : {1.0 / 362880.0, 1.0 / 40320.0, 1.0 / 5040.0, 1.0 / 720.0, 1.0 / 120.0,
                           1.0 / 24.0, 1.0 / 6.0, 0.5, 1.0, 1.0})
        q = _mm512_fmadd_pd(q, f, _mm512_set1_pd(c));
    return _mm512_scalef_pd(q, k);
}

/// Bounds on glibc's powf(a, 2.4f) for the floats \p a in [2^-4, 1]: pow24Avx512 less and plus
/// 2^-21 of it. powf is within 0.82 ulp of the power (glibc's own bound: a float's ulp is at most
/// 2^-23 of it), pow24Avx512 within ~1e-12: the margin is four times what is needed
/// (LeafTint.PowfWithinItsBounds holds every float a of [2^-4, 1]).
__attribute__((target("avx512f"))) inline void powfBoundsAvx512(__m512d a, __m512d& lo,
                                                                __m512d& hi) {
    const __m512d y = pow24Avx512(a);
    lo = _mm512_mul_pd(y, _mm512_set1_pd(1.0 - 0x1p-21));
    hi = _mm512_mul_pd(y, _mm512_set1_pd(1.0 + 0x1p-21));
}

// toByte of each lane of q (in [0.25, 1]) as a double, as the packed multipliers round it: the
// truncation of q * 255 plus one where its fraction is a half or more (the product rounded on its
// own; the truncation of a value under 2^31 is its int's).
__attribute__((target("avx512f"))) inline __m512d bytesAvx512(__m512d q) {
    const __m512d x = _mm512_mul_round_pd(q, _mm512_set1_pd(255.0), _MM_FROUND_CUR_DIRECTION);
    const __m512d i = _mm512_roundscale_pd(x, _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
    const __m512d fraction = _mm512_sub_round_pd(x, i, _MM_FROUND_CUR_DIRECTION);
    const __mmask8 up = _mm512_cmp_pd_mask(fraction, _mm512_set1_pd(0.5), _CMP_GE_OQ);
    return _mm512_mask_add_pd(i, up, i, _mm512_set1_pd(1.0));
}

// The multipliers' bytes of a block's turned colours \p rgb (rgb[k][c], lanes past n zero)
// without powf: each channel's srgbToLinear where it takes powf is bounded (powfBoundsAvx512), and
// every step after it (the ratio to the reference, the scale, the clamped quotient, the rounded
// byte) is a correctly rounded operation that never decreases as its operand grows (the quotient
// never increases as the scale grows; the values are all >= 0): the byte made from the lower
// bounds (the scale from the upper ones) is at most the multiplier's, the byte from the upper
// bounds at least. Where the two are the same for every channel of every card, they are the
// multiplier's bytes, written to out (the bounds are ~10^-3 of a byte apart at most: a block in
// about a hundred has a rounding boundary between them). Returns false, writing nothing, where
// they differ, or where a channel is outside [0, 1] or NaN: multipliers takes powf then. glibc's
// powf was 2 % of the English oak's time, three calls a card.
__attribute__((target("avx512f"))) bool boundedMultipliersAvx512(const Reference& r,
                                                                 const __m256 (&rgb)[3],
                                                                 glm::u8vec4* out, std::size_t n) {
    static_assert(kTintLanes == 8, "a block is a register of doubles");
    const __m512d zero = _mm512_setzero_pd(), one = _mm512_set1_pd(1.0);
    __m512d mlo[3], mhi[3];
    for (int k = 0; k < 3; ++k) {
        const __m256 x = rgb[k];
        const __m512d xd = _mm512_cvtps_pd(x);
        // NaN fails both comparisons.
        if (_mm512_cmp_pd_mask(xd, zero, _CMP_GE_OQ) != 0xff ||
            _mm512_cmp_pd_mask(xd, one, _CMP_LE_OQ) != 0xff)
            return false;
        // srgbToLinear's two branches in floats (a quotient each: no product to fuse).
        const __m512d low = _mm512_cvtps_pd(_mm256_div_ps(x, _mm256_set1_ps(12.92f)));
        const __m512d a = _mm512_cvtps_pd(
            _mm256_div_ps(_mm256_add_ps(x, _mm256_set1_ps(0.055f)), _mm256_set1_ps(1.055f)));
        const __mmask8 linear =
            _mm512_cmp_pd_mask(xd, _mm512_set1_pd(static_cast<double>(0.04045f)), _CMP_LE_OQ);
        __m512d lo, hi;
        powfBoundsAvx512(a, lo, hi);
        lo = _mm512_mask_blend_pd(linear, lo, low);
        hi = _mm512_mask_blend_pd(linear, hi, low);
        const __m512d ref = _mm512_set1_pd(r.lin[k]);
        mlo[k] = _mm512_div_pd(lo, ref);
        mhi[k] = _mm512_div_pd(hi, ref);
    }
    __m512d scaleLo = one, scaleHi = one;
    for (int k = 0; k < 3; ++k)
        if (r.strong[k]) {
            scaleLo = _mm512_max_pd(mlo[k], scaleLo);
            scaleHi = _mm512_max_pd(mhi[k], scaleHi);
        }
    const __m512d quarter = _mm512_set1_pd(0.25);
    alignas(32) std::int32_t bytes[3][kTintLanes];
    for (int k = 0; k < 3; ++k) {
        const __m512d qlo =
            _mm512_min_pd(_mm512_max_pd(_mm512_div_pd(mlo[k], scaleHi), quarter), one);
        const __m512d qhi =
            _mm512_min_pd(_mm512_max_pd(_mm512_div_pd(mhi[k], scaleLo), quarter), one);
        const __m512d b = bytesAvx512(qlo);
        if (_mm512_cmp_pd_mask(b, bytesAvx512(qhi), _CMP_NEQ_UQ) != 0) return false;
        _mm256_store_si256(reinterpret_cast<__m256i*>(bytes[k]), _mm512_cvttpd_epi32(b));
    }
    for (std::size_t c = 0; c < n; ++c)
        out[c] = glm::u8vec4(static_cast<std::uint8_t>(bytes[0][c]),
                             static_cast<std::uint8_t>(bytes[1][c]),
                             static_cast<std::uint8_t>(bytes[2][c]), 255);
    return true;
}

// std::clamp(v, lo, hi) lane by lane: (v < lo) ? lo : (hi < v) ? hi : v (a NaN stays).
__attribute__((target("avx512f"))) inline __m512 clamp512(__m512 v, __m512 lo, __m512 hi) {
    const __m512 r = _mm512_mask_mov_ps(v, _mm512_cmp_ps_mask(hi, v, _CMP_LT_OQ), hi);
    return _mm512_mask_mov_ps(r, _mm512_cmp_ps_mask(v, lo, _CMP_LT_OQ), lo);
}
__attribute__((target("avx512f"))) inline __m512d clamp512(__m512d v, __m512d lo, __m512d hi) {
    const __m512d r = _mm512_mask_mov_pd(v, _mm512_cmp_pd_mask(hi, v, _CMP_LT_OQ), hi);
    return _mm512_mask_mov_pd(r, _mm512_cmp_pd_mask(v, lo, _CMP_LT_OQ), lo);
}

// Eight doubles as floats in the low half of a register, the high half zeros.
__attribute__((target("avx512f"))) inline __m512 floats512(__m512d d) {
    return _mm512_zextps256_ps512(_mm512_cvtpd_ps(d));
}
// The lanes of i equal to k.
__attribute__((target("avx512f"))) inline __mmask16 sector512(__m512i i, int k) {
    return _mm512_cmpeq_epi32_mask(i, _mm512_set1_epi32(k));
}

// The whole block on AVX-512: the turns (as the SSE2 block makes them), hsvToRgb eight cards to
// an instruction (floats in the low half of a register, each lane hsvToRgb's operations in its
// order, products and sums by simd::mul / sub so that none is fused; the sector's values picked
// by masks), then boundedMultipliersAvx512 on the turned colours in registers (card by card,
// hsvToRgb's switch and its results stored and read back as vectors waited on each other).
// False, nothing written, where a turned hue is not finite or boundedMultipliersAvx512 is false.
__attribute__((target("avx512f"))) bool multipliersAvx512(const Reference& r, const double* hue,
                                                          const double* saturation,
                                                          const double* value, glm::u8vec4* out,
                                                          std::size_t n) {
    // A block of fewer cards (the last) copied with zeros past n: no read past the caller's cards.
    double padded[3][kTintLanes];
    if (n < kTintLanes) {
        for (auto& lanes : padded)
            std::fill_n(lanes, kTintLanes, 0.0);
        std::copy(hue, hue + n, padded[0]);
        std::copy(saturation, saturation + n, padded[1]);
        std::copy(value, value + n, padded[2]);
        hue = padded[0];
        saturation = padded[1];
        value = padded[2];
    }
    const __m512d hu = _mm512_loadu_pd(hue), sa = _mm512_loadu_pd(saturation),
                  va = _mm512_loadu_pd(value);
    const __m512 f0 = _mm512_setzero_ps(), f1 = _mm512_set1_ps(1.0f);
    // hsv.x + float(hue / 360), clamp(hsv.y * float(1 + saturation), 0, 1),
    // hsv.z * float(clamp(value, 0, 1)).
    const __m512 h =
        simd::add(_mm512_set1_ps(r.hsv.x), floats512(_mm512_div_pd(hu, _mm512_set1_pd(360.0))));
    const __m512 s = clamp512(
        simd::mul(_mm512_set1_ps(r.hsv.y), floats512(simd::add(_mm512_set1_pd(1.0), sa))), f0, f1);
    const __m512 v = simd::mul(_mm512_set1_ps(r.hsv.z),
                               floats512(clamp512(va, _mm512_setzero_pd(), _mm512_set1_pd(1.0))));
    if (_mm512_cmp_ps_mask(simd::sub(h, h), f0, _CMP_EQ_OQ) != 0xffff) return false; // inf, NaN
    // hsvToRgb: floorExact is the floor (the value itself from 2^23 on, -0 kept).
    constexpr int kFloor = _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC;
    const __m512 hx =
        simd::mul(simd::sub(h, _mm512_roundscale_ps(h, kFloor)), _mm512_set1_ps(6.0f));
    const __m512 fh = _mm512_roundscale_ps(hx, kFloor); // 0 to 6
    const __m512i i = _mm512_cvttps_epi32(fh);
    const __m512 f = simd::sub(hx, fh);
    const __m512 p = simd::mul(v, simd::sub(f1, s));
    const __m512 q = simd::mul(v, simd::sub(f1, simd::mul(s, f)));
    const __m512 t = simd::mul(v, simd::sub(f1, simd::mul(s, simd::sub(f1, f))));
    const __mmask16 s0 = sector512(i, 0) | sector512(i, 6), s1 = sector512(i, 1),
                    s2 = sector512(i, 2), s3 = sector512(i, 3), s4 = sector512(i, 4);
    // 0: (v, t, p), 1: (q, v, p), 2: (p, v, t), 3: (p, q, v), 4: (t, p, v), else (v, p, q).
    __m512 red = _mm512_mask_mov_ps(v, s1, q);
    red = _mm512_mask_mov_ps(red, s2 | s3, p);
    red = _mm512_mask_mov_ps(red, s4, t);
    __m512 green = _mm512_mask_mov_ps(p, s0, t);
    green = _mm512_mask_mov_ps(green, s1 | s2, v);
    green = _mm512_mask_mov_ps(green, s3, q);
    __m512 blue = _mm512_mask_mov_ps(q, s0 | s1, p);
    blue = _mm512_mask_mov_ps(blue, s2, t);
    blue = _mm512_mask_mov_ps(blue, s3 | s4, v);
    const __m256 rgb[3] = {_mm512_castps512_ps256(red), _mm512_castps512_ps256(green),
                           _mm512_castps512_ps256(blue)};
    return boundedMultipliersAvx512(r, rgb, out, n);
}

// SYLVA_NO_AVX512=1 (or SYLVA_NO_AVX=1) takes powf on any processor.
const bool kBoundedMultipliers = simd::useAvx512();
#endif

void multipliers(const Reference& r, const double* hue, const double* saturation,
                 const double* value, glm::u8vec4* out, std::size_t n) {
    static_assert(kTintLanes % 4 == 0, "the block is whole registers of floats");
#if defined(SYLVA_X86_INTRINSICS)
    if (kBoundedMultipliers && multipliersAvx512(r, hue, saturation, value, out, n)) return;
#endif
    // The lanes past n take zeros; their results are not stored.
    alignas(16) double hu[kTintLanes] = {}, sa[kTintLanes] = {}, va[kTintLanes] = {};
    for (std::size_t c = 0; c < n; ++c) {
        hu[c] = hue[c];
        sa[c] = saturation[c];
        va[c] = value[c];
    }
    // The turns: hsv.x + float(hue / 360), clamp(hsv.y * float(1 + saturation), 0, 1),
    // hsv.z * float(clamp(value, 0, 1)).
    alignas(16) float th[kTintLanes], ts[kTintLanes], tv[kTintLanes];
    {
        const __m128d d360 = _mm_set1_pd(360.0), d0 = _mm_setzero_pd(), d1 = _mm_set1_pd(1.0);
        const __m128 rh = _mm_set1_ps(r.hsv.x), rs = _mm_set1_ps(r.hsv.y),
                     rv = _mm_set1_ps(r.hsv.z), f0 = _mm_setzero_ps(), f1 = _mm_set1_ps(1.0f);
        for (std::size_t c = 0; c < kTintLanes; c += 4) {
            const __m128 h = toFloats(_mm_div_pd(_mm_load_pd(hu + c), d360),
                                      _mm_div_pd(_mm_load_pd(hu + c + 2), d360));
            _mm_store_ps(th + c, _mm_add_ps(rh, h));
            const __m128 s = toFloats(_mm_add_pd(d1, _mm_load_pd(sa + c)),
                                      _mm_add_pd(d1, _mm_load_pd(sa + c + 2)));
            _mm_store_ps(ts + c, clampPs(_mm_mul_ps(rs, s), f0, f1));
            const __m128 v = toFloats(clampPd(_mm_load_pd(va + c), d0, d1),
                                      clampPd(_mm_load_pd(va + c + 2), d0, d1));
            _mm_store_ps(tv + c, _mm_mul_ps(rv, v));
        }
    }
    // The turned colours, channel by channel (rgb[k][c]); srgbToLinear's two quotients made
    // for every lane, the one it takes picked lane by lane (powf only where it is taken).
    alignas(16) float rgb[3][kTintLanes] = {};
    for (std::size_t c = 0; c < n; ++c) {
        const glm::vec3 t = hsvToRgb({th[c], ts[c], tv[c]});
        rgb[0][c] = t.x;
        rgb[1][c] = t.y;
        rgb[2][c] = t.z;
    }
    alignas(16) float low[3][kTintLanes], high[3][kTintLanes];
    {
        const __m128 a = _mm_set1_ps(0.055f), b = _mm_set1_ps(1.055f), d = _mm_set1_ps(12.92f);
        for (int k = 0; k < 3; ++k)
            for (std::size_t c = 0; c < kTintLanes; c += 4) {
                const __m128 x = _mm_load_ps(&rgb[k][c]);
                _mm_store_ps(&low[k][c], _mm_div_ps(x, d));
                _mm_store_ps(&high[k][c], _mm_div_ps(_mm_add_ps(x, a), b));
            }
    }
    alignas(16) float linear[3][kTintLanes] = {};
    for (int k = 0; k < 3; ++k)
        for (std::size_t c = 0; c < n; ++c)
            linear[k][c] = rgb[k][c] <= 0.04045f ? low[k][c] : std::pow(high[k][c], 2.4f);
    // The ratios to the reference, the scale (the strong channels' largest ratio, at least 1),
    // the clamped ratios to it and their bytes (llroundExact of x * 255: below 2^31 the
    // truncation, plus one from a fraction of a half or more; a NaN lane takes toByte).
    alignas(16) std::int32_t bytes[3][kTintLanes];
    {
        const __m128d d1 = _mm_set1_pd(1.0), quarter = _mm_set1_pd(0.25), d255 = _mm_set1_pd(255.0),
                      half = _mm_set1_pd(0.5);
        const __m128d ref[3] = {_mm_set1_pd(r.lin[0]), _mm_set1_pd(r.lin[1]),
                                _mm_set1_pd(r.lin[2])};
        for (std::size_t c = 0; c < kTintLanes; c += 2) {
            __m128d m[3];
            const std::size_t half4 = c & 3;
            for (int k = 0; k < 3; ++k) {
                const __m128 four = _mm_load_ps(&linear[k][c - half4]);
                const __m128 two = half4 == 0 ? four : _mm_movehl_ps(four, four);
                m[k] = _mm_div_pd(_mm_cvtps_pd(two), ref[k]);
            }
            __m128d scale = d1;
            for (int k = 0; k < 3; ++k)
                if (r.strong[k]) scale = _mm_max_pd(m[k], scale); // (scale < m) ? m : scale
            for (int k = 0; k < 3; ++k) {
                const __m128d q = clampPd(_mm_div_pd(m[k], scale), quarter, d1);
                const __m128d x = _mm_mul_pd(q, d255);
                const __m128i i = _mm_cvttpd_epi32(x);
                const __m128d fraction = _mm_sub_pd(x, _mm_cvtepi32_pd(i));
                const __m128i up = _mm_castpd_si128(_mm_cmpge_pd(fraction, half));
                // The comparison's lanes are 64 bits: their low halves to the two int lanes.
                const __m128i round = _mm_shuffle_epi32(up, _MM_SHUFFLE(3, 3, 2, 0));
                _mm_storel_epi64(reinterpret_cast<__m128i*>(&bytes[k][c]), _mm_sub_epi32(i, round));
                if (_mm_movemask_pd(_mm_cmpunord_pd(x, x)) != 0) {
                    alignas(16) double qs[2];
                    _mm_store_pd(qs, q);
                    for (int l = 0; l < 2; ++l)
                        bytes[k][c + static_cast<std::size_t>(l)] = toByte(qs[l]);
                }
            }
        }
    }
    for (std::size_t c = 0; c < n; ++c)
        out[c] = glm::u8vec4(static_cast<std::uint8_t>(bytes[0][c]),
                             static_cast<std::uint8_t>(bytes[1][c]),
                             static_cast<std::uint8_t>(bytes[2][c]), 255);
}

#else

void multipliers(const Reference& r, const double* hue, const double* saturation,
                 const double* value, glm::u8vec4* out, std::size_t n) {
    glm::vec3 turned[kTintLanes];
    for (std::size_t c = 0; c < n; ++c) {
        glm::vec3 hsv = r.hsv;
        hsv.x += static_cast<float>(hue[c] / 360.0);
        hsv.y = std::clamp(hsv.y * static_cast<float>(1.0 + saturation[c]), 0.0f, 1.0f);
        hsv.z *= static_cast<float>(std::clamp(value[c], 0.0, 1.0));
        turned[c] = hsvToRgb(hsv);
    }
    float linear[kTintLanes][3];
    for (std::size_t c = 0; c < n; ++c)
        for (int k = 0; k < 3; ++k)
            linear[c][k] = srgbToLinear(turned[c][k]);
    for (std::size_t c = 0; c < n; ++c) {
        double m[3];
        for (int k = 0; k < 3; ++k)
            m[k] = linear[c][k] / r.lin[k];
        // A multiplier cannot brighten: when a channel would have to grow (green turned toward
        // yellow needs more red), the others shrink instead, so the hue turns as asked and the
        // card is a little darker. Channels that carry under a quarter of the colour's
        // strongest are left out of that (a leaf green's blue, an autumn orange's blue: their
        // ratios swing wildly for no visible change), and every channel keeps a quarter at
        // least, so as not to strip it from a texture's highlights.
        double scale = 1.0;
        for (int k = 0; k < 3; ++k)
            if (r.strong[k]) scale = std::max(scale, m[k]);
        out[c] = glm::u8vec4(255);
        for (int k = 0; k < 3; ++k)
            out[c][k] = toByte(std::clamp(m[k] / scale, 0.25, 1.0));
    }
}

#endif

// A block's cards' own variations, signedUnit(mixSeed(h, k)) for k = 0, 1, 2 (own[k][c]), where
// h is the card's hash: the seed mixed with its centre's x, y and z to a millimetre
// (llroundExact(centre * 1000)). Card by card: six mixSeed in a chain of three and three more.
void ownVariationsPlain(const glm::dvec3* centre, std::size_t n, std::uint64_t seed,
                        double own[3][kTintLanes]) {
    for (std::size_t c = 0; c < n; ++c) {
        // The centre to a millimetre: two sheets of one crossed cluster card (the same centre
        // line, their corners rounded differently) get one colour.
        std::uint64_t h = seed;
        for (int k = 0; k < 3; ++k)
            h = mixSeed(h, static_cast<std::uint64_t>(llroundExact(centre[c][k] * 1000.0)));
        for (int k = 0; k < 3; ++k)
            own[k][c] = signedUnit(mixSeed(h, static_cast<std::uint64_t>(k)));
    }
}

#if defined(SYLVA_X86_INTRINSICS)
// The same for a block of eight cards, a card a lane of AVX-512 (its 64-bit products, vpmullq,
// are AVX512DQ's): each lane the scalar operations in order (the product by 1000 and the
// fraction's difference with explicit rounding, so that no fused multiply-add contracts them;
// the truncation and the conversions back are exact below 2^52). A block with a centre at or past
// 2^52 mm (or NaN: llroundExact's std::llround) returns false and is made card by card. The
// hashes' chains (six mixSeed a card, two 64-bit products each) were half of tintLeafCards' own
// time in perf annotate of the English oak.
__attribute__((target("avx512f,avx512dq"), always_inline)) inline __m512i mix512(__m512i a,
                                                                                 __m512i b) {
    const __m512i one = _mm512_set1_epi64(1);
    __m512i z = _mm512_add_epi64(
        a, _mm512_mullo_epi64(_mm512_set1_epi64(static_cast<long long>(0x9E3779B97F4A7C15ull)),
                              _mm512_add_epi64(b, one)));
    z = _mm512_mullo_epi64(_mm512_xor_si512(z, _mm512_srli_epi64(z, 30)),
                           _mm512_set1_epi64(static_cast<long long>(0xBF58476D1CE4E5B9ull)));
    z = _mm512_mullo_epi64(_mm512_xor_si512(z, _mm512_srli_epi64(z, 27)),
                           _mm512_set1_epi64(static_cast<long long>(0x94D049BB133111EBull)));
    return _mm512_xor_si512(z, _mm512_srli_epi64(z, 31));
}

__attribute__((target("avx512f,avx512dq"))) bool
ownVariationsAvx512(const glm::dvec3* centre, std::uint64_t seed, double own[3][kTintLanes]) {
    static_assert(kTintLanes == 8 && sizeof(glm::dvec3) == 3 * sizeof(double));
    constexpr int kRound = _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC;
    const __m512i stride = _mm512_setr_epi64(0, 3, 6, 9, 12, 15, 18, 21);
    const __m512i one = _mm512_set1_epi64(1);
    const __m512d thousand = _mm512_set1_pd(1000.0), limit = _mm512_set1_pd(0x1p52),
                  half = _mm512_set1_pd(0.5), minusHalf = _mm512_set1_pd(-0.5);
    __m512i h = _mm512_set1_epi64(static_cast<long long>(seed));
    for (int k = 0; k < 3; ++k) {
        const __m512d c = _mm512_i64gather_pd(stride, &centre[0][k], 8);
        const __m512d x = _mm512_mul_round_pd(c, thousand, kRound);
        if (_mm512_cmp_pd_mask(_mm512_abs_pd(x), limit, _CMP_LT_OQ) != 0xff) return false;
        const __m512i i = _mm512_cvttpd_epi64(x);
        const __m512d fraction = _mm512_sub_round_pd(x, _mm512_cvtepi64_pd(i), kRound);
        __m512i r =
            _mm512_mask_add_epi64(i, _mm512_cmp_pd_mask(fraction, half, _CMP_GE_OQ), i, one);
        r = _mm512_mask_sub_epi64(r, _mm512_cmp_pd_mask(fraction, minusHalf, _CMP_LE_OQ), r, one);
        h = mix512(h, r);
    }
    for (int k = 0; k < 3; ++k) {
        // signedUnit: h >> 11 (below 2^53, so its conversion is exact) times 2^-52 (exact), less 1.
        const __m512d unit = _mm512_mul_round_pd(
            _mm512_cvtepi64_pd(_mm512_srli_epi64(mix512(h, _mm512_set1_epi64(k)), 11)),
            _mm512_set1_pd(0x1.0p-52), kRound);
        _mm512_storeu_pd(own[k], _mm512_sub_round_pd(unit, _mm512_set1_pd(1.0), kRound));
    }
    return true;
}

// SYLVA_NO_AVX512=1 (or SYLVA_NO_AVX=1) takes the card-by-card hashes on any processor.
const bool kTintAvx512 = simd::useAvx512Dq();
#endif

void ownVariations(const glm::dvec3* centre, std::size_t n, std::uint64_t seed,
                   double own[3][kTintLanes]) {
#if defined(SYLVA_X86_INTRINSICS)
    if (n == kTintLanes && kTintAvx512 && ownVariationsAvx512(centre, seed, own)) return;
#endif
    ownVariationsPlain(centre, n, seed, own);
}

} // namespace

glm::u8vec4 tintMultiplier(const glm::vec3& referenceSrgb, double hue, double saturation,
                           double value) {
    glm::u8vec4 out;
    multipliers(reference(referenceSrgb), &hue, &saturation, &value, &out, 1);
    return out;
}

void tintMultipliers(const glm::vec3& referenceSrgb, std::span<const double> hue,
                     std::span<const double> saturation, std::span<const double> value,
                     std::span<glm::u8vec4> out) {
    const Reference ref = reference(referenceSrgb);
    for (std::size_t first = 0; first < out.size(); first += kTintLanes)
        multipliers(ref, &hue[first], &saturation[first], &value[first], &out[first],
                    std::min(kTintLanes, out.size() - first));
}

#if defined(SYLVA_X86_INTRINSICS)
namespace {
__attribute__((target("avx512f"))) void powfBoundsOf(const float* a, double* lo, double* hi,
                                                     std::size_t n) {
    for (std::size_t i = 0; i < n; i += kTintLanes) {
        const std::size_t lanes = std::min(kTintLanes, n - i);
        const __mmask8 m = static_cast<__mmask8>((1u << lanes) - 1);
        float block[kTintLanes] = {};
        std::copy(a + i, a + i + lanes, block);
        __m512d l, h;
        powfBoundsAvx512(_mm512_cvtps_pd(_mm256_loadu_ps(block)), l, h);
        _mm512_mask_storeu_pd(lo + i, m, l);
        _mm512_mask_storeu_pd(hi + i, m, h);
    }
}
} // namespace
#endif

bool tintPowfBounds(std::span<const float> a, std::span<double> lo, std::span<double> hi) {
#if defined(SYLVA_X86_INTRINSICS)
    if (!kBoundedMultipliers) return false;
    powfBoundsOf(a.data(), lo.data(), hi.data(), std::min({a.size(), lo.size(), hi.size()}));
    return true;
#else
    (void)a, (void)lo, (void)hi;
    return false;
#endif
}

void vertexBox(std::span<const glm::vec3> points, glm::vec3& lo, glm::vec3& hi) {
    lo = hi = points[0];
    std::size_t v = 1;
#if defined(__SSE2__)
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "a vec3 is three packed floats");
    if (points.size() >= 5) {
        // Four points are three registers, (x y z x) (y z x y) (z x y z); each lane's chain
        // starts from the first point's coordinate as the plain loop does, and _mm_min_ps(p, m)
        // is glm::min(m, p) ((p < m) ? p : m), _mm_max_ps(p, m) glm::max(m, p).
        const glm::vec3 f = points[0];
        const __m128 initA = _mm_setr_ps(f.x, f.y, f.z, f.x);
        const __m128 initB = _mm_setr_ps(f.y, f.z, f.x, f.y);
        const __m128 initC = _mm_setr_ps(f.z, f.x, f.y, f.z);
        __m128 loA = initA, loB = initB, loC = initC, hiA = initA, hiB = initB, hiC = initC;
        for (; v + 4 <= points.size(); v += 4) {
            const float* p = &points[v].x;
            const __m128 a = _mm_loadu_ps(p), b = _mm_loadu_ps(p + 4), c = _mm_loadu_ps(p + 8);
            loA = _mm_min_ps(a, loA);
            loB = _mm_min_ps(b, loB);
            loC = _mm_min_ps(c, loC);
            hiA = _mm_max_ps(a, hiA);
            hiB = _mm_max_ps(b, hiB);
            hiC = _mm_max_ps(c, hiC);
        }
        float l[12], h[12];
        _mm_storeu_ps(l, loA);
        _mm_storeu_ps(l + 4, loB);
        _mm_storeu_ps(l + 8, loC);
        _mm_storeu_ps(h, hiA);
        _mm_storeu_ps(h + 4, hiB);
        _mm_storeu_ps(h + 8, hiC);
        for (int k = 0; k < 4; ++k) {
            const glm::vec3 lk(l[3 * k], l[3 * k + 1], l[3 * k + 2]);
            const glm::vec3 hk(h[3 * k], h[3 * k + 1], h[3 * k + 2]);
            lo = glm::min(lo, lk);
            hi = glm::max(hi, hk);
        }
    }
#endif
    for (; v < points.size(); ++v) {
        lo = glm::min(lo, points[v]);
        hi = glm::max(hi, points[v]);
    }
}

void tintLeafCards(Mesh& mesh, std::size_t firstVertex, const LeafColorVariation& variation,
                   const glm::vec3& referenceSrgb, double patchSize, std::uint64_t seed,
                   std::span<const float> cardLight, double lightShading) {
    const bool shaded = lightShading > 0.0 && !cardLight.empty();
    if (!variation.active() && !shaded) return;
    const std::size_t n = mesh.positions.size();
    mesh.colors.resize(n, glm::u8vec4(255));
    if (firstVertex >= n) return;
    ValueNoise noise(mixSeed(seed, 0x9a7c));
    const Reference ref = reference(referenceSrgb);
    const double invPatch = patchSize > 0.0 ? 1.0 / patchSize : 0.0;
    if (invPatch > 0.0) {
        // Every card's centre is in its vertices' box: its patches' lattice values made once.
        glm::vec3 lo, hi;
        vertexBox(std::span(mesh.positions).subspan(firstVertex), lo, hi);
        noise.cover(glm::dvec3(lo) * invPatch, glm::dvec3(hi) * invPatch,
                    2 * (n - firstVertex) + 64);
    }
    // The cards' variations kTintLanes at a time, each stage for every card of the block before
    // the next (their centres and hash chains, their noises, their variations, their
    // multipliers): one card's hash chain (six mixSeed) and noise interleave with the others'.
    // Each card's arithmetic its own, in its order: the same bytes as one card at a time.
    double hue[kTintLanes], saturation[kTintLanes], value[kTintLanes];
    glm::dvec3 centre[kTintLanes], patch[kTintLanes];
    double own[3][kTintLanes];
    glm::u8vec4 tint[kTintLanes];
    for (std::size_t v0 = firstVertex; v0 < n; v0 += 4 * kTintLanes) {
        const std::size_t lanes = std::min(kTintLanes, (n - v0 + 3) / 4);
        for (std::size_t c = 0; c < lanes; ++c) {
            const std::size_t v = v0 + 4 * c, end = std::min(n, v + 4);
            glm::dvec3 sum(0.0);
            for (std::size_t k = v; k < end; ++k)
                sum += glm::dvec3(mesh.positions[k]);
            // Four corners: times a quarter, the quotient's bits without a division (on the
            // way to the card's hash chain).
            centre[c] = end - v == 4 ? sum * 0.25 : sum / static_cast<double>(end - v);
        }
        ownVariations(centre, lanes, seed, own);
        for (std::size_t c = 0; c < lanes; ++c)
            patch[c] = invPatch > 0.0 ? noise(centre[c] * invPatch) : glm::dvec3(0.0);
        for (std::size_t c = 0; c < lanes; ++c) {
            double r[3];
            for (int k = 0; k < 3; ++k) {
                // Value noise keeps to about ±0.3 (std): doubled, the patches reach the range.
                r[k] =
                    invPatch > 0.0
                        ? std::clamp(kOwnShare * own[k][c] + (1.0 - kOwnShare) * 2.0 * patch[c][k],
                                     -1.0, 1.0)
                        : own[k][c];
            }
            // Squared: most cards keep near the texture's brightness, a few are clearly darker
            // (a crown a third as much darker on average as with a linear spread: one of the
            // same look is b/3 darker, not b/2).
            const double dark = 0.5 + 0.5 * r[2];
            const std::size_t card = (v0 - firstVertex) / 4 + c;
            const double lit =
                shaded && card < cardLight.size() ? static_cast<double>(cardLight[card]) : 1.0;
            hue[c] = variation.hue * r[0];
            saturation[c] = variation.saturation * r[1];
            value[c] =
                (1.0 - variation.brightness * dark * dark) * (1.0 - lightShading * (1.0 - lit));
        }
        multipliers(ref, hue, saturation, value, tint, lanes);
        for (std::size_t c = 0; c < lanes; ++c)
            for (std::size_t k = v0 + 4 * c; k < std::min(n, v0 + 4 * c + 4); ++k)
                mesh.colors[k] = tint[c];
    }
}

} // namespace sylva::mesh
