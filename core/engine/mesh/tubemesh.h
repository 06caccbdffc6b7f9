#pragma once

#include <cstddef>

#include "engine/mesh/barkrelief.h"
#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"

namespace sylva::mesh {

/// Where branch radii come from.
enum class ThicknessMode {
    Skeleton,  ///< the skeleton's radii (turtle width, pipe model)
    Branching, ///< t = i·m^b (reference 000 §4.4): b = branching points below the node
};

/// Most triangles one call of appendTubes() may add (about 3 GB of mesh): past it, it throws
/// LimitExceeded before allocating. 20 million L-system segments at resolution 64 would ask for
/// 2.6 billion.
inline constexpr std::size_t kMaxTubeTriangles = 100'000'000;

/// Parameters of the generalized-cylinder branch mesher.
struct TubeSettings {
    int resolution = 8; ///< vertices around a ring, 3..64
    bool caps = true;   ///< close branch tips and root bases with flat caps
    ThicknessMode thickness = ThicknessMode::Skeleton;
    double initialThickness = 0.2;    ///< i: trunk DIAMETER (metres) in Branching mode
    double thicknessMultiplier = 0.8; ///< m: factor per branching point in Branching mode, (0, 1]
    double radiusScale = 1.0;         ///< multiplies every radius
    /// Lateral branches whose base radius (after scaling) is below this are dropped with
    /// everything they carry (used by LOD to drop thin twigs); metres, 0 keeps everything.
    double minBranchRadius = 0.0;
    /// Along each axis, nodes are skipped while the straight tube from the last kept node stays
    /// within this distance of every skipped node (position and radius); metres, 0 keeps every
    /// node. LOD sets it to a fraction of a pixel's footprint.
    double simplifyTolerance = 0.0;
    /// Axes whose own base radius (after scaling) is below this are drawn as flat ribbons, two
    /// triangles a segment, turned toward ribbonCamera (LOD: branches a pixel or two wide look
    /// the same from the camera at a third of the cost of the thinnest tube); metres, 0 = none.
    double ribbonBelowRadius = 0.0;
    glm::vec3 ribbonCamera{0.0f}; ///< in the skeleton's frame
    /// Axes whose own base radius (after scaling) is below this get twigResolution sides
    /// instead of resolution: a twig a centimetre thick shows no roundness that eight sides
    /// draw better than four (issue #33: most of a spruce's triangles were such twigs);
    /// metres, 0 = every axis gets resolution.
    double twigBelowRadius = 0.0;
    int twigResolution = 4;        ///< 3..64, used with twigBelowRadius
    double ribbonWidthScale = 1.0; ///< ribbon width = 2 · radius · this
    /// Root flare: a root's tube is this many times its skeleton radius at the ground, widening
    /// smoothly over the flare's height (1 + (rootFlare - 1)(1 - h/height)²); [1, 4], 1: none.
    double rootFlare = 1.0;
    /// Height of the flare above a root node, metres, at most kMaxFlareRadii times the root's
    /// radius (a twig-thin stem flares over a few centimetres, not a metre); [0, 100].
    double flareHeight = 0.0;
    /// A root's tube goes on this far below its root node, flared as at the root, so the tree
    /// stands in the ground rather than on it like a post; metres, [0, 10].
    double groundDepth = 0.0;
    /// Buttresses: a root's cross-section near the ground has this many lobes (0: round),
    /// standing out up to buttressDepth of the radius at the ground and fading over the
    /// flare's height; a lobed root's axis gets at least 3 · buttressLobes sides. [0, 12].
    int buttressLobes = 0;
    double buttressDepth = 0.35; ///< [0, 1]
    /// Bark relief as geometry (issue #44): axes whose own base radius (after scaling) is at
    /// least barkReliefRadius get their surface displaced outward by up to barkRelief times the
    /// ring's radius in barkPattern (the skeleton's radius is the furrows' bottom), columns
    /// about barkReliefScale metres wide, kBarkSidesPerColumn ring vertices a column (at most
    /// barkReliefSides, at least resolution) and rings every barkRingSpacing columns along the
    /// axis. The relief fades in from the threshold radius to 1.5 times it along an axis and
    /// over the first parent radius of a lateral (its base stays inside its parent). LOD sets
    /// barkRelief to 0 past its first band. barkRelief [0, 0.5], 0: none; scale [0.01, 2] m;
    /// radius [0, 100] m; sides [3, 128].
    double barkRelief = 0.0;
    BarkPattern barkPattern = BarkPattern::Ridges;
    double barkReliefScale = 0.08;
    double barkReliefRadius = 0.08;
    int barkReliefSides = 64;
    /// The bark texture's width in metres: an axis whose own base circumference (after
    /// scaling) holds k widths gets the texture k times around (k = round(circumference /
    /// width), at least 1) and as often along per circumference, so its features keep their
    /// size in metres from the trunk to the twigs (texels stay square). 0: once around each
    /// axis, whatever its girth (the texture's features as wide on a trunk as on a twig
    /// scaled up, a metre on a thick oak). [0, 10] m.
    double barkTextureWidth = 0.0;
    /// Bark colour by height (issue #44: the Scots pine grey-brown low, orange high): where
    /// barkColorTop > barkColorBottom (metres above the first root node), bark vertices get
    /// Mesh::colors, barkColorLow up to barkColorBottom blending smoothly into barkColorHigh at
    /// barkColorTop (a factor on the bark texture, as the leaf tints are on theirs); otherwise
    /// the bark stays white. Colours in [0, 1].
    glm::vec3 barkColorLow{1.0f};
    glm::vec3 barkColorHigh{1.0f};
    double barkColorBottom = 0.0;
    double barkColorTop = 0.0;
    bool windAttributes = false; ///< fill Mesh::branchOrder and Mesh::flexibility
    bool nodeIds = false;        ///< fill Mesh::node (for colouring by node attributes)
    std::size_t maxTriangles = kMaxTubeTriangles; ///< lowered by tests only
    /// Room the mesh's arrays are made with past the bark, for what the caller appends next
    /// (a tree's leaf cards, buildTreeMesh): vertices and indices. Changes no output; growing
    /// the arrays for the cards afterwards moved the bark's (~2 MB for the English oak).
    std::size_t reserveVertices = 0, reserveIndices = 0;
};

/// The flare rises at most this many root radii (see TubeSettings::flareHeight).
inline constexpr double kMaxFlareRadii = 8.0;

/// Smallest radius a ring gets (metres): zero-width branches would give degenerate triangles.
inline constexpr float kMinTubeRadius = 1e-4f;

/// Builds branch tubes for a skeleton, appended to \p out as one "bark" submesh.
///
/// Each axis (a node followed by the children of the same branch order) is one generalized
/// cylinder: one ring of resolution+1 vertices (the seam is duplicated for UVs) per node,
/// oriented by rotation-minimizing (parallel-transport, double-reflection) frames, so there is
/// no twist along a branch. A lateral branch starts with a ring centred on its parent node,
/// with its own radius clamped to the parent's, so the ring lies inside the parent's surface:
/// forks have neither gaps nor slivers. A root's axis gets the root flare (extra rings over the
/// flare's height) and goes on below the ground by groundDepth. UVs: u = 0..k around (k from
/// barkTextureWidth, 1 without), v = k · arc length / circumference. Normals are smooth and tilted
/// by the taper. Hidden nodes (kHidden) are skipped with their subtrees. Deterministic and parallel
/// (OpenMP) with identical output on any thread count. \throw InvalidInput for a resolution
/// outside 3..64 or an invalid skeleton. \throw LimitExceeded "tube mesh would have N triangles,
/// more than the limit of 100000000;
///        ..." past TubeSettings::maxTriangles.
void appendTubes(Mesh& out, const skel::Skeleton& skeleton, const TubeSettings& settings,
                 Progress& progress = noProgress());

/// Convenience: a new mesh holding only the tubes.
Mesh buildTubeMesh(const skel::Skeleton& skeleton, const TubeSettings& settings,
                   Progress& progress = noProgress());

/// Effective ring radius per node for \p settings (thickness mode, scale, minimum), metres.
std::vector<float> tubeRadii(const skel::Skeleton& skeleton, const TubeSettings& settings);

} // namespace sylva::mesh
