#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <new>
#include <vector>

#include <glm/glm.hpp>

namespace sylva::growth {

/// How LitCandidates scores its candidates: weight × spread × jitter, spread = √(squared
/// distance to the nearest centre visited) or 1.
enum class CandidateScore {
    Weight,        ///< weight × 1 × jitter (before any centre)
    Spread,        ///< spread × jitter
    WeightedSpread ///< weight × spread × jitter
};

/// What a visit of LitCandidates updates.
enum class CandidateVisit {
    Lit,           ///< the lit flags only (the distances are not needed again)
    Nearest,       ///< the lit flags and the distances to the nearest centre
    Spread,        ///< both, then the best of CandidateScore::Spread
    WeightedSpread ///< both, then the best of CandidateScore::WeightedSpread
};

/// Which lanes a visit runs on: the widest the processor has (AVX-512, else AVX, else SSE2), or
/// one named for the tests that check they agree.
enum class CandidateLanes { Widest, Scalar, Sse2, Avx, Avx512 };

/// The candidate cluster centres of litAttractors() (a subset of the points, in index order),
/// struct of arrays. Each centre chosen is visited once: every candidate's squared distance to
/// it (summed as glm::dot sums it) lowers its distance to the nearest centre and marks it lit
/// when it is within that centre's radius, and the same pass scores the candidates for the next
/// centre and keeps the first of the highest score. Four lanes at a time on SSE2, eight where
/// the processor has AVX, sixteen where it has AVX-512 (dispatched at run time; no fused
/// multiply-add on either): each lane the scalar code's operations in its order, so every lane
/// count gives the same floats and centres.
class LitCandidates {
public:
    /// Room for \p capacity candidates.
    explicit LitCandidates(std::size_t capacity);

    /// Appends the point when \p take. Written either way, so that choosing between two sets
    /// (the outer and the inner candidates, about half and half) takes no branch.
    void offer(bool take, const glm::vec3& p, float weight, float jitter, std::size_t index) {
        mX[mCount] = p.x;
        mY[mCount] = p.y;
        mZ[mCount] = p.z;
        mWeight[mCount] = weight;
        mJitter[mCount] = jitter;
        mIndex[mCount] = static_cast<std::uint32_t>(index);
        mCount += take ? 1 : 0;
    }
    std::size_t size() const { return mCount; }
    glm::vec3 point(std::size_t k) const { return {mX[k], mY[k], mZ[k]}; }
    /// The squared distance to the nearest centre visited (float max before any).
    float nearest(std::size_t k) const { return mNearest[k]; }
    bool lit(std::size_t k) const { return mLit[k] != 0; }

    /// The first candidate of the highest score (size() when none beats -1).
    std::size_t best(CandidateScore score) const;

    /// A centre chosen, of squared radius \p r2: lit when |p - centre|² <= r2, nearest =
    /// min(nearest, |p - centre|²) unless CandidateVisit::Lit; returns best() of the scores
    /// after it, or size() for Lit and Nearest, which score nothing.
    std::size_t visit(const glm::vec3& centre, float r2, CandidateVisit what,
                      CandidateLanes lanes = CandidateLanes::Widest);

    /// Marks lit[index] for every candidate a visit lit (a point is a candidate once: the
    /// others are left as they are).
    void markLit(std::vector<std::uint8_t>& lit) const;

    /// Whether CandidateLanes::Avx runs here (the processor has AVX and SYLVA_NO_AVX is unset).
    static bool hasAvx();
    /// Whether CandidateLanes::Avx512 runs here (AVX-512F, and neither SYLVA_NO_AVX nor
    /// SYLVA_NO_AVX512 set).
    static bool hasAvx512();

private:
    float scoreOf(std::size_t k, CandidateScore score) const;

    /// Frees what an aligned new[] allocated.
    struct AlignedDelete {
        template <class T> void operator()(T* p) const {
            ::operator delete[](p, std::align_val_t{64});
        }
    };
    std::unique_ptr<float[], AlignedDelete> mFloats; ///< the float arrays below, one block
    std::unique_ptr<std::uint32_t[], AlignedDelete> mInts;
    float *mX, *mY, *mZ, *mWeight, *mJitter, *mNearest;
    std::uint32_t* mLit;   ///< ~0u once within a centre's radius
    std::uint32_t* mIndex; ///< the point's index
    std::size_t mCount = 0;
};

} // namespace sylva::growth
