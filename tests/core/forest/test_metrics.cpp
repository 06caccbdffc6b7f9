#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/constants.hpp>

#include "engine/forest/metrics.h"
#include "engine/util/error.h"

using namespace sylva;
using namespace sylva::forest;

namespace {

/// A straight vertical stem from y = 0 to y = height in \p n segments, radius linear from r0 to
/// r1.
skel::Skeleton stem(double height, int n, float r0, float r1) {
    skel::Skeleton s;
    for (int i = 0; i <= n; ++i) {
        const float f = static_cast<float>(i) / static_cast<float>(n);
        s.addNode(glm::vec3(0, static_cast<float>(height) * f, 0), i - 1, r0 + (r1 - r0) * f, 0,
                  glm::quat(1, 0, 0, 0));
    }
    return s;
}

} // namespace

TEST(Metrics, CylinderTrunkByHand) {
    const skel::Skeleton s = stem(10.0, 4, 0.2f, 0.2f);
    const TreeMetrics m = measureTree(s);
    const double pi = glm::pi<double>();
    EXPECT_NEAR(m.heightM, 10.0, 1e-6);
    EXPECT_NEAR(m.dbhM, 0.4, 1e-6);
    EXPECT_NEAR(m.crownWidthM, 0.0, 1e-9);
    const double v = pi * 0.2 * 0.2 * 10.0;
    EXPECT_NEAR(m.woodVolumeM3, v, 1e-6);
    EXPECT_NEAR(m.dryBiomassKg, v * 550.0, 1e-3);
    EXPECT_NEAR(m.carbonKg, v * 550.0 * 0.47, 1e-3);
    EXPECT_NEAR(m.co2Kg, v * 550.0 * 0.47 * 44.0 / 12.0, 1e-3);
    // Chave et al. 2014 with ρ = 0.55 g/cm³, D = 40 cm, H = 10 m.
    // (The radius is a float: 0.2f is 0.2 to 7 digits, hence the relative tolerance.)
    const double chave = 0.0673 * std::pow(0.55 * 40.0 * 40.0 * 10.0, 0.976);
    EXPECT_NEAR(m.chaveAgbKg, chave, 1e-6 * chave);
    EXPECT_NEAR(chaveAgb(0.55, 40.0, 10.0), chave, 1e-9);
}

TEST(Metrics, TaperedTrunkUsesFrustaAndInterpolatesDbh) {
    const skel::Skeleton s = stem(13.0, 1, 0.3f, 0.1f);
    const TreeMetrics m = measureTree(s, WoodProperties{600.0, 0.5});
    EXPECT_NEAR(m.dbhM, 2.0 * (0.3 - 0.2 * 0.1), 1e-6); // 1.3 m is a tenth of the way up
    const double v = glm::pi<double>() * 13.0 / 3.0 * (0.09 + 0.03 + 0.01);
    EXPECT_NEAR(m.woodVolumeM3, v, 1e-6);
    EXPECT_NEAR(frustumVolume(13.0, 0.3, 0.1), v, 1e-12);
    EXPECT_NEAR(m.carbonKg, v * 600.0 * 0.5, 1e-3);
}

TEST(Metrics, ScaleHiddenBranchesForksAndShortTrees) {
    skel::Skeleton s = stem(10.0, 4, 0.2f, 0.2f);
    // Scale 2: twice as tall, eight times the volume, breast height at 0.65 m of the skeleton.
    const TreeMetrics scaled = measureTree(s, {}, 2.0);
    EXPECT_NEAR(scaled.heightM, 20.0, 1e-5);
    EXPECT_NEAR(scaled.dbhM, 0.8, 1e-6);
    EXPECT_NEAR(scaled.woodVolumeM3, 8.0 * glm::pi<double>() * 0.04 * 10.0, 1e-5);

    // A hidden side branch counts for nothing.
    const std::int32_t b = s.addNode(glm::vec3(3, 5, 0), 2, 0.1f, 1, glm::quat(1, 0, 0, 0));
    const TreeMetrics withBranch = measureTree(s);
    EXPECT_GT(withBranch.woodVolumeM3, glm::pi<double>() * 0.04 * 10.0 + 1e-3);
    EXPECT_NEAR(withBranch.crownWidthM, 1.5, 1e-6); // x extent 3, z extent 0
    s.flags[static_cast<std::size_t>(b)] |= skel::kHidden;
    const TreeMetrics hiddenBranch = measureTree(s);
    EXPECT_NEAR(hiddenBranch.woodVolumeM3, glm::pi<double>() * 0.04 * 10.0, 1e-6);
    EXPECT_NEAR(hiddenBranch.crownWidthM, 0.0, 1e-9);

    // Two stems forking at 1 m: DBH = sqrt(d1² + d2²).
    skel::Skeleton fork;
    fork.addNode(glm::vec3(0), -1, 0.2f, 0, glm::quat(1, 0, 0, 0));
    fork.addNode(glm::vec3(0, 1, 0), 0, 0.2f, 0, glm::quat(1, 0, 0, 0));
    fork.addNode(glm::vec3(-1, 3, 0), 1, 0.1f, 0, glm::quat(1, 0, 0, 0));
    fork.addNode(glm::vec3(1, 3, 0), 1, 0.15f, 0, glm::quat(1, 0, 0, 0));
    const TreeMetrics f = measureTree(fork);
    const double d1 = 2.0 * (0.2 - 0.1 * 0.15), d2 = 2.0 * (0.2 - 0.05 * 0.15);
    EXPECT_NEAR(f.dbhM, std::sqrt(d1 * d1 + d2 * d2), 1e-6);
    EXPECT_NEAR(f.heightM, 3.0, 1e-6);
    EXPECT_NEAR(f.crownWidthM, 1.0, 1e-6);

    // Shorter than breast height: no DBH, no allometric biomass, but wood volume.
    const TreeMetrics sapling = measureTree(stem(1.0, 2, 0.02f, 0.01f));
    EXPECT_EQ(sapling.dbhM, 0.0);
    EXPECT_EQ(sapling.chaveAgbKg, 0.0);
    EXPECT_GT(sapling.woodVolumeM3, 0.0);
}

TEST(Metrics, SceneSumsAndMeans) {
    SceneMetrics scene;
    const TreeMetrics a = measureTree(stem(10.0, 2, 0.2f, 0.2f));
    const TreeMetrics b = measureTree(stem(20.0, 2, 0.3f, 0.1f));
    scene.add(a);
    scene.add(b);
    EXPECT_EQ(scene.trees, 2u);
    EXPECT_NEAR(scene.meanHeightM, 15.0, 1e-6);
    EXPECT_NEAR(scene.meanDbhM, 0.5 * (a.dbhM + b.dbhM), 1e-9);
    EXPECT_NEAR(scene.woodVolumeM3, a.woodVolumeM3 + b.woodVolumeM3, 1e-9);
    EXPECT_NEAR(scene.co2Kg, a.co2Kg + b.co2Kg, 1e-6);
    EXPECT_NEAR(scene.chaveAgbKg, a.chaveAgbKg + b.chaveAgbKg, 1e-6);
}

TEST(Metrics, BadInputsGetTheirMessages) {
    const skel::Skeleton s = stem(10.0, 2, 0.2f, 0.2f);
    try {
        measureTree(s, WoodProperties{0.0, 0.47});
        ADD_FAILURE();
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("wood density"), std::string::npos);
    }
    EXPECT_THROW(measureTree(s, WoodProperties{550.0, 1.5}), InvalidInput);
    EXPECT_THROW(measureTree(s, {}, 0.0), InvalidInput);
    EXPECT_EQ(measureTree(skel::Skeleton{}).heightM, 0.0);
}

// A forest measures each instance of a variant at its own scale from one prepared measure
// (issue 30): the same numbers, bit for bit, as measuring the skeleton each time.
TEST(Metrics, OnePreparedMeasureServesEveryScale) {
    skel::Skeleton s = stem(10.0, 5, 0.3f, 0.05f);
    const std::int32_t b = s.addNode(glm::vec3(2, 4, 1), 2, 0.08f, 1, glm::quat(1, 0, 0, 0));
    s.addNode(glm::vec3(-2, 6, 0), 3, 0.06f, 1, glm::quat(1, 0, 0, 0));
    s.flags[static_cast<std::size_t>(b)] |= skel::kHidden;
    const SkeletonMeasure measure = prepareMeasure(s);
    EXPECT_EQ(measure.segments.size(), 6u) << "the hidden segment is left out";
    const WoodProperties oak{700.0, 0.5};
    for (double scale : {0.1, 0.37, 1.0, 1.05, 2.0}) {
        const TreeMetrics a = measureTree(measure, oak, scale), b2 = measureTree(s, oak, scale);
        EXPECT_EQ(a.heightM, b2.heightM) << scale;
        EXPECT_EQ(a.dbhM, b2.dbhM) << scale;
        EXPECT_EQ(a.crownWidthM, b2.crownWidthM) << scale;
        EXPECT_EQ(a.woodVolumeM3, b2.woodVolumeM3) << scale;
        EXPECT_EQ(a.co2Kg, b2.co2Kg) << scale;
        EXPECT_EQ(a.chaveAgbKg, b2.chaveAgbKg) << scale;
    }
    EXPECT_EQ(measureTree(measure, oak, 0.1).dbhM, 0.0) << "1 m tall: no breast height";
    EXPECT_GT(measureTree(measure, oak, 1.0).dbhM, 0.0);
    EXPECT_THROW(measureTree(measure, oak, 0.0), InvalidInput);
}
