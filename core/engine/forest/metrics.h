#pragma once

#include <cstdint>
#include <vector>

#include "engine/skeleton/skeleton.h"

namespace sylva::forest {

/// Wood properties of a species.
struct WoodProperties {
    double densityKgM3 = 550.0;   ///< oven-dry wood density, kg/m³ (0.55 g/cm³), (0, 2000]
    double carbonFraction = 0.47; ///< carbon per dry mass, (0, 1]
};

/// Per-tree measurements. Hidden (pruned) segments do not count.
struct TreeMetrics {
    double heightM = 0.0;      ///< highest visible node above the lowest root, m
    double dbhM = 0.0;         ///< diameter at breast height (1.3 m above the root), m; 0 when
                               ///< the tree is shorter than 1.3 m
    double crownWidthM = 0.0;  ///< mean of the x and z extents of the visible nodes, m
    double woodVolumeM3 = 0.0; ///< sum of the frusta of the visible segments, m³
    double dryBiomassKg = 0.0; ///< woodVolume · density, kg
    double carbonKg = 0.0;     ///< dryBiomass · carbonFraction, kg
    double co2Kg = 0.0;        ///< carbon · 44/12, kg CO2-equivalent
    /// Chave et al. 2014 pantropical allometry, 0.0673 · (ρ D² H)^0.976 with ρ in g/cm³, D (DBH)
    /// in cm and H in m; kg. 0 when DBH is 0. An independent estimate beside dryBiomassKg.
    double chaveAgbKg = 0.0;
};

/// Sums over a scene (height, DBH and crown width are averaged, the rest summed).
struct SceneMetrics {
    std::size_t trees = 0;
    double meanHeightM = 0.0;
    double meanDbhM = 0.0;
    double meanCrownWidthM = 0.0;
    double woodVolumeM3 = 0.0;
    double dryBiomassKg = 0.0;
    double carbonKg = 0.0;
    double co2Kg = 0.0;
    double chaveAgbKg = 0.0;

    void add(const TreeMetrics& tree);
};

/// Measures a tree. \p scale is the tree's uniform world scale (Instance scale · growth): lengths
/// scale by it, volumes by its cube. The skeleton is in metres, Y up; breast height is measured
/// along Y from the lowest root. DBH is the diameter (2·radius, interpolated along the segment)
/// of the lowest-order visible segments crossing breast height; several stems of that order
/// (a fork below 1.3 m) combine as sqrt(Σ d²), the forestry convention for multi-stem trees.
/// \throw InvalidInput for an invalid skeleton or properties out of range.
TreeMetrics measureTree(const skel::Skeleton& skeleton, const WoodProperties& wood = {},
                        double scale = 1.0);

/// What measureTree needs of a skeleton, taken once, so that the instances of one variant (a
/// forest measures every tree, 9 in 10 of them instances) are measured at their own scale
/// without walking and checking the skeleton again: the same numbers, bit for bit.
struct SkeletonMeasure {
    bool empty = true;
    double height = 0.0, crownWidth = 0.0; ///< at scale 1
    double volume = 0.0;                   ///< the visible frusta at scale 1, m³
    double ground = 0.0;                   ///< the lowest root's y
    /// The visible segments' ends (parent first), in node order, for the DBH at any scale.
    struct Segment {
        float y1, y2, r1, r2;
        std::uint16_t order;
    };
    std::vector<Segment> segments;
};
/// \throw InvalidInput for an invalid skeleton.
SkeletonMeasure prepareMeasure(const skel::Skeleton& skeleton);
/// measureTree(skeleton, wood, scale) from prepareMeasure(skeleton).
TreeMetrics measureTree(const SkeletonMeasure& measure, const WoodProperties& wood = {},
                        double scale = 1.0);

/// The frustum volume π·h/3·(r1² + r1·r2 + r2²), m³ (a cylinder when r1 == r2).
double frustumVolume(double length, double r1, double r2);

/// Chave et al. 2014: 0.0673 · (ρ D² H)^0.976, ρ in g/cm³, D in cm, H in m, result in kg.
double chaveAgb(double densityGcm3, double dbhCm, double heightM);

} // namespace sylva::forest
