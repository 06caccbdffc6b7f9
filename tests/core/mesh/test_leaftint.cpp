#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <vector>

#include "../common/testtrees.h"
#include "engine/mesh/impostor.h"
#include "engine/mesh/leafcards.h"
#include "engine/mesh/leaftint.h"
#include "engine/mesh/treemesh.h"
#include "engine/mesh/valuenoise.h"
#include "engine/util/exactround.h"
#include "engine/util/random.h"

using namespace sylva;
using sylva::testing::leafyTree;

namespace {

const glm::vec3 kGreen{0.26f, 0.40f, 0.12f};

mesh::TreeMeshSettings tinted(double hue, double saturation, double brightness) {
    mesh::TreeMeshSettings settings;
    settings.seed = 7;
    settings.leafTint.summer = {hue, saturation, brightness};
    settings.leafTint.autumn = {3 * hue, saturation, brightness};
    return settings;
}

// The first vertex of the leaf submesh.
std::size_t firstLeafVertex(const mesh::Mesh& m) {
    for (const mesh::Submesh& s : m.submeshes)
        if (s.material == "leaf") return m.indices[s.firstIndex];
    return m.positions.size();
}

// The hue (degrees) of a leaf green multiplied by each card's tint, in linear light.
std::vector<double> cardHues(const mesh::Mesh& m) {
    std::vector<double> hues;
    for (std::size_t v = firstLeafVertex(m); v + 3 < m.positions.size(); v += 4) {
        glm::vec3 c;
        for (int k = 0; k < 3; ++k)
            c[k] = mesh::srgbToLinear(kGreen[k]) * m.colors[v][k] / 255.0f;
        const float mx = std::max({c.x, c.y, c.z}), mn = std::min({c.x, c.y, c.z});
        double h = 0.0;
        if (mx == c.y)
            h = 60.0 * (2.0 + (c.z - c.x) / (mx - mn));
        else if (mx == c.x)
            h = 60.0 * (c.y - c.z) / (mx - mn);
        else
            h = 60.0 * (4.0 + (c.x - c.y) / (mx - mn));
        hues.push_back(h);
    }
    return hues;
}

double stddev(const std::vector<double>& v) {
    double mean = 0.0, sq = 0.0;
    for (double x : v)
        mean += x;
    mean /= static_cast<double>(v.size());
    for (double x : v)
        sq += (x - mean) * (x - mean);
    return std::sqrt(sq / static_cast<double>(v.size()));
}

} // namespace

TEST(LeafTint, NoChangeIsWhiteAndAMultiplierNeverBrightens) {
    EXPECT_EQ(mesh::tintMultiplier(kGreen, 0.0, 0.0, 1.0), glm::u8vec4(255));
    // Darker by a fifth of its HSV value: every channel alike, about 0.8^2.3 in linear light.
    const glm::u8vec4 dark = mesh::tintMultiplier(kGreen, 0.0, 0.0, 0.8);
    EXPECT_NEAR(dark.x, dark.y, 8);
    EXPECT_NEAR(dark.y / 255.0, std::pow(0.8, 2.3), 0.03);
    // Toward yellow (hue down from green), green keeps red (it would have to grow) and loses
    // blue; toward blue (hue up), the other way round.
    const glm::u8vec4 yellow = mesh::tintMultiplier(kGreen, -20.0, 0.0, 1.0);
    EXPECT_EQ(yellow.x, 255);
    EXPECT_LT(yellow.y, 200);
    EXPECT_LT(yellow.z, 200);
    const glm::u8vec4 blue = mesh::tintMultiplier(kGreen, 20.0, 0.0, 1.0);
    EXPECT_LT(blue.x, 200);
    EXPECT_EQ(blue.z, 255);
    // More saturated: the weakest channel goes down; never below a quarter.
    const glm::u8vec4 vivid = mesh::tintMultiplier(kGreen, 0.0, 0.5, 1.0);
    EXPECT_LT(vivid.z, 200);
    EXPECT_GE(mesh::tintMultiplier(kGreen, 90.0, 1.0, 0.0).z, 63);
}

TEST(LeafTint, EachCardOneColourBarkWhiteDeterministic) {
    const skel::Skeleton s = leafyTree();
    const mesh::Mesh a = mesh::buildTreeMesh(s, tinted(10.0, 0.2, 0.2));
    const mesh::Mesh b = mesh::buildTreeMesh(s, tinted(10.0, 0.2, 0.2));
    ASSERT_EQ(a.colors.size(), a.positions.size());
    EXPECT_EQ(a.colors, b.colors);
    const std::size_t leaf = firstLeafVertex(a);
    ASSERT_LT(leaf, a.positions.size());
    for (std::size_t v = 0; v < leaf; ++v)
        ASSERT_EQ(a.colors[v], glm::u8vec4(255)) << "bark vertex " << v;
    std::set<std::uint32_t> distinct;
    for (std::size_t v = leaf; v < a.positions.size(); v += 4) {
        for (std::size_t k = 1; k < 4; ++k)
            ASSERT_EQ(a.colors[v + k], a.colors[v]) << "card at " << v;
        const glm::u8vec4 c = a.colors[v];
        distinct.insert(c.x | c.y << 8 | c.z << 16);
    }
    const std::size_t cards = (a.positions.size() - leaf) / 4;
    EXPECT_GT(distinct.size(), cards / 4) << "cards differ";
    // Another tree seed: other colours.
    mesh::TreeMeshSettings other = tinted(10.0, 0.2, 0.2);
    other.seed = 8;
    EXPECT_NE(mesh::buildTreeMesh(s, other).colors, a.colors);
}

TEST(LeafTint, VariationStaysInItsRangeAndZeroMeansNone) {
    const skel::Skeleton s = leafyTree();
    EXPECT_TRUE(mesh::buildTreeMesh(s, tinted(0.0, 0.0, 0.0)).colors.empty());
    // Brightness alone: every channel between the darkest card's and white.
    const mesh::Mesh m = mesh::buildTreeMesh(s, tinted(0.0, 0.0, 0.3));
    const glm::u8vec4 darkest = mesh::tintMultiplier(kGreen, 0.0, 0.0, 0.7);
    double lo = 255.0, hi = 0.0;
    for (std::size_t v = firstLeafVertex(m); v < m.positions.size(); ++v)
        for (int k = 0; k < 3; ++k) {
            ASSERT_GE(m.colors[v][k] + 1, darkest[k]);
            lo = std::min<double>(lo, m.colors[v][k]);
            hi = std::max<double>(hi, m.colors[v][k]);
        }
    EXPECT_GT(hi - lo, 0.5 * (255 - darkest.y)) << "the range is used";
    // Hue: the cards' hues spread with the setting, and not at all without it.
    const double spread = stddev(cardHues(mesh::buildTreeMesh(s, tinted(12.0, 0.0, 0.0))));
    EXPECT_GT(spread, 2.0);
    EXPECT_LT(spread, 12.0);
    EXPECT_LT(stddev(cardHues(mesh::buildTreeMesh(s, tinted(0.0, 0.0, 0.2)))), 0.5);
}

TEST(LeafTint, AutumnHasItsOwnSpreadEvergreensKeepSummers) {
    const skel::Skeleton s = leafyTree();
    mesh::TreeMeshSettings autumn = tinted(8.0, 0.0, 0.0);
    autumn.season = mesh::Season::Autumn;
    autumn.deciduous = true;
    autumn.leafTint.autumnColor = {0.92f, 0.52f, 0.08f};
    EXPECT_EQ(&mesh::leafVariationFor(autumn.leafTint, autumn.season, true),
              &autumn.leafTint.autumn);
    EXPECT_EQ(&mesh::leafVariationFor(autumn.leafTint, autumn.season, false),
              &autumn.leafTint.summer);
    EXPECT_EQ(mesh::leafReferenceColor(autumn.leafTint, autumn.season, true),
              autumn.leafTint.autumnColor);
    const mesh::Mesh m = mesh::buildTreeMesh(s, autumn);
    ASSERT_EQ(m.colors.size(), m.positions.size());
    // Only the autumn spread set: no variation in summer.
    autumn.leafTint.summer = {};
    autumn.season = mesh::Season::Summer;
    EXPECT_TRUE(mesh::buildTreeMesh(s, autumn).colors.empty());
}

TEST(LeafTint, CarriedThroughLodLevelsAndClusters) {
    const skel::Skeleton s = leafyTree();
    mesh::TreeMeshSettings settings = tinted(10.0, 0.2, 0.2);
    settings.leafClusterSize = 4;
    const auto chain = sylva::testing::bandLevels(s, settings);
    ASSERT_GE(chain.size(), 2u);
    for (const auto& level : chain) {
        ASSERT_EQ(level.second.colors.size(), level.second.positions.size())
            << "level at " << level.first << " m";
        std::set<std::uint32_t> distinct;
        for (std::size_t v = firstLeafVertex(level.second); v < level.second.positions.size();
             ++v) {
            const glm::u8vec4 c = level.second.colors[v];
            distinct.insert(c.x | c.y << 8 | c.z << 16);
        }
        EXPECT_GT(distinct.size(), 3u) << "level at " << level.first << " m";
    }
    // A leaf card of the same place keeps its colour from level to level: at 25 m (no leaf
    // merged by the default bands' thresholds at this size) most cards are where they were.
    const mesh::Mesh& near = chain[0].second;
    const mesh::Mesh& far = chain[1].second;
    auto centre = [](const mesh::Mesh& m, std::size_t v) {
        return (m.positions[v] + m.positions[v + 1] + m.positions[v + 2] + m.positions[v + 3]) /
               4.0f;
    };
    std::size_t same = 0, matched = 0;
    for (std::size_t v = firstLeafVertex(far); v + 3 < far.positions.size(); v += 4)
        for (std::size_t w = firstLeafVertex(near); w + 3 < near.positions.size(); w += 4)
            if (centre(far, v) == centre(near, w)) {
                ++matched;
                same += far.colors[v] == near.colors[w];
                break;
            }
    EXPECT_EQ(same, matched);
}

TEST(LeafTint, ImpostorBakeShowsTheTint) {
    // One card facing the view, plain white material: the baked colour is the tint's.
    mesh::Mesh card;
    card.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    card.normals.assign(4, glm::vec3(0, 0, 1));
    card.indices = {0, 1, 2, 0, 2, 3};
    card.submeshes = {{"leaf", 0, 6}};
    const mesh::ImpostorMaterials white = [](const mesh::Submesh&) {
        mesh::ImpostorMaterial m;
        m.colour = glm::vec3(1.0f);
        return m;
    };
    const Image plain =
        mesh::renderOrthographicView(card, white, {0, 0, -1}, glm::vec3(0.0f), 1.5f, 16, 1);
    card.colors.assign(4, glm::u8vec4(255, 64, 64, 255));
    const Image tinted =
        mesh::renderOrthographicView(card, white, {0, 0, -1}, glm::vec3(0.0f), 1.5f, 16, 1);
    EXPECT_EQ(plain.at(8, 8)[0], 255);
    EXPECT_EQ(plain.at(8, 8)[1], 255);
    EXPECT_EQ(tinted.at(8, 8)[0], 255);
    // 64/255 linear is about 0.53 in sRGB.
    EXPECT_NEAR(tinted.at(8, 8)[1], 0.53 * 255, 6);
}

TEST(LeafTint, CrossedSheetsOfOneCardShareTheirColour) {
    // A cluster card and its crossing sheet (the same centre line turned a quarter round it,
    // as leafclusters makes crossed cards) take one colour; a card beside them another.
    mesh::Mesh m;
    const glm::vec3 lo(0.31f, 2.17f, -0.43f), hi(0.36f, 2.49f, -0.41f);
    const glm::vec3 a(0.07f, 0.0f, 0.013f), b(0.0f, 0.011f, 0.071f);
    for (const glm::vec3& half : {a, b})
        for (const glm::vec3& p : {lo + half, lo - half, hi - half, hi + half})
            m.positions.push_back(p);
    for (const glm::vec3& p : {lo, lo + a, hi + a, hi})
        m.positions.push_back(p + glm::vec3(0.5f, 0.0f, 0.0f));
    mesh::tintLeafCards(m, 0, {8.0, 0.2, 0.2}, kGreen, 1.5, 3);
    ASSERT_EQ(m.colors.size(), 12u);
    EXPECT_EQ(m.colors[0], m.colors[4]);
    EXPECT_NE(m.colors[0], m.colors[8]);
}

TEST(LeafTint, CardsAddedLaterKeepTheColoursInStep) {
    // Mesh::colors stays empty or of the positions' size: cards appended to a tinted mesh (the
    // leaves node after tube_mesh) are white until tinted.
    const skel::Skeleton s = leafyTree();
    mesh::Mesh m = mesh::buildTreeMesh(s, tinted(10.0, 0.2, 0.2));
    const std::size_t before = m.positions.size();
    mesh::appendLeafCards(m, s.leaves, {});
    ASSERT_EQ(m.colors.size(), m.positions.size());
    EXPECT_EQ(m.colors.back(), glm::u8vec4(255));
    EXPECT_NE(m.colors[before - 1], glm::u8vec4(255));
}

// The multipliers made eight cards at a time (what tintLeafCards does) are tintMultiplier's,
// card by card, for every batch length, the reference colours of the seasons and an autumn
// orange, and variations past their ranges (clamped).
TEST(LeafTint, BatchedMultipliersAreTheSingleOnes) {
    Rng rng(17);
    for (const glm::vec3& reference :
         {kGreen, glm::vec3(0.42f, 0.58f, 0.18f), glm::vec3(0.8f, 0.45f, 0.1f)})
        for (std::size_t count : {1u, 5u, 8u, 9u, 100u}) {
            std::vector<double> hue(count), saturation(count), value(count);
            for (std::size_t i = 0; i < count; ++i) {
                hue[i] = rng.uniform(-100.0, 100.0);
                saturation[i] = rng.uniform(-1.2, 1.2);
                value[i] = rng.uniform(-0.1, 1.1);
            }
            std::vector<glm::u8vec4> batched(count);
            mesh::tintMultipliers(reference, hue, saturation, value, batched);
            for (std::size_t i = 0; i < count; ++i)
                EXPECT_EQ(batched[i],
                          mesh::tintMultiplier(reference, hue[i], saturation[i], value[i]))
                    << count << " " << i;
        }
}

namespace {

// tintMultiplier as it was written card by card before its block took SSE2 (its divisions,
// conversions, clamps and roundings two or four lanes to an instruction): the reference's HSV
// and linear values, the turn, hsvToRgb, srgbToLinear, the ratios, the scale and the bytes.
glm::u8vec4 plainMultiplier(const glm::vec3& referenceSrgb, double hue, double saturation,
                            double value) {
    const glm::vec3 ref = glm::clamp(referenceSrgb, glm::vec3(0.02f), glm::vec3(1.0f));
    const float mx = std::max({ref.x, ref.y, ref.z}), mn = std::min({ref.x, ref.y, ref.z});
    const float d = mx - mn;
    float h = 0.0f;
    if (d > 1e-6f) {
        if (mx == ref.x)
            h = (ref.y - ref.z) / d;
        else if (mx == ref.y)
            h = 2.0f + (ref.z - ref.x) / d;
        else
            h = 4.0f + (ref.x - ref.y) / d;
        h /= 6.0f;
        if (h < 0.0f) h += 1.0f;
    }
    glm::vec3 hsv{h, mx > 0.0f ? d / mx : 0.0f, mx};
    double lin[3], strongest = 0.0;
    for (int k = 0; k < 3; ++k) {
        lin[k] = mesh::srgbToLinear(ref[k]);
        strongest = std::max(strongest, lin[k]);
    }
    hsv.x += static_cast<float>(hue / 360.0);
    hsv.y = std::clamp(hsv.y * static_cast<float>(1.0 + saturation), 0.0f, 1.0f);
    hsv.z *= static_cast<float>(std::clamp(value, 0.0, 1.0));
    const float sh = (hsv.x - floorExact(hsv.x)) * 6.0f, s = hsv.y, v = hsv.z;
    const int sector = static_cast<int>(floorExact(sh)) % 6;
    const float f = sh - floorExact(sh);
    const float p = v * (1.0f - s), q = v * (1.0f - s * f), t = v * (1.0f - s * (1.0f - f));
    const glm::vec3 turned = sector == 0   ? glm::vec3(v, t, p)
                             : sector == 1 ? glm::vec3(q, v, p)
                             : sector == 2 ? glm::vec3(p, v, t)
                             : sector == 3 ? glm::vec3(p, q, v)
                             : sector == 4 ? glm::vec3(t, p, v)
                                           : glm::vec3(v, p, q);
    double m[3];
    for (int k = 0; k < 3; ++k)
        m[k] = static_cast<double>(mesh::srgbToLinear(turned[k])) / lin[k];
    double scale = 1.0;
    for (int k = 0; k < 3; ++k)
        if (lin[k] >= 0.25 * strongest) scale = std::max(scale, m[k]);
    glm::u8vec4 out(255);
    for (int k = 0; k < 3; ++k)
        out[k] = static_cast<std::uint8_t>(
            llroundExact(std::clamp(std::clamp(m[k] / scale, 0.25, 1.0), 0.0, 1.0) * 255.0));
    return out;
}

} // namespace

// The multipliers of a block (SSE2: two or four cards to an instruction) against the plain
// card-by-card ones above, bit for bit: every block length and its padding lanes (1 to 17 cards,
// then 300), the seasons' greens, an autumn orange, a grey (every channel strong, no hue) and a
// near-black reference, variations past their ranges (clamped), turned colours dark enough for
// srgbToLinear's linear segment, and NaN or infinite inputs (a grey's saturation times +inf is a
// NaN that std::max keeps out of the scale).
TEST(LeafTint, PackedMultipliersAreThePlainOnes) {
    Rng rng(29);
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::size_t> counts;
    for (std::size_t c = 1; c <= 17; ++c)
        counts.push_back(c);
    counts.push_back(300);
    for (const glm::vec3& reference :
         {kGreen, glm::vec3(0.42f, 0.58f, 0.18f), glm::vec3(0.8f, 0.45f, 0.1f),
          glm::vec3(0.5f, 0.5f, 0.5f), glm::vec3(0.03f, 0.02f, 0.05f)})
        for (std::size_t count : counts) {
            std::vector<double> hue(count), saturation(count), value(count);
            for (std::size_t i = 0; i < count; ++i) {
                hue[i] = rng.uniform(-200.0, 200.0);
                saturation[i] = rng.uniform(-1.5, 1.5);
                // A tenth of the cards dark (their channels in srgbToLinear's linear segment).
                value[i] = i % 10 == 3 ? rng.uniform(0.0, 0.05) : rng.uniform(-0.2, 1.2);
                if (i % 37 == 5) saturation[i] = inf;
                if (i % 41 == 7) value[i] = nan;
                if (i % 43 == 11) saturation[i] = -inf;
            }
            std::vector<glm::u8vec4> packed(count);
            mesh::tintMultipliers(reference, hue, saturation, value, packed);
            for (std::size_t i = 0; i < count; ++i)
                EXPECT_EQ(packed[i], plainMultiplier(reference, hue[i], saturation[i], value[i]))
                    << reference.x << " " << count << " " << i;
        }
}

// The bounds the AVX-512 multipliers take on powf(a, 2.4f) instead of calling it hold the C
// library's powf for every float a in [2^-4, 1] (srgbToLinear's powers: a = (c + 0.055) / 1.055
// for c in (0.04045, 1] is in [0.09, 1]), and are about 2^-20 of it apart (so that the bytes
// made from them mostly agree). Fails with the upper bound's margin 2^-26 instead of 2^-21.
TEST(LeafTint, PowfWithinItsBounds) {
    std::vector<float> a;
    std::vector<double> lo, hi;
    const std::uint32_t first = std::bit_cast<std::uint32_t>(0.0625f),
                        last = std::bit_cast<std::uint32_t>(1.0f);
    std::size_t outside = 0, wide = 0, checked = 0;
    for (std::uint32_t b0 = first; b0 <= last; b0 += 1u << 16) {
        const std::uint32_t b1 = std::min(last + 1, b0 + (1u << 16));
        a.resize(b1 - b0);
        for (std::uint32_t b = b0; b < b1; ++b)
            a[b - b0] = std::bit_cast<float>(b);
        lo.assign(a.size(), 0.0);
        hi.assign(a.size(), 0.0);
        if (!mesh::tintPowfBounds(a, lo, hi)) GTEST_SKIP() << "the multipliers call powf here";
        for (std::size_t i = 0; i < a.size(); ++i) {
            const double p = std::pow(a[i], 2.4f); // powf, as srgbToLinear's
            if (!(lo[i] <= p && p <= hi[i]) && outside++ < 5)
                ADD_FAILURE() << "powf(" << a[i] << ", 2.4f) = " << p << " outside [" << lo[i]
                              << ", " << hi[i] << "]";
            wide += !(hi[i] - lo[i] <= 0x1.01p-20 * p);
        }
        checked += a.size();
    }
    EXPECT_EQ(outside, 0u);
    EXPECT_EQ(wide, 0u);
    EXPECT_EQ(checked, static_cast<std::size_t>(last - first) + 1);
}

// The multipliers with AVX-512 (the turns and hsvToRgb eight cards to an instruction, powf
// bounded, not called, where the bounds' bytes agree) against the plain card-by-card ones, bit
// for bit, over 200,000 cards of each reference colour (the oak's spread and wider, every sector,
// turns of whole sectors; about a block in a hundred takes powf, its bytes not decided by the
// bounds). Fails with the fourth sector's green taken from p.
TEST(LeafTint, BoundedMultipliersAreThePlainOnes) {
    Rng rng(31);
    for (const glm::vec3& reference : {kGreen, glm::vec3(0.42f, 0.58f, 0.18f),
                                       glm::vec3(0.8f, 0.45f, 0.1f), glm::vec3(0.5f, 0.5f, 0.5f)}) {
        const std::size_t count = 200000;
        std::vector<double> hue(count), saturation(count), value(count);
        for (std::size_t i = 0; i < count; ++i) {
            const bool wider = i % 2 == 1;
            hue[i] = wider ? rng.uniform(-120.0, 120.0) : rng.uniform(-20.0, 20.0);
            saturation[i] = wider ? rng.uniform(-1.0, 1.0) : rng.uniform(-0.3, 0.3);
            value[i] = wider ? rng.uniform(0.0, 1.0) : rng.uniform(0.6, 1.0);
            // Turns of whole sectors (a grey's hue is 0: its turned hue on a sector's edge).
            if (i % 7 == 3) hue[i] = 60.0 * static_cast<double>(static_cast<int>(i / 7 % 13) - 6);
        }
        std::vector<glm::u8vec4> bounded(count);
        mesh::tintMultipliers(reference, hue, saturation, value, bounded);
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < count; ++i) {
            const glm::u8vec4 plain = plainMultiplier(reference, hue[i], saturation[i], value[i]);
            if (bounded[i] != plain && wrong++ < 5)
                ADD_FAILURE() << reference.x << " card " << i << ": " << int(bounded[i].x) << " "
                              << int(bounded[i].y) << " " << int(bounded[i].z) << " against "
                              << int(plain.x) << " " << int(plain.y) << " " << int(plain.z);
        }
        EXPECT_EQ(wrong, 0u);
    }
}

namespace {

// The plain box: glm::min and glm::max from the first point on, one point after the other.
void plainBox(const std::vector<glm::vec3>& points, glm::vec3& lo, glm::vec3& hi) {
    lo = hi = points[0];
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
}

bool sameBits(const glm::vec3& a, const glm::vec3& b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

// vertexBox (four points a step on SSE2, then the rest) against the plain loop bit for bit: every
// count from 1 to 40 (each remainder, the step's first and last point), each axis's extreme at
// every position in turn (a lane or a register mixed up fails), NaN points skipped as the plain
// loop skips them, and a NaN first point (kept, as glm::min keeps it).
TEST(LeafTint, VertexBoxIsThePlainBox) {
    Rng rng(23);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t count = 1; count <= 40; ++count)
        for (std::size_t at = 0; at < count; ++at)
            for (int variant = 0; variant < 3; ++variant) {
                std::vector<glm::vec3> points(count);
                for (glm::vec3& p : points)
                    p = glm::vec3(static_cast<float>(rng.uniform(-5.0, 5.0)),
                                  static_cast<float>(rng.uniform(10.0, 20.0)),
                                  static_cast<float>(rng.uniform(-30.0, -20.0)));
                // The extremes of every axis at point `at`.
                points[at] =
                    variant == 0 ? glm::vec3(-9.0f, 25.0f, -35.0f) : glm::vec3(9.0f, 5.0f, -15.0f);
                if (variant == 2) points[(at + 1) % count] = glm::vec3(nan, 0.0f, nan);
                if (variant == 2 && count > 3 && at == 0) points[0].y = nan;
                glm::vec3 lo, hi, plainLo, plainHi;
                mesh::vertexBox(points, lo, hi);
                plainBox(points, plainLo, plainHi);
                EXPECT_TRUE(sameBits(lo, plainLo) && sameBits(hi, plainHi))
                    << count << " " << at << " " << variant;
            }
}

namespace {

// tintLeafCards one card at a time, as it was before its cards were taken in blocks: each card's
// centre (its corners' mean in doubles, a division), its hash and noise, its variation and its
// multiplier by tintMultiplier, then the next card.
void cardByCardTint(mesh::Mesh& mesh, std::size_t firstVertex,
                    const mesh::LeafColorVariation& variation, const glm::vec3& reference,
                    double patchSize, std::uint64_t seed, std::span<const float> cardLight,
                    double lightShading) {
    const std::size_t n = mesh.positions.size();
    mesh.colors.resize(n, glm::u8vec4(255));
    mesh::ValueNoise noise(mixSeed(seed, 0x9a7c));
    const double invPatch = patchSize > 0.0 ? 1.0 / patchSize : 0.0;
    const bool shaded = lightShading > 0.0 && !cardLight.empty();
    auto signedUnit = [](std::uint64_t h) {
        return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0;
    };
    for (std::size_t v = firstVertex; v < n; v += 4) {
        const std::size_t end = std::min(n, v + 4);
        glm::dvec3 centre(0.0);
        for (std::size_t k = v; k < end; ++k)
            centre += glm::dvec3(mesh.positions[k]);
        centre /= static_cast<double>(end - v);
        std::uint64_t h = seed;
        for (int k = 0; k < 3; ++k)
            h = mixSeed(h, static_cast<std::uint64_t>(llroundExact(centre[k] * 1000.0)));
        const glm::dvec3 patch = invPatch > 0.0 ? noise(centre * invPatch) : glm::dvec3(0.0);
        double r[3];
        for (int k = 0; k < 3; ++k) {
            const double own = signedUnit(mixSeed(h, static_cast<std::uint64_t>(k)));
            r[k] = invPatch > 0.0 ? std::clamp(0.4 * own + 0.6 * 2.0 * patch[k], -1.0, 1.0) : own;
        }
        const double dark = 0.5 + 0.5 * r[2];
        const std::size_t card = (v - firstVertex) / 4;
        const double lit =
            shaded && card < cardLight.size() ? static_cast<double>(cardLight[card]) : 1.0;
        const glm::u8vec4 tint = mesh::tintMultiplier(
            reference, variation.hue * r[0], variation.saturation * r[1],
            (1.0 - variation.brightness * dark * dark) * (1.0 - lightShading * (1.0 - lit)));
        for (std::size_t k = v; k < end; ++k)
            mesh.colors[k] = tint;
    }
}

} // namespace

// tintLeafCards (its cards eight at a time, each stage for the block's cards before the next)
// against the card-by-card version above, bit for bit: card counts on either side of a block's
// eight, a last card of one to three vertices, cards far apart and close together (a noise cell
// shared or not), patches and none, light shading with fewer lights than cards, and colours
// already on the mesh (white bark before the cards).
TEST(LeafTint, BlocksOfCardsAreTheCardByCardColours) {
    Rng rng(41);
    for (std::size_t cards : {1u, 7u, 8u, 9u, 16u, 17u, 203u})
        for (std::size_t extra : {0u, 1u, 2u, 3u})
            for (int variant = 0; variant < 3; ++variant) {
                const std::size_t vertices = 4 * cards + extra;
                mesh::Mesh m;
                const std::size_t bark = variant == 2 ? 5 : 0;
                const double spread = variant == 0 ? 0.3 : 40.0;
                for (std::size_t v = 0; v < bark + vertices; ++v)
                    m.positions.push_back(
                        glm::vec3(static_cast<float>(rng.uniform(-spread, spread)),
                                  static_cast<float>(rng.uniform(0.0, 2.0 * spread)),
                                  static_cast<float>(rng.uniform(-spread, spread))));
                if (variant == 2) m.colors.assign(m.positions.size(), glm::u8vec4(9, 8, 7, 255));
                std::vector<float> light(cards / 2 + 1);
                for (float& l : light)
                    l = static_cast<float>(rng.uniform(0.0, 1.0));
                const mesh::LeafColorVariation variation{12.0, 0.3, 0.4};
                const double patch = variant == 1 ? 0.0 : 1.5;
                const double shading = variant == 0 ? 0.0 : 0.3;
                mesh::Mesh blocks = m, plain = m;
                mesh::tintLeafCards(blocks, bark, variation, kGreen, patch, 99, light, shading);
                cardByCardTint(plain, bark, variation, kGreen, patch, 99, light, shading);
                ASSERT_EQ(blocks.colors.size(), plain.colors.size());
                EXPECT_TRUE(std::memcmp(blocks.colors.data(), plain.colors.data(),
                                        plain.colors.size() * sizeof(glm::u8vec4)) == 0)
                    << cards << " " << extra << " " << variant;
            }
}

// The cards' hashes eight at a time (AVX-512 where the processor has it) against the card-by-card
// tint, bit for bit, where llroundExact's rounding decides: centres whose millimetres are exact
// halves (a sixteenth of a metre is 62.5 mm), either side of zero, and integers; a block with a
// centre past 2^52 mm (made card by card, llroundExact's std::llround) between blocks that are
// not. The ctest LeafTint.SameWithoutAvx512 runs these tests on the card-by-card hashes.
TEST(LeafTint, CardHashesRoundHalvesAndFarCentresAsTheCardByCardOnes) {
    Rng rng(53);
    for (int variant = 0; variant < 2; ++variant) {
        mesh::Mesh m;
        const std::size_t cards = 40;
        for (std::size_t c = 0; c < cards; ++c) {
            // Every corner at the centre: the corners' mean is the centre exactly.
            glm::vec3 centre(static_cast<float>(static_cast<int>(rng.below(81)) - 40) / 16.0f,
                             static_cast<float>(static_cast<int>(rng.below(81)) - 40) / 16.0f,
                             static_cast<float>(static_cast<int>(rng.below(81)) - 40) / 16.0f);
            if (variant == 1 && c / 8 == 2 && c % 8 == 5) centre.x = 1e13f;
            for (int k = 0; k < 4; ++k)
                m.positions.push_back(centre);
        }
        const mesh::LeafColorVariation variation{12.0, 0.3, 0.4};
        mesh::Mesh blocks = m, plain = m;
        mesh::tintLeafCards(blocks, 0, variation, kGreen, 0.0, 5, {}, 0.0);
        cardByCardTint(plain, 0, variation, kGreen, 0.0, 5, {}, 0.0);
        ASSERT_EQ(blocks.colors.size(), plain.colors.size());
        for (std::size_t v = 0; v < plain.colors.size(); ++v)
            EXPECT_EQ(blocks.colors[v], plain.colors[v]) << variant << " " << v;
    }
}
