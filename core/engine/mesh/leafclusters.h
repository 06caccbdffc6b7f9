#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "engine/mesh/leafcards.h"
#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"

namespace sylva::mesh {

/// Leaf clusters (issue #33): one card carries several leaves, drawn from a species' cluster
/// atlas (make_textures.py's <species>_leafcluster.png), so a crown costs a fraction of the
/// triangles of one card a leaf at the same silhouette.
///
/// The atlas is 4 x 2 tiles (1024 x 512 pixels), numbered from the bottom left along rows:
/// tiles 0-6 are sprays of leaves (or of needle shoots, for the conifers and shrubs) on a twig,
/// stem at the bottom edge of the tile, each drawn differently; tile 7 is the single leaf
/// stretched to the tile (for a leaf alone in its cell). A card shows one of the seven sprays,
/// mirrored or not: fourteen looks, so that neighbouring cards rarely repeat.
inline constexpr int kClusterAtlasColumns = 4;
inline constexpr int kClusterAtlasRows = 2;
inline constexpr int kClusterSprays = kClusterAtlasColumns * kClusterAtlasRows - 1;

struct LeafClusterSettings {
    /// Mean leaves a card carries; 0 or 1: one card a leaf (appendLeafCards); [0, 64].
    int leavesPerCard = 0;
    std::uint64_t seed = 0; ///< which spray tile a cluster shows, mirrored or not
    /// Each card of two or more leaves gets a second one crossing it along its stem-to-tip
    /// centre line, at right angles (the same size and tile, mirrored the other way): a tuft
    /// of needles round its shoot seen from any side, not a flat frond edge on (issue #33:
    /// the Scots pine). Twice the cards.
    bool crossed = false;
};

/// Appends the leaves as cluster cards ("leaf" submesh). Leaves are grouped by cubic cells whose
/// edge starts at 1.2 x the mean leaf length and grows by 8 % until there are no more cells than
/// leaves / leavesPerCard (the 40th size taken whatever it gives). Each group's card lies in the
/// plane that best fits its leaf cards' corners (the two largest principal axes; its normal turned
/// toward the leaves' mean up axis), stem edge toward where its leaves start, and covers the
/// corners' extent in that plane; so the cards keep the leaves' spread and their varied
/// orientations, not one facing. A leaf alone keeps its own card (tile 7). Wind attributes and
/// node ids as appendLeafCards (a card takes its first leaf's node). A cluster card that
/// \p accept (when given) refuses, tested as a leaf whose card (size long, cards.aspect x size
/// wide, times cards.sizeScale) holds it, is not made: its leaves keep their own cards (a forest
/// refuses cards that reach into an obstacle; adaptation already checked the leaves).
/// With LeafClusterSettings::crossed a group's card comes with its crossing card.
/// Deterministic. \return the number of cards made.
std::size_t appendLeafClusterCards(Mesh& out, const std::vector<skel::Leaf>& leaves,
                                   const LeafCardSettings& cards,
                                   const LeafClusterSettings& clusters,
                                   const skel::Skeleton* skeleton = nullptr,
                                   const std::function<bool(const skel::Leaf&)>& accept = {});

/// appendLeafClusterCards in two steps: the leaves grouped, the groups' cards fitted and
/// checked with \p accept (planLeafClusterCards), then written (appendLeafClusterCards with the
/// plan). A tree's mesh makes the plan before its bark, so that the bark's arrays are made with
/// room for the cards (TubeSettings::reserveVertices): growing them for the cards moved the
/// bark's ~2 MB (the English oak).
class LeafClusterPlan {
public:
    LeafClusterPlan();
    ~LeafClusterPlan();
    LeafClusterPlan(LeafClusterPlan&&) noexcept;
    LeafClusterPlan& operator=(LeafClusterPlan&&) noexcept;
    /// The cards (quads: four vertices, six indices) appendLeafClusterCards will append.
    std::size_t cards() const { return mCards; }

private:
    struct Data;
    std::unique_ptr<Data> mData;
    std::size_t mCards = 0, mLeaves = 0;
    bool mCrossed = false;
    friend LeafClusterPlan planLeafClusterCards(const std::vector<skel::Leaf>&,
                                                const LeafCardSettings&, const LeafClusterSettings&,
                                                const std::function<bool(const skel::Leaf&)>&);
    friend std::size_t appendLeafClusterCards(Mesh&, const std::vector<skel::Leaf>&,
                                              const LeafClusterSettings&, const skel::Skeleton*,
                                              const LeafClusterPlan&);
};
LeafClusterPlan planLeafClusterCards(const std::vector<skel::Leaf>& leaves,
                                     const LeafCardSettings& cards,
                                     const LeafClusterSettings& clusters,
                                     const std::function<bool(const skel::Leaf&)>& accept = {});
/// Writes \p plan's cards for the same \p leaves and \p clusters it was made with (else
/// \throw InvalidInput). \return the number of cards made.
std::size_t appendLeafClusterCards(Mesh& out, const std::vector<skel::Leaf>& leaves,
                                   const LeafClusterSettings& clusters,
                                   const skel::Skeleton* skeleton, const LeafClusterPlan& plan);

/// The groups appendLeafClusterCards makes: for each card, the indices of its leaves (in
/// order of their first leaf). Exposed for tests.
std::vector<std::vector<std::uint32_t>> groupLeaves(const std::vector<skel::Leaf>& leaves,
                                                    double sizeScale, int leavesPerCard);

} // namespace sylva::mesh
