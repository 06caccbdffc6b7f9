#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "engine/skeleton/skeleton.h"

namespace sylva::skel {

/// One branch of a grown Skeleton: the chain of nodes from where it leaves its parent's axis to
/// its tip (docs/branch-edits.md). At a fork the axis goes on in the child of the same order
/// (the thickest of them, ties: the lower index), or, when none has it, in the thickest child;
/// every other child starts a branch of its own.
struct Branch {
    /// Stable id from the growth structure: the ranks of the branches from the root, "0" for the
    /// (first) trunk, "0.3" for the trunk's fourth branch, "0.3.1" for that branch's second.
    /// A branch's rank is its place among its parent's branches ordered by where they leave it
    /// (the node along the parent), then by their direction's angle about the parent's axis.
    std::string id;
    std::string parent;            ///< the parent branch's id, empty for a trunk
    std::int32_t parentIndex = -1; ///< index of the parent in branchesOf's list, -1 for a trunk
    std::uint16_t order = 0;       ///< branch order of its first node (0: the trunk)
    /// Its nodes from the first after the parent's axis (a trunk: its root) to the tip.
    std::vector<std::int32_t> nodes;
    std::int32_t baseNode = -1; ///< the node of the parent's axis it leaves from (-1: a trunk)
    glm::vec3 base{0.0f};       ///< where it leaves its parent (a trunk: its root), metres
    glm::vec3 tip{0.0f};        ///< its last node
    float length = 0.0f;        ///< along its segments, base to tip, metres
    float baseRadius = 0.0f;    ///< radius of its first node, metres
};

/// Splits \p skeleton into branches, parents before their branches (the list's order: each
/// branch after its parent, a parent's branches by rank). Hidden nodes count like the others.
std::vector<Branch> branchesOf(const Skeleton& skeleton);

/// One node of a locked branch's kept geometry (BranchEdit::locked), in the skeleton's frame.
struct LockedNode {
    std::int32_t parent = -1; ///< index into the locked nodes; -1: the node the branch leaves
    std::uint16_t order = 0;
    float radius = 0.0f;
    glm::vec3 offset{0.0f}; ///< from the branch's base, metres
    glm::quat orientation{1, 0, 0, 0};
    bool operator==(const LockedNode&) const = default;
};

/// A leaf card of a locked branch's kept geometry.
struct LockedLeaf {
    std::int32_t node = 0; ///< index into the locked nodes
    float size = 1.0f;
    glm::vec3 offset{0.0f}; ///< from the branch's base, metres
    glm::quat orientation{1, 0, 0, 0};
    bool operator==(const LockedLeaf&) const = default;
};

/// Where an edited branch was in the tree as grown when the edit was made (the skeleton's
/// frame): what re-attaches the edit when a change of topology shifts the ids
/// (docs/branch-edits.md#anchors).
struct BranchAnchor {
    glm::vec3 base{0.0f};      ///< Branch::base, metres
    glm::vec3 direction{0.0f}; ///< unit base -> tip
    float length = 0.0f;       ///< Branch::length, metres
    bool operator==(const BranchAnchor&) const = default;
};

/// The anchor of \p branch (its base, direction and length).
BranchAnchor anchorOf(const Branch& branch);

/// A hand edit of one branch (a project's "branch_edits"), applied after growth and before
/// adaptation to obstacles.
struct BranchEdit {
    std::string branch; ///< Branch::id
    /// Where the branch was when edited: the edit goes to the branch there (the id's own when it
    /// still is there, else the branch of the same depth whose base and direction are nearest,
    /// within kAnchorReach and kAnchorAngle); without one, or when none is near, by id alone.
    std::optional<BranchAnchor> anchor;
    bool prune = false; ///< remove the branch and everything it carries
    /// Turn the branch and everything it carries rigidly about its base so that its base -> tip
    /// direction points along this direction (the skeleton's frame; need not be unit length).
    std::optional<glm::vec3> bend;
    float length = 1.0f; ///< scale of the branch's own segments about its base, [0.05, 20]
    float radius = 1.0f; ///< scale of the radii of the branch and what it carries, [0.05, 20]
    /// Keep the branch's geometry through regrowth: with `locked` geometry, the branch and what
    /// it carries are replaced by it (after the other edits, which it already holds); when the
    /// id no longer exists but its parent does, it is grafted onto the parent's node nearest
    /// `lockedBase`. Without geometry (lockBranch not yet run) the flag alone changes nothing.
    bool lock = false;
    glm::vec3 lockedBase{0.0f}; ///< where the branch left its parent when locked
    std::vector<LockedNode> locked;
    std::vector<LockedLeaf> lockedLeaves;

    bool operator==(const BranchEdit&) const = default;
};

/// How far an anchored edit looks for its branch: a base within this share of the tree's height
/// (plus half the branch's length), a direction within kAnchorAngle degrees.
inline constexpr float kAnchorReach = 0.25f;
inline constexpr float kAnchorAngle = 60.0f;

/// The range of BranchEdit::length and ::radius.
inline constexpr float kBranchScaleMin = 0.05f;
inline constexpr float kBranchScaleMax = 20.0f;

/// Throws InvalidInput for an edit out of range (a scale outside [0.05, 20], a zero bend, a
/// trunk pruned, an empty id).
void validate(const BranchEdit& edit);

/// What applyBranchEdits did.
struct BranchEditReport {
    std::size_t applied = 0;           ///< edits whose branch was found
    std::vector<std::string> orphaned; ///< ids of edits whose branch does not exist
    std::size_t prunedNodes = 0;       ///< nodes removed by prune edits
    std::size_t reattached = 0; ///< locked edits grafted onto their parent (their id was gone)
    /// Anchored edits applied to another branch than their id's (ids shifted): old id, new id.
    std::vector<std::pair<std::string, std::string>> moved;
    /// Locked branches replaced by their kept geometry: id and the index of its first node.
    std::vector<std::pair<std::string, std::int32_t>> grafted;
};

/// Applies \p edits to \p skeleton: ids are resolved on the skeleton as given; edits of
/// parents come before those of their branches (so a branch bent after its parent still points
/// where its edit says); within an edit length, then bend, then radius; pruned nodes are
/// removed last (indices change; leaves on them go too). An edit whose branch does not exist is
/// reported, never an error. With \p nodeMap: each former node's index after the edits, -1 for a
/// pruned one. \throw InvalidInput for an edit out of range.
BranchEditReport applyBranchEdits(Skeleton& skeleton, const std::vector<BranchEdit>& edits,
                                  std::vector<std::int32_t>* nodeMap = nullptr);

/// Sets \p edit's locked geometry (lock, lockedBase, locked, lockedLeaves) to its branch's
/// subtree in \p grown with \p others (the tree's other edits) applied. \throw InvalidInput
/// when \p grown has no branch edit.branch or it is a trunk.
void lockBranch(const Skeleton& grown, const std::vector<BranchEdit>& others, BranchEdit& edit);

/// The branches of \p grown (their ids) as \p edits leave them: pruned ones left out, the others'
/// nodes, base, tip, length and radius those of the edited skeleton. What an editor lists and
/// what edits name: ids never shift when a sibling is pruned. With \p edited: the edited
/// skeleton the branches' nodes index (what the branch tool picks and highlights).
std::vector<Branch> editedBranches(const Skeleton& grown, const std::vector<BranchEdit>& edits,
                                   Skeleton* edited = nullptr);

} // namespace sylva::skel
