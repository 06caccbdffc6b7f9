#include "engine/mesh/lodchain.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "engine/mesh/silhouette.h"
#include "engine/util/error.h"

namespace sylva::mesh {

void validateLodChain(const LodChainSettings& s) {
    if (s.budgets.empty()) throw InvalidInput("LOD budgets must not be empty");
    if (s.budgets[0] != 1.0) throw InvalidInput("the first LOD budget (LOD0) must be 1");
    for (std::size_t i = 1; i < s.budgets.size(); ++i) {
        const std::string where = "LOD" + std::to_string(i) + " budget";
        if (!(s.budgets[i] > 0.0 && s.budgets[i] < s.budgets[i - 1]))
            throw InvalidInput(where + " must be above 0 and below the one before (" +
                               std::to_string(s.budgets[i - 1]) + ")");
    }
    requireRange("LOD budget tolerance", s.tolerance, 0.0, 0.9);
    requireRange("impostor pixels", s.impostorPixels, 1.0, 4096.0);
    requireRange("LOD leaf cluster pixels", s.leafClusterPixels, 0.25, 8.0);
    requireRange("LOD minimum silhouette IoU", s.minSilhouetteIoU, 0.0, 1.0);
    validateImpostor(s.impostorSettings);
}

double distanceForScreenSize(const LodSettings& lod, double radius, double screenSize) {
    const double halfFov = lod.fovYDegrees * std::numbers::pi / 360.0;
    return 2.0 * radius / (screenSize * 2.0 * std::tan(halfFov));
}

double screenSizeAt(const LodSettings& lod, double radius, double distance) {
    if (distance <= 0.0) return 1.0;
    const double halfFov = lod.fovYDegrees * std::numbers::pi / 360.0;
    return 2.0 * radius / (2.0 * distance * std::tan(halfFov));
}

std::vector<DistanceLevel> buildDistanceLevels(const skel::Skeleton& skeleton,
                                               const TreeMeshSettings& settings,
                                               std::shared_ptr<const Mesh> full, double factor,
                                               double minPixels, Progress& progress) {
    requireRange("distance level factor", factor, 1.01, 100.0);
    requireRange("distance level pixels", minPixels, 0.1, 1e4);
    validateLod(settings.lod);
    std::vector<DistanceLevel> levels;
    if (!full) {
        TreeMeshSettings s = settings;
        s.useLod = false;
        full = std::make_shared<const Mesh>(buildTreeMesh(skeleton, s, progress));
    }
    glm::vec3 centre;
    float radius = 1.0f;
    boundingSphere(*full, centre, radius);
    const double farthest =
        distanceForScreenSize(settings.lod, radius, minPixels / settings.lod.screenHeightPx);
    levels.push_back({0.0, std::move(full)});
    double d = settings.lod.bands.size() > 1 ? settings.lod.bands[1].distance : 25.0;
    for (; d <= farthest; d *= factor) {
        progress.checkCancelled();
        TreeMeshSettings s = settings;
        s.useLod = true;
        s.hasCamera = false;
        s.cameraDistance = d;
        auto mesh = std::make_shared<const Mesh>(buildTreeMesh(skeleton, s, progress));
        // A level no cheaper than the one before is left out: the nearer one is as good.
        if (mesh->triangleCount() >= levels.back().mesh->triangleCount()) continue;
        levels.push_back({d, std::move(mesh)});
    }
    return levels;
}

std::size_t levelFor(const std::vector<DistanceLevel>& levels, double distance) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < levels.size(); ++i)
        if (levels[i].distance <= distance) k = i;
    return k;
}

double silhouetteIoU(const Mesh& reference, const Mesh& level, const glm::vec3& centre,
                     float radius, const LodSettings& lod, double distance, int views) {
    const double halfFov = lod.fovYDegrees * std::numbers::pi / 360.0;
    const double metresPerPixel =
        2.0 * std::max(distance, 1e-6) * std::tan(halfFov) / lod.screenHeightPx;
    // A square around the bounding sphere, the centre on a pixel corner (as a camera aimed at it
    // puts it); a pixel counts when any triangle overlaps it at all (conservative rasterisation:
    // a twig thinner than a pixel still shows in an antialiased frame).
    const int pixels =
        2 * (static_cast<int>(std::ceil(static_cast<double>(radius) / metresPerPixel)) + 1);
    if (pixels > 2000) return 1.0; // too near to matter: no chain level switches that near
    const double scale = 1.0 / metresPerPixel;
    std::vector<std::uint8_t> a, b;
    double sum = 0.0;
    for (int k = 0; k < views; ++k) {
        const glm::vec3 dir = silhouetteView(k, views);
        glm::vec3 right, up;
        impostorViewBasis(dir, right, up);
        coverageMask(reference, centre, right, up, scale, pixels, a);
        coverageMask(level, centre, right, up, scale, pixels, b);
        sum += maskIoU(a, b);
    }
    return sum / views;
}

BudgetLodChain buildBudgetLodChain(const skel::Skeleton& skeleton, const TreeMeshSettings& settings,
                                   const LodChainSettings& chain,
                                   const ImpostorMaterials& materials, Progress& progress) {
    validateLodChain(chain);
    validateLod(settings.lod);
    BudgetLodChain out;
    TreeMeshSettings full = settings;
    full.useLod = false;
    full.hasCamera = false;
    BudgetLevel lod0;
    lod0.mesh = buildTreeMesh(skeleton, full, progress);
    boundingSphere(lod0.mesh, out.centre, out.radius);
    const double t0 = static_cast<double>(lod0.mesh.triangleCount());
    out.levels.push_back(std::move(lod0));

    auto meshAt = [&](double distance, double clusterPixels) {
        TreeMeshSettings s = settings;
        s.lod.leafClusterPixels = clusterPixels;
        s.useLod = true;
        s.hasCamera = false;
        s.cameraDistance = distance;
        progress.checkCancelled();
        return buildTreeMesh(skeleton, s, progress);
    };
    // Farthest distance searched: the sphere spans 4 pixels; nearest: the first band that
    // reduces anything.
    const double pixel = 1.0 / settings.lod.screenHeightPx;
    const double farthest = distanceForScreenSize(settings.lod, out.radius, 4.0 * pixel);
    double from = settings.lod.bands.size() > 1
                      ? settings.lod.bands[1].distance
                      : distanceForScreenSize(settings.lod, out.radius, 1.0);
    from = std::min(from, farthest);
    // The nearest distance from `from` on where the camera LOD with leaf clusters of
    // \p clusterPixels has no more than \p budget triangles; false when not even at `farthest`.
    const auto search = [&](double budget, double clusterPixels, BudgetLevel& level) {
        const double accept = budget * (1.0 - chain.tolerance);
        Mesh m = meshAt(from, clusterPixels);
        if (static_cast<double>(m.triangleCount()) <= budget) {
            level.distance = from;
            level.mesh = std::move(m);
            return true;
        }
        Mesh far = meshAt(farthest, clusterPixels);
        if (static_cast<double>(far.triangleCount()) > budget) {
            level.distance = farthest;
            level.mesh = std::move(far);
            return false;
        }
        // Bisection in log distance for the nearest distance within budget.
        double lo = from, hi = farthest;
        Mesh best = std::move(far);
        for (int it = 0; it < 24 && hi / lo > 1.005; ++it) {
            const double mid = std::sqrt(lo * hi);
            Mesh mm = meshAt(mid, clusterPixels);
            const auto tris = static_cast<double>(mm.triangleCount());
            if (tris <= budget) {
                hi = mid;
                best = std::move(mm);
                if (tris >= accept) break;
            } else {
                lo = mid;
            }
        }
        level.distance = hi;
        level.mesh = std::move(best);
        return true;
    };
    for (std::size_t i = 1; i < chain.budgets.size(); ++i) {
        const double budget = chain.budgets[i] * t0;
        // Leaf cluster sizes tried, in order, until the level keeps LOD0's silhouette at its
        // switch distance (chain.minSilhouetteIoU); else the one that keeps the most. The
        // clusters' sizes change the outline of a crown only a few pixels across by a pixel or
        // two, either way, so the first size is not always the best there.
        std::vector<double> clusters{chain.leafClusterPixels};
        if (chain.minSilhouetteIoU > 0.0)
            for (double f : {1.4, 0.7, 2.0})
                clusters.push_back(std::clamp(chain.leafClusterPixels * f, 0.25, 8.0));
        BudgetLevel level;
        bool found = false;
        for (std::size_t c = 0; c < clusters.size(); ++c) {
            if (c > 0 && clusters[c] == clusters[c - 1]) continue;
            BudgetLevel candidate;
            candidate.budget = chain.budgets[i];
            candidate.leafClusterPixels = clusters[c];
            if (!search(budget, clusters[c], candidate)) {
                if (c == 0) break; // the budget cannot be met at all: the level is dropped
                continue;
            }
            candidate.silhouetteIoU =
                silhouetteIoU(out.levels.front().mesh, candidate.mesh, out.centre, out.radius,
                              settings.lod, candidate.distance);
            if (!found || candidate.silhouetteIoU > level.silhouetteIoU) {
                level = std::move(candidate);
                found = true;
            }
            if (level.silhouetteIoU >= chain.minSilhouetteIoU) break;
        }
        if (!found) {
            // Even the coarsest mesh the camera LOD makes before the tree is 4 px high is above
            // this budget (a tree of a few hundred triangles): the level is left out and
            // reported; the next level or the impostor takes over from the level before.
            DroppedLevel d;
            d.budget = chain.budgets[i];
            d.budgetTriangles = static_cast<std::size_t>(std::floor(budget));
            d.coarsestTriangles = meshAt(farthest, chain.leafClusterPixels).triangleCount();
            d.reason = "budget below the coarsest mesh the camera LOD makes before the tree is "
                       "4 px high (" +
                       std::to_string(d.coarsestTriangles) + " triangles)";
            out.dropped.push_back(std::move(d));
            continue;
        }
        level.screenSize = screenSizeAt(settings.lod, out.radius, level.distance);
        from = level.distance;
        out.levels.push_back(std::move(level));
        progress.report(static_cast<double>(i) / static_cast<double>(chain.budgets.size()),
                        "levels");
    }
    if (chain.impostor) {
        // The last mesh level keeps a range of its own (half again its distance) even when
        // the camera LOD only reaches its budget where the tree is already that small.
        const double lastMesh = out.levels.back().distance * (out.levels.size() > 1 ? 1.5 : 1.0);
        out.impostorDistance = std::max(
            lastMesh, distanceForScreenSize(settings.lod, out.radius,
                                            chain.impostorPixels / settings.lod.screenHeightPx));
        out.impostorScreenSize = screenSizeAt(settings.lod, out.radius, out.impostorDistance);
        progress.report(0.0, "impostor");
        out.impostor =
            bakeImpostor(out.levels.front().mesh, materials, chain.impostorSettings, progress);
    }
    return out;
}

} // namespace sylva::mesh
