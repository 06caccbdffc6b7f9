#include "engine/mesh/leafplacement.h"

#include <cmath>
#include <numbers>

#include <glm/gtc/quaternion.hpp>

#include "engine/util/error.h"
#include "engine/util/random.h"

namespace sylva::mesh {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

glm::vec3 perpendicular(const glm::vec3& t, const glm::vec3& hint) {
    glm::vec3 p = hint - glm::dot(hint, t) * t;
    if (glm::dot(p, p) < 1e-8f) {
        const glm::vec3 a = std::abs(t.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        p = glm::cross(t, a);
    }
    return glm::normalize(p);
}

// glm::quat_cast of a rotation matrix without its branches: the same four candidates, the same
// comparisons in the same order and the same arithmetic, so the same quaternion bit for bit. A
// leaf's frame turns every way, so which candidate is the largest was mispredicted about every
// other leaf (perf record of the English oak: Placer::leaf 10 % of the tree, its samples on
// quat_cast's branches).
glm::quat quatOfFrame(const glm::mat3& m) {
    const float fx = m[0][0] - m[1][1] - m[2][2];
    const float fy = m[1][1] - m[0][0] - m[2][2];
    const float fz = m[2][2] - m[0][0] - m[1][1];
    const float fw = m[0][0] + m[1][1] + m[2][2];
    int index = 0;
    float biggest = fw;
    index = fx > biggest ? 1 : index;
    biggest = fx > biggest ? fx : biggest;
    index = fy > biggest ? 2 : index;
    biggest = fy > biggest ? fy : biggest;
    index = fz > biggest ? 3 : index;
    biggest = fz > biggest ? fz : biggest;
    const float big = std::sqrt(biggest + 1.0f) * 0.5f;
    const float mult = 0.25f / big;
    const float v[7] = {big,
                        (m[1][2] - m[2][1]) * mult,
                        (m[2][0] - m[0][2]) * mult,
                        (m[0][1] - m[1][0]) * mult,
                        (m[0][1] + m[1][0]) * mult,
                        (m[2][0] + m[0][2]) * mult,
                        (m[1][2] + m[2][1]) * mult};
    // w, x, y, z of each of glm's four cases.
    static constexpr int kPick[4][4] = {{0, 1, 2, 3}, {1, 0, 4, 5}, {2, 4, 0, 6}, {3, 5, 6, 0}};
    const int* pick = kPick[index];
    return {v[pick[0]], v[pick[1]], v[pick[2]], v[pick[3]]};
}

struct Placer {
    const LeafPlacement& p;
    glm::vec3 light;
    std::vector<skel::Leaf>& out;
    // The petiole angle's sine and cosine, made once (they were made again for every leaf).
    float sinPetiole = std::sin(static_cast<float>(p.petioleAngle * kDeg));
    float cosPetiole = std::cos(static_cast<float>(p.petioleAngle * kDeg));

    // A leaf at \p base on a branch with tangent \p t, radial direction \p radial.
    void leaf(const glm::vec3& base, const glm::vec3& t, const glm::vec3& radial, float forward,
              Rng& rng, std::int32_t node) {
        glm::vec3 h = glm::normalize(sinPetiole * radial + cosPetiole * t + forward * t);
        glm::vec3 n = static_cast<float>(p.normalWeight) * radial +
                      static_cast<float>(p.upWeight) * glm::vec3(0, 1, 0) +
                      static_cast<float>(p.lightWeight) * light;
        // The card must not contain its own normal: keep n perpendicular to the heading.
        n -= glm::dot(n, h) * h;
        if (glm::dot(n, n) < 1e-8f) n = perpendicular(h, glm::cross(h, t) + radial);
        n = glm::normalize(n);
        const glm::vec3 l = glm::cross(n, h); // U × H = L for a right-handed H, L, U frame
        skel::Leaf leaf;
        leaf.position = base;
        leaf.orientation = glm::normalize(quatOfFrame(glm::mat3(-l, h, n)));
        const double v = p.sizeVariation * rng.uniform(-1.0, 1.0);
        leaf.size = static_cast<float>(p.size * (1.0 + v));
        leaf.node = node;
        out.push_back(leaf);
    }

    // The cosines and sines of the leaves' angles at position index k (radians), as floats.
    // They depend on k only (spiral) or on its parity: made once each, from the same double
    // angle as before (std::sincos of a double was a tenth of the placement).
    void angles(std::uint64_t k, std::vector<glm::vec2>& a) {
        a.clear();
        if (p.phyllotaxis == Phyllotaxis::Spiral) {
            const std::uint64_t j = k % 100000;
            if (j >= spiral.size() && j < kSpiralTable)
                for (std::uint64_t q = spiral.size(); q <= j; ++q)
                    spiral.push_back(trig(137.5 * kDeg * static_cast<double>(q)));
            a.push_back(j < spiral.size() ? spiral[j]
                                          : trig(137.5 * kDeg * static_cast<double>(j)));
            return;
        }
        std::vector<glm::vec2>& cached = parity[k % 2];
        if (cached.empty()) {
            switch (p.phyllotaxis) {
            case Phyllotaxis::Alternate:
                cached.push_back(trig(std::numbers::pi * static_cast<double>(k % 2)));
                break;
            case Phyllotaxis::Opposite: {
                const double base = 0.5 * std::numbers::pi * static_cast<double>(k % 2);
                cached.push_back(trig(base));
                cached.push_back(trig(base + std::numbers::pi));
                break;
            }
            case Phyllotaxis::Whorled: {
                const double gap = 2.0 * std::numbers::pi / p.whorlCount;
                const double base = 0.5 * gap * static_cast<double>(k % 2);
                for (int i = 0; i < p.whorlCount; ++i)
                    cached.push_back(trig(base + gap * i));
                break;
            }
            case Phyllotaxis::Spiral:
                break;
            }
        }
        a = cached;
    }

    static glm::vec2 trig(double ang) {
        return {static_cast<float>(std::cos(ang)), static_cast<float>(std::sin(ang))};
    }
    static constexpr std::uint64_t kSpiralTable = 1u << 16;
    std::vector<glm::vec2> spiral{};    ///< by k % 100000, filled as far as asked
    std::vector<glm::vec2> parity[2]{}; ///< the other arrangements, by k % 2
};

// At least as many leaves as placeLeaves makes (one more a segment than its density gives):
// the output reserved once, not grown by copying.
std::size_t leafBound(const skel::Skeleton& s, const LeafPlacement& p,
                      const std::vector<std::uint8_t>& hidden,
                      const std::vector<std::uint32_t>& children) {
    const std::size_t perPosition = p.phyllotaxis == Phyllotaxis::Opposite  ? 2
                                    : p.phyllotaxis == Phyllotaxis::Whorled ? p.whorlCount
                                                                            : 1;
    std::size_t bound = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
        const std::int32_t par = s.parent[i];
        if (par < 0 || hidden[i]) continue;
        if (p.alongBranches && s.radius[i] <= p.maxBranchRadius) {
            const float len =
                glm::length(s.position[i] - s.position[static_cast<std::size_t>(par)]);
            bound += perPosition * (static_cast<std::size_t>(p.density * len) + 1);
        }
        if (p.atTips && children[i] == 0) bound += static_cast<std::size_t>(p.tipCount);
    }
    return bound;
}

} // namespace

std::vector<skel::Leaf> placeLeaves(const skel::Skeleton& s, const LeafPlacement& p) {
    requireRange("whorl_count", p.whorlCount, 2, 12);
    requireRange("size", p.size, 1e-6, 100.0);
    requireRange("size_variation", p.sizeVariation, 0.0, 1.0);
    requireRange("density", p.density, 0.0, 1000.0);
    requireRange("tip_count", p.tipCount, 0, 32);
    requireRange("max_branch_radius", p.maxBranchRadius, 0.0, 1e3);
    requireRange("petiole_angle", p.petioleAngle, 0.0, 90.0);
    requireRange("normal_weight", p.normalWeight, 0.0, 1e3);
    requireRange("up_weight", p.upWeight, 0.0, 1e3);
    requireRange("light_weight", p.lightWeight, 0.0, 1e3);
    s.validate();

    std::vector<skel::Leaf> out;
    if (p.keepGrammarLeaves) out = s.leaves;
    const float ll = glm::length(p.lightDirection);
    Placer placer{p, ll > 0.0f ? p.lightDirection / ll : glm::vec3(0, 1, 0), out};

    const std::size_t n = s.size();
    std::vector<std::uint32_t> children(n, 0);
    std::vector<std::uint8_t> hidden(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t par = s.parent[i];
        hidden[i] =
            (s.flags[i] & skel::kHidden) || (par >= 0 && hidden[static_cast<std::size_t>(par)]);
        if (par >= 0 && !hidden[i]) ++children[static_cast<std::size_t>(par)];
    }
    // Running position index along each axis so phyllotaxis continues across segments.
    std::vector<std::uint64_t> index(n, 0);
    std::vector<glm::vec2> a;
    out.reserve(out.size() + leafBound(s, p, hidden, children));
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t par = s.parent[i];
        if (par < 0 || hidden[i]) continue;
        const auto pi = static_cast<std::size_t>(par);
        Rng rng(mixSeed(p.seed, i));
        const glm::vec3 a0 = s.position[pi], a1 = s.position[i];
        const float len = glm::length(a1 - a0);
        const glm::vec3 t = len > 1e-9f ? (a1 - a0) / len : skel::headingOf(s.orientation[i]);
        const glm::vec3 e1 = perpendicular(t, skel::upOf(s.orientation[i]));
        const glm::vec3 e2 = glm::cross(t, e1);
        std::uint64_t k = s.order[i] == s.order[pi] ? index[pi] : 0;
        if (p.alongBranches && s.radius[i] <= p.maxBranchRadius && len > 0.0f) {
            const auto count = static_cast<std::uint64_t>(p.density * len + rng.uniform());
            for (std::uint64_t c = 0; c < count; ++c, ++k) {
                const float f = (static_cast<float>(c) + 0.5f) / static_cast<float>(count);
                const glm::vec3 axis = a0 + f * (a1 - a0);
                const float r = s.radius[pi] + f * (s.radius[i] - s.radius[pi]);
                placer.angles(k, a);
                for (const glm::vec2& cs : a) {
                    const glm::vec3 radial = cs.x * e1 + cs.y * e2;
                    placer.leaf(axis + r * radial, t, radial, 0.0f, rng,
                                static_cast<std::int32_t>(i));
                }
            }
        }
        index[i] = k;
        if (p.atTips && children[i] == 0) {
            for (int c = 0; c < p.tipCount; ++c) {
                const double ang = 2.0 * std::numbers::pi * c / p.tipCount + rng.uniform(0.0, 0.5);
                const glm::vec3 radial =
                    static_cast<float>(std::cos(ang)) * e1 + static_cast<float>(std::sin(ang)) * e2;
                placer.leaf(a1, t, radial, 1.0f, rng, static_cast<std::int32_t>(i));
            }
        }
    }
    return out;
}

} // namespace sylva::mesh
