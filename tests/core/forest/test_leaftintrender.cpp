// Issue #33: leaf cards of one species differ in colour. A library species is rendered by the
// engine's CPU rasteriser (the impostor bake's, which applies Mesh::colors) from the side, its
// leaves in one plain leaf green so that what varies between pixels is only the cards' tint:
// the hue's spread across the crown must be clearly above zero with the preset's variation and
// zero with it set to 0; with the species' own textures, the crown's leaves must stay
// within 15 % of their brightness without it. Prints the figures (docs/geometry.md, "Leaf
// colour variation").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "engine/graph/graph.h"
#include "engine/mesh/impostor.h"
#include "presetfile.h"

using namespace sylva;

namespace {

const std::filesystem::path kPresets = SYLVA_PRESETS_DIR;

struct Spread {
    double hue = 0.0;   ///< std dev of the leaf pixels' hue, degrees
    double value = 0.0; ///< std dev of their HSV value, 0..1
    double meanValue = 0.0;
    std::size_t pixels = 0;
};

Spread measure(const Image& img, const mesh::Mesh& m, bool plain) {
    (void)m;
    double sh = 0, sh2 = 0, sv = 0, sv2 = 0;
    std::size_t n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.at(x, y);
            if (p[3] < 255) continue; // edges mix with the background
            const double r = p[0] / 255.0, g = p[1] / 255.0, b = p[2] / 255.0;
            // Leaf pixels: green dominant (plain) or anything not the bark's grey-brown.
            const double mx = std::max({r, g, b}), mn = std::min({r, g, b});
            if (mx - mn < 0.04 || (plain && g < r)) continue;
            double h;
            if (mx == r)
                h = 60.0 * std::fmod((g - b) / (mx - mn) + 6.0, 6.0);
            else if (mx == g)
                h = 60.0 * ((b - r) / (mx - mn) + 2.0);
            else
                h = 60.0 * ((r - g) / (mx - mn) + 4.0);
            sh += h;
            sh2 += h * h;
            sv += mx;
            sv2 += mx * mx;
            ++n;
        }
    Spread s;
    s.pixels = n;
    if (n == 0) return s;
    const double dn = static_cast<double>(n);
    s.hue = std::sqrt(std::max(0.0, sh2 / dn - (sh / dn) * (sh / dn)));
    s.value = std::sqrt(std::max(0.0, sv2 / dn - (sv / dn) * (sv / dn)));
    s.meanValue = sv / dn;
    return s;
}

struct Rendered {
    Spread tinted, untinted;
};

Rendered render(const char* species, const char* season, bool plain) {
    graph::SpeciesGraph g = sylva::testing::loadPreset(kPresets / (std::string(species) + ".json"));
    std::string meshNode;
    for (const graph::NodeDesc& n : g.nodes)
        if (n.type == "tube_mesh") meshNode = n.id;
    graph::Evaluator with(g);
    with.setParam(meshNode, "season", Value(std::string(season)));
    const std::shared_ptr<const mesh::Mesh> a = with.evaluate(1).mesh;
    graph::Evaluator without(g);
    without.setParam(meshNode, "season", Value(std::string(season)));
    for (const char* key :
         {"leaf_hue_variation", "leaf_saturation_variation", "leaf_brightness_variation",
          "leaf_autumn_hue_variation", "leaf_autumn_saturation_variation",
          "leaf_autumn_brightness_variation", "leaf_light_shading"})
        without.setParam(meshNode, key, Value(0.0));
    const std::shared_ptr<const mesh::Mesh> b = without.evaluate(1).mesh;
    EXPECT_TRUE(a && b);
    if (!a || !b) return {};
    EXPECT_EQ(a->colors.size(), a->positions.size());
    EXPECT_TRUE(b->colors.empty());
    const mesh::ImpostorTextures textures(kPresets.parent_path() / "resources" / "textures");
    const mesh::ImpostorMaterials materials = [&](const mesh::Submesh& s) {
        if (!plain) return textures(s);
        mesh::ImpostorMaterial m;
        m.colour = s.material == "leaf" ? glm::vec3(0.26f, 0.40f, 0.12f) : glm::vec3(0.4f);
        return m;
    };
    glm::vec3 centre;
    float radius;
    mesh::boundingSphere(*a, centre, radius);
    Rendered r;
    const glm::vec3 side(0, 0, -1);
    r.tinted = measure(mesh::renderOrthographicView(*a, materials, side, centre, radius, 320, 1),
                       *a, plain);
    r.untinted = measure(mesh::renderOrthographicView(*b, materials, side, centre, radius, 320, 1),
                         *b, plain);
    return r;
}

} // namespace

TEST(LeafTintRender, PlainLeavesShowOnlyTheCardsTint) {
    for (const char* season : {"summer", "autumn"})
        for (const char* species : {"english-oak", "european-beech", "norway-maple"}) {
            const Rendered r = render(species, season, true);
            std::printf("%s plain, %s: hue spread %.2f° (%.2f° without), value spread %.3f "
                        "(%.3f), %zu leaf pixels\n",
                        species, season, r.tinted.hue, r.untinted.hue, r.tinted.value,
                        r.untinted.value, r.tinted.pixels);
            EXPECT_GT(r.tinted.pixels, 5000u) << species;
            EXPECT_GT(r.tinted.hue, 1.5) << species << " " << season;
            EXPECT_GT(r.tinted.value, 0.01) << species << " " << season;
            EXPECT_LT(r.untinted.hue, 0.05) << species << " " << season;
            EXPECT_LT(r.untinted.value, 0.002) << species << " " << season;
        }
}

// The cost of a multiplier that cannot brighten: the textured crown's leaves are darker on
// average. Bounded so that a change of the spread's shape cannot quietly darken the library.
// Issue #44 lowered the bound from 0.85 to 0.8 on purpose: leaf_light_shading darkens the
// shaded half of the cards, the crown's underside included (measured ×0.84–0.91).
TEST(LeafTintRender, TexturedCrownsStayNearTheirBrightness) {
    for (const char* season : {"summer", "autumn"})
        for (const char* species : {"english-oak", "european-beech", "norway-maple"}) {
            const Rendered r = render(species, season, false);
            const double ratio = r.tinted.meanValue / r.untinted.meanValue;
            std::printf("%s textured, %s: mean value %.3f (%.3f without, x%.3f), hue spread "
                        "%.2f° (%.2f°)\n",
                        species, season, r.tinted.meanValue, r.untinted.meanValue, ratio,
                        r.tinted.hue, r.untinted.hue);
            EXPECT_GT(ratio, 0.8) << species << " " << season;
            EXPECT_LT(ratio, 1.0) << species << " " << season;
        }
}
