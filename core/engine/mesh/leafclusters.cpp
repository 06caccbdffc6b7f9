#include "engine/mesh/leafclusters.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>

#include "engine/mesh/cardfit.h"
#include "engine/mesh/cardfitlanes.h"
#include "engine/mesh/leafcards.h"
#include "engine/mesh/leafcell.h"
#include "engine/mesh/leafcellhash.h"
#include "engine/mesh/powereigen.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

namespace sylva::mesh {

namespace {

using CellKey = LeafCell;

/// The leaves' cells at one cell size: an open-addressing table of the distinct cells, each
/// with its group (the order the cells are first met), reused from size to size.
class CellTable {
public:
    /// A table for up to \p cells distinct cells: four slots a cell, a quarter full at most
    /// (half full, the English oak's two fills took 0.50 ms a tree, 0.46 ms so: fewer probes
    /// past a neighbour's slot, each a mispredicted branch; eight slots a cell, no better).
    explicit CellTable(std::size_t cells) {
        std::size_t n = 16;
        while (n < 4 * cells)
            n *= 2;
        mSlots.resize(n);
        mMask = n - 1;
    }
    /// The number of distinct cells of \p mids at \p cell, or limit + 1 as soon as there are
    /// more than \p limit (at most the table's size), and each leaf's group: the index of its
    /// cell in the order the cells are first met.
    std::size_t fill(const RawVector<glm::dvec3>& mids, double cell, std::size_t limit,
                     std::vector<std::uint32_t>& groupOf) {
        ++mStamp;
        // Room for every key a fill may write (one past the limit), written in place below.
        mKeys.resize(std::min(limit, mids.size()) + 1);
        groupOf.resize(mids.size());
        mCells.resize(kChunk);
        mHashes.resize(kChunk);
        // Every leaf looks its cell up; only a new cell's table slot is written. A shortcut for a
        // leaf in the cell of the leaf before it was a branch taken about every other leaf,
        // mispredicted (perf record of the English oak: CellTable::fill 10 % of the tree). Writing
        // every leaf's slot whether or not its cell was new (no branch on it) was slower once the
        // table was a quarter full: 0.46 ms a tree for the oak's two fills, 0.43 ms with the
        // branch (a leaf's table read waited on the slot writes of the leaves before it).
        // A chunk's cells and hashes first, then their lookups, each slot fetched kAhead
        // leaves before its lookup and the key it holds kKeyAhead leaves before (the table is
        // in L2: every lookup waited on it, two dependent reads; 0.43 -> 0.35 ms a tree for the
        // oak's fills).
        std::uint32_t count = 0;
        const std::size_t keyLast = mKeys.size() - 1;
        Slot scratch;
        for (std::size_t c0 = 0; c0 < mids.size(); c0 += kChunk) {
            const std::size_t c1 = std::min(mids.size(), c0 + kChunk);
            // Eight leaves a register with AVX-512 (leafCellsHashed: perf annotate, the cells'
            // divisions, floors and hashes were a third of the fill's samples).
            leafCellsHashed(mids.data() + c0, c1 - c0, cell, mMask, mCells.data(), mHashes.data());
            for (std::size_t i = c0; i < c1; ++i) {
                const std::size_t k = i - c0;
                if (k + kAhead < c1 - c0) __builtin_prefetch(&mSlots[mHashes[k + kAhead]]);
                if (k + kKeyAhead < c1 - c0)
                    __builtin_prefetch(&mKeys[std::min<std::size_t>(
                        mSlots[mHashes[k + kKeyAhead]].group, mKeys.size() - 1)]);
                const CellKey& key = mCells[k];
                std::size_t slot = mHashes[k];
                // The first probe without a branch on what it finds (a new cell about one leaf
                // in four, at random: the branch on it was mispredicted, most of the fill's
                // samples in perf record of the English oak; the compiler put the branch back
                // unless the flags are opaque); only a neighbour's cell in the slot probes on.
                Slot s = mSlots[slot];
                std::uint32_t used = opaque(s.stamp == mStamp);
                if (opaque(used & !sameCell(mKeys[std::min<std::size_t>(s.group, keyLast)], key))) {
                    do {
                        slot = (slot + 1) & mMask;
                        s = mSlots[slot];
                    } while (s.stamp == mStamp && !sameCell(mKeys[s.group], key));
                    used = opaque(s.stamp == mStamp);
                }
                // A new cell's slot and key are written; for a known cell the key goes past the
                // last group (overwritten by the next new one) and the slot to a scratch slot
                // (every leaf's table slot written was slower: the next reads waited on those
                // stores). The same groups and slots as a branch on the cell being new.
                const std::uint32_t keep = 0u - used; // all ones for a known cell
                const std::uintptr_t keepPtr = 0u - static_cast<std::uintptr_t>(used);
                mKeys[count] = key;
                auto* const dst = reinterpret_cast<Slot*>(
                    (reinterpret_cast<std::uintptr_t>(&scratch) & keepPtr) |
                    (reinterpret_cast<std::uintptr_t>(&mSlots[slot]) & ~keepPtr));
                *dst = Slot{mStamp, count};
                groupOf[i] = (s.group & keep) | (count & ~keep);
                count += 1u - used;
                if (count > limit) return limit + 1;
            }
        }
        return count;
    }

private:
    // \p v, hidden from the optimiser so that it selects with it instead of branching on it.
    static std::uint32_t opaque(std::uint32_t v) {
#if defined(__GNUC__)
        __asm__("" : "+r"(v));
#endif
        return v;
    }
    static bool sameCell(const CellKey& a, const CellKey& b) {
        return ((a.x ^ b.x) | (a.y ^ b.y) | (a.z ^ b.z)) == 0;
    }
    // A slot is 8 bytes and the table is sized for the limit, the keys kept apart in the order
    // the cells are met: the table's random reads stay in L2 (with the keys in the slots, 32
    // bytes a slot, sized for every leaf, it was 2 MiB for the English oak's 19,900 leaves and
    // its probes missed the cache).
    struct Slot {
        std::uint32_t stamp = 0;
        std::uint32_t group = 0;
    };
    std::vector<Slot> mSlots;
    static constexpr std::size_t kChunk = 512, kAhead = 10, kKeyAhead = 4;
    std::vector<CellKey> mKeys;         ///< the cells of the current fill, by group
    std::vector<CellKey> mCells;        ///< a chunk's cells
    std::vector<std::uint32_t> mHashes; ///< and their first slots
    std::size_t mMask = 0;
    std::uint32_t mStamp = 0;
};

/// Whether \p mids have more than \p limit distinct cells at \p cell, shown by a lower bound on
/// their count: a bit a hash of a cell (the hash's top bits), the set bits counted. Cells whose
/// hashes share a bit count once, so the bits never outnumber the cells: a count past \p limit
/// means more cells than \p limit. One pass of cells and hashes, no table lookups and no groups
/// (about half a CellTable::fill's work a leaf). The leaves are taken in strides of 16 (leaves
/// of a twig, side by side in the array, share cells): the English oak's count passes its limit
/// ~72 % through them, ~90 % in leaf order.
/// \return how many leaves it took for the count to pass \p limit, or 0 where that was not
/// shown: every leaf taken, or fewer bits than 0.8 x limit with half of them taken (on the
/// presets, sizes with too many cells had 0.84 x limit or more there, sizes taken 0.77 or less).
std::size_t leavesPastCellLimit(const RawVector<glm::dvec3>& mids, double cell, std::size_t limit) {
    // About 32 bits a cell allowed, 2 MB at most: few hashes share a bit (the oak: 2^18 bits,
    // 32 KB, in L1).
    int bitsLog2 = 6;
    while ((std::size_t{1} << bitsLog2) < 32 * (limit + 1) && bitsLog2 < 24)
        ++bitsLog2;
    std::vector<std::uint64_t> bits(std::size_t{1} << (bitsLog2 - 6), 0);
    const int shift = 64 - bitsLog2;
    std::size_t count = 0, taken = 0;
    constexpr std::size_t kStride = 16;
    for (std::size_t s0 = 0; s0 < kStride; ++s0) {
        if (s0 == kStride / 2 && 5 * count < 4 * limit) return 0;
        for (std::size_t i = s0; i < mids.size(); i += kStride) {
            const std::uint64_t b = leafCellHash(leafCell(mids[i], cell)) >> shift;
            std::uint64_t& word = bits[b >> 6];
            const std::uint64_t bit = std::uint64_t{1} << (b & 63);
            count += (word & bit) == 0;
            word |= bit;
            ++taken;
            if (count > limit) return taken;
        }
    }
    return 0;
}

/// Groups of leaf indices, one after the other in one array (compressed rows): a group a
/// vector was an allocation a group (5,000 for the English oak, and as many frees).
class LeafGroups {
public:
    std::size_t size() const { return mOffsets.size() - 1; }
    std::span<const std::uint32_t> operator[](std::size_t g) const {
        return {mLeaves.data() + mOffsets[g], mOffsets[g + 1] - mOffsets[g]};
    }
    void reserve(std::size_t groups, std::size_t leaves) {
        mOffsets.reserve(groups + 1);
        mLeaves.reserve(leaves);
    }
    void add(std::span<const std::uint32_t> group) {
        mLeaves.insert(mLeaves.end(), group.begin(), group.end());
        mOffsets.push_back(static_cast<std::uint32_t>(mLeaves.size()));
    }
    /// The groups of \p groupOf (each leaf's group, count groups), leaves in index order.
    static LeafGroups of(const std::vector<std::uint32_t>& groupOf, std::size_t count) {
        LeafGroups out;
        out.mOffsets.assign(count + 1, 0);
        for (std::uint32_t g : groupOf)
            ++out.mOffsets[g + 1];
        for (std::size_t g = 0; g < count; ++g)
            out.mOffsets[g + 1] += out.mOffsets[g];
        out.mLeaves.resize(groupOf.size());
        std::vector<std::uint32_t> next(out.mOffsets.begin(), out.mOffsets.end() - 1);
        for (std::size_t i = 0; i < groupOf.size(); ++i)
            out.mLeaves[next[groupOf[i]]++] = static_cast<std::uint32_t>(i);
        return out;
    }

private:
    std::vector<std::uint32_t> mOffsets{0}; ///< group g is [mOffsets[g], mOffsets[g + 1])
    std::vector<std::uint32_t> mLeaves;
};

// The card of a group of two or more leaves (see appendLeafClusterCards): corners then normal,
// five vec3 one after the other (finishCardFitLanes writes them so).
struct FittedCard {
    glm::vec3 corners[4];
    glm::vec3 normal;
};
static_assert(offsetof(FittedCard, normal) == 4 * sizeof(glm::vec3));

// A fitted card as a leaf whose card (size long, aspect x size wide) holds it: what the
// obstacle check of a forest tests; made only for an accept callback (kept apart: the oak's
// ~4,800 fits a tree were written, zeroed first, and read back at 132 bytes each, not 60).
struct CardBounds {
    skel::Leaf bounds;
    skel::Leaf crossBounds; ///< the same for the crossing card (LeafClusterSettings::crossed)
};

// glm::normalize(v) given glm::length(v): v * (1 / sqrt(dot(v, v))), glm's own arithmetic, the
// square root taken once where a length test comes first (the same doubles as glm::normalize).
glm::dvec3 scaledBy(const glm::dvec3& v, double length) {
    return v * (1.0 / length);
}

glm::dvec3 firstSeed(const CardFitInput& in) {
    const double length = glm::length(in.heading);
    const glm::dvec3 seed1 = length > 1e-9 ? scaledBy(in.heading, length) : glm::dvec3(0, 1, 0);
    return seed1 + glm::dvec3(1e-3, 2e-3, 3e-3);
}

// \p extent: cardExtent's a0, a1, c0 and c1.
void finishFit(const std::vector<skel::Leaf>& leaves, std::span<const std::uint32_t> group,
               float aspect, float scale, const CardFitInput& in, const CardAxes& axes,
               const double (&extent)[4], FittedCard& f, CardBounds* bounds) {
    const CardRect r = cardRect(in, axes, extent);
    cardCorners(r, axes, f.corners, f.normal);
    // The bounds only for the obstacle check (two quat_casts a card whose branches the cards'
    // turning every way mispredicted, for nothing without one).
    if (!bounds) return;
    CardBounds& b = *bounds;
    const glm::dvec3 &n = axes.n, &along = axes.along, &across = axes.across;
    const double length = r.a1 - r.a0, width = r.c1 - r.c0;
    b.bounds.position = glm::vec3(r.lo + r.cm * across);
    b.bounds.orientation =
        glm::quat_cast(glm::mat3(glm::vec3(-across), glm::vec3(along), glm::vec3(n)));
    b.bounds.size = static_cast<float>(std::max(length, width / aspect) / scale);
    b.bounds.node = leaves[group.front()].node;
    // The crossing card is the card turned a quarter round its centre line: across -> n.
    b.crossBounds = b.bounds;
    b.crossBounds.position = glm::vec3(r.lo + r.cm * across);
    b.crossBounds.orientation =
        glm::quat_cast(glm::mat3(glm::vec3(-n), glm::vec3(along), glm::vec3(-across)));
}

/// The cards of the groups of two or more leaves (the others' stay default): the two power
/// iterations of kPowerLanes groups at a time in step (each group's own arithmetic, in its own
/// order: the same cards as one group at a time, without waiting on one chain of divisions and
/// square roots after another: they were 20 % of the English oak's time; eight in step keep the
/// divider busy where four waited on it, principal 0.97 -> 0.56 ms a tree in perf record;
/// sixteen, two AVX-512 registers, overlap two chains of 24 products, as four CardFitLanes).
/// With AVX the preparation and the extent take four groups a register (CardFitLanes; eight
/// with AVX-512), the groups taken by size so that the lanes of a register have as many leaves
/// (which groups share a batch changes only the time: each lane's arithmetic is its own group's).
RawVector<FittedCard> fitCards(const std::vector<skel::Leaf>& leaves, const LeafGroups& groups,
                               float aspect, float scale, std::vector<CardBounds>* bounds) {
    // Room, not zeros (the oak's ~4,700 cards, 280 KB): a single leaf's card is set to the
    // default here, every other card is fitted.
    RawVector<FittedCard> cards(groups.size());
    if (bounds) bounds->assign(groups.size(), CardBounds{});
    const bool lanes = cardFitLanesAvailable();
    // Groups a CardFitLanes: 8 with AVX-512, 4 with AVX.
    const std::size_t width = cardFitLanesWidth();
    // The axes, extent and corners eight cards a register too (finishCardFitLanes: the bounds of
    // an obstacle check are made by the scalar finishFit).
    const bool finishLanes = width == 8 && !bounds;
    const bool secondLanes = width == 8;
    // The groups to fit, in group order, or by size (then group order) for the lanes.
    RawVector<std::uint32_t> order(groups.size());
    std::size_t fits = 0, largest = 0;
    // Without a branch on the group's size (perf annotate: a single leaf's default card, its
    // branch mispredicted, ~6 % of fitCards' samples): every card set to the default, the fits
    // overwriting theirs, and every group written to the order, counted only with two leaves.
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const std::size_t size = groups[g].size();
        cards[g] = FittedCard{};
        order[fits] = static_cast<std::uint32_t>(g);
        fits += size >= 2;
        largest = std::max(largest, size);
    }
    order.resize(fits);
    if (lanes) {
        std::vector<std::uint32_t> start(largest + 2, 0);
        for (const std::uint32_t g : order)
            ++start[groups[g].size() + 1];
        for (std::size_t s = 1; s < start.size(); ++s)
            start[s] += start[s - 1];
        RawVector<std::uint32_t> bySize(fits);
        for (const std::uint32_t g : order)
            bySize[start[groups[g].size()]++] = g;
        order = std::move(bySize);
    }
    constexpr std::size_t kLanes = kPowerLanes;
    static_assert(kLanes % 4 == 0, "whole CardFitLanes a batch");
    CardFitInput in[kLanes];
    CardFitLanes corners[kLanes / 4];
    for (std::size_t b = 0; b < fits; b += kLanes) {
        const std::size_t n = std::min(kLanes, fits - b);
        std::span<const std::uint32_t> members[kLanes];
        const std::uint32_t* const lane = order.data() + b;
        for (std::size_t k = 0; k < n; ++k)
            members[k] = groups[lane[k]];
        if (lanes) {
            for (std::size_t h = 0; width * h < n; ++h)
                prepareCardFitLanes(leaves, members + width * h, std::min(width, n - width * h),
                                    aspect, scale, in + width * h, corners[h]);
        } else {
            for (std::size_t k = 0; k < n; ++k)
                prepareCardFit(leaves, members[k], aspect, scale, in[k]);
        }
        glm::dmat3 c[kLanes];
        glm::dvec3 e1[kLanes], e2[kLanes];
        for (std::size_t k = 0; k < n; ++k) {
            c[k] = in[k].cov;
            e1[k] = firstSeed(in[k]);
        }
        largestEigenvectors(c, e1, n);
        // Eight cards a register with AVX-512 (a register whose seed vanishes in a lane: the
        // scalar secondMatrix).
        for (std::size_t first = 0; first < n; first += 8) {
            const std::size_t count = std::min<std::size_t>(8, n - first);
            if (secondLanes &&
                secondMatrixLanes(in + first, e1 + first, count, c + first, e2 + first))
                continue;
            for (std::size_t k = first; k < first + count; ++k)
                c[k] = secondMatrix(in[k], e1[k], e2[k]);
        }
        largestEigenvectors(c, e2, n);
        // The axes, extent and corners of groups [first, first + count) (whole CardFitLanes
        // where there are lanes), one stage after the other.
        const auto finish = [&](std::size_t first, std::size_t count) {
            CardAxes axes[kLanes];
            cardAxes(in + first, members + first, e1 + first, e2 + first, axes, count);
            double extent[kLanes][4];
            if (lanes) {
                glm::dvec3 along[kLanes], across[kLanes];
                for (std::size_t k = 0; k < count; ++k) {
                    along[k] = axes[k].along;
                    across[k] = axes[k].across;
                }
                for (std::size_t h = 0; width * h < count; ++h)
                    cardExtentLanes(corners[first / width + h], in + first + width * h,
                                    along + width * h, across + width * h,
                                    std::min(width, count - width * h), extent + width * h);
            } else {
                for (std::size_t k = 0; k < count; ++k)
                    cardExtent(in[first + k], axes[k].along, axes[k].across, extent[k][0],
                               extent[k][1], extent[k][2], extent[k][3]);
            }
            for (std::size_t k = 0; k < count; ++k)
                finishFit(leaves, members[first + k], aspect, scale, in[first + k], axes[k],
                          extent[k], cards[lane[first + k]],
                          bounds ? &(*bounds)[lane[first + k]] : nullptr);
        };
        if (!finishLanes) {
            finish(0, n);
            continue;
        }
        // Eight cards a zmm register (AVX-512, no obstacle bounds wanted): the same axes, extent
        // and corners; a register with a lane whose e2 runs along its e1 takes the scalar path.
        for (std::size_t h = 0; width * h < n; ++h) {
            const std::size_t first = width * h, count = std::min(width, n - first);
            glm::vec3* out[8];
            for (std::size_t k = 0; k < count; ++k)
                out[k] = cards[lane[first + k]].corners;
            if (!finishCardFitLanes(corners[h], in + first, members + first, e1 + first, e2 + first,
                                    count, out))
                finish(first, count);
        }
    }
    return cards;
}

// groupLeaves' groups as LeafGroups.
LeafGroups groupLeafIndices(const std::vector<skel::Leaf>& leaves, double sizeScale,
                            int leavesPerCard) {
    if (leaves.empty()) return {};
    std::vector<std::uint32_t> groupOf(leaves.size());
    if (leavesPerCard <= 1) {
        for (std::size_t i = 0; i < leaves.size(); ++i)
            groupOf[i] = static_cast<std::uint32_t>(i);
        return LeafGroups::of(groupOf, leaves.size());
    }

    // The first cell size of 1.2 x the mean leaf, growing by 8 %, at which there are no more
    // than leaves / leavesPerCard groups (40 sizes at most, the last taken whatever it gives).
    // Each size only counts its cells, and stops counting past the limit; the groups are made
    // once, for the size chosen.
    // The leaf's middle, not its stem: a leaf belongs where most of it is. The same for every
    // cell size tried, so made once a leaf.
    RawVector<glm::dvec3> mids;
    const double mean =
        std::max(leafMiddles(leaves, sizeScale, mids) / static_cast<double>(leaves.size()), 1e-4);
    // The groups come from the count that passed, not from one more pass over the leaves.
    const auto limit = static_cast<std::size_t>(
        std::floor(static_cast<double>(leaves.size()) / static_cast<double>(leavesPerCard)));
    CellTable table(std::min(limit + 1, leaves.size()));
    double cell = 1.2 * mean;
    std::size_t count = limit + 1;
    // A size is first ruled out by a bound on its cells' count where that is likely to (about
    // half a fill's work a leaf, less where it passes the limit early); the table is filled
    // where the bound does not rule it out. Which sizes are bounded changes only the time: the
    // first, and each after one the bound ruled out within 60 % of the leaves (the oak's first
    // size within ~72 %: its second, taken, is filled at once; the beech's and the willow's
    // first sizes within ~45-65 %).
    bool bound = true;
    for (int step = 0; step < 39 && count > limit; ++step) {
        if (bound) {
            const std::size_t taken = leavesPastCellLimit(mids, cell, limit);
            if (taken > 0) {
                bound = 10 * taken < 6 * mids.size();
                cell *= 1.08;
                continue;
            }
        }
        bound = false;
        count = table.fill(mids, cell, limit, groupOf);
        if (count > limit) cell *= 1.08;
    }
    if (count > limit) count = CellTable(leaves.size()).fill(mids, cell, leaves.size(), groupOf);
    // The groups one after the other in group order, each in leaf order.
    return LeafGroups::of(groupOf, count);
}

} // namespace

std::vector<std::vector<std::uint32_t>> groupLeaves(const std::vector<skel::Leaf>& leaves,
                                                    double sizeScale, int leavesPerCard) {
    const LeafGroups groups = groupLeafIndices(leaves, sizeScale, leavesPerCard);
    std::vector<std::vector<std::uint32_t>> out(groups.size());
    for (std::size_t g = 0; g < groups.size(); ++g)
        out[g].assign(groups[g].begin(), groups[g].end());
    return out;
}

struct LeafClusterPlan::Data {
    LeafGroups groups;
    RawVector<FittedCard> fitted;      ///< a group's card (a single leaf's: unused)
    float aspect = 0.0f, scale = 0.0f; ///< a single leaf's card (leafCorners)
};

LeafClusterPlan::LeafClusterPlan() = default;
LeafClusterPlan::~LeafClusterPlan() = default;
LeafClusterPlan::LeafClusterPlan(LeafClusterPlan&&) noexcept = default;
LeafClusterPlan& LeafClusterPlan::operator=(LeafClusterPlan&&) noexcept = default;

LeafClusterPlan planLeafClusterCards(const std::vector<skel::Leaf>& leaves,
                                     const LeafCardSettings& cards,
                                     const LeafClusterSettings& clusters,
                                     const std::function<bool(const skel::Leaf&)>& accept) {
    requireRange("leaf_aspect", cards.aspect, 1e-6, 4.0);
    requireRange("leaf_scale", cards.sizeScale, 1e-6, 100.0);
    requireRange("leaf_cluster_size", clusters.leavesPerCard, 0.0, 64.0);
    LeafClusterPlan plan;
    plan.mLeaves = leaves.size();
    plan.mCrossed = clusters.crossed;
    if (leaves.empty()) return plan;
    const auto aspect = static_cast<float>(cards.aspect);
    const auto scale = static_cast<float>(cards.sizeScale);
    LeafGroups groups = groupLeafIndices(leaves, cards.sizeScale, clusters.leavesPerCard);
    // Each group's card, fitted once (it was fitted again for the mesh after the check).
    std::vector<CardBounds> bounds;
    RawVector<FittedCard> fitted =
        fitCards(leaves, groups, aspect, scale, accept ? &bounds : nullptr);
    if (accept) {
        LeafGroups kept;
        RawVector<FittedCard> keptFits;
        kept.reserve(groups.size(), leaves.size());
        keptFits.reserve(groups.size());
        for (std::size_t k = 0; k < groups.size(); ++k) {
            const std::span<const std::uint32_t> g = groups[k];
            const CardBounds& b = bounds[k];
            if (g.size() < 2 ||
                (accept(b.bounds) && (!clusters.crossed || accept(b.crossBounds)))) {
                kept.add(g);
                keptFits.push_back(fitted[k]);
            } else {
                for (const std::uint32_t& i : g) {
                    kept.add({&i, 1});
                    keptFits.push_back(FittedCard{});
                }
            }
        }
        groups = std::move(kept);
        fitted = std::move(keptFits);
    }
    std::size_t cardCount = groups.size();
    if (clusters.crossed)
        for (std::size_t g = 0; g < groups.size(); ++g)
            cardCount += groups[g].size() > 1;
    plan.mCards = cardCount;
    plan.mData = std::make_unique<LeafClusterPlan::Data>();
    plan.mData->groups = std::move(groups);
    plan.mData->fitted = std::move(fitted);
    plan.mData->aspect = aspect;
    plan.mData->scale = scale;
    return plan;
}

std::size_t appendLeafClusterCards(Mesh& out, const std::vector<skel::Leaf>& leaves,
                                   const LeafClusterSettings& clusters,
                                   const skel::Skeleton* skeleton, const LeafClusterPlan& plan) {
    if (plan.mLeaves != leaves.size() || plan.mCrossed != clusters.crossed)
        throw InvalidInput("leaf cluster cards: the plan was made for other leaves or settings");
    if (leaves.empty()) return 0;
    const LeafGroups& groups = plan.mData->groups;
    const RawVector<FittedCard>& fitted = plan.mData->fitted;
    const float aspect = plan.mData->aspect, scale = plan.mData->scale;
    const std::size_t cardCount = plan.mCards;
    // Room made, not filled: the positions, normals, uvs and indices are appended below.
    // resize() within the capacity the bark reserved for the cards (TubeSettings::
    // reserveVertices) value-initialised the glm vectors one at a time through a stack
    // temporary written in parts and read back whole, a failed store-to-load forwarding a
    // vertex (perf annotate: ~3 % of the English oak's samples, more than the move it saved).
    const CardSpan span = reserveForCards(out, cardCount);
    const std::size_t v0 = span.firstVertex;
    const bool wind = span.wind;
    const bool ids = span.ids;
    Rng rng(mixSeed(clusters.seed, salt::kLeafClusters));
    // Two texels of inset (of the 1024 x 512 atlas) keep a tile's neighbours out of its
    // bilinear footprint.
    const glm::vec2 inset(2.0f / 1024.0f, 2.0f / 512.0f);
    const glm::vec2 tileSize(1.0f / static_cast<float>(kClusterAtlasColumns),
                             1.0f / static_cast<float>(kClusterAtlasRows));
    // Each tile's corners' uvs, plain and mirrored, made once (not once a vertex).
    glm::vec2 tileUvs[kClusterSprays + 1][2][4];
    for (int tile = 0; tile <= kClusterSprays; ++tile)
        for (int mirror = 0; mirror < 2; ++mirror) {
            const glm::vec2 origin =
                tileSize * glm::vec2(static_cast<float>(tile % kClusterAtlasColumns),
                                     static_cast<float>(tile / kClusterAtlasColumns));
            const float u0 = mirror ? 1.0f : 0.0f, u1 = mirror ? 0.0f : 1.0f;
            const glm::vec2 local[4] = {{u0, 0}, {u1, 0}, {u1, 1}, {u0, 1}};
            for (int c = 0; c < 4; ++c)
                tileUvs[tile][mirror][c] = origin + inset + local[c] * (tileSize - 2.0f * inset);
        }
    std::size_t card = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const std::span<const std::uint32_t> group = groups[g];
        const skel::Leaf& first = leaves[group.front()];
        glm::vec3 corners[4];
        glm::vec3 normal;
        int tile = kClusterSprays; // the single leaf
        bool mirror = false;
        if (group.size() == 1) {
            leafCorners(first, aspect, scale, corners);
            normal = glm::normalize(skel::upOf(first.orientation));
            // Drawn every time so that a cluster's look does not depend on its neighbours.
            (void)rng.below(kClusterSprays);
            (void)rng.uniformf(0.0f, 1.0f);
        } else {
            const FittedCard& f = fitted[g];
            for (int c = 0; c < 4; ++c)
                corners[c] = f.corners[c];
            normal = f.normal;
            tile = static_cast<int>(rng.below(kClusterSprays));
            mirror = rng.uniformf(0.0f, 1.0f) < 0.5f;
        }
        const bool known =
            skeleton && first.node >= 0 && static_cast<std::size_t>(first.node) < skeleton->size();
        const std::uint32_t nodeId =
            first.node >= 0 ? static_cast<std::uint32_t>(first.node) : Mesh::kNoNode;
        const auto order = known ? skeleton->order[static_cast<std::size_t>(first.node)]
                                 : decltype(skeleton->order)::value_type{0};
        const int sheets = clusters.crossed && group.size() > 1 ? 2 : 1;
        for (int sheet = 0; sheet < sheets; ++sheet, ++card) {
            if (sheet == 1) {
                // The crossing card: the same centre line (stem edge to tip edge), turned a
                // quarter round it.
                const glm::vec3 lo = 0.5f * (corners[0] + corners[1]);
                const glm::vec3 hi = 0.5f * (corners[2] + corners[3]);
                const glm::vec3 half = 0.5f * (corners[0] - corners[1]);
                const glm::vec3 turned = normal * glm::length(half);
                corners[0] = lo + turned;
                corners[1] = lo - turned;
                corners[2] = hi - turned;
                corners[3] = hi + turned;
                const float len = glm::length(half);
                normal = len > 0.0f ? -half / len : normal; // as the winding faces
                mirror = !mirror;
                tile = (tile + 3) % kClusterSprays; // another spray: no twin pictures
            }
            const std::size_t v = v0 + 4 * card;
            const glm::vec2* uv = tileUvs[tile][mirror ? 1 : 0];
            for (std::size_t c = 0; c < 4; ++c) {
                out.positions.push_back(corners[c]);
                out.normals.push_back(normal);
                out.uvs.push_back(uv[c]);
            }
            if (ids) std::fill_n(out.node.begin() + static_cast<std::ptrdiff_t>(v), 4, nodeId);
            if (wind) {
                std::fill_n(out.branchOrder.begin() + static_cast<std::ptrdiff_t>(v), 4, order);
                std::fill_n(out.flexibility.begin() + static_cast<std::ptrdiff_t>(v), 4, 1.0f);
            }
            // One index at a time: the six written to a stack array and inserted were read
            // back 8 and 16 bytes at a time from 4-byte stores, a failed store-to-load forwarding
            // a card (perf annotate: ~27 % of appendLeafClusterCards' samples).
            const auto b = static_cast<std::uint32_t>(v);
            out.indices.push_back(b);
            out.indices.push_back(b + 1);
            out.indices.push_back(b + 2);
            out.indices.push_back(b);
            out.indices.push_back(b + 2);
            out.indices.push_back(b + 3);
        }
    }
    out.submeshes.push_back({"leaf", static_cast<std::uint32_t>(span.firstIndex),
                             static_cast<std::uint32_t>(6 * cardCount)});
    return cardCount;
}

std::size_t appendLeafClusterCards(Mesh& out, const std::vector<skel::Leaf>& leaves,
                                   const LeafCardSettings& cards,
                                   const LeafClusterSettings& clusters,
                                   const skel::Skeleton* skeleton,
                                   const std::function<bool(const skel::Leaf&)>& accept) {
    return appendLeafClusterCards(out, leaves, clusters, skeleton,
                                  planLeafClusterCards(leaves, cards, clusters, accept));
}

} // namespace sylva::mesh
