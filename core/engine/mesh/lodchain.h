#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "engine/mesh/impostor.h"
#include "engine/mesh/lod.h"

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
    /// IoU >= 0.9, for 34 of the library's 36 levels, 2 for 25; docs/lods.md). 0.25..8.
    double leafClusterPixels = 0.5;
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
    double budget = 1.0;     ///< the fraction of LOD0's triangles it was asked for
    double distance = 0.0;   ///< metres from the camera where it takes over (LOD0: 0)
    double screenSize = 1.0; ///< bounding sphere diameter / viewport height at that distance
    bool budgetMet = true;   ///< false: the coarsest the camera LOD makes is still above budget
    Mesh mesh;
};

struct BudgetLodChain {
    std::vector<BudgetLevel> levels;
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

/// Builds the chain: LOD0 is the full mesh; each further level is the mesh the camera LOD
/// (buildTreeMesh with useLod, the same silhouette-keeping rules a forest's trees follow) makes
/// at the nearest distance where it has no more than its budget of LOD0's triangles, found by
/// bisection over the distance; that distance is where the level takes over. The impostor is
/// baked from LOD0 with \p materials.
/// \throw InvalidInput, Cancelled.
BudgetLodChain buildBudgetLodChain(const skel::Skeleton& skeleton, const TreeMeshSettings& settings,
                                   const LodChainSettings& chain,
                                   const ImpostorMaterials& materials = {},
                                   Progress& progress = noProgress());

} // namespace sylva::mesh
