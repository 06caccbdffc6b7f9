#include "engine/growth/shadowgrid.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <string>

#include <omp.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "engine/util/error.h"
#include "engine/util/hugepages.h"

namespace sylva::growth {

namespace {
/// Sources from which applyBatch() runs on several threads.
constexpr std::int64_t kParallelSources = 32768;
} // namespace

ShadowKernel ShadowKernel::make(double a, double b, int depth) {
    requireRange("shadow_a", a, 1e-6, 100.0);
    requireRange("shadow_b", b, 1.0 + 1e-6, 100.0);
    requireRange("shadow_depth", depth, 0, 32);
    ShadowKernel k;
    k.depth = depth;
    k.delta.resize(static_cast<std::size_t>(depth) + 1);
    for (int q = 0; q <= depth; ++q)
        k.delta[static_cast<std::size_t>(q)] =
            static_cast<std::int32_t>(std::lround(a * std::pow(b, -q) * ShadowGrid::kScale));
    return k;
}

ShadowGrid::ShadowGrid(float voxelSize, float floorY, int margin)
    : mVoxelSize(voxelSize), mMargin(std::max(margin, 0)) {
    requireRange("voxel size", voxelSize, 1e-4, 1e3);
    mFloor = static_cast<int>(std::floor(floorY / voxelSize));
}

void ShadowGrid::voxelsOf(std::span<const glm::vec3> points, std::span<ShadowSource> out) const {
    std::size_t i = 0;
#if defined(__SSE2__)
    // The points as one array of floats, twelve (four points) at a time.
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float));
    const float* f = &points.data()->x;
    const __m128 size = _mm_set1_ps(mVoxelSize), one = _mm_set1_ps(1.0f);
    alignas(16) std::int32_t v[12];
    for (; i + 4 <= points.size(); i += 4) {
        for (int r = 0; r < 3; ++r) {
            const __m128 q = _mm_div_ps(_mm_loadu_ps(f + 3 * i + 4 * r), size);
            // floor(q): the truncation, one less where it is above q. Exact within the int
            // range; beyond it (and for NaN) the truncation is INT_MIN, and INT_MIN - 1 rounds
            // back to it as a float: INT_MIN, as the scalar conversion of floor(q) gives.
            const __m128 t = _mm_cvtepi32_ps(_mm_cvttps_epi32(q));
            const __m128 fl = _mm_sub_ps(t, _mm_and_ps(_mm_cmpgt_ps(t, q), one));
            _mm_store_si128(reinterpret_cast<__m128i*>(v + 4 * r), _mm_cvttps_epi32(fl));
        }
        for (std::size_t k = 0; k < 4; ++k)
            out[i + k].voxel = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
    }
#endif
    for (; i < points.size(); ++i)
        out[i].voxel = voxelOf(points[i]);
}

glm::vec3 ShadowGrid::centreOf(const glm::ivec3& v) const {
    return (glm::vec3(v) + 0.5f) * mVoxelSize;
}

void ShadowGrid::neighbourhood(const glm::ivec3& v, std::int32_t (&out)[27]) const {
    if (v.y - 1 >= mFloor && inside(v - 1) && inside(v + 1)) {
        const std::int32_t* base = mValues.data() + index(v - 1);
        const std::uint8_t* opaque = mBlocked.data() + index(v - 1);
        const auto sx = static_cast<std::size_t>(mDim.z);
        const std::size_t sy = sx * static_cast<std::size_t>(mDim.x);
        for (std::size_t y = 0; y < 3; ++y)
            for (std::size_t x = 0; x < 3; ++x)
                for (std::size_t z = 0; z < 3; ++z) {
                    const std::size_t o = y * sy + x * sx + z;
                    out[y * 9 + x * 3 + z] = mAnyBlocked && opaque[o] ? kOpaque : base[o];
                }
        return;
    }
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x)
            for (int z = 0; z < 3; ++z) {
                const glm::ivec3 u = v + glm::ivec3(x - 1, y - 1, z - 1);
                out[y * 9 + x * 3 + z] = blocked(u) ? kOpaque : raw(u);
            }
}

void ShadowGrid::setBlocked(const glm::ivec3& v) {
    if (v.y < mFloor) return;
    reserveAround(v);
    mBlocked[index(v)] = 1;
    mAnyBlocked = true;
}

void ShadowGrid::clearShadow() {
    std::fill(mValues.begin(), mValues.end(), 0);
}

void ShadowGrid::reserveAround(const glm::ivec3& v) {
    const glm::ivec3 needLo(v.x - mMargin, mFloor, v.z - mMargin);
    const glm::ivec3 needHi(v.x + mMargin, std::max(v.y, mFloor), v.z + mMargin);
    if (!mValues.empty() && inside(needLo) && inside(needHi)) return;
    glm::ivec3 lo = needLo, hi = needHi;
    if (!mValues.empty()) {
        // Grow by half the current size on the side that overflows, so that a growing tree
        // triggers only O(log n) copies.
        const glm::ivec3 curHi = mLo + mDim - 1;
        const glm::ivec3 slack = glm::max(mDim / 2, glm::ivec3(4));
        for (int a = 0; a < 3; ++a) {
            lo[a] = needLo[a] < mLo[a] ? std::min(needLo[a], mLo[a] - slack[a]) : mLo[a];
            hi[a] = needHi[a] > curHi[a] ? std::max(needHi[a], curHi[a] + slack[a]) : curHi[a];
        }
        lo.y = mFloor;
    }
    resize(lo, hi);
}

void ShadowGrid::resize(const glm::ivec3& lo, const glm::ivec3& hi) {
    const glm::ivec3 dim = hi - lo + 1;
    const std::size_t count = static_cast<std::size_t>(dim.x) * static_cast<std::size_t>(dim.y) *
                              static_cast<std::size_t>(dim.z);
    if (count > kMaxShadowVoxels)
        throw LimitExceeded(
            "shadow grid would need " + std::to_string(count) + " voxels (" +
            std::to_string(dim.x) + " x " + std::to_string(dim.y) + " x " + std::to_string(dim.z) +
            " of " + std::to_string(mVoxelSize) + " m), more than the limit of " +
            std::to_string(kMaxShadowVoxels) +
            " (1.3 GB); use a larger voxel_size, or fewer cycles or a lower max_internodes when "
            "shoots grow far beyond the crown");
    // Bud lookups land anywhere in a grid of tens of MB: with 4 KiB pages nearly every one is
    // a TLB miss too. Huge pages are advised before the zero fill touches the memory.
    std::vector<std::int32_t> values;
    values.reserve(count);
    adviseHugePages(values);
    values.resize(count, 0);
    std::vector<std::uint8_t> blockedNew(count, 0);
    for (int y = mLo.y; y < mLo.y + mDim.y; ++y)
        for (int x = mLo.x; x < mLo.x + mDim.x; ++x) {
            const std::size_t from = index({x, y, mLo.z});
            const std::size_t to =
                (static_cast<std::size_t>(y - lo.y) * static_cast<std::size_t>(dim.x) +
                 static_cast<std::size_t>(x - lo.x)) *
                    static_cast<std::size_t>(dim.z) +
                static_cast<std::size_t>(mLo.z - lo.z);
            std::copy_n(mValues.begin() + static_cast<std::ptrdiff_t>(from), mDim.z,
                        values.begin() + static_cast<std::ptrdiff_t>(to));
            std::copy_n(mBlocked.begin() + static_cast<std::ptrdiff_t>(from), mDim.z,
                        blockedNew.begin() + static_cast<std::ptrdiff_t>(to));
        }
    mLo = lo;
    mDim = dim;
    mValues = std::move(values);
    mBlocked = std::move(blockedNew);
}

void ShadowGrid::addPyramid(const glm::ivec3& v, const ShadowKernel& kernel, int sign) {
    if (kernel.depth > mMargin)
        throw InvalidInput("shadow_depth " + std::to_string(kernel.depth) +
                           " exceeds the grid margin " + std::to_string(mMargin));
    reserveAround(v);
    for (int q = 0; q <= kernel.depth; ++q) {
        const int y = v.y - q;
        if (y < mFloor) break;
        const std::int32_t d = sign * kernel.delta[static_cast<std::size_t>(q)];
        for (int x = v.x - q; x <= v.x + q; ++x) {
            std::int32_t* row = mValues.data() + index({x, y, v.z - q});
            for (int k = 0; k <= 2 * q; ++k)
                row[k] += d;
        }
    }
}

void ShadowGrid::applyBatch(std::span<const ShadowSource> sources,
                            std::span<const ShadowKernel> kernels) {
    if (sources.empty()) return;
    int maxDepth = 0;
    for (const ShadowKernel& k : kernels)
        maxDepth = std::max(maxDepth, k.depth);
    if (maxDepth > mMargin)
        throw InvalidInput("shadow_depth " + std::to_string(maxDepth) +
                           " exceeds the grid margin " + std::to_string(mMargin));
    // Counting sort of the sources by their layer (sources below the floor cast nothing) into a
    // contiguous copy, so that each layer's sources are read in sequence; with per layer the
    // extent of its sources and, per depth q, how many of them reach q. In parallel: each
    // thread counts its share, the counts are merged in thread order, then each thread places
    // its share, so the order within a layer is the input order on any number of threads.
    const auto total = static_cast<std::int64_t>(sources.size());
    // Parallel from kParallelSources on: a smaller batch (one tree's lit attractors: the English
    // oak's ~10k) takes about a millisecond, and a parallel region then leaves libgomp's
    // threads spinning for milliseconds after it under the default waiting (Python, the editor).
    const int threads = total >= kParallelSources ? omp_get_max_threads() : 1;
    const auto depths = static_cast<std::size_t>(maxDepth) + 1;
    const glm::ivec4 noExtent(std::numeric_limits<int>::max(), std::numeric_limits<int>::min(),
                              std::numeric_limits<int>::max(), std::numeric_limits<int>::min());
    glm::ivec3 lo = sources[0].voxel, hi = lo;
    int firstSource = 0;
    std::size_t layers = 0;
    bool nothing = false;
    // An exception must not leave the parallel region (that terminates the process): the grid's
    // limit is caught here and thrown again after it (fuzz finding 17 found the limit reached).
    std::exception_ptr failure;
    // The steps of the sort: a share's bounds; the grid made to hold them and the layers (one
    // thread); a share counted; the counts merged (one thread); a share placed.
    auto setup = [&](std::size_t nt) {
        // One share per thread of the team actually running, which can be smaller than
        // omp_get_max_threads() (one thread when called inside another parallel region).
        mPart.resize(nt);
        // Pyramids are clipped only below the floor; the grid's margin covers them sideways.
        try {
            reserveAround(lo);
            reserveAround(hi);
        } catch (...) {
            failure = std::current_exception();
        }
        nothing = failure || hi.y < mFloor;
        firstSource = std::max(lo.y, mFloor);
        layers = nothing ? 0 : static_cast<std::size_t>(hi.y - firstSource + 1);
    };
    auto countShare = [&](Part& part, std::size_t begin, std::size_t end) {
        if (nothing) return;
        part.count.assign(layers, 0);
        part.extent.assign(layers, noExtent);
        part.reach.assign(layers * depths, 0);
        for (std::size_t i = begin; i < end; ++i) {
            const ShadowSource& s = sources[i];
            if (s.voxel.y < firstSource) continue;
            const auto b = static_cast<std::size_t>(s.voxel.y - firstSource);
            ++part.count[b];
            glm::ivec4& e = part.extent[b];
            e = {std::min(e.x, s.voxel.x), std::max(e.y, s.voxel.x), std::min(e.z, s.voxel.z),
                 std::max(e.w, s.voxel.z)};
            // Counted at its own depth; the suffix sums below make it "reaches q".
            ++part.reach[b * depths + static_cast<std::size_t>(kernels[s.kernel].depth)];
        }
    };
    auto merge = [&] {
        if (nothing) return;
        mBucketStart.assign(layers + 1, 0);
        mLayerExtent.assign(layers, noExtent);
        mReach.assign(layers * depths, 0);
        std::uint32_t at = 0;
        for (std::size_t b = 0; b < layers; ++b) {
            mBucketStart[b] = at;
            glm::ivec4& e = mLayerExtent[b];
            for (Part& p : mPart) {
                const std::uint32_t c = p.count[b];
                p.count[b] = at; // becomes this part's first slot in the bucket
                at += c;
                const glm::ivec4& pe = p.extent[b];
                e = {std::min(e.x, pe.x), std::max(e.y, pe.y), std::min(e.z, pe.z),
                     std::max(e.w, pe.w)};
                for (std::size_t q = 0; q < depths; ++q)
                    mReach[b * depths + q] += p.reach[b * depths + q];
            }
            for (std::size_t q = depths - 1; q-- > 0;)
                mReach[b * depths + q] += mReach[b * depths + q + 1];
        }
        mBucketStart[layers] = at;
        mSorted.resize(at);
    };
    auto place = [&](Part& part, std::size_t begin, std::size_t end) {
        if (nothing) return;
        for (std::size_t i = begin; i < end; ++i) {
            const ShadowSource& s = sources[i];
            if (s.voxel.y < firstSource) continue;
            const auto b = static_cast<std::size_t>(s.voxel.y - firstSource);
            mSorted[part.count[b]++] = {s.voxel.x, s.voxel.z, s.weight, s.kernel};
        }
    };
    // The region only where it has threads: a team of one still ends at a barrier (a futex
    // call a batch: the self-organizing model applies one a cycle).
    if (threads > 1) {
#pragma omp parallel num_threads(threads)
        {
            const auto t = static_cast<std::size_t>(omp_get_thread_num());
            const auto nt = static_cast<std::size_t>(omp_get_num_threads());
            const std::size_t begin = sources.size() * t / nt;
            const std::size_t end = sources.size() * (t + 1) / nt;
            glm::ivec3 plo = sources[begin].voxel, phi = plo;
            for (std::size_t i = begin; i < end; ++i) {
                plo = glm::min(plo, sources[i].voxel);
                phi = glm::max(phi, sources[i].voxel);
            }
#pragma omp critical(sylva_shadow_bounds)
            {
                lo = glm::min(lo, plo);
                hi = glm::max(hi, phi);
            }
#pragma omp barrier
#pragma omp single
            setup(nt);
            countShare(mPart[t], begin, end);
#pragma omp barrier
#pragma omp single
            merge();
            place(mPart[t], begin, end);
        }
    } else {
        for (const ShadowSource& s : sources) {
            lo = glm::min(lo, s.voxel);
            hi = glm::max(hi, s.voxel);
        }
        setup(1);
        countShare(mPart[0], 0, sources.size());
        merge();
        place(mPart[0], 0, sources.size());
    }
    if (failure) std::rethrow_exception(failure);
    if (nothing) return;

    // Each output layer gathers the pyramid slices (squares) of the sources up to maxDepth
    // above it. Where the squares cover much more than their bounding rectangle, they go into a
    // 2D difference array (4 corners each) that one prefix-sum sweep turns into the values;
    // otherwise they are added directly. Both are exact integer sums.
    const int firstLayer = std::max(mFloor, firstSource - maxDepth);
    const int layerCount = hi.y - firstLayer + 1;
    // Δs(q) per kernel in one flat table (0 where q is beyond the kernel's depth), so the loops
    // below read one int per source instead of the kernel's vector, and skip those sources.
    const std::size_t kernelCount = kernels.size();
    mDeltaByDepth.assign(depths * kernelCount, 0);
    for (std::size_t k = 0; k < kernelCount; ++k)
        for (std::size_t q = 0; q <= static_cast<std::size_t>(kernels[k].depth); ++q)
            mDeltaByDepth[q * kernelCount + k] = kernels[k].delta[q];
    const auto dx = static_cast<std::size_t>(mDim.x), dz = static_cast<std::size_t>(mDim.z);
    const std::size_t planeD = (dx + 1) * (dz + 1);
    mDiff.resize(static_cast<std::size_t>(omp_get_max_threads()));
    for (std::vector<std::int32_t>& d : mDiff)
        if (d.size() != planeD) d.assign(planeD, 0);
    // One output layer (a task of the loop below), with its thread's difference plane and column
    // sums.
    auto layer = [&](int l, std::vector<std::int32_t>& diff, std::vector<std::int32_t>& colAcc) {
        const int y = firstLayer + l;
        std::int32_t* plane = mValues.data() + static_cast<std::size_t>(y - mLo.y) * dx * dz;
        // Extent and direct cost of this layer's squares, from the per-layer summaries.
        int x0 = std::numeric_limits<int>::max(), z0 = x0;
        int x1 = std::numeric_limits<int>::min(), z1 = x1;
        std::int64_t cells = 0;
        for (int q = 0; q <= maxDepth; ++q) {
            const int sy = y + q;
            if (sy < firstSource || sy > hi.y) continue;
            const auto b = static_cast<std::size_t>(sy - firstSource);
            const std::uint32_t reach = mReach[b * depths + static_cast<std::size_t>(q)];
            if (reach == 0) continue;
            const glm::ivec4& e = mLayerExtent[b];
            x0 = std::min(x0, e.x - q);
            x1 = std::max(x1, e.y + q);
            z0 = std::min(z0, e.z - q);
            z1 = std::max(z1, e.w + q);
            cells += static_cast<std::int64_t>(reach) * (2 * q + 1) * (2 * q + 1);
        }
        if (cells == 0) return;
        // Calls f(source, q, Δs) for every source slice that reaches this layer (all the
        // loop state in locals, so that the writes into int arrays cannot force reloads).
        auto forEach = [&](auto&& f) {
            for (int q = 0; q <= maxDepth; ++q) {
                const int sy = y + q;
                if (sy < firstSource || sy > hi.y) continue;
                const auto b = static_cast<std::size_t>(sy - firstSource);
                if (mReach[b * depths + static_cast<std::size_t>(q)] == 0) continue;
                const std::int32_t* delta =
                    mDeltaByDepth.data() + static_cast<std::size_t>(q) * kernelCount;
                const SortedSource* s = mSorted.data() + mBucketStart[b];
                const SortedSource* const end = mSorted.data() + mBucketStart[b + 1];
                for (; s != end; ++s) {
                    const std::int32_t d = s->weight * delta[s->kernel];
                    if (d != 0) f(*s, q, d); // 0: beyond the kernel's depth, or no change
                }
            }
        };
        const std::int64_t area =
            static_cast<std::int64_t>(x1 - x0 + 1) * static_cast<std::int64_t>(z1 - z0 + 1);

        if (cells < 2 * area) {
            forEach([&](const SortedSource& s, int q, std::int32_t d) {
                for (int x = s.x - q; x <= s.x + q; ++x) {
                    std::int32_t* row = plane + static_cast<std::size_t>(x - mLo.x) * dz +
                                        static_cast<std::size_t>(s.z - q - mLo.z);
                    for (int z = 0; z <= 2 * q; ++z)
                        row[z] += d;
                }
            });
            return;
        }
        // The difference array covers just this layer's extent (local coordinates, one extra
        // row and column for the far corners), so the corners and the sweeps stay in a
        // compact block of the thread's cache instead of spanning the whole grid's plane.
        const std::size_t width = static_cast<std::size_t>(z1 - z0) + 1;
        const std::size_t rows = static_cast<std::size_t>(x1 - x0) + 1;
        const std::size_t stride = width + 1;
        // Corner (x − q, z − q) of a slice is at x·stride + z − origin(q); the other three
        // are w = 2q + 1 columns and/or rows further.
        std::int32_t* __restrict corners = diff.data();
        const auto iStride = static_cast<std::ptrdiff_t>(stride);
        forEach([&](const SortedSource& s, int q, std::int32_t d) {
            const std::ptrdiff_t w = 2 * q + 1;
            const std::ptrdiff_t origin = (x0 + q) * iStride + (z0 + q);
            const std::ptrdiff_t i = s.x * iStride + s.z - origin;
            corners[i] += d;
            corners[i + w] -= d;
            corners[i + w * iStride] -= d;
            corners[i + w * iStride + w] += d;
        });
        // Two sweeps so that the second vectorizes: prefix sums along z in place (a chain
        // per row), then running sums down x added into the layer; the array is left zeroed.
        std::fill_n(colAcc.begin(), width, 0);
        for (std::size_t x = 0; x < rows; ++x) {
            std::int32_t* drow = diff.data() + x * stride;
            std::int32_t run = 0;
            for (std::size_t z = 0; z < width; ++z) {
                run += drow[z];
                drow[z] = run;
            }
            drow[width] = 0;
        }
        const std::size_t planeOrigin =
            static_cast<std::size_t>(x0 - mLo.x) * dz + static_cast<std::size_t>(z0 - mLo.z);
        for (std::size_t x = 0; x < rows; ++x) {
            std::int32_t* __restrict drow = diff.data() + x * stride;
            std::int32_t* __restrict srow = plane + planeOrigin + x * dz;
            std::int32_t* __restrict acc = colAcc.data();
            for (std::size_t z = 0; z < width; ++z) {
                acc[z] += drow[z];
                srow[z] += acc[z];
                drow[z] = 0;
            }
        }
        std::fill_n(diff.data() + rows * stride, stride, 0);
    };
    // The region only where it runs in parallel: a team of one still ends at a barrier (a
    // futex call a batch: the self-organizing model applies one a cycle).
    if (total >= kParallelSources) {
#pragma omp parallel
        {
            std::vector<std::int32_t>& diff = mDiff[static_cast<std::size_t>(omp_get_thread_num())];
            std::vector<std::int32_t> colAcc(dz + 1);
#pragma omp for schedule(dynamic, 1)
            for (int l = 0; l < layerCount; ++l)
                layer(l, diff, colAcc);
        }
    } else {
        std::vector<std::int32_t> colAcc(dz + 1);
        for (int l = 0; l < layerCount; ++l)
            layer(l, mDiff[0], colAcc);
    }
}

bool ShadowGrid::sameShadow(const ShadowGrid& other) const {
    const glm::ivec3 lo = glm::min(mLo, other.mLo);
    const glm::ivec3 hi = glm::max(mLo + mDim, other.mLo + other.mDim);
    for (int y = lo.y; y < hi.y; ++y)
        for (int x = lo.x; x < hi.x; ++x)
            for (int z = lo.z; z < hi.z; ++z) {
                const glm::ivec3 v(x, y, z);
                const std::int32_t a = inside(v) ? mValues[index(v)] : 0;
                const std::int32_t b = other.inside(v) ? other.mValues[other.index(v)] : 0;
                if (a != b) return false;
            }
    return true;
}

} // namespace sylva::growth
