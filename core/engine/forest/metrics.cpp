#include "engine/forest/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/constants.hpp>

#include "engine/util/error.h"

namespace sylva::forest {

double frustumVolume(double length, double r1, double r2) {
    return glm::pi<double>() * length / 3.0 * (r1 * r1 + r1 * r2 + r2 * r2);
}

double chaveAgb(double densityGcm3, double dbhCm, double heightM) {
    const double x = densityGcm3 * dbhCm * dbhCm * heightM;
    return x > 0.0 ? 0.0673 * std::pow(x, 0.976) : 0.0;
}

void SceneMetrics::add(const TreeMetrics& t) {
    const double n = static_cast<double>(trees);
    meanHeightM = (meanHeightM * n + t.heightM) / (n + 1.0);
    meanDbhM = (meanDbhM * n + t.dbhM) / (n + 1.0);
    meanCrownWidthM = (meanCrownWidthM * n + t.crownWidthM) / (n + 1.0);
    ++trees;
    woodVolumeM3 += t.woodVolumeM3;
    dryBiomassKg += t.dryBiomassKg;
    carbonKg += t.carbonKg;
    co2Kg += t.co2Kg;
    chaveAgbKg += t.chaveAgbKg;
}

SkeletonMeasure prepareMeasure(const skel::Skeleton& s) {
    s.validate();
    SkeletonMeasure m;
    if (s.empty()) return m;
    m.empty = false;
    const auto visible = [&s](std::size_t i) { return (s.flags[i] & skel::kHidden) == 0; };

    double ground = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.parent[i] < 0) ground = std::min(ground, static_cast<double>(s.position[i].y));
    double top = ground;
    glm::dvec2 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!visible(i)) continue;
        top = std::max(top, static_cast<double>(s.position[i].y));
        lo = glm::min(lo, glm::dvec2(s.position[i].x, s.position[i].z));
        hi = glm::max(hi, glm::dvec2(s.position[i].x, s.position[i].z));
    }
    m.ground = ground;
    m.height = top - ground;
    if (lo.x <= hi.x) m.crownWidth = 0.5 * ((hi.x - lo.x) + (hi.y - lo.y));
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s.parent[i] < 0 || !visible(i)) continue;
        const auto p = static_cast<std::size_t>(s.parent[i]);
        const double len = glm::length(glm::dvec3(s.position[i] - s.position[p]));
        m.volume += frustumVolume(len, s.radius[p], s.radius[i]);
        m.segments.push_back(
            {s.position[p].y, s.position[i].y, s.radius[p], s.radius[i], s.order[i]});
    }
    return m;
}

TreeMetrics measureTree(const SkeletonMeasure& s, const WoodProperties& wood, double scale) {
    requireRange("wood density (kg/m3)", wood.densityKgM3, 1e-6, 2000.0);
    requireRange("carbon fraction", wood.carbonFraction, 1e-6, 1.0);
    requireRange("scale", scale, 1e-9, 1e9);
    TreeMetrics m;
    if (s.empty) return m;
    m.heightM = s.height * scale;
    m.crownWidthM = s.crownWidth * scale;

    // Breast height in the skeleton's own units.
    const double breast = s.ground + 1.3 / scale;
    int bestOrder = std::numeric_limits<int>::max();
    double sumD2 = 0.0;
    for (const SkeletonMeasure::Segment& g : s.segments) {
        const double y1 = g.y1, y2 = g.y2;
        // Half-open so that a node exactly at breast height counts for one segment only.
        if (!(std::min(y1, y2) <= breast && breast < std::max(y1, y2))) continue;
        const double r1 = g.r1, r2 = g.r2;
        const double f = (breast - y1) / (y2 - y1);
        const double d = 2.0 * (r1 + f * (r2 - r1));
        const int order = g.order;
        if (order < bestOrder) {
            bestOrder = order;
            sumD2 = 0.0;
        }
        if (order == bestOrder) sumD2 += d * d;
    }
    m.dbhM = std::sqrt(sumD2) * scale;
    m.woodVolumeM3 = s.volume * (scale * scale * scale);
    m.dryBiomassKg = m.woodVolumeM3 * wood.densityKgM3;
    m.carbonKg = m.dryBiomassKg * wood.carbonFraction;
    m.co2Kg = m.carbonKg * 44.0 / 12.0;
    m.chaveAgbKg =
        m.dbhM > 0.0 ? chaveAgb(wood.densityKgM3 / 1000.0, m.dbhM * 100.0, m.heightM) : 0.0;
    return m;
}

TreeMetrics measureTree(const skel::Skeleton& s, const WoodProperties& wood, double scale) {
    requireRange("wood density (kg/m3)", wood.densityKgM3, 1e-6, 2000.0);
    requireRange("carbon fraction", wood.carbonFraction, 1e-6, 1.0);
    requireRange("scale", scale, 1e-9, 1e9);
    return measureTree(prepareMeasure(s), wood, scale);
}

} // namespace sylva::forest
