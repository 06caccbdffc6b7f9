// The game-engine LOD chain (issue #32): levels by triangle budget made by the camera LOD's
// silhouette-keeping rules, each checked against LOD0 drawn at the level's switch distance, and
// the baked octahedral impostor checked against the full tree from random views.
//
// Measures (printed, and asserted):
// - budget: LOD_i has at most budget_i · LOD0's triangles and at least half of that (the camera
//   LOD's steps are discrete: the search stops at the first distance within budget).
// - silhouette: conservative coverage masks (tests/core/forest/coverageraster.h, an oracle the
//   engine does not use) of LOD_i and LOD0 on the reference screen (1920 × 1080, 60 degrees) at
//   the level's switch distance, from 8 views around and above; the mean IoU per level >= 0.9.
// - impostor: from 16 random directions of the upper hemisphere, the reference sampler
//   (mesh::renderImpostor, what docs/lods.md's shader does) against the full tree drawn by the
//   baker's own orthographic view at the size where the impostor takes over (the bounding
//   sphere 64 px across): the silhouettes (pixels with any coverage, closed by a 1-pixel disc;
//   the tree's found with 32 x 32 samples a pixel, treeSilhouette) overlap with IoU >= 0.9 in
//   every view for every library species, and colour: the mean absolute difference of the
//   sRGB channels over the pixels both cover, in 0..1, at most kMaxColourDifference; the
//   distance between the two pictures' mean colours is printed too. The atlas is the default
//   one (8 x 8 cells of 256 px) at the mip level a renderer samples at that size (mipLevel1:
//   128-px cells, box-filtered; sampled without mipmaps, 256-px cells alias: pine 0.899 worst,
//   palm 0.784 before the reference was sampled finely).
//   SYLVA_IMPOSTOR_PICTURES=<folder> writes the pictures, with a diff (red: only the impostor
//   covers, blue: only the tree).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include <glm/gtc/matrix_transform.hpp>
#include <omp.h>

#include "coverageraster.h"
#include "engine/graph/graph.h"
#include "engine/mesh/impostor.h"
#include "engine/mesh/lodchain.h"
#include "engine/mesh/raster.h"
#include "engine/nodes/meshnodes.h"
#include "engine/util/random.h"
#include "presetfile.h"

using namespace sylva;

namespace {

const std::filesystem::path kPresets = SYLVA_PRESETS_DIR;
const std::filesystem::path kTextures = kPresets / ".." / "resources" / "textures";
/// The impostor is compared where it takes over: the bounding sphere 64 pixels across
/// (LodChainSettings::impostorPixels).
constexpr int kViewPixels = 64;
constexpr double kMaxColourDifference = 0.1;
/// The impostor's coverage (the sum of its alpha) against the tree's, per view: at least this
/// (thinner, the crown lightens where it takes over; the views diluting each other's coverage
/// measured 0.75-0.9) and at most kMaxCoverage (the date palm's view 11 is 1.12: its fronds a
/// little wider where the three views do not quite agree).
constexpr double kMinCoverage = 0.85, kMaxCoverage = 1.2;
constexpr int kClosePixels = 1;

struct Species {
    std::shared_ptr<const skel::Skeleton> skeleton;
    mesh::TreeMeshSettings settings;
};

Species grow(const std::string& name, std::uint64_t seed) {
    graph::registerBuiltinNodeTypes();
    const graph::SpeciesGraph g = sylva::testing::loadPreset(kPresets / (name + ".json"));
    graph::Evaluator evaluator(g);
    const graph::NodeOutput& grown = evaluator.evaluateNode(g.skeletonSource(), true, seed);
    Species s;
    s.skeleton = grown.skeleton;
    s.settings = mesh::treeMeshSettingsFromParams(g.findNode(g.output)->params, seed, g.baseDir);
    return s;
}

mesh::LodChainSettings testChain() {
    mesh::LodChainSettings c;
    c.impostorSettings.cellPixels = 128;
    return c;
}

const mesh::BudgetLodChain& alderChain() {
    static const mesh::BudgetLodChain chain = [] {
        const Species s = grow("alder", 1);
        return mesh::buildBudgetLodChain(*s.skeleton, s.settings, testChain(),
                                         mesh::ImpostorTextures(kTextures));
    }();
    return chain;
}

/// The silhouette of a picture: the pixels with any coverage, closed by a disc of
/// kClosePixels (dilated, then eroded) so that the gaps between leaves inside the crown count as
/// crown, as they do for an eye at this size; holes wider than the disc stay open.
std::vector<std::uint32_t> silhouette(const Image& image) {
    const int w = image.width, h = image.height, r = kClosePixels;
    std::vector<std::uint8_t> m(static_cast<std::size_t>(w) * h), d(m.size()), e(m.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            m[static_cast<std::size_t>(y) * w + x] = image.at(x, y)[3] > 0;
    const auto disc = [&](const std::vector<std::uint8_t>& in, std::vector<std::uint8_t>& out,
                          bool dilate) {
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                bool v = !dilate;
                for (int dy = -r; dy <= r; ++dy)
                    for (int dx = -r; dx <= r; ++dx) {
                        if (dx * dx + dy * dy > r * r) continue;
                        const int xx = x + dx, yy = y + dy;
                        const bool inside = xx >= 0 && yy >= 0 && xx < w && yy < h &&
                                            in[static_cast<std::size_t>(yy) * w + xx];
                        if (dilate)
                            v = v || inside;
                        else
                            v = v && inside;
                    }
                out[static_cast<std::size_t>(y) * w + x] = v;
            }
    };
    disc(m, d, true);
    disc(d, e, false);
    std::vector<std::uint32_t> mask;
    for (std::size_t k = 0; k < e.size(); ++k)
        if (e[k] || m[k]) mask.push_back(static_cast<std::uint32_t>(k));
    return mask;
}

} // namespace

TEST(ImpostorEncoding, DirectionsRoundTrip) {
    Rng rng(7);
    for (bool hemi : {true, false})
        for (int i = 0; i < 200; ++i) {
            glm::vec3 d(rng.uniformf(-1, 1), rng.uniformf(-1, 1), rng.uniformf(-1, 1));
            if (glm::length(d) < 0.1f) continue;
            d = glm::normalize(d);
            if (hemi) d.y = std::abs(d.y);
            const glm::vec3 back =
                mesh::impostorViewDirection(mesh::impostorAtlasCoord(d, hemi), hemi);
            EXPECT_NEAR(glm::dot(back, d), 1.0f, 1e-4f) << hemi;
        }
    // Hemi-octahedral: the centre looks straight down, the corners lie on the horizon.
    EXPECT_NEAR(mesh::impostorViewDirection({0.5f, 0.5f}, true).y, 1.0f, 1e-6f);
    for (glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1), glm::vec2(1, 1)})
        EXPECT_NEAR(mesh::impostorViewDirection(c, true).y, 0.0f, 1e-6f);
    // Below the horizon clamps onto it.
    EXPECT_NEAR(mesh::impostorViewDirection(mesh::impostorAtlasCoord({1, -1, 0}, true), true).y,
                0.0f, 1e-6f);
    glm::vec3 r, u;
    mesh::impostorViewBasis({0, 1, 0}, r, u);
    EXPECT_NEAR(glm::dot(r, u), 0.0f, 1e-6f);
    EXPECT_NEAR(glm::length(r), 1.0f, 1e-6f);
}

TEST(ImpostorEncoding, SettingsAreChecked) {
    mesh::ImpostorSettings s;
    s.grid = 1;
    EXPECT_THROW(mesh::validateImpostor(s), InvalidInput);
    s.grid = 8;
    s.cellPixels = 4096;
    EXPECT_THROW(mesh::validateImpostor(s), InvalidInput);
    mesh::LodChainSettings c;
    c.budgets = {1.0, 0.5, 0.6};
    EXPECT_THROW(mesh::validateLodChain(c), InvalidInput);
    c.budgets = {0.9, 0.5};
    EXPECT_THROW(mesh::validateLodChain(c), InvalidInput);
}

// The engine's rasteriser covers exactly the pixel centres the tests' oracle covers.
TEST(Raster, MatchesTheOracleOnPixelCentres) {
    const Species s = grow("alder", 2);
    mesh::TreeMeshSettings plain = s.settings;
    const mesh::Mesh m = mesh::buildTreeMesh(*s.skeleton, plain);
    glm::vec3 c;
    float r;
    mesh::boundingSphere(m, c, r);
    const int n = 200;
    // Orthographic from +Z: x right, y up, the sphere filling the square.
    test::RasterCamera cam;
    cam.width = cam.height = n;
    cam.viewProj = glm::ortho(-r, r, -r, r, -100.0f * r, 100.0f * r) *
                   glm::lookAt(c + glm::vec3(0, 0, 2 * r), c, glm::vec3(0, 1, 0));
    std::vector<std::uint8_t> scratch;
    const test::Mask oracle = test::coverage(m, glm::mat4(1.0f), cam, scratch, false);
    std::vector<std::uint8_t> hit(static_cast<std::size_t>(n) * n, 0);
    std::vector<glm::vec3> screen;
    for (const glm::vec3& p : m.positions)
        screen.push_back({(p.x - c.x + r) / (2 * r) * n, (r - (p.y - c.y)) / (2 * r) * n, 0});
    for (std::size_t t = 0; t < m.triangleCount(); ++t)
        mesh::rasterizeTriangle(screen[m.indices[3 * t]], screen[m.indices[3 * t + 1]],
                                screen[m.indices[3 * t + 2]], n, n,
                                [&](int x, int y, float, float, float) {
                                    hit[static_cast<std::size_t>(y) * n + x] = 1;
                                });
    test::Mask ours;
    for (std::size_t k = 0; k < hit.size(); ++k)
        if (hit[k]) ours.push_back(static_cast<std::uint32_t>(k));
    ASSERT_GT(oracle.size(), 500u);
    EXPECT_GE(test::iou(oracle, ours), 0.995);
}

namespace {

/// Per mesh level of \p chain (LOD1..n), the silhouette IoU against LOD0 on the reference screen
/// at the level's switch distance from 8 views around the tree (every other one 20 degrees
/// above): the mean and the worst view.
std::vector<std::pair<double, double>> levelSilhouettes(const mesh::BudgetLodChain& chain,
                                                        const std::string& name) {
    const mesh::LodSettings ref;
    std::vector<std::uint8_t> scratch;
    std::vector<std::pair<double, double>> out;
    for (std::size_t i = 1; i < chain.levels.size(); ++i) {
        const mesh::BudgetLevel& l = chain.levels[i];
        double sum = 0.0, worst = 1.0;
        int views = 0;
        std::size_t pixels = 0;
        for (int k = 0; k < 8; ++k) {
            const double az = k * std::numbers::pi / 4.0;
            const double el = (k % 2) ? 0.35 : 0.0;
            const glm::vec3 dir(static_cast<float>(std::cos(el) * std::sin(az)),
                                static_cast<float>(std::sin(el)),
                                static_cast<float>(std::cos(el) * std::cos(az)));
            const test::RasterCamera cam = test::RasterCamera::lookAt(
                chain.centre + dir * static_cast<float>(l.distance), chain.centre, ref.fovYDegrees,
                1920, static_cast<int>(ref.screenHeightPx));
            const test::Mask full =
                test::coverage(chain.levels[0].mesh, glm::mat4(1.0f), cam, scratch);
            const test::Mask lod = test::coverage(l.mesh, glm::mat4(1.0f), cam, scratch);
            const double v = test::iou(full, lod);
            sum += v;
            worst = std::min(worst, v);
            ++views;
            if (k == 0) pixels = full.size();
        }
        std::cout << name << " LOD" << i << " at " << l.distance << " m (" << pixels
                  << " px): silhouette IoU mean " << sum / views << ", worst " << worst << "\n";
        out.emplace_back(sum / views, worst);
    }
    return out;
}

/// Each level's triangles against its budget: printed; at most the budget, and at least
/// (1 - \p tolerance) of it, unless the level is in \p coarser (the camera LOD's discrete steps
/// jump past the band: the level is cheaper than asked).
void checkBudgets(const mesh::BudgetLodChain& chain, const std::string& name, double tolerance,
                  const std::set<std::size_t>& coarser = {}) {
    const auto t0 = static_cast<double>(chain.levels[0].mesh.triangleCount());
    for (std::size_t i = 0; i < chain.levels.size(); ++i) {
        const mesh::BudgetLevel& l = chain.levels[i];
        const double ratio = static_cast<double>(l.mesh.triangleCount()) / t0;
        std::cout << name << " LOD" << i << ": " << l.mesh.triangleCount() << " triangles ("
                  << ratio << " of LOD0, budget " << l.budget << ") from " << l.distance
                  << " m, screen size " << l.screenSize << ", leaf clusters " << l.leafClusterPixels
                  << " px, silhouette (engine) " << l.silhouetteIoU << "\n";
        if (i > 0) {
            EXPECT_GE(l.distance, chain.levels[i - 1].distance) << name << " LOD" << i;
        }
        EXPECT_TRUE(l.budgetMet) << name << " LOD" << i;
        EXPECT_LE(ratio, l.budget + 1e-9) << name << " LOD" << i;
        if (coarser.count(i))
            EXPECT_LT(ratio, (1.0 - tolerance) * l.budget) << name << " LOD" << i << ": fixed?";
        else
            EXPECT_GE(ratio, (1.0 - tolerance) * l.budget) << name << " LOD" << i;
        if (i > 0) {
            EXPECT_GT(l.distance, chain.levels[i - 1].distance) << name << " LOD" << i;
        }
    }
}

} // namespace

TEST(LodChain, BudgetsAreMet) {
    const mesh::BudgetLodChain& chain = alderChain();
    const mesh::LodChainSettings settings = testChain();
    ASSERT_EQ(chain.levels.size(), settings.budgets.size());
    checkBudgets(chain, "alder", 0.5);
    std::cout << "impostor from " << chain.impostorDistance << " m, screen size "
              << chain.impostorScreenSize << "\n";
    EXPECT_GE(chain.impostorDistance, chain.levels.back().distance);
}

// A budget the camera LOD cannot reach before the tree is 4 px high is left out of the chain and
// reported with the fewest triangles the LOD makes; the chain goes on from the level before.
TEST(LodChain, UnreachableBudgetsAreDroppedAndReported) {
    const Species s = grow("alder", 1);
    mesh::LodChainSettings settings = testChain();
    settings.budgets = {1.0, 0.35, 0.0005, 0.0001};
    settings.impostorSettings.cellPixels = 16;
    const mesh::BudgetLodChain chain = mesh::buildBudgetLodChain(*s.skeleton, s.settings, settings,
                                                                 mesh::ImpostorTextures(kTextures));
    ASSERT_EQ(chain.levels.size(), 2u);
    ASSERT_EQ(chain.dropped.size(), 2u);
    EXPECT_DOUBLE_EQ(chain.dropped[0].budget, 0.0005);
    EXPECT_DOUBLE_EQ(chain.dropped[1].budget, 0.0001);
    for (const mesh::DroppedLevel& d : chain.dropped) {
        EXPECT_GT(d.coarsestTriangles, d.budgetTriangles);
        EXPECT_NE(d.reason.find("4 px"), std::string::npos) << d.reason;
    }
    EXPECT_TRUE(chain.levels[1].budgetMet);
    // The impostor follows the last level that was made.
    EXPECT_GE(chain.impostorDistance, 1.5 * chain.levels[1].distance - 1e-9);
}

// The chain's own silhouette measure: 1 for the same mesh, lower for the mesh moved by pixels.
TEST(LodChain, SilhouetteMeasure) {
    const mesh::BudgetLodChain& chain = alderChain();
    const mesh::Mesh& m = chain.levels[0].mesh;
    const mesh::LodSettings ref;
    const double d = chain.levels[2].distance;
    EXPECT_DOUBLE_EQ(mesh::silhouetteIoU(m, m, chain.centre, chain.radius, ref, d), 1.0);
    mesh::Mesh moved = m;
    const double metresPerPixel =
        2.0 * d * std::tan(ref.fovYDegrees * std::numbers::pi / 360.0) / ref.screenHeightPx;
    for (glm::vec3& p : moved.positions)
        p.y += static_cast<float>(3.0 * metresPerPixel);
    const double shifted = mesh::silhouetteIoU(m, moved, chain.centre, chain.radius, ref, d);
    EXPECT_LT(shifted, 0.9);
    EXPECT_GT(shifted, 0.2);
    EXPECT_NEAR(mesh::silhouetteIoU(m, chain.levels[2].mesh, chain.centre, chain.radius, ref, d),
                chain.levels[2].silhouetteIoU, 1e-12);
}

TEST(LodChain, EveryLevelKeepsTheSilhouetteAtItsDistance) {
    for (const auto& [mean, worst] : levelSilhouettes(alderChain(), "alder")) {
        EXPECT_GE(mean, 0.9);
        EXPECT_GE(worst, 0.85);
    }
}

// Issue #32 for every species of the library (seed 1, default budgets 100 / 35 / 12 / 4 %):
// each mesh level within its budget's tolerance (80-100 % of it) and, drawn at its switch
// distance on the reference screen, keeping LOD0's silhouette: mean IoU of 8 views >= 0.9 per
// level, worst view >= 0.85. The levels' leaf clusters are half a pixel at the switch distance
// (LodChainSettings::leafClusterPixels; with the forest's 2 pixels, 11 of the 36 levels missed,
// down to 0.71: docs/lods.md). Where the bar does not hold today the measured value is held
// instead (the tables below). SYLVA_LOD_SPECIES=<name> runs one species.
TEST(LodChain, LibraryLevelsKeepTheSilhouetteWithinBudget) {
    // Every level at the bar. The rhododendron's 4 % level (46 px in area at 437 m) measured
    // 0.890 / worst 0.827 with 0.5-px leaf clusters; the chain now checks each level's
    // silhouette itself (mesh::silhouetteIoU) and made that one with 0.7-px clusters (377 m,
    // 59 px: 0.931 / 0.894).
    // Levels the camera LOD makes coarser than 80 % of their budget (its steps jump past it).
    // (Measured with the needle-cluster and fuller-crown presets: willow LOD1 21 %, pine LOD1
    // 27.9 % and LOD2 6.4 %, cypress LOD1 25.7 %.)
    const std::map<std::string, std::set<std::size_t>> coarser = {
        {"weeping-willow", {1}},
        {"scots-pine", {1, 2}},
        {"italian-cypress", {1}},
        {"norway-spruce", {1}}}; // 26.6 % since its LOD0 lost its twigs' bark (issue #33)
    // (The birch's LOD1, 27.9 % with the radius pass and the root flare, is 28.3 % with its
    // smaller, more numerous leaves of issue #44: back in its band.)
    // The date palm has 456 triangles: 12 % and 4 % of them (54 and 18) are not reached before
    // it is 4 px high (its coarsest mesh has 66): those two levels are dropped and reported.
    const std::map<std::string, std::size_t> dropped = {{"date-palm", 2}};
    const char* only = std::getenv("SYLVA_LOD_SPECIES");
    int levels = 0, atBar = 0;
    for (const char* species : {"english-oak", "silver-birch", "european-beech", "norway-maple",
                                "weeping-willow", "lombardy-poplar", "scots-pine", "norway-spruce",
                                "date-palm", "italian-cypress", "rhododendron", "privet-hedge"}) {
        if (only && std::string(only) != species) continue;
        const Species s = grow(species, 1);
        mesh::LodChainSettings settings = testChain();
        settings.impostor = false;
        const mesh::BudgetLodChain chain =
            mesh::buildBudgetLodChain(*s.skeleton, s.settings, settings);
        const auto d = dropped.find(species);
        ASSERT_EQ(chain.dropped.size(), d == dropped.end() ? 0u : d->second) << species;
        ASSERT_EQ(chain.levels.size() + chain.dropped.size(), settings.budgets.size()) << species;
        for (const mesh::DroppedLevel& l : chain.dropped) {
            std::cout << species << " dropped the " << l.budget << " level: " << l.reason << "\n";
            EXPECT_GT(l.coarsestTriangles, l.budgetTriangles) << species;
        }
        const auto c = coarser.find(species);
        checkBudgets(chain, species, settings.tolerance,
                     c == coarser.end() ? std::set<std::size_t>{} : c->second);
        const auto measured = levelSilhouettes(chain, species);
        for (std::size_t i = 0; i < measured.size(); ++i) {
            const std::size_t level = i + 1;
            ++levels;
            atBar += measured[i].first >= 0.9 && measured[i].second >= 0.85;
            EXPECT_GE(measured[i].first, 0.9) << species << " LOD" << level;
            EXPECT_GE(measured[i].second, 0.85) << species << " LOD" << level;
            // The chain's own measure agrees with this oracle (different rasterisers, an
            // orthographic view instead of the perspective one).
            EXPECT_NEAR(chain.levels[level].silhouetteIoU, measured[i].first, 0.02)
                << species << " LOD" << level;
        }
    }
    std::cout << atBar << " of " << levels << " levels at the 0.9 bar\n";
}

namespace {

/// The atlas a renderer samples where the impostor takes over (the tree 64 px across, about a
/// texel a pixel): mip level 1 of the default 256-px cells, every map box-filtered 2 x 2 as
/// glGenerateMipmap does (the cells are powers of two, so no texel mixes two views). Its
/// coverage is that of 4 x 4 samples a texel (a separate bake of 128-px cells has 2 x 2).
mesh::Impostor mipLevel1(mesh::Impostor imp) {
    const auto down = [](const Image& in) {
        Image out(in.width / 2, in.height / 2, in.channels);
        for (int y = 0; y < out.height; ++y)
            for (int x = 0; x < out.width; ++x)
                for (int c = 0; c < in.channels; ++c) {
                    const int sum = in.at(2 * x, 2 * y)[c] + in.at(2 * x + 1, 2 * y)[c] +
                                    in.at(2 * x, 2 * y + 1)[c] + in.at(2 * x + 1, 2 * y + 1)[c];
                    out.at(x, y)[c] = static_cast<std::uint8_t>((sum + 2) / 4);
                }
        return out;
    };
    imp.color = down(imp.color);
    imp.normal = down(imp.normal);
    imp.depth = down(imp.depth);
    imp.settings.cellPixels /= 2;
    return imp;
}

/// The reference silhouette's samples: the tree drawn kReferenceScale times finer with 4 x 4
/// samples a pixel, so 32 x 32 samples a pixel of the compared picture.
constexpr int kReferenceScale = 8;

/// The tree's silhouette as the measure means it: the pixels of the kViewPixels² picture that
/// any of its surface covers (then closed as silhouette() does). Drawn with the 4 x 4 samples a
/// pixel of the colour picture, the date palm's leaflets seen nearly edge on fall between the
/// samples: in its worst view (11) that picture keeps only 0.85 of this silhouette, less than
/// the impostor does (which sees those leaflets from its atlas views, more open).
test::Mask treeSilhouette(const mesh::Mesh& mesh, const mesh::ImpostorMaterials& materials,
                          const glm::vec3& dir, const mesh::Impostor& imp) {
    const Image fine = mesh::renderOrthographicView(mesh, materials, dir, imp.centre, imp.radius,
                                                    kViewPixels * kReferenceScale, 4);
    Image any(kViewPixels, kViewPixels, 4);
    for (int y = 0; y < fine.height; ++y)
        for (int x = 0; x < fine.width; ++x)
            if (fine.at(x, y)[3] > 0) any.at(x / kReferenceScale, y / kReferenceScale)[3] = 255;
    return silhouette(any);
}

/// The default impostor of \p species (seed 1, LOD0, \p grid × \p grid views; the default
/// 8 x 8 of 256-px cells sampled at mip level 1) against the tree from 16 random views of the
/// upper hemisphere: every view's IoU at least \p minIou; returns the worst and mean IoU.
std::pair<double, double> compareImpostor(const std::string& species, double minIou, int grid = 8) {
    const Species s = grow(species, 1);
    const mesh::Mesh lod0 = mesh::buildTreeMesh(*s.skeleton, s.settings);
    mesh::ImpostorSettings settings;
    EXPECT_EQ(settings.grid, 8); // the defaults
    EXPECT_EQ(settings.cellPixels, 256);
    settings.grid = grid;
    const mesh::Impostor imp =
        mipLevel1(mesh::bakeImpostor(lod0, mesh::ImpostorTextures(kTextures), settings));
    EXPECT_EQ(imp.color.width, grid * 128);
    EXPECT_EQ(imp.normal.channels, 3);
    EXPECT_EQ(imp.depth.channels, 1);
    const mesh::ImpostorTextures textures(kTextures);
    Rng rng(32);
    std::vector<glm::vec3> dirs;
    for (int v = 0; v < 16; ++v) {
        // Uniform on the upper hemisphere.
        const float y = rng.uniformf(0.0f, 1.0f), phi = rng.uniformf(0.0f, 6.2831853f);
        const float h = std::sqrt(1.0f - y * y);
        dirs.emplace_back(h * std::cos(phi), y, h * std::sin(phi));
    }
    // The references are the expensive part (32 x 32 samples a pixel): drawn in parallel.
    std::vector<test::Mask> references(dirs.size());
#pragma omp parallel for schedule(dynamic, 1)
    for (int v = 0; v < static_cast<int>(dirs.size()); ++v)
        references[static_cast<std::size_t>(v)] = treeSilhouette(lod0, textures, dirs[v], imp);
    double worstIou = 1.0, worstColour = 0.0, sumIou = 0.0, worstCoverage = 2.0, mostCoverage = 0.0;
    for (int v = 0; v < 16; ++v) {
        const glm::vec3 dir = dirs[static_cast<std::size_t>(v)];
        // The colour picture (4 x 4 samples a pixel), for the colour and the coverage.
        const Image truth = mesh::renderOrthographicView(lod0, textures, dir, imp.centre,
                                                         imp.radius, kViewPixels, 4);
        const Image drawn = mesh::renderImpostor(imp, dir, kViewPixels);
        if (const char* out = std::getenv("SYLVA_IMPOSTOR_PICTURES")) {
            const std::filesystem::path dirOut(out);
            std::filesystem::create_directories(dirOut);
            writePng(dirOut / ("view" + species + std::to_string(v) + "-tree.png"), truth);
            writePng(dirOut / ("view" + species + std::to_string(v) + "-impostor.png"), drawn);
            if (v == 0) writePng(dirOut / (species + "-atlas.png"), imp.color);
        }
        const test::Mask& truthMask = references[static_cast<std::size_t>(v)];
        const test::Mask drawnMask = silhouette(drawn);
        const double iou = test::iou(truthMask, drawnMask);
        // Where they differ: pixels only the tree covers (the impostor misses them) and pixels
        // only the impostor covers.
        const double inter =
            iou * static_cast<double>(truthMask.size() + drawnMask.size()) / (1.0 + iou);
        if (const char* out = std::getenv("SYLVA_IMPOSTOR_PICTURES")) {
            // Black where both cover, red where only the impostor does, blue only the tree.
            Image diffImage(kViewPixels, kViewPixels, 3);
            std::vector<std::uint8_t> in(static_cast<std::size_t>(kViewPixels) * kViewPixels, 0);
            for (std::uint32_t k : truthMask)
                in[k] |= 1;
            for (std::uint32_t k : drawnMask)
                in[k] |= 2;
            for (std::size_t k = 0; k < in.size(); ++k) {
                static const std::uint8_t kColours[4][3] = {
                    {255, 255, 255}, {0, 0, 255}, {255, 0, 0}, {0, 0, 0}};
                std::copy_n(kColours[in[k]], 3,
                            diffImage.at(static_cast<int>(k % kViewPixels),
                                         static_cast<int>(k / kViewPixels)));
            }
            writePng(std::filesystem::path(out) /
                         ("view" + species + std::to_string(v) + "-diff.png"),
                     diffImage);
        }
        const double missed = static_cast<double>(truthMask.size()) - inter;
        const double extra = static_cast<double>(drawnMask.size()) - inter;
        double diff = 0.0;
        glm::dvec3 meanT(0.0), meanD(0.0);
        std::size_t both = 0;
        for (int py = 0; py < kViewPixels; ++py)
            for (int px = 0; px < kViewPixels; ++px) {
                const std::uint8_t* a = truth.at(px, py);
                const std::uint8_t* b = drawn.at(px, py);
                if (a[3] == 0 || b[3] == 0) continue;
                ++both;
                for (int k = 0; k < 3; ++k) {
                    diff += std::abs(a[k] - b[k]) / 255.0 / 3.0;
                    meanT[k] += a[k] / 255.0;
                    meanD[k] += b[k] / 255.0;
                }
            }
        EXPECT_GT(both, 100u);
        // How much the impostor covers against the tree (the sum of coverage): an impostor
        // thinner than the tree lightens the crown where it takes over (an alpha test then
        // drops more of it).
        double coverTree = 0.0, coverDrawn = 0.0;
        for (int k = 0; k < kViewPixels * kViewPixels; ++k) {
            coverTree += truth.pixels[4 * static_cast<std::size_t>(k) + 3];
            coverDrawn += drawn.pixels[4 * static_cast<std::size_t>(k) + 3];
        }
        const double coverage = coverDrawn / coverTree;
        worstCoverage = std::min(worstCoverage, coverage);
        mostCoverage = std::max(mostCoverage, coverage);
        EXPECT_GE(coverage, kMinCoverage) << species << " view " << v;
        EXPECT_LE(coverage, kMaxCoverage) << species << " view " << v;
        diff /= static_cast<double>(both);
        const double meanDiff = glm::length(meanT - meanD) / static_cast<double>(both);
        std::cout << "view " << v << " (elevation " << std::asin(dir.y) * 180 / std::numbers::pi
                  << " deg): IoU " << iou << ", coverage " << coverage << ", colour difference "
                  << diff << ", mean colours apart " << meanDiff << " (" << truthMask.size()
                  << " px, missed " << missed << ", extra " << extra << ")\n";
        worstIou = std::min(worstIou, iou);
        worstColour = std::max(worstColour, diff);
        sumIou += iou;
        EXPECT_GE(iou, minIou) << species << " view " << v;
        EXPECT_LE(diff, kMaxColourDifference) << species << " view " << v;
    }
    std::cout << species << " impostor: IoU worst " << worstIou << ", mean " << sumIou / 16
              << "; worst colour difference " << worstColour << "; coverage " << worstCoverage
              << " to " << mostCoverage << "\n";
    return {worstIou, sumIou / 16};
}

} // namespace

// Issue #32's bar for every species of the library, on the default 8 x 8 atlas: every one of
// the 16 random views IoU >= 0.9, and their mean too. Worst / mean views measured: docs/lods.md.
class LibraryImpostor : public ::testing::TestWithParam<const char*> {};

TEST_P(LibraryImpostor, MatchesTheTreeInEveryView) {
    EXPECT_GE(compareImpostor(GetParam(), 0.9).second, 0.9) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(LodChain, LibraryImpostor,
                         ::testing::Values("english-oak", "silver-birch", "european-beech",
                                           "norway-maple", "weeping-willow", "lombardy-poplar",
                                           "scots-pine", "norway-spruce", "date-palm",
                                           "italian-cypress", "rhododendron", "privet-hedge"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             std::string name = info.param;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name;
                         });

// The alder's open crown of small leaves (not in the library) is speckle at 64 pixels: a leaf
// that turns out of view between two atlas views changes the mask. Held to 0.88 a view and 0.9
// on average (measured: docs/lods.md).
TEST(LodChain, SparseCrownImpostor) {
    EXPECT_GE(compareImpostor("alder", 0.88).second, 0.9);
}

TEST(LodChain, ImpostorIsTheSameOnAnyThreadCount) {
    const Species s = grow("alder", 3);
    const mesh::Mesh m = mesh::buildTreeMesh(*s.skeleton, s.settings);
    mesh::ImpostorSettings is;
    is.grid = 4;
    is.cellPixels = 32;
    const mesh::ImpostorTextures textures(kTextures);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const mesh::Impostor a = mesh::bakeImpostor(m, textures, is);
    omp_set_num_threads(2);
    const mesh::Impostor b = mesh::bakeImpostor(m, textures, is);
    omp_set_num_threads(threads);
    EXPECT_EQ(a.color.pixels, b.color.pixels);
    EXPECT_EQ(a.normal.pixels, b.normal.pixels);
    EXPECT_EQ(a.depth.pixels, b.depth.pixels);
    // The empty texels got the colour of their covered neighbours (no black fringe).
    std::size_t empty = 0, dark = 0;
    for (int y = 0; y < a.color.height; ++y)
        for (int x = 0; x < a.color.width; ++x) {
            const std::uint8_t* p = a.color.at(x, y);
            if (p[3] != 0) continue;
            ++empty;
            dark += p[0] + p[1] + p[2] == 0;
        }
    EXPECT_GT(empty, 0u);
    EXPECT_LT(dark, empty / 2);
}

// SYLVA_LOD_STRIP=<file.png>: the chain side by side, one row a species (english oak,
// rhododendron, scots pine, date palm; SYLVA_LOD_STRIP_SPECIES=a,b,... for others), each level at
// the same size (LOD0..LOD3, a blank where a level was dropped, then the impostor from the same
// direction and from 25 degrees around), to look at.
TEST(LodChain, StripPicture) {
    const char* out = std::getenv("SYLVA_LOD_STRIP");
    if (!out) GTEST_SKIP() << "SYLVA_LOD_STRIP not set";
    std::vector<std::string> species{"english-oak", "rhododendron", "scots-pine", "date-palm"};
    if (const char* list = std::getenv("SYLVA_LOD_STRIP_SPECIES")) {
        species.clear();
        std::stringstream in(list);
        for (std::string item; std::getline(in, item, ',');)
            species.push_back(item);
    }
    const mesh::ImpostorTextures textures(kTextures);
    const int px = 256, columns = 6;
    const glm::vec3 dir = glm::normalize(glm::vec3(0.3f, 0.25f, 1.0f));
    Image strip(px * columns, px * static_cast<int>(species.size()), 3);
    std::fill(strip.pixels.begin(), strip.pixels.end(), std::uint8_t{255});
    for (std::size_t row = 0; row < species.size(); ++row) {
        const Species s = grow(species[row], 1);
        // The CLI's default atlas (8 x 8 views of 256 px): the strip draws it at its cells' size.
        const mesh::LodChainSettings defaults;
        const mesh::BudgetLodChain chain = mesh::buildBudgetLodChain(
            *s.skeleton, s.settings, defaults, mesh::ImpostorTextures(kTextures));
        std::vector<Image> tiles(columns);
        // Levels by their budget's column (a dropped level leaves its column grey).
        for (const mesh::BudgetLevel& l : chain.levels) {
            const auto column = static_cast<std::size_t>(
                std::find(defaults.budgets.begin(), defaults.budgets.end(), l.budget) -
                defaults.budgets.begin());
            tiles[column] = mesh::renderOrthographicView(l.mesh, textures, dir, chain.centre,
                                                         chain.radius, px, 2);
        }
        tiles[4] = mesh::renderImpostor(*chain.impostor, dir, px);
        tiles[5] = mesh::renderImpostor(*chain.impostor,
                                        glm::normalize(glm::vec3(0.75f, 0.25f, 0.8f)), px);
        for (int k = 0; k < columns; ++k)
            for (int y = 0; y < px; ++y)
                for (int x = 0; x < px; ++x) {
                    std::uint8_t* q = strip.at(k * px + x, static_cast<int>(row) * px + y);
                    if (tiles[k].width != px) {
                        std::fill_n(q, 3, std::uint8_t{190});
                        continue;
                    }
                    const std::uint8_t* p = tiles[k].at(x, y);
                    // The mesh levels antialiased; the impostor as its shader draws it (an alpha
                    // test at 0.5, the glTF material's MASK).
                    float a = p[3] / 255.0f;
                    if (k >= 4) a = a >= 0.5f ? 1.0f : 0.0f;
                    for (int c = 0; c < 3; ++c) // over a pale sky
                        q[c] = static_cast<std::uint8_t>(p[c] * a + (c == 2 ? 235 : 215) * (1 - a));
                }
    }
    writePng(out, strip);
}

TEST(Image, PngRoundTrip) {
    Image image(5, 3, 4);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        image.pixels[i] = static_cast<std::uint8_t>(i * 7);
    const auto dir = std::filesystem::temp_directory_path() / "sylva_png_test";
    std::filesystem::create_directories(dir);
    writePng(dir / "a.png", image);
    const Image back = readPng(dir / "a.png");
    EXPECT_EQ(back.width, 5);
    EXPECT_EQ(back.height, 3);
    EXPECT_EQ(back.pixels, image.pixels);
    EXPECT_THROW(readPng(dir / "missing.png"), IoError);
    std::filesystem::remove_all(dir);
}

// Seen from exactly an atlas view's own direction the impostor is that view's picture: the
// march sinks through the whole sphere in one step there, and the fixed 0.2-radius shell once
// stepped over every surface (an empty picture, IoU 0).
TEST(LodChain, ImpostorFromAnAtlasViewIsThatView) {
    const Species s = grow("alder", 1);
    const mesh::Mesh lod0 = mesh::buildTreeMesh(*s.skeleton, s.settings);
    const mesh::ImpostorTextures textures(kTextures);
    const mesh::Impostor imp = mesh::bakeImpostor(lod0, textures, testChain().impostorSettings);
    for (glm::vec2 uv : {glm::vec2(1.0f, 1.0f / 7.0f), glm::vec2(3.0f / 7.0f, 4.0f / 7.0f)}) {
        const glm::vec3 dir = mesh::impostorViewDirection(uv, true);
        const Image truth = mesh::renderOrthographicView(lod0, textures, dir, imp.centre,
                                                         imp.radius, kViewPixels, 4);
        const Image drawn = mesh::renderImpostor(imp, dir, kViewPixels);
        const double iou = test::iou(silhouette(truth), silhouette(drawn));
        std::cout << "atlas view (" << uv.x << ", " << uv.y << "): IoU " << iou << "\n";
        EXPECT_GE(iou, 0.9);
    }
}
