#pragma once

#include <cstdint>

namespace sylva {

/// Mixes two 64-bit values into a well-distributed seed (SplitMix64 finaliser). Used to derive
/// per-tree and per-stage seeds from (project seed, instance id) so results never depend on the
/// order in which threads run.
constexpr std::uint64_t mixSeed(std::uint64_t a, std::uint64_t b) {
    std::uint64_t z = a + 0x9E3779B97F4A7C15ull * (b + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/// Small, fast, portable PRNG (xoshiro256**). Unlike std:: distributions, every value it
/// produces is the same on every platform and standard library, which the byte-identical
/// output guarantee needs.
class Rng {
public:
    explicit Rng(std::uint64_t seed = 0) { reseed(seed); }

    void reseed(std::uint64_t seed) {
        for (int i = 0; i < 4; ++i)
            mState[i] = mixSeed(seed, static_cast<std::uint64_t>(i));
    }

    std::uint64_t next() {
        const std::uint64_t result = rotl(mState[1] * 5, 7) * 9;
        const std::uint64_t t = mState[1] << 17;
        mState[2] ^= mState[0];
        mState[3] ^= mState[1];
        mState[1] ^= mState[2];
        mState[0] ^= mState[3];
        mState[2] ^= t;
        mState[3] = rotl(mState[3], 45);
        return result;
    }

    /// Uniform in [0, 1) with 53 bits of precision.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    /// Uniform in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    float uniformf(float lo, float hi) { return static_cast<float>(uniform(lo, hi)); }
    /// Uniform integer in [0, n); n > 0.
    std::uint64_t below(std::uint64_t n) { return static_cast<std::uint64_t>(uniform() * n); }

private:
    static constexpr std::uint64_t rotl(std::uint64_t x, int k) {
        return (x << k) | (x >> (64 - k));
    }
    std::uint64_t mState[4];
};

} // namespace sylva
