#include "engine/environment/adapt.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <iterator>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>
#include <omp.h>

#include "engine/util/error.h"

namespace sylva::env {

bool segmentHitsCrown(const Segment& s, const CrownVolume& crown, glm::vec3* point) {
    const glm::dvec3 a(s.a), d(s.b - s.a);
    double t0 = 0.0, t1 = 1.0;
    const double y0 = static_cast<double>(crown.base.y) + crown.bottom;
    const double y1 = static_cast<double>(crown.base.y) + crown.top;
    if (std::abs(d.y) < 1e-30) {
        if (a.y < y0 || a.y > y1) return false;
    } else {
        double ta = (y0 - a.y) / d.y, tb = (y1 - a.y) / d.y;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    // |o + t·e|² <= r² in the horizontal plane.
    const glm::dvec2 o(a.x - crown.base.x, a.z - crown.base.z), e(d.x, d.z);
    const double r2 = static_cast<double>(crown.radius) * crown.radius;
    const double qa = glm::dot(e, e), qb = 2.0 * glm::dot(o, e), qc = glm::dot(o, o) - r2;
    if (qa < 1e-30) {
        if (qc > 0.0) return false;
    } else {
        const double disc = qb * qb - 4.0 * qa * qc;
        if (disc < 0.0) return false;
        const double sq = std::sqrt(disc);
        t0 = std::max(t0, (-qb - sq) / (2.0 * qa));
        t1 = std::min(t1, (-qb + sq) / (2.0 * qa));
        if (t0 > t1) return false;
    }
    if (point != nullptr) *point = glm::vec3(a + t0 * d);
    return true;
}

namespace {

/// A leaf card's seven test segments in world space (stem from \p stemWorld to the anchor, four
/// edges, two diagonals) and their bounds.
struct CardSegments {
    Segment seg[7];
    glm::vec3 lo, hi;
};

CardSegments cardSegments(const glm::mat4& m, const skel::Leaf& leaf, const glm::vec3& stemWorld,
                          float leafScale, float leafAspect) {
    const float len = leaf.size * leafScale;
    const glm::vec3 h = skel::headingOf(leaf.orientation) * len;
    const glm::vec3 l = skel::leftOf(leaf.orientation) * (0.5f * leafAspect * len);
    const glm::vec3 c[4] = {leaf.position + l, leaf.position - l, leaf.position - l + h,
                            leaf.position + l + h};
    CardSegments out;
    glm::vec3 w[4];
    const glm::vec3 anchor(m * glm::vec4(leaf.position, 1.0f));
    out.lo = glm::min(stemWorld, anchor);
    out.hi = glm::max(stemWorld, anchor);
    for (int k = 0; k < 4; ++k) {
        w[k] = glm::vec3(m * glm::vec4(c[k], 1.0f));
        out.lo = glm::min(out.lo, w[k]);
        out.hi = glm::max(out.hi, w[k]);
    }
    out.seg[0] = {stemWorld, anchor};
    for (int k = 0; k < 4; ++k)
        out.seg[1 + k] = {w[k], w[(k + 1) % 4]};
    out.seg[5] = {w[0], w[2]};
    out.seg[6] = {w[1], w[3]};
    return out;
}

} // namespace

bool leafCardTouches(const ObstacleScene& scene, const glm::mat4& m, const skel::Leaf& leaf,
                     const glm::vec3& stemFrom, float leafScale, float leafAspect) {
    const CardSegments card =
        cardSegments(m, leaf, glm::vec3(m * glm::vec4(stemFrom, 1.0f)), leafScale, leafAspect);
    if (!scene.overlapsBounds(card.lo, card.hi)) return false;
    for (const Segment& seg : card.seg)
        if (scene.occluded(seg)) return true;
    return false;
}

double visibleLength(const skel::Skeleton& s) {
    double sum = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i)
        if (s.parent[i] >= 0 && (s.flags[i] & skel::kHidden) == 0)
            sum += glm::length(s.position[i] - s.position[static_cast<std::size_t>(s.parent[i])]);
    return sum;
}

namespace {

struct Hit {
    std::size_t node = 0;
    glm::vec3 point{0.0f};
    float top = 0.0f; // world height of the obstacle part that was hit
};

class Collider {
public:
    /// \p bark: per node, the world-space radius of the tube of the segment ending there (empty
    /// for axes only, as for leaf cards).
    Collider(const ObstacleScene& scene, std::span<const CrownVolume> crowns,
             std::span<const float> bark, AdaptStats& stats)
        : mScene(scene), mCrowns(crowns), mBark(bark), mStats(stats) {}

    /// Segments ending at \p nodes (world positions \p w); hits with their obstacle tops. A
    /// segment whose axis misses but whose tube touches an obstacle hits at the obstacle's point
    /// nearest to it.
    std::vector<Hit> intersect(const skel::Skeleton& s, const std::vector<glm::vec3>& w,
                               const std::vector<std::size_t>& nodes) {
        std::vector<Segment> segs = segments(s, w, nodes);
        std::vector<SegmentHit> hits(segs.size());
        mScene.intersect(segs, hits);
        mStats.segmentsTested += segs.size();
        std::vector<Hit> out;
        for (std::size_t k = 0; k < segs.size(); ++k) {
            Hit h;
            h.node = nodes[k];
            bool any = false;
            SegmentHit hit = hits[k];
            if (!hit.hit && !mBark.empty() && mBark[nodes[k]] > 0.0f)
                hit = mScene.nearest(segs[k], mBark[nodes[k]]);
            if (hit.hit) {
                any = true;
                h.point = hit.point;
                glm::vec3 v0, v1, v2;
                mScene.triangle(hit.mesh, hit.triangle, v0, v1, v2);
                h.top = std::max({v0.y, v1.y, v2.y});
            }
            for (const CrownVolume& c : mCrowns) {
                glm::vec3 p;
                if (!segmentHitsCrown(segs[k], c, &p)) continue;
                if (!any) h.point = p;
                h.top = any ? std::max(h.top, c.base.y + c.top) : c.base.y + c.top;
                any = true;
            }
            if (any) out.push_back(h);
        }
        return out;
    }

    /// Which of \p nodes' segments touch anything (1 per colliding entry).
    std::vector<std::uint8_t> occluded(const skel::Skeleton& s, const std::vector<glm::vec3>& w,
                                       const std::vector<std::size_t>& nodes) {
        std::vector<Segment> segs = segments(s, w, nodes);
        std::vector<std::uint8_t> out(segs.size(), 0);
        if (mBark.empty()) {
            mScene.occluded(segs, out);
        } else {
            std::vector<float> radii(nodes.size());
            for (std::size_t k = 0; k < nodes.size(); ++k)
                radii[k] = mBark[nodes[k]];
            mScene.touches(segs, radii, out);
        }
        mStats.segmentsTested += segs.size();
        for (std::size_t k = 0; k < segs.size(); ++k)
            for (std::size_t c = 0; c < mCrowns.size() && out[k] == 0; ++c)
                if (segmentHitsCrown(segs[k], mCrowns[c])) out[k] = 1;
        return out;
    }

    /// Which of \p segs (world space, axes only) touch anything.
    std::vector<std::uint8_t> occluded(const std::vector<Segment>& segs) {
        std::vector<std::uint8_t> out(segs.size(), 0);
        mScene.occluded(segs, out);
        mStats.segmentsTested += segs.size();
        for (std::size_t k = 0; k < segs.size(); ++k)
            for (std::size_t c = 0; c < mCrowns.size() && out[k] == 0; ++c)
                if (segmentHitsCrown(segs[k], mCrowns[c])) out[k] = 1;
        return out;
    }

private:
    static std::vector<Segment> segments(const skel::Skeleton& s, const std::vector<glm::vec3>& w,
                                         const std::vector<std::size_t>& nodes) {
        std::vector<Segment> segs(nodes.size());
        for (std::size_t k = 0; k < nodes.size(); ++k)
            segs[k] = {w[static_cast<std::size_t>(s.parent[nodes[k]])], w[nodes[k]]};
        return segs;
    }

    const ObstacleScene& mScene;
    std::span<const CrownVolume> mCrowns;
    std::span<const float> mBark;
    AdaptStats& mStats;
};

std::vector<glm::vec3> toWorld(const std::vector<glm::vec3>& p, const glm::mat4& m) {
    std::vector<glm::vec3> w(p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
        w[i] = glm::vec3(m * glm::vec4(p[i], 1.0f));
    return w;
}

/// Largest factor by which \p m stretches a length (the tree transform's uniform scale).
float maxScale(const glm::mat4& m) {
    return std::max(
        {glm::length(glm::vec3(m[0])), glm::length(glm::vec3(m[1])), glm::length(glm::vec3(m[2]))});
}

/// A leaf card's reach from its anchor: card length L, half width aspect·L/2.
float leafReach(const skel::Leaf& leaf, const AdaptParams& params) {
    const float len = leaf.size * params.leafScale;
    return len * (1.0f + 0.5f * params.leafAspect);
}

/// Drops the leaves of \p s whose card (the quad tube_mesh draws: edges and diagonals) or stem
/// (node to anchor) touches what \p collider tests (the obstacles only: a leaf reaching into a
/// neighbour's crown is as natural as two crowns touching). \p world holds the nodes' world
/// positions. Returns how many were dropped.
std::size_t dropTouchingLeaves(skel::Skeleton& s, const std::vector<glm::vec3>& world,
                               const glm::mat4& m, const AdaptParams& params,
                               const ObstacleScene& scene, Collider& collider) {
    if (s.leaves.empty()) return 0;
    constexpr std::size_t kPerLeaf = 7;
    std::vector<Segment> segs;
    std::vector<std::size_t> tested; // leaves whose card box overlaps an obstacle's bounds
    for (std::size_t i = 0; i < s.leaves.size(); ++i) {
        const skel::Leaf& leaf = s.leaves[i];
        const bool onNode = leaf.node >= 0 && static_cast<std::size_t>(leaf.node) < world.size();
        // A leaf without a node has no stem: a zero-length segment never hits.
        const glm::vec3 stem = onNode ? world[static_cast<std::size_t>(leaf.node)]
                                      : glm::vec3(m * glm::vec4(leaf.position, 1.0f));
        const CardSegments card = cardSegments(m, leaf, stem, params.leafScale, params.leafAspect);
        if (!scene.overlapsBounds(card.lo, card.hi)) continue;
        tested.push_back(i);
        segs.insert(segs.end(), std::begin(card.seg), std::end(card.seg));
    }
    if (tested.empty()) return 0;
    const std::vector<std::uint8_t> hit = collider.occluded(segs);
    std::vector<std::uint8_t> drop(s.leaves.size(), 0);
    std::size_t dropped = 0;
    for (std::size_t t = 0; t < tested.size(); ++t) {
        for (std::size_t k = 0; k < kPerLeaf; ++k)
            drop[tested[t]] = drop[tested[t]] || hit[kPerLeaf * t + k] != 0;
        dropped += drop[tested[t]];
    }
    if (dropped == 0) return 0;
    std::vector<skel::Leaf> kept;
    kept.reserve(s.leaves.size() - dropped);
    for (std::size_t i = 0; i < s.leaves.size(); ++i)
        if (!drop[i]) kept.push_back(s.leaves[i]);
    s.leaves = std::move(kept);
    return dropped;
}

} // namespace

AdaptResult adaptTree(const skel::Skeleton& rest, const ObstacleScene& scene,
                      const glm::mat4& treeTransform, const AdaptParams& params,
                      std::span<const CrownVolume> neighbours) {
    requireRange("max_bend", params.maxBend, 0.0, glm::half_pi<double>());
    requireRange("bend_multiplier", params.bendMultiplier, 0.0, 1.0);
    for (int k = 0; k < 3; ++k)
        requireRange("light direction", params.lightDirection[k], -1e6, 1e6);
    requireRange("leaf_scale", params.leafScale, 1e-6, 100.0);
    requireRange("leaf_aspect", params.leafAspect, 1e-6, 4.0);
    rest.validate();
    if (!params.barkRadii.empty() && params.barkRadii.size() != rest.size())
        throw InvalidInput("adaptTree: " + std::to_string(params.barkRadii.size()) +
                           " bark radii for a skeleton of " + std::to_string(rest.size()) +
                           " nodes");

    AdaptResult result;
    result.skeleton = rest;
    skel::Skeleton& out = result.skeleton;
    AdaptStats& stats = result.stats;
    const std::size_t n = rest.size();
    for (std::uint8_t& f : out.flags)
        f &= static_cast<std::uint8_t>(~skel::kHidden);
    for (std::size_t i = 0; i < n; ++i)
        if (rest.parent[i] >= 0)
            stats.totalLengthBefore += glm::length(
                rest.position[i] - rest.position[static_cast<std::size_t>(rest.parent[i])]);
    stats.visibleLengthAfter = stats.totalLengthBefore;
    if (n < 2) return result;

    std::vector<glm::vec3> world = toWorld(rest.position, treeTransform);
    const float worldScale = maxScale(treeTransform);
    // Per segment (by its end node), the world radius of its tube: the larger of its two rings.
    std::vector<float> bark(n, 0.0f);
    float maxBark = 0.0f;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t p = rest.parent[i];
        if (p < 0) continue;
        const auto radiusAt = [&](std::size_t k) {
            const float r = params.barkRadii.empty() ? rest.radius[k] : params.barkRadii[k];
            return std::isfinite(r) ? std::max(r, 0.0f) : 0.0f;
        };
        bark[i] = std::max(radiusAt(static_cast<std::size_t>(p)), radiusAt(i)) * worldScale;
        maxBark = std::max(maxBark, bark[i]);
    }
    glm::vec3 lo = world[0], hi = world[0];
    for (const glm::vec3& p : world) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    lo -= glm::vec3(maxBark);
    hi += glm::vec3(maxBark);
    // Leaf cards reach beyond their nodes.
    for (const skel::Leaf& leaf : rest.leaves) {
        const glm::vec3 a(treeTransform * glm::vec4(leaf.position, 1.0f));
        const glm::vec3 r(leafReach(leaf, params) * worldScale);
        lo = glm::min(lo, a - r);
        hi = glm::max(hi, a + r);
    }
    // Only neighbours that can touch this tree at all; keeps the per-segment loop short.
    std::vector<CrownVolume> crowns;
    for (const CrownVolume& c : neighbours) {
        const glm::vec3 clo(c.base.x - c.radius, c.base.y + c.bottom, c.base.z - c.radius);
        const glm::vec3 chi(c.base.x + c.radius, c.base.y + c.top, c.base.z + c.radius);
        if (glm::all(glm::lessThanEqual(clo, hi)) && glm::all(glm::lessThanEqual(lo, chi)))
            crowns.push_back(c);
    }
    // Leaves are only tested against obstacles (not crowns): none to test when far from them.
    const bool nearObstacles = scene.overlapsBounds(lo, hi);
    if (crowns.empty() && !nearObstacles) return result;

    Collider collider(scene, crowns, bark, stats);
    Collider leafCollider(scene, {}, {}, stats);
    std::vector<std::size_t> allSegments;
    allSegments.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        if (rest.parent[i] >= 0) allSegments.push_back(i);

    const std::vector<Hit> hits = collider.intersect(rest, world, allSegments);
    stats.collidingBefore = hits.size();
    if (hits.empty()) {
        if (params.prune && nearObstacles)
            stats.droppedLeaves =
                dropTouchingLeaves(out, world, treeTransform, params, scene, leafCollider);
        return result;
    }

    // Topology: the root of every node and how many children each node has.
    std::vector<std::size_t> rootOf(n);
    std::vector<std::uint32_t> children(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t p = rest.parent[i];
        rootOf[i] = p < 0 ? i : rootOf[static_cast<std::size_t>(p)];
        if (p >= 0) ++children[static_cast<std::size_t>(p)];
    }

    // Per root: the average direction of its hits seen from the root, and the top of what it hit.
    struct RootBend {
        glm::dvec3 sum{0.0};
        float top = -std::numeric_limits<float>::max();
        glm::vec3 axisLocal{0.0f};
        bool bend = false;
    };
    std::vector<RootBend> bends(n);
    for (const Hit& h : hits) {
        RootBend& b = bends[rootOf[h.node]];
        const glm::dvec3 d = glm::dvec3(h.point - world[rootOf[h.node]]);
        const double len = glm::length(d);
        if (len > 1e-9) b.sum += d / len;
        b.top = std::max(b.top, h.top);
    }
    const glm::mat3 invLinear = glm::inverse(glm::mat3(treeTransform));
    for (std::size_t r = 0; r < n; ++r) {
        RootBend& b = bends[r];
        // Bend in the horizontal plane only: an obstacle straight above (a roof) gives no
        // direction to lean to, and such trees are only pruned.
        const glm::dvec3 away(-b.sum.x, 0.0, -b.sum.z);
        if (glm::length(away) < 1e-9 || params.maxBend <= 0.0f) continue;
        const glm::vec3 axisWorld =
            glm::normalize(glm::cross(glm::vec3(0, 1, 0), glm::vec3(glm::normalize(away))));
        const glm::vec3 axisLocal = invLinear * axisWorld;
        if (glm::length(axisLocal) < 1e-12f) continue;
        b.axisLocal = glm::normalize(axisLocal);
        b.bend = true;
    }

    // Bend: one forward pass from the roots; every node's accumulated lean about its root's
    // axis, rotations about a common axis commute so a segment turns by its lean alone.
    std::vector<float> lean(n, 0.0f);
    std::vector<std::uint32_t> level(n, 0);
    std::vector<glm::vec3> bent(rest.position);
    const glm::vec4 worldYRow(treeTransform[0][1], treeTransform[1][1], treeTransform[2][1],
                              treeTransform[3][1]);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t pi = rest.parent[i];
        if (pi < 0) continue;
        const auto p = static_cast<std::size_t>(pi);
        const RootBend& b = bends[rootOf[i]];
        if (!b.bend) continue;
        const bool fork = children[p] > 1;
        level[i] = level[p] + (fork && rest.parent[p] >= 0 ? 1u : 0u);
        const bool startsBranch = rest.parent[p] < 0 || fork;
        float theta = 0.0f;
        const float parentWorldY = glm::dot(worldYRow, glm::vec4(bent[p], 1.0f));
        if (params.returnToVertical && rest.order[i] == 0 && parentWorldY >= b.top) {
            // Above the obstacle the trunk straightens, as the reference's photographed alder does.
            theta = -std::copysign(std::min(std::abs(lean[p]), params.maxBend), lean[p]);
        } else if (startsBranch) {
            theta = params.maxBend * std::pow(params.bendMultiplier, static_cast<float>(level[i]));
        }
        lean[i] = lean[p] + theta;
        const glm::quat q = glm::angleAxis(lean[i], b.axisLocal);
        bent[i] = bent[p] + q * (rest.position[i] - rest.position[p]);
        stats.leanRadians = std::max(stats.leanRadians, static_cast<double>(std::abs(lean[i])));
    }
    stats.bent = stats.leanRadians > 0.0;

    // Re-check and prune.
    std::vector<std::uint8_t> hidden(n, 0);
    {
        world = toWorld(bent, treeTransform);
        std::vector<std::size_t> recheck;
        if (params.recheckAll) {
            recheck = allSegments;
        } else {
            for (const Hit& h : hits)
                recheck.push_back(h.node);
        }
        const std::vector<std::uint8_t> still = collider.occluded(rest, world, recheck);
        for (std::size_t k = 0; k < recheck.size(); ++k) {
            stats.collidingAfterBend += still[k];
            if (still[k] && params.prune) hidden[recheck[k]] = 1;
        }
    }
    // Hidden nodes hide their subtrees; the pruned length is counted from scratch each time.
    const auto hideSubtrees = [&] {
        stats.hiddenNodes = 0;
        stats.prunedLength = 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            const std::int32_t p = rest.parent[i];
            if (p >= 0 && hidden[static_cast<std::size_t>(p)]) hidden[i] = 1;
            if (hidden[i]) {
                ++stats.hiddenNodes;
                if (p >= 0)
                    stats.prunedLength +=
                        glm::length(rest.position[i] - rest.position[static_cast<std::size_t>(p)]);
            }
        }
    };

    // Redistribute: grow each visible segment that is not frozen along itself, by a share of
    // the pruned length weighted toward the light, so the visible length equals the rest pose's
    // total length. Writes the grown pose and each segment's growth.
    const float lightLen = glm::length(params.lightDirection);
    const glm::vec3 towardLight =
        lightLen > 1e-12f ? -params.lightDirection / lightLen : glm::vec3(0.0f);
    const glm::mat3 linear(treeTransform);
    std::vector<double> weight(n, 0.0), growth(n, 0.0);
    const auto redistribute = [&](const std::vector<std::uint8_t>& frozen,
                                  std::vector<glm::vec3>& grown) {
        grown = bent;
        std::fill(growth.begin(), growth.end(), 0.0);
        stats.redistributedLength = 0.0;
        if (!params.redistribute || stats.prunedLength <= 0.0) return;
        std::fill(weight.begin(), weight.end(), 0.0);
        double weightSum = 0.0;
        std::size_t candidates = 0;
        for (std::size_t i : allSegments) {
            if (hidden[i] || frozen[i]) continue;
            const glm::vec3 d = bent[i] - bent[static_cast<std::size_t>(rest.parent[i])];
            if (glm::length(d) <= 0.0f) continue;
            ++candidates;
            double w = 1.0;
            if (lightLen > 1e-12f) {
                const glm::vec3 dw = linear * d;
                w = 0.5 * (1.0 + static_cast<double>(glm::dot(glm::normalize(dw), towardLight)));
            }
            weight[i] = w;
            weightSum += w;
        }
        if (candidates == 0) return;
        if (weightSum <= 0.0) {
            // Everything that may grow points straight away from the light: share equally.
            for (std::size_t i : allSegments)
                if (!hidden[i] && !frozen[i] &&
                    glm::length(bent[i] - bent[static_cast<std::size_t>(rest.parent[i])]) > 0.0f) {
                    weight[i] = 1.0;
                    weightSum += 1.0;
                }
        }
        for (std::size_t i = 0; i < n; ++i) {
            const std::int32_t pi = rest.parent[i];
            if (pi < 0) continue;
            const auto p = static_cast<std::size_t>(pi);
            const glm::vec3 d = bent[i] - bent[p];
            const double len = glm::length(glm::dvec3(d));
            growth[i] = weight[i] > 0.0 ? stats.prunedLength * weight[i] / weightSum : 0.0;
            grown[i] =
                grown[p] + glm::vec3(glm::dvec3(d) * ((len + growth[i]) / std::max(len, 1e-300)));
            if (len <= 0.0) grown[i] = grown[p];
            stats.redistributedLength += growth[i];
        }
    };

    // Growth moves whole subtrees, so the grown pose is checked again (the reference grew after
    // its collision test, which let tips and whole crowns into the mesh). A segment that now
    // collides withdraws the growth of its path to the root (the length goes to the others); one
    // whose path did not grow is hidden. Every round freezes or hides at least one segment;
    // after kFreezeRounds all growth stops, so the loop ends.
    constexpr std::size_t kFreezeRounds = 8;
    std::vector<std::uint8_t> frozen(n, 0);
    std::vector<glm::vec3> grown;
    hideSubtrees();
    for (std::size_t round = 0;; ++round) {
        redistribute(frozen, grown);
        ++stats.growthRounds;
        std::vector<std::size_t> visible;
        for (std::size_t i : allSegments)
            if (!hidden[i]) visible.push_back(i);
        world = toWorld(grown, treeTransform);
        const std::vector<std::uint8_t> still = collider.occluded(rest, world, visible);
        stats.collidingAfter = 0;
        for (std::uint8_t h : still)
            stats.collidingAfter += h;
        if (stats.collidingAfter == 0 || !params.prune) break;
        for (std::size_t k = 0; k < visible.size(); ++k) {
            if (!still[k]) continue;
            const std::size_t j = visible[k];
            bool grew = false;
            for (std::int32_t x = static_cast<std::int32_t>(j); x >= 0 && !grew;
                 x = rest.parent[static_cast<std::size_t>(x)])
                grew = growth[static_cast<std::size_t>(x)] > 0.0;
            if (!grew) {
                hidden[j] = 1;
                continue;
            }
            for (std::int32_t x = static_cast<std::int32_t>(j);
                 x >= 0 && !frozen[static_cast<std::size_t>(x)];
                 x = rest.parent[static_cast<std::size_t>(x)])
                frozen[static_cast<std::size_t>(x)] = 1;
        }
        if (round + 1 >= kFreezeRounds) std::fill(frozen.begin(), frozen.end(), 1);
        hideSubtrees();
    }

    // Final pose, flags, frames and leaves.
    for (std::size_t i = 0; i < n; ++i) {
        out.position[i] = grown[i];
        if (hidden[i]) out.flags[i] |= skel::kHidden;
        const RootBend& b = bends[rootOf[i]];
        if (b.bend && lean[i] != 0.0f)
            out.orientation[i] =
                glm::normalize(glm::angleAxis(lean[i], b.axisLocal) * rest.orientation[i]);
    }
    out.leaves.clear();
    for (const skel::Leaf& leaf : rest.leaves) {
        if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) {
            out.leaves.push_back(leaf);
            continue;
        }
        const auto k = static_cast<std::size_t>(leaf.node);
        if (hidden[k]) continue;
        skel::Leaf moved = leaf;
        const RootBend& b = bends[rootOf[k]];
        const glm::quat q = b.bend ? glm::angleAxis(lean[k], b.axisLocal) : glm::quat(1, 0, 0, 0);
        moved.position = grown[k] + q * (leaf.position - rest.position[k]);
        moved.orientation = glm::normalize(q * leaf.orientation);
        out.leaves.push_back(moved);
    }
    stats.visibleLengthAfter = visibleLength(out);
    if (params.prune) {
        // Growth may have carried the crown toward an obstacle: bounds of the final pose.
        glm::vec3 flo = world[0], fhi = world[0];
        for (const glm::vec3& p : world) {
            flo = glm::min(flo, p);
            fhi = glm::max(fhi, p);
        }
        flo -= glm::vec3(maxBark);
        fhi += glm::vec3(maxBark);
        for (const skel::Leaf& leaf : out.leaves) {
            const glm::vec3 a(treeTransform * glm::vec4(leaf.position, 1.0f));
            const glm::vec3 r(leafReach(leaf, params) * worldScale);
            flo = glm::min(flo, a - r);
            fhi = glm::max(fhi, a + r);
        }
        if (scene.overlapsBounds(flo, fhi))
            stats.droppedLeaves =
                dropTouchingLeaves(out, world, treeTransform, params, scene, leafCollider);
    }
    return result;
}

std::vector<AdaptResult> adaptTrees(std::span<const skel::Skeleton* const> rest,
                                    std::span<const glm::mat4> transforms,
                                    const ObstacleScene& scene, const AdaptParams& params,
                                    std::span<const std::vector<CrownVolume>> neighbours,
                                    Progress& progress) {
    if (rest.size() != transforms.size() ||
        (!neighbours.empty() && neighbours.size() != rest.size()))
        throw InvalidInput("adaptTrees: one transform (and neighbour list) per tree");
    progress.checkCancelled();
    std::vector<AdaptResult> out(rest.size());
    const auto n = static_cast<std::ptrdiff_t>(rest.size());
    std::atomic<bool> stop{false};
    std::atomic<std::size_t> done{0};
    std::exception_ptr error;
    std::mutex errorMutex;
#pragma omp parallel for schedule(dynamic, 4)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        if (stop.load(std::memory_order_relaxed)) continue;
        const auto k = static_cast<std::size_t>(i);
        try {
            out[k] = adaptTree(*rest[k], scene, transforms[k], params,
                               neighbours.empty() ? std::span<const CrownVolume>()
                                                  : std::span<const CrownVolume>(neighbours[k]));
        } catch (...) {
            const std::lock_guard<std::mutex> lock(errorMutex);
            if (!error) error = std::current_exception();
            stop = true;
        }
        const std::size_t finished = ++done;
        // Only the master thread talks to the Progress: implementations need not be thread-safe.
        if (omp_get_thread_num() == 0) {
            progress.report(static_cast<double>(finished) / static_cast<double>(n), "adapt");
            if (progress.isCancelled()) stop = true;
        }
    }
    if (error) std::rethrow_exception(error);
    // Under load thread 0 may have run no iteration at all: ask once more after the loop.
    if (stop || progress.isCancelled()) throw Cancelled();
    return out;
}

} // namespace sylva::env
