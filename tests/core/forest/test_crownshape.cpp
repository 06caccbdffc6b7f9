// Issue #33: crowns that read as real trees. Each broadleaf of the species library is grown at
// seeds 1-3 and seen from two sides (0 and 90 degrees) by the CPU rasterizer; the crown rows'
// silhouette must not be a blob (solidity <= kMaxSolidity, the mean of both views) and each
// species keeps its habit. SYLVA_CROWN_PICTURES=<folder> writes the silhouettes as PGM files.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "crownshape.h"
#include "engine/graph/graph.h"
#include "presetfile.h"

using namespace sylva;

namespace {

const std::filesystem::path kPresets = SYLVA_PRESETS_DIR;
constexpr int kPixelsTall = 320;
// The target (ez-tree's oak and ash measure 0.79 and 0.81; our ellipsoid-filling crowns
// measured 0.89-0.94 before they were grown by light).
constexpr double kMaxSolidity = 0.85;
// Covered fraction of the crown's middle, seen from the side (crownshape.h's middleCover).
constexpr double kMinMiddleCover = 0.6;

struct Measured {
    double solidity = 0.0, width = 0.0, height = 0.0, treeHeight = 0.0, crownBase = 0.0,
           widestAt = 0.0, middleCover = 0.0;
};

void writePgm(const test::Silhouette& s, const std::filesystem::path& file) {
    std::ofstream out(file, std::ios::binary);
    out << "P5\n" << s.width << " " << s.height << "\n255\n";
    for (std::size_t k = 0; k < s.any.size(); ++k)
        out.put(static_cast<char>(s.leaf[k] ? 40 : (s.any[k] ? 110 : 255)));
}

Measured measure(const std::string& species, std::uint64_t seed) {
    graph::registerBuiltinNodeTypes();
    graph::Evaluator evaluator(sylva::testing::loadPreset(kPresets / (species + ".json")));
    const graph::NodeOutput& out = evaluator.evaluate(seed);
    Measured m;
    EXPECT_TRUE(out.mesh) << species;
    if (!out.mesh) return m;
    for (float yaw : {0.0f, 90.0f}) {
        const test::Silhouette s = test::sideSilhouette(*out.mesh, kPixelsTall, yaw);
        if (const char* dir = std::getenv("SYLVA_CROWN_PICTURES"))
            writePgm(s,
                     std::filesystem::path(dir) / (species + "-" + std::to_string(seed) + "-" +
                                                   std::to_string(static_cast<int>(yaw)) + ".pgm"));
        const test::CrownShape c = test::crownShape(s);
        m.solidity += 0.5 * c.solidity;
        m.width += 0.5 * c.width;
        m.height += 0.5 * c.height;
        m.treeHeight += 0.5 * c.treeHeight;
        m.crownBase += 0.5 * c.crownBase;
        m.widestAt += 0.5 * c.widestAt;
        m.middleCover += 0.5 * c.middleCover;
    }
    return m;
}

} // namespace

TEST(CrownShape, SolidityOfABlobIsOneAndOfACrossIsLess) {
    test::Silhouette s;
    s.width = s.height = 40;
    s.metresPerPixel = 0.1;
    s.any.assign(1600, 0);
    s.leaf.assign(1600, 0);
    for (int y = 5; y < 35; ++y)
        for (int x = 5; x < 35; ++x)
            s.any[y * 40 + x] = s.leaf[y * 40 + x] = 1;
    EXPECT_NEAR(test::crownShape(s).solidity, 1.0, 1e-9);
    EXPECT_NEAR(test::crownShape(s).width, 3.0, 1e-9);
    // A plus sign: arms 10 wide in a 30 x 30 square: 500 / 900 of a square hull, and the hull
    // is the octagon through the arm ends (900 - 4 * 50 = 700).
    for (int y = 5; y < 35; ++y)
        for (int x = 5; x < 35; ++x)
            if ((x < 15 || x >= 25) && (y < 15 || y >= 25))
                s.any[y * 40 + x] = s.leaf[y * 40 + x] = 0;
    EXPECT_NEAR(test::crownShape(s).solidity, 500.0 / 700.0, 0.02);
}

// Broadleaves grown by light: lumps and gaps in the outline, each species' habit kept.
TEST(CrownShape, BroadleavesAreNotBlobsAndKeepTheirHabit) {
    const std::array<const char*, 6> broadleaves = {"english-oak",     "european-beech",
                                                    "norway-maple",    "silver-birch",
                                                    "lombardy-poplar", "weeping-willow"};
    std::printf("| species | seed | solidity | crown width (m) | crown height (m) | tree height "
                "(m) | crown base (m) | middle cover |\n|---|---|---|---|---|---|---|---|\n");
    for (const char* species : broadleaves) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            const Measured m = measure(species, seed);
            std::printf("| %s | %d | %.3f | %.1f | %.1f | %.1f | %.1f | %.2f |\n", species,
                        static_cast<int>(seed), m.solidity, m.width, m.height, m.treeHeight,
                        m.crownBase, m.middleCover);
            std::fflush(stdout);
            const std::string sp = species;
            EXPECT_LE(m.solidity, kMaxSolidity) << sp << " seed " << seed << " reads as a blob";
            // Not a ring round an empty middle either (the light-grown maple, birch and beech
            // measured 0.43-0.73 before their inner clusters; a blob is about 0.95).
            if (sp == "norway-maple" || sp == "silver-birch" || sp == "european-beech") {
                EXPECT_GE(m.middleCover, kMinMiddleCover) << sp << " seed " << seed << " is hollow";
            }
            if (sp == "english-oak") { // wider than tall, low limbs
                EXPECT_GT(m.width, 1.3 * m.height) << sp << " seed " << seed;
                EXPECT_LT(m.crownBase, 0.3 * m.treeHeight) << sp << " seed " << seed;
            } else if (sp == "silver-birch") { // narrow
                EXPECT_LT(m.width, 0.75 * m.height) << sp << " seed " << seed;
            } else if (sp == "european-beech") { // a tall dome on a clear bole
                EXPECT_GT(m.height, 0.9 * m.width) << sp << " seed " << seed;
                EXPECT_GT(m.treeHeight, 13.0) << sp << " seed " << seed;
            } else if (sp == "lombardy-poplar") { // a column
                EXPECT_LT(m.width, 0.3 * m.height) << sp << " seed " << seed;
            } else if (sp == "weeping-willow") { // a curtain down to near the ground
                EXPECT_LT(m.crownBase, 0.15 * m.treeHeight) << sp << " seed " << seed;
                EXPECT_GT(m.width, m.height) << sp << " seed " << seed;
            } else if (sp == "norway-maple") { // round
                EXPECT_NEAR(m.width / m.height, 1.05, 0.25) << sp << " seed " << seed;
            }
        }
    }
}
