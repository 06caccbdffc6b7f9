#include "engine/mesh/leaflight.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "engine/mesh/rankselect.h"

namespace sylva::mesh {

namespace {

constexpr double kCell = 0.5; // metres: a few leaves' spread, finer than a branch's spray

std::uint64_t cellKey(int x, int y, int z) {
    auto u = [](int v) {
        return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v) & 0x1fffff);
    };
    return (u(x) << 42) | (u(y) << 21) | u(z);
}

// floor(v) as an int without a call to floor (not inlined below SSE4.1): the same value for
// every v in the int range.
int floorToInt(double v) {
    const auto i = static_cast<int>(v);
    return static_cast<double>(i) > v ? i - 1 : i;
}

glm::ivec3 cellOf(const glm::dvec3& p) {
    const glm::dvec3 q = p / kCell;
    return {floorToInt(q.x), floorToInt(q.y), floorToInt(q.z)};
}

// cellOf(glm::dvec3(leaf.position)) in floats, three axes to an SSE2 register: a float
// coordinate times 2 (one over kCell) is exact in float as in double (an overflow to infinity
// converts to the same out-of-range int as the double), so the floors and the ints are the same;
// the conversions and the floors' corrections are the same operations in single precision.
#if defined(__SSE2__)
// The cell's x, y and z in the low three lanes (the fourth: the next float's, unused).
__m128i leafCellLanes(const skel::Leaf& leaf) {
    static_assert(sizeof(skel::Leaf) >= 16 && offsetof(skel::Leaf, position) == 0);
    static_assert(1.0 / kCell == 2.0);
    float xyzw[4];
    std::memcpy(xyzw, &leaf, sizeof xyzw); // the position and the next float (unused)
    const __m128 q = _mm_mul_ps(_mm_loadu_ps(xyzw), _mm_set1_ps(2.0f));
    const __m128i i = _mm_cvttps_epi32(q);
    // floorToInt: one less where the truncation is above the quotient (same for NaN: none).
    return _mm_add_epi32(i, _mm_castps_si128(_mm_cmpgt_ps(_mm_cvtepi32_ps(i), q)));
}

glm::ivec3 lanesToCell(__m128i c) {
    return {_mm_cvtsi128_si32(c), _mm_cvtsi128_si32(_mm_shuffle_epi32(c, 0x55)),
            _mm_cvtsi128_si32(_mm_shuffle_epi32(c, 0xAA))};
}
#endif

glm::ivec3 leafCellOf(const skel::Leaf& leaf) {
#if defined(__SSE2__)
    return lanesToCell(leafCellLanes(leaf));
#else
    return cellOf(glm::dvec3(leaf.position));
#endif
}

} // namespace

// The box of the cells of the leaves on a node below \p n (glm::min and glm::max of their
// cells, from INT_MAX and INT_MIN), and their count: on SSE2 the three axes in one register,
// kept there (each cell stored and read back as three ints was a tenth of leafCardLight).
std::size_t leafCellBoxOfCells(const std::vector<skel::Leaf>& leaves, std::size_t n, glm::ivec3& lo,
                               glm::ivec3& hi) {
    std::size_t count = 0;
#if defined(__SSE2__)
    // Two boxes, of the even and the odd leaves, joined at the end (integers: the same box): each
    // step's compare and select (three operations in a chain) waited on the step before.
    auto least = [](__m128i a, __m128i b) { // lane by lane the lesser
        const __m128i above = _mm_cmpgt_epi32(a, b);
        return _mm_or_si128(_mm_and_si128(above, b), _mm_andnot_si128(above, a));
    };
    auto greatest = [](__m128i a, __m128i b) { // lane by lane the greater
        const __m128i below = _mm_cmpgt_epi32(b, a);
        return _mm_or_si128(_mm_and_si128(below, b), _mm_andnot_si128(below, a));
    };
    __m128i l[2], h[2];
    for (int k = 0; k < 2; ++k) {
        l[k] = _mm_set1_epi32(std::numeric_limits<int>::max());
        h[k] = _mm_set1_epi32(std::numeric_limits<int>::min());
    }
    const std::size_t size = leaves.size();
    for (std::size_t i = 0; i < size; i += 2)
        for (std::size_t k = 0; k < 2 && i + k < size; ++k) {
            const skel::Leaf& leaf = leaves[i + k];
            if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) continue;
            const __m128i c = leafCellLanes(leaf);
            l[k] = least(l[k], c);
            h[k] = greatest(h[k], c);
            ++count;
        }
    // (a box with no leaf is INT_MAX and INT_MIN: the other one's is kept)
    l[0] = least(l[0], l[1]);
    h[0] = greatest(h[0], h[1]);
    lo = lanesToCell(l[0]);
    hi = lanesToCell(h[0]);
#else
    lo = glm::ivec3(std::numeric_limits<int>::max());
    hi = glm::ivec3(std::numeric_limits<int>::min());
    for (const skel::Leaf& leaf : leaves) {
        if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) continue;
        const glm::ivec3 c = leafCellOf(leaf);
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
        ++count;
    }
#endif
    return count;
}

// leafCellBoxOfCells' box from the positions' box: a cell is floor(2 v) of each coordinate v, which
// never decreases as v grows, so the least cell is the least coordinate's and the greatest the
// greatest's, where every 2 v is a number within the int range (then floor(2 v) is exact, and
// a float's 2 v is exact). A leaf a minps and a maxps (no conversions, floors, compares and
// selects a leaf: the box was a fifth of leafCardLight); where a coordinate is NaN or a box's
// 2 v is past 2^30, the cells' own box (leafCellBoxOfCells), whose conversions say what such a
// leaf's cell is.
std::size_t leafCellBox(const std::vector<skel::Leaf>& leaves, std::size_t n, glm::ivec3& lo,
                        glm::ivec3& hi) {
#if defined(__SSE2__)
    __m128 l[2], h[2], nan[2];
    for (int k = 0; k < 2; ++k) {
        l[k] = _mm_set1_ps(std::numeric_limits<float>::infinity());
        h[k] = _mm_set1_ps(-std::numeric_limits<float>::infinity());
        nan[k] = _mm_setzero_ps();
    }
    std::size_t count = 0;
    const std::size_t size = leaves.size();
    for (std::size_t i = 0; i < size; i += 2)
        for (std::size_t k = 0; k < 2 && i + k < size; ++k) {
            const skel::Leaf& leaf = leaves[i + k];
            if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) continue;
            float xyzw[4];
            std::memcpy(xyzw, &leaf, sizeof xyzw); // the position and the next float (unused)
            const __m128 p = _mm_loadu_ps(xyzw);
            l[k] = _mm_min_ps(l[k], p);
            h[k] = _mm_max_ps(h[k], p);
            nan[k] = _mm_or_ps(nan[k], _mm_cmpunord_ps(p, p));
            ++count;
        }
    if (count == 0) {
        lo = glm::ivec3(std::numeric_limits<int>::max());
        hi = glm::ivec3(std::numeric_limits<int>::min());
        return 0;
    }
    const __m128 least = _mm_mul_ps(_mm_min_ps(l[0], l[1]), _mm_set1_ps(2.0f));
    const __m128 greatest = _mm_mul_ps(_mm_max_ps(h[0], h[1]), _mm_set1_ps(2.0f));
    const __m128 limit = _mm_set1_ps(1073741824.0f); // 2^30
    const __m128 outside =
        _mm_or_ps(_mm_or_ps(nan[0], nan[1]),
                  _mm_or_ps(_mm_cmplt_ps(least, _mm_sub_ps(_mm_setzero_ps(), limit)),
                            _mm_cmpgt_ps(greatest, limit)));
    if ((_mm_movemask_ps(outside) & 7) != 0) return leafCellBoxOfCells(leaves, n, lo, hi);
    auto floors = [](__m128 q) { // floorToInt of each lane (q within the int range)
        const __m128i i = _mm_cvttps_epi32(q);
        return lanesToCell(_mm_add_epi32(i, _mm_castps_si128(_mm_cmpgt_ps(_mm_cvtepi32_ps(i), q))));
    };
    lo = floors(least);
    hi = floors(greatest);
    return count;
#else
    return leafCellBoxOfCells(leaves, n, lo, hi);
#endif
}

namespace {

// The mean of a card's \p count corners in doubles, summed in order from +0.
glm::dvec3 centreOf(const glm::vec3* corners, std::size_t count) {
    glm::dvec3 centre(0.0);
    for (std::size_t k = 0; k < count; ++k)
        centre += glm::dvec3(corners[k]);
    // Four corners: times a quarter, the quotient's bits without a division.
    if (count == 4)
        centre *= 0.25;
    else
        centre /= static_cast<double>(count);
    return centre;
}

// cellOf(centreOf(...)) of a card's four corners, x and y in one SSE2 register of doubles
// (each lane the same sums from +0, the same quarter and floor as the scalar ones).
glm::ivec3 cardCellOf(const glm::vec3* corners) {
#if defined(__SSE2__)
    __m128d xy = _mm_setzero_pd();
    double z = 0.0;
    for (int k = 0; k < 4; ++k) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &corners[k].x, sizeof bits); // x and y
        xy = _mm_add_pd(
            xy, _mm_cvtps_pd(_mm_castsi128_ps(_mm_cvtsi64_si128(static_cast<long long>(bits)))));
        z += static_cast<double>(corners[k].z);
    }
    const __m128d q = _mm_mul_pd(_mm_mul_pd(xy, _mm_set1_pd(0.25)), _mm_set1_pd(1.0 / kCell));
    const __m128i i = _mm_cvttpd_epi32(q); // two ints, low lanes
    const __m128i above = _mm_shuffle_epi32(_mm_castpd_si128(_mm_cmpgt_pd(_mm_cvtepi32_pd(i), q)),
                                            _MM_SHUFFLE(3, 3, 2, 0));
    alignas(16) int c[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(c), _mm_add_epi32(i, above));
    return {c[0], c[1], floorToInt(z * 0.25 / kCell)};
#else
    return cellOf(centreOf(corners, 4));
#endif
}

// The light a node gathers itself: its record less its children's (a space colonization node's
// own exposure, a self-organizing tip's buds'); where that is nothing (a self-organizing node
// whose buds all grew or were shed), the mean per tip of its subtree.
std::vector<float> ownLight(const skel::Skeleton& s) {
    const std::size_t n = s.size();
    std::vector<double> children(n, 0.0), tips(n, 0.0);
    std::vector<char> hasChild(n, 0);
    std::vector<float> out(n);
    // One walk from the last node back: a node comes after its parent (Skeleton::validate), so
    // its children have added to its sums and marked it by the time it is reached (three walks
    // before, one to mark the parents and one for the results; the same sums in the same order).
    for (std::size_t i = n; i-- > 0;) {
        if (!hasChild[i]) tips[i] += 1.0;
        const double own = s.light[i] - children[i];
        out[i] = static_cast<float>(own > 1e-4 * std::max(1.0, static_cast<double>(s.light[i]))
                                        ? own
                                        : s.light[i] / std::max(tips[i], 1.0));
        if (s.parent[i] < 0) continue;
        const auto p = static_cast<std::size_t>(s.parent[i]);
        hasChild[p] = 1;
        tips[p] += tips[i];
        children[p] += s.light[i];
    }
    return out;
}

struct Sum {
    double light = 0.0;
    double count = 0.0;
};

/// The leaves' cells: open addressing over cellKey's 63-bit keys, doubled when half full (a
/// std::unordered_map was a node allocation and a pointer chase a cell: most of this file's
/// time in perf record of the English oak; the oak's ~20k leaves fill about 2k cells).
class CellSums {
public:
    CellSums() { resize(1024); }
    Sum& operator[](std::uint64_t key) {
        std::size_t slot = slotOf(key);
        if (mKeys[slot] != kEmpty) return mSums[slot];
        if (2 * (mUsed + 1) > mKeys.size()) {
            resize(2 * mKeys.size());
            slot = slotOf(key);
        }
        ++mUsed;
        mKeys[slot] = key;
        return mSums[slot];
    }
    const Sum* find(std::uint64_t key) const {
        const std::size_t slot = slotOf(key);
        return mKeys[slot] == key ? &mSums[slot] : nullptr;
    }

private:
    static constexpr std::uint64_t kEmpty = ~std::uint64_t{0}; ///< no cellKey has bit 63
    void resize(std::size_t n) {
        std::vector<std::uint64_t> keys(n, kEmpty);
        std::vector<Sum> sums(n);
        std::swap(keys, mKeys);
        std::swap(sums, mSums);
        mShift = 64;
        for (std::size_t k = n; k > 1; k /= 2)
            --mShift;
        for (std::size_t i = 0; i < keys.size(); ++i)
            if (keys[i] != kEmpty) {
                const std::size_t slot = slotOf(keys[i]);
                mKeys[slot] = keys[i];
                mSums[slot] = sums[i];
            }
    }
    // The slot of key, or the empty slot where it would go: the product's top bits (which
    // every bit of the key reaches).
    std::size_t slotOf(std::uint64_t key) const {
        const std::size_t mask = mKeys.size() - 1;
        std::size_t slot = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> mShift);
        while (mKeys[slot] != kEmpty && mKeys[slot] != key)
            slot = (slot + 1) & mask;
        return slot;
    }
    std::vector<std::uint64_t> mKeys;
    std::vector<Sum> mSums;
    std::size_t mUsed = 0;
    int mShift = 54;
};

/// The leaves' sums by cell, and a card's: its own cell's, or where no leaf is in it, its 27
/// cells' (in the order dx, dy, dz, each from -1 to 1). Over the leaves' box of cells a dense
/// grid of the cells' sums (no hash and no probe; the 27-cell fallback was a quarter
/// of this file's time in perf record of the English oak, most of it probing for empty cells);
/// CellSums where that box is much larger than the leaves. Both look cells up by cellKey's
/// 21-bit coordinates, so the same cells meet (far ones alias alike).
class LeafSums {
public:
    LeafSums(const std::vector<skel::Leaf>& leaves, const std::vector<float>& perTip) {
        const std::size_t n = perTip.size();
        mLeaves = &leaves;
        mPerTip = &perTip;
        // The box of the counted leaves' cells first; their cells are made again as they are
        // summed (kept from this pass, 20 bytes a leaf written and read back, they were slower).
        glm::ivec3 lo, hi;
        mCount = leafCellBox(leaves, n, lo, hi);
        if (mCount == 0) lo = hi = glm::ivec3(0);
        mLo = lo;
        std::int64_t size = 1;
        bool narrow = true;
        for (int a = 0; a < 3; ++a) {
            mExtent[a] = static_cast<std::int64_t>(hi[a]) - lo[a] + 1;
            narrow = narrow && mExtent[a] <= (std::int64_t{1} << 21);
            // (an extent past 2^21 is not narrow: capped there, the product cannot overflow)
            size = std::min<std::int64_t>(
                size * std::min<std::int64_t>(mExtent[a], (std::int64_t{1} << 21) + 1),
                std::int64_t{1} << 40);
        }
        // The grid where it is at most about 8 cells a leaf (the oak: ~17k cells, ~19k leaves;
        // 16 bytes a cell, what 32 cells a leaf of 4-byte slots into the sums took).
        mDense = mCount > 0 && narrow && size <= 4096 + 8 * static_cast<std::int64_t>(mCount);
        if (mDense) mGrid.assign(static_cast<std::size_t>(size), Sum{});
        // Each cell's sums in the grid itself: no slot to look up and no branch on a new cell
        // (slots into sums made as cells were met: a branch about one leaf in ten, mispredicted).
        if (mDense) {
            // The grid's box and strides in locals (members reloaded after every sum's store).
            const auto lx = static_cast<std::uint32_t>(mLo.x),
                       ly = static_cast<std::uint32_t>(mLo.y),
                       lz = static_cast<std::uint32_t>(mLo.z);
            const auto ey = static_cast<std::size_t>(mExtent[1]),
                       ez = static_cast<std::size_t>(mExtent[2]);
            Sum* const grid = mGrid.data();
            const float* const light = perTip.data();
#if defined(__SSE2__)
            // Where every offset and the x stride (ey ez) fit 15 bits (the oak's box: ~17k
            // cells), the slot in the register: the offsets packed to 16 bits, ox ey ez + oy ez
            // and oz + 0 by one pmaddwd, then added (the same integer as the scalar slot below:
            // nothing overflows); the three cells' ints extracted, and ten integer operations, a
            // leaf before.
            const std::size_t strideX = ey * ez;
            if (mExtent[0] < 32768 && strideX < 32768) {
                const __m128i lo = _mm_setr_epi32(mLo.x, mLo.y, mLo.z, 0);
                const __m128i mask = _mm_set1_epi32(0x1fffff);
                const __m128i weights = _mm_setr_epi16(static_cast<short>(strideX),
                                                       static_cast<short>(ez), 1, 0, 0, 0, 0, 0);
                for (const skel::Leaf& leaf : leaves) {
                    if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) continue;
                    const __m128i o = _mm_and_si128(_mm_sub_epi32(leafCellLanes(leaf), lo), mask);
                    const __m128i terms = _mm_madd_epi16(_mm_packs_epi32(o, o), weights);
                    const auto slot = static_cast<std::size_t>(static_cast<std::uint32_t>(
                        _mm_cvtsi128_si32(_mm_add_epi32(terms, _mm_shuffle_epi32(terms, 0x55)))));
                    Sum& s = grid[slot];
                    s.light += light[static_cast<std::size_t>(leaf.node)];
                    s.count += 1.0;
                }
                return;
            }
#endif
            for (const skel::Leaf& leaf : leaves) {
                if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) continue;
                const glm::ivec3 c = leafCellOf(leaf);
                // The cell's slot: offset() of each axis, z fastest, then y (as at() reads).
                const std::size_t slot =
                    ((static_cast<std::size_t>((static_cast<std::uint32_t>(c.x) - lx) & 0x1fffff) *
                          ey +
                      ((static_cast<std::uint32_t>(c.y) - ly) & 0x1fffff)) *
                     ez) +
                    ((static_cast<std::uint32_t>(c.z) - lz) & 0x1fffff);
                Sum& s = grid[slot];
                s.light += light[static_cast<std::size_t>(leaf.node)];
                s.count += 1.0;
            }
        } else {
            for (const skel::Leaf& leaf : leaves) {
                if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) continue;
                const glm::ivec3 c = leafCellOf(leaf);
                Sum& s = mCells[cellKey(c.x, c.y, c.z)];
                s.light += perTip[static_cast<std::size_t>(leaf.node)];
                s.count += 1.0;
            }
        }
    }

    bool empty() const {
        return mCount == 0;
    }

    /// Every leaf's sums, in leaf order: made only for a card with no leaf in its 27 cells (one
    /// chain of additions over all the leaves, a tenth of leafCardLight where it was made as
    /// the cells were filled).
    Sum all() const {
        Sum s;
        for (const skel::Leaf& leaf : *mLeaves) {
            if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= mPerTip->size()) continue;
            s.light += (*mPerTip)[static_cast<std::size_t>(leaf.node)];
            s.count += 1.0;
        }
        return s;
    }

    Sum around(const glm::ivec3& c) const {
        if (!mDense) {
            Sum s;
            if (const Sum* own = mCells.find(cellKey(c.x, c.y, c.z))) s = *own;
            if (s.count == 0.0)
                for (int dx = -1; dx <= 1; ++dx)
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dz = -1; dz <= 1; ++dz)
                            if (const Sum* near =
                                    mCells.find(cellKey(c.x + dx, c.y + dy, c.z + dz))) {
                                s.light += near->light;
                                s.count += near->count;
                            }
            return s;
        }
        Sum s = at(c.x, c.y, c.z);
        if (s.count == 0.0)
            // An empty cell's sums are +0, and no sum is -0 (sums start at +0, and +0
            // plus -0 is +0): adding them leaves s's bits as skipping them did.
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dz = -1; dz <= 1; ++dz) {
                        const Sum& near = at(c.x + dx, c.y + dy, c.z + dz);
                        s.light += near.light;
                        s.count += near.count;
                    }
        return s;
    }

private:
    // The offset of a cell inside the box (its coordinates taken modulo 2^21 as cellKey takes
    // them: the box is narrower than 2^21 cells, so each cell of it has its own key).
    std::uint32_t offset(int v, int a) const {
        return (static_cast<std::uint32_t>(v) - static_cast<std::uint32_t>(mLo[a])) & 0x1fffff;
    }
    // A cell's sums, +0 where no leaf is in it.
    const Sum& at(int x, int y, int z) const {
        static constexpr Sum kNone{};
        const std::uint32_t ox = offset(x, 0), oy = offset(y, 1), oz = offset(z, 2);
        if (ox >= mExtent[0] || oy >= mExtent[1] || oz >= mExtent[2]) return kNone;
        return mGrid[(static_cast<std::size_t>(ox) * static_cast<std::size_t>(mExtent[1]) + oy) *
                         static_cast<std::size_t>(mExtent[2]) +
                     oz];
    }

    bool mDense = false;
    glm::ivec3 mLo{0};
    std::int64_t mExtent[3]{};
    std::vector<Sum> mGrid; ///< the box's cells' sums, z fastest, then y
    CellSums mCells;
    const std::vector<skel::Leaf>* mLeaves = nullptr;
    const std::vector<float>* mPerTip = nullptr;
    std::size_t mCount = 0; ///< the leaves counted (on a node of the skeleton)
};

} // namespace

std::vector<float> leafCardLight(const Mesh& mesh, std::size_t firstVertex,
                                 const std::vector<skel::Leaf>& leaves,
                                 const skel::Skeleton& skeleton) {
    const std::size_t n = skeleton.size();
    if (n == 0 || skeleton.light.size() != n || firstVertex >= mesh.positions.size()) return {};
    const std::vector<float> perTip = ownLight(skeleton);
    const LeafSums sums(leaves, perTip);
    if (sums.empty()) return {};
    Sum all;
    bool allMade = false;
    const std::size_t vertices = mesh.positions.size() - firstVertex;
    std::vector<float> light((vertices + 3) / 4);
    for (std::size_t card = 0; card < light.size(); ++card) {
        const std::size_t v = firstVertex + 4 * card;
        const std::size_t end = std::min(mesh.positions.size(), v + 4);
        Sum s = sums.around(end - v == 4 ? cardCellOf(&mesh.positions[v])
                                         : cellOf(centreOf(&mesh.positions[v], end - v)));
        if (s.count == 0.0) {
            if (!allMade) all = sums.all();
            allMade = true;
            s = all;
        }
        light[card] = static_cast<float>(s.light / s.count);
    }
    // Spread between the 5th and 50th percentiles: the records' scale depends on the crown's
    // density and the voxel size; what the tint needs is which cards are lit among these. The
    // lit half keeps the texture's brightness, so the crown's outside is no darker than it was
    // (with the 80th, the side views of the oak, beech and maple lost 12-23 % of their
    // brightness; with the 50th, 9-16 %).
    // The two order statistics by selection, not a full sort (the same values): by the floats'
    // bits where every value is +0 or above (the usual case: the two std::nth_element were ~35 us
    // of the English oak's ~4,800 cards), else by std::nth_element.
    const std::size_t midRank = light.size() / 2, lowRank = light.size() / 20;
    float hi = 0.0f, lo = 0.0f;
    if (!valueAtRank(light, midRank, hi) || !valueAtRank(light, lowRank, lo)) {
        std::vector<float> sorted = light;
        const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(midRank);
        std::nth_element(sorted.begin(), mid, sorted.end());
        hi = *mid;
        const auto low = sorted.begin() + static_cast<std::ptrdiff_t>(lowRank);
        std::nth_element(sorted.begin(), low, mid);
        lo = *low;
    }
    const float span = hi - lo;
    for (float& l : light)
        l = span > 1e-9f ? std::clamp((l - lo) / span, 0.0f, 1.0f) : 1.0f;
    return light;
}

} // namespace sylva::mesh
