#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/environment/obstaclescene.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/progress.h"

namespace sylva::env {

/// A neighbouring tree's crown as an obstacle: a vertical cylinder standing on \p base (world
/// space). Used so that trees of a forest avoid each other without meshing every neighbour.
struct CrownVolume {
    glm::vec3 base{0.0f}; ///< centre of the bottom disc, metres
    float radius = 0.0f;  ///< metres, >= 0
    float bottom = 0.0f;  ///< height of the crown's bottom above base.y, metres
    float top = 0.0f;     ///< height of the crown's top above base.y, metres
};

/// Parameters of adaptation (the `adapt` node's parameters, same names in snake_case).
struct AdaptParams {
    float maxBend = 0.1f;        ///< radians added at the root's first branch level, [0, pi/2]
    float bendMultiplier = 0.9f; ///< factor per branching level (deeper bends less), [0, 1]
    bool prune = true;           ///< hide branches that still collide after bending
    bool redistribute = true;    ///< give the pruned length back to the visible branches
    /// Re-check every visible branch after bending, not only the first colliders (the reference
    /// only re-checked the colliders, so bending could push other branches into a mesh).
    bool recheckAll = true;
    /// Let the trunk bend back toward its rest direction once it is above the top of the
    /// obstacles it touched (at most maxBend per trunk segment), instead of leaning forever.
    bool returnToVertical = true;
    /// Direction the light travels (world space, need not be unit; the project's
    /// light.direction). Redistribution favours branches that point against it (toward the
    /// light). A zero vector grows every branch by the same length (the reference's grow()).
    glm::vec3 lightDirection{0.0f, -1.0f, 0.0f};
    /// Leaf cards as the mesher will draw them (tube_mesh's leaf_scale and leaf_aspect): a leaf
    /// whose card or stem touches an obstacle is dropped. Card length = Leaf::size · leafScale.
    float leafScale = 1.0f;  ///< (0, 100]
    float leafAspect = 0.5f; ///< card width / length, (0, 4]
    /// Bark: per node of the rest skeleton, the radius of the ring the mesher draws there, in
    /// the skeleton's units (mesh::tubeRadii for the species' tube_mesh settings). Empty: the
    /// skeleton's own radii. A segment collides when the tube of the larger of its two radii
    /// around it (a capsule) touches an obstacle, so no bark, not only no branch axis, ends
    /// inside one. Zero radii test the axes only.
    std::span<const float> barkRadii;
};

/// What adaptation did to one tree. Lengths are in the skeleton's own units (metres before the
/// tree transform's scale).
struct AdaptStats {
    std::size_t segmentsTested = 0;     ///< segment queries made (all passes)
    std::size_t collidingBefore = 0;    ///< segments that hit an obstacle in the rest pose
    std::size_t collidingAfterBend = 0; ///< segments hitting after bending (of those re-checked)
    std::size_t collidingAfter = 0;     ///< visible segments hitting in the final pose (0 with
                                        ///< prune on)
    std::size_t growthRounds = 0;       ///< redistribution passes (each one re-checked)
    std::size_t droppedLeaves = 0;      ///< leaves dropped because their card touched an obstacle
    std::size_t hiddenNodes = 0;        ///< nodes flagged kHidden (pruned with their children)
    double prunedLength = 0.0;          ///< total length of the hidden segments
    double redistributedLength = 0.0;   ///< length added to visible segments (== prunedLength
                                        ///< when redistribute is on and something is visible)
    double totalLengthBefore = 0.0;     ///< sum of all segment lengths in the rest pose
    double visibleLengthAfter = 0.0;    ///< sum of the visible segment lengths at the end
    double leanRadians = 0.0;           ///< largest bend applied along any root-to-tip path
    bool bent = false;
};

struct AdaptResult {
    skel::Skeleton skeleton; ///< same node count and order as the rest pose, in its local frame
    AdaptStats stats;
};

/// Adapts one tree to its environment, from its rest pose (so adapting again never
/// accumulates). \p treeTransform maps the skeleton's local frame to the world (a rotation,
/// uniform scale and translation: what placement produces). Steps, after the reference (§4.3):
/// find the segments that hit an obstacle (or a neighbour's crown), average the directions of
/// the hits seen from the root, rotate the tree away from them branch level by branch level
/// (maxBend · bendMultiplier^level, children inherit their parent's rotation), re-check, hide
/// what still collides together with its descendants (flag kHidden; nodes are kept), and grow
/// the remaining visible segments by the pruned length. The grown pose is checked again: growth
/// that pushes a segment into an obstacle is withdrawn from that segment's path to the root (the
/// length goes to the other segments) and, with prune on, a segment that collides without any
/// growth is hidden, until nothing visible collides. Leaves hanging on hidden nodes are dropped,
/// the others follow their node; a leaf whose card or stem touches an obstacle is dropped too.
/// Segments are tested as tubes of their bark radius (AdaptParams::barkRadii), leaf cards as
/// their edges and diagonals. With prune on, no visible segment's tube comes nearer to an
/// obstacle than its bark radius and no leaf card crosses an obstacle's surface, so a tree rooted
/// outside the obstacles keeps no bark and no leaf inside one. Trees whose
/// bounds (leaf cards included) touch no obstacle are returned unchanged after one bounds test.
/// \throw InvalidInput for parameters out of range, an invalid skeleton or barkRadii of another
/// size than the skeleton.
AdaptResult adaptTree(const skel::Skeleton& rest, const ObstacleScene& scene,
                      const glm::mat4& treeTransform, const AdaptParams& params,
                      std::span<const CrownVolume> neighbours = {});

/// adaptTree for many trees in parallel (OpenMP, dynamic schedule): result i is tree i adapted
/// with transform i, identical whatever the thread count. \p rest and \p transforms have the
/// same size; \p neighbours is empty or has one list per tree. Reports progress as "adapt" and
/// throws Cancelled (after the running trees finish) when asked to stop.
std::vector<AdaptResult> adaptTrees(std::span<const skel::Skeleton* const> rest,
                                    std::span<const glm::mat4> transforms,
                                    const ObstacleScene& scene, const AdaptParams& params,
                                    std::span<const std::vector<CrownVolume>> neighbours = {},
                                    Progress& progress = noProgress());

/// Whether a leaf card (the quad tube_mesh draws: Leaf::size · \p leafScale long, \p leafAspect
/// times as wide; its edges and diagonals) or its stem from \p stemFrom to its anchor touches
/// an obstacle of \p scene. Leaf and stem are in the tree's frame, \p treeTransform maps it to
/// the world. Cards whose bounds overlap no obstacle's bounds are answered without a query.
bool leafCardTouches(const ObstacleScene& scene, const glm::mat4& treeTransform,
                     const skel::Leaf& leaf, const glm::vec3& stemFrom, float leafScale,
                     float leafAspect);

/// Length of every segment whose end node is not hidden (the skeleton's units).
double visibleLength(const skel::Skeleton& skeleton);

/// Segment against a vertical cylinder (solid): true when any point of the segment is inside.
/// The first entry point is written to \p point.
bool segmentHitsCrown(const Segment& s, const CrownVolume& crown, glm::vec3* point = nullptr);

} // namespace sylva::env
