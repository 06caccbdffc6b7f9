#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/mesh/impostor.h"
#include "engine/mesh/treemesh.h"

namespace sylva::mesh {

/// A game engine's LOD chain: mesh levels by triangle budget, then an impostor.
struct LodChainSettings {
    /// Triangles of each level as a fraction of LOD0's: 1 first, then strictly decreasing, > 0.
    std::vector<double> budgets{1.0, 0.35, 0.12, 0.04};
    /// A level is accepted once its triangles lie in [budget · (1 - tolerance), budget] · LOD0
    /// (the camera LOD's steps are discrete; the search keeps the nearest distance within it).
    double tolerance = 0.2;
    /// The leaf clusters of the levels' meshes, in pixels of the reference view at the level's
    /// switch distance (the camera LOD's LodSettings::leafClusterPixels, 2 for a forest's trees,
    /// which draw each mesh over a band of distances; a chain level is drawn from its switch
    /// distance on, where finer clusters keep the crown's outline: 0.5 keeps LOD0's silhouette,
    /// IoU >= 0.9, for 35 of the library's 36 levels, 2 for 25; minSilhouetteIoU checks each level;
    /// docs/lods.md). 0.25..8.
    double leafClusterPixels = 0.5;
    /// A level whose silhouette IoU against LOD0 at its switch distance (silhouetteIoU) is
    /// under this is made again with leaf clusters 1.4, 0.7 and 2 times leafClusterPixels, and
    /// the first that keeps it (else the best) is taken. 0: no check (one search a level).
    double minSilhouetteIoU = 0.9;
    bool impostor = true;
    /// The impostor takes over where the tree's bounding sphere spans this many pixels of the
    /// reference view (LodSettings: 1080 px high, 60 degrees), or at 1.5 times the last mesh
    /// level's distance when that is farther (so that level is drawn somewhere).
    double impostorPixels = 64.0;
    ImpostorSettings impostorSettings;
};

/// Checks the budgets (non-empty, first 1, strictly decreasing, > 0), the tolerance (0..0.9),
/// the impostor's pixels (1..4096) and settings; throws InvalidInput naming the offender.
void validateLodChain(const LodChainSettings& settings);

/// A level of the chain made by budget.
struct BudgetLevel {
    double budget = 1.0;            ///< the fraction of LOD0's triangles it was asked for
    double distance = 0.0;          ///< metres from the camera where it takes over (LOD0: 0)
    double screenSize = 1.0;        ///< bounding sphere diameter / viewport height at that distance
    bool budgetMet = true;          ///< always true: a level that cannot meet its budget is dropped
    double leafClusterPixels = 0.0; ///< the leaf clusters it was made with (0 for LOD0)
    double silhouetteIoU = 1.0;     ///< against LOD0 at its switch distance (silhouetteIoU())
    Mesh mesh;
};

/// A budget of LodChainSettings::budgets the chain left out, and why.
struct DroppedLevel {
    double budget = 0.0;               ///< the fraction of LOD0's triangles it was asked for
    std::size_t budgetTriangles = 0;   ///< that many triangles
    std::size_t coarsestTriangles = 0; ///< the fewest the camera LOD makes (above the budget)
    std::string reason;
};

struct BudgetLodChain {
    std::vector<BudgetLevel> levels;
    /// Budgets the camera LOD cannot reach before the tree is 4 px high (a tree of a few
    /// hundred triangles): left out, so levels[i] is not always budgets[i].
    std::vector<DroppedLevel> dropped;
    glm::vec3 centre{0.0f}; ///< LOD0's bounding sphere
    float radius = 1.0f;
    std::optional<Impostor> impostor;
    double impostorDistance = 0.0;
    double impostorScreenSize = 0.0;
};

/// Distance (m) at which a sphere of \p radius spans \p screenSize of the reference view's
/// height (\p lod's screenHeightPx and fovYDegrees), and the inverse.
double distanceForScreenSize(const LodSettings& lod, double radius, double screenSize);
double screenSizeAt(const LodSettings& lod, double radius, double distance);

/// A level of a tree drawn at many distances (a forest's variant): the camera LOD's mesh for a
/// viewer \p distance metres away (0: the full mesh), shared by every tree drawn with it.
struct DistanceLevel {
    double distance = 0.0;
    std::shared_ptr<const Mesh> mesh;
};

/// The full mesh \p full, then the camera LOD (buildTreeMesh with useLod, no camera: no
/// ribbons, which face one viewer) at distances settings.lod.bands[1] · factor^k, k = 0, 1, ...,
/// until the bounding sphere spans fewer than \p minPixels of the reference view. A tree seen
/// from distance d (scaled to 1) may draw the last level whose distance is <= d (levelFor):
/// each keeps the silhouette from its own distance on.
/// \throw InvalidInput (factor <= 1, minPixels <= 0), Cancelled.
std::vector<DistanceLevel> buildDistanceLevels(const skel::Skeleton& skeleton,
                                               const TreeMeshSettings& settings,
                                               std::shared_ptr<const Mesh> full,
                                               double factor = 1.25, double minPixels = 8.0,
                                               Progress& progress = noProgress());

/// Index of the last level of \p levels (distances increasing) whose distance is <= \p distance.
std::size_t levelFor(const std::vector<DistanceLevel>& levels, double distance);

/// The silhouette IoU of \p level against \p reference as the reference view (\p lod's screen
/// height and field of view) draws them \p distance metres away: the mean over \p views
/// directions around the tree (every other one 20 degrees above the horizon) of the IoU of the
/// pixels each overlaps at all (conservative rasterisation, geometry only), the square around the
/// sphere (\p centre, \p radius) drawn orthographically. 1 where the tree would be over 2,000
/// pixels across (the measure's cost; no chain level switches that near).
double silhouetteIoU(const Mesh& reference, const Mesh& level, const glm::vec3& centre,
                     float radius, const LodSettings& lod, double distance, int views = 8);

/// Builds the chain: LOD0 is the full mesh; each further level is the mesh the camera LOD
/// (buildTreeMesh with useLod, the same silhouette-keeping rules a forest's trees follow) makes
/// at the nearest distance where it has no more than its budget of LOD0's triangles, found by
/// bisection over the distance; that distance is where the level takes over. A level whose
/// silhouette there is under chain.minSilhouetteIoU is searched again with other leaf cluster
/// sizes; a budget not reached before the tree is 4 px high is dropped (BudgetLodChain::dropped).
/// The impostor is baked from LOD0 with \p materials.
/// \throw InvalidInput, Cancelled.
BudgetLodChain buildBudgetLodChain(const skel::Skeleton& skeleton, const TreeMeshSettings& settings,
                                   const LodChainSettings& chain,
                                   const ImpostorMaterials& materials = {},
                                   Progress& progress = noProgress());

} // namespace sylva::mesh
