// The species library (issue #20): every preset named after a real species grows leaves and
// carries its own bark and leaf textures, and its seed varies the tree; every other preset
// that stands for a leafy plant has leaves too.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <set>
#include <string>

#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "presetfile.h"

using namespace sylva;

namespace {

const std::filesystem::path kPresets = SYLVA_PRESETS_DIR;

// The library: at least twelve real species, each with foliage and textures of its own.
const std::array<const char*, 12> kLibrary = {
    "english-oak",    "silver-birch",    "european-beech", "norway-maple",
    "weeping-willow", "lombardy-poplar", "scots-pine",     "norway-spruce",
    "date-palm",      "italian-cypress", "rhododendron",   "privet-hedge"};

// Presets that are structures rather than plants with foliage: the L-system figures of ABOP
// and the space-colonization skeleton demos (their species would have leaves, but they show
// the branching alone on purpose).
const std::set<std::string> kBare = {"abop-1.24a",           "abop-1.24b",   "abop-1.24c",
                                     "abop-1.24d",           "abop-1.24e",   "abop-1.24f",
                                     "abop-1.27-stochastic", "ternary-tree", "sc-round",
                                     "sc-columnar",          "sc-umbrella",  "sc-lsystem-trunk"};

struct Grown {
    std::size_t leafTriangles = 0, barkTriangles = 0;
    std::set<std::string> barkTextures, leafTextures;
    double height = 0.0;
    double xSum = 0.0; ///< sums of coordinates: a fingerprint of the shape
};

Grown grow(const std::filesystem::path& preset, std::uint64_t seed) {
    graph::registerBuiltinNodeTypes();
    graph::Evaluator evaluator(sylva::testing::loadPreset(preset));
    const graph::NodeOutput& out = evaluator.evaluate(seed);
    Grown g;
    EXPECT_TRUE(out.mesh) << preset;
    if (!out.mesh) return g;
    for (const mesh::Submesh& s : out.mesh->submeshes) {
        if (s.material == "leaf") {
            g.leafTriangles += s.indexCount / 3;
            g.leafTextures.insert(s.texture);
        } else if (s.material == "bark") {
            g.barkTriangles += s.indexCount / 3;
            g.barkTextures.insert(s.texture);
        }
    }
    for (const glm::vec3& p : out.mesh->positions) {
        g.height = std::max(g.height, static_cast<double>(p.y));
        g.xSum += p.x;
    }
    return g;
}

} // namespace

TEST(SpeciesLibrary, EverySpeciesHasFoliageAndItsOwnTexturesAndVariesBySeed) {
    std::set<std::string> barks, leaves;
    for (const char* species : kLibrary) {
        const std::filesystem::path file = kPresets / (std::string(species) + ".json");
        ASSERT_TRUE(std::filesystem::exists(file)) << file;
        const Grown a = grow(file, 1), b = grow(file, 2);
        EXPECT_GT(a.barkTriangles, 0u) << species;
        // Foliage that reads as a crown, not a few stray cards (the palm's 30 fronds are 60
        // cards; every other species has thousands).
        EXPECT_GE(a.leafTriangles, 100u) << species;
        ASSERT_EQ(a.barkTextures.size(), 1u) << species;
        ASSERT_EQ(a.leafTextures.size(), 1u) << species;
        const std::filesystem::path bark = *a.barkTextures.begin(), leaf = *a.leafTextures.begin();
        EXPECT_TRUE(std::filesystem::exists(bark)) << species << ": " << bark;
        EXPECT_TRUE(std::filesystem::exists(leaf)) << species << ": " << leaf;
        EXPECT_NE(bark.filename().string().find(species), std::string::npos) << bark;
        EXPECT_NE(leaf.filename().string().find(species), std::string::npos) << leaf;
        barks.insert(bark.filename().string());
        leaves.insert(leaf.filename().string());
        // Another seed, another tree of the same species.
        EXPECT_NE(a.xSum, b.xSum) << species << ": seeds 1 and 2 grow the same tree";
        EXPECT_GT(b.leafTriangles, 0u) << species;
        EXPECT_NEAR(b.height, a.height, 0.35 * a.height) << species;
    }
    EXPECT_EQ(barks.size(), kLibrary.size());
    EXPECT_EQ(leaves.size(), kLibrary.size());
}

TEST(SpeciesLibrary, EveryPresetOfALeafyPlantHasLeaves) {
    std::size_t leafy = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kPresets)) {
        if (entry.path().extension() != ".json") continue;
        const std::string name = entry.path().stem().string();
        if (kBare.count(name)) continue;
        EXPECT_GT(grow(entry.path(), 7).leafTriangles, 0u) << name << " has no leaves";
        ++leafy;
    }
    EXPECT_GE(leafy, kLibrary.size() + 1); // the library and the alder at least
}
