// Every preset grammar parses, derives and gives a plant of plausible size in metres.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/lsystem/turtle.h"
#include "lsystemtest.h"

using namespace sylva;
using namespace sylva::lsys;
using namespace sylva::lsys::test;

namespace {

const std::filesystem::path kGrammarDir = std::filesystem::path(SYLVA_PRESETS_DIR) / "lsystem";

Grammar load(const std::string& name) {
    std::ifstream in(kGrammarDir / name);
    EXPECT_TRUE(in.good()) << name;
    std::stringstream ss;
    ss << in.rdbuf();
    return parseGrammar(ss.str(), name);
}

struct Preset {
    const char* file;
    double minHeight; ///< metres
    double maxHeight;
    std::size_t expectedF; ///< 0: not checked (stochastic or parametric)
};

// F counts: 1.24a/b: 5 F per F -> 5^5; 1.24c: 8 F per F -> 8^4; the node-rewriting ones follow
// f' = 2f + kx, x' = mx from f = 0, x = 1 (d, e: k = 2, m = 3; f: k = 3, m = 4).
std::size_t nodeRewritingF(int n, std::size_t k, std::size_t m) {
    std::size_t f = 0, x = 1;
    for (int i = 0; i < n; ++i) {
        f = 2 * f + k * x;
        x *= m;
    }
    return f;
}

const Preset kPresets[] = {
    {"abop-1.24a.lsys", 1.0, 3.0, 3125},
    {"abop-1.24b.lsys", 1.0, 3.0, 3125},
    {"abop-1.24c.lsys", 1.0, 6.0, 4096},
    {"abop-1.24d.lsys", 1.0, 4.0, nodeRewritingF(7, 2, 3)},
    {"abop-1.24e.lsys", 1.0, 4.0, nodeRewritingF(7, 2, 3)},
    {"abop-1.24f.lsys", 1.0, 5.0, nodeRewritingF(5, 3, 4)},
    {"abop-1.27-stochastic.lsys", 0.5, 3.0, 0},
    {"ternary-tree.lsys", 8.0, 20.0, 0},
    {"alder.lsys", 15.0, 21.0, 0},
    {"norway-spruce.lsys", 10.0, 18.0, 0},
    {"scots-pine.lsys", 11.0, 18.0, 0},
    {"weeping-willow.lsys", 5.0, 11.0, 0},
};

} // namespace

TEST(Presets, EveryGrammarFileParsesAndDerives) {
    // Also covers grammar files that other presets (e.g. space-colonization trunks) keep here.
    std::size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(kGrammarDir)) {
        if (e.path().extension() != ".lsys") continue;
        ++files;
        SCOPED_TRACE(e.path().string());
        const Grammar g = load(e.path().filename().string());
        const ModuleString w = derive(g);
        EXPECT_GT(w.size(), 0u);
        EXPECT_EQ(countOf(w.symbols, '['), countOf(w.symbols, ']'));
    }
    EXPECT_GE(files, std::size(kPresets));
}

TEST(Presets, DeriveAndInterpretToPlausiblePlants) {
    for (const Preset& p : kPresets) {
        SCOPED_TRACE(p.file);
        const Grammar g = load(p.file);
        for (std::uint64_t seed : {g.seed, g.seed + 1, g.seed + 2}) {
            const ModuleString w = derive(g, options(std::nullopt, seed));
            EXPECT_GT(w.size(), 1000u);
            EXPECT_LT(w.size(), 500'000u);
            EXPECT_EQ(countOf(w.symbols, '['), countOf(w.symbols, ']'));
            for (double v : w.params)
                ASSERT_TRUE(std::isfinite(v));
            if (p.expectedF) {
                EXPECT_EQ(countOf(w.symbols, 'F'), p.expectedF);
            }

            TurtleSettings t;
            t.angleDegrees = g.angleDegrees;
            t.step = g.step;
            t.width = g.width;
            t.widthFactor = g.widthFactor;
            const skel::Skeleton s = interpret(w, t);
            glm::vec3 lo, hi;
            s.bounds(lo, hi);
            EXPECT_GE(hi.y - lo.y, p.minHeight);
            EXPECT_LE(hi.y - lo.y, p.maxHeight);
            // Tapering: the thickest node is the root, and twigs are thinner than it.
            ASSERT_FALSE(s.radius.empty());
            float thinnest = s.radius[0];
            for (float r : s.radius) {
                EXPECT_LE(r, s.radius[0] + 1e-6f);
                thinnest = std::min(thinnest, r);
            }
            EXPECT_LT(thinnest, 0.5f * s.radius[0]);
            if (!p.expectedF) continue;
            break; // deterministic: one seed is enough
        }
    }
}

TEST(Presets, EveryGrammarHasASpeciesFile) {
    for (const Preset& p : kPresets) {
        const std::string stem = std::filesystem::path(p.file).stem().string();
        const std::filesystem::path species =
            std::filesystem::path(SYLVA_PRESETS_DIR) / (stem + ".json");
        std::ifstream in(species);
        ASSERT_TRUE(in.good()) << species;
        std::stringstream ss;
        ss << in.rdbuf();
        EXPECT_NE(ss.str().find("\"lsystem/" + std::string(p.file) + "\""), std::string::npos)
            << species;
    }
}
