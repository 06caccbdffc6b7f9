// The first, straightforward tube mesher (engine/mesh/tubemesh.cpp before the scratch-block
// rewrite, kept verbatim): resizes the mesh arrays and writes each chain at its offset. The
// oracle of the optimized mesher in the tests (identical bytes) and its same-run baseline in
// the benchmark. Only for tests and benchmarks.
#include "referencetubemesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "engine/util/error.h"

namespace sylva::mesh::reference {

namespace {

constexpr float kCoincident = 1e-7f;

// Axes of the skeleton, flattened: chain c covers nodes[begin[c] .. begin[c+1]).
// For a lateral chain the first entry is the parent node (the fork), whose position the base
// ring uses with the lateral's radius.
struct Chains {
    std::vector<std::int32_t> nodes;
    std::vector<std::uint32_t> begin{0};
    std::vector<std::uint8_t> lateral;
    std::size_t count() const { return lateral.size(); }
};

Chains buildChains(const skel::Skeleton& s, const std::vector<float>& radius,
                   double minBranchRadius) {
    const std::size_t n = s.size();
    std::vector<std::int32_t> cont(n, -1);
    std::vector<std::uint8_t> dropped(n, 0);
    std::vector<std::uint8_t> isStart(n, 0);
    for (std::size_t j = 0; j < n; ++j) {
        const std::int32_t p = s.parent[j];
        if (s.flags[j] & skel::kHidden) {
            dropped[j] = 1;
        } else if (p < 0) {
            isStart[j] = 1;
        } else if (dropped[static_cast<std::size_t>(p)]) {
            dropped[j] = 1;
        } else if (s.order[j] == s.order[static_cast<std::size_t>(p)] &&
                   cont[static_cast<std::size_t>(p)] < 0) {
            cont[static_cast<std::size_t>(p)] = static_cast<std::int32_t>(j);
        } else if (radius[j] < minBranchRadius) {
            dropped[j] = 1;
        } else {
            isStart[j] = 2;
        }
    }
    Chains chains;
    chains.nodes.reserve(n + n / 4);
    for (std::size_t j = 0; j < n; ++j) {
        if (!isStart[j]) continue;
        const std::size_t first = chains.nodes.size();
        if (isStart[j] == 2) chains.nodes.push_back(s.parent[j]);
        for (std::int32_t x = static_cast<std::int32_t>(j); x >= 0;
             x = cont[static_cast<std::size_t>(x)]) {
            if (chains.nodes.size() > first) {
                const glm::vec3 d = s.position[static_cast<std::size_t>(x)] -
                                    s.position[static_cast<std::size_t>(chains.nodes.back())];
                if (glm::dot(d, d) < kCoincident * kCoincident) continue;
            }
            chains.nodes.push_back(x);
        }
        if (chains.nodes.size() - first < 2) {
            chains.nodes.resize(first);
            continue;
        }
        chains.begin.push_back(static_cast<std::uint32_t>(chains.nodes.size()));
        chains.lateral.push_back(isStart[j] == 2 ? 1 : 0);
    }
    return chains;
}

glm::vec3 anyPerpendicular(const glm::vec3& t) {
    const glm::vec3 a = std::abs(t.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(t, a));
}

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    const float len2 = glm::dot(v, v);
    return len2 > 1e-20f ? v / std::sqrt(len2) : fallback;
}

struct Layout {
    std::size_t vertices = 0;
    std::size_t indices = 0;
};

Layout chainLayout(std::size_t rings, bool lateral, bool caps, int res) {
    Layout l;
    const std::size_t ringVerts = static_cast<std::size_t>(res) + 1;
    l.vertices = rings * ringVerts;
    l.indices = (rings - 1) * static_cast<std::size_t>(res) * 6;
    if (caps) {
        const std::size_t capCount = lateral ? 1 : 2;
        l.vertices += capCount * (ringVerts + 1);
        l.indices += capCount * static_cast<std::size_t>(res) * 3;
    }
    return l;
}

struct Writer {
    Mesh& m;
    bool wind;
    std::size_t v;
    std::size_t i;
    std::uint16_t order;
    float invRMax;
    float flex = 0.0f;

    void vertex(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
        m.positions[v] = p;
        m.normals[v] = n;
        m.uvs[v] = uv;
        if (wind) {
            m.branchOrder[v] = order;
            m.flexibility[v] = flex;
        }
        ++v;
    }
    void triangle(std::size_t a, std::size_t b, std::size_t c) {
        m.indices[i] = static_cast<std::uint32_t>(a);
        m.indices[i + 1] = static_cast<std::uint32_t>(b);
        m.indices[i + 2] = static_cast<std::uint32_t>(c);
        i += 3;
    }
};

void cap(Writer& w, const glm::vec3& centre, const glm::vec3& n, const glm::vec3& b,
         const glm::vec3& normal, float r, const std::vector<glm::vec3>& cs, bool flip) {
    const int res = static_cast<int>(cs.size()) - 1;
    const std::size_t c = w.v;
    w.vertex(centre, normal, {0.5f, 0.5f});
    for (int j = 0; j <= res; ++j) {
        const glm::vec3 a = cs[static_cast<std::size_t>(j)];
        w.vertex(centre + r * (a.x * n + a.y * b), normal, {0.5f + 0.5f * a.x, 0.5f + 0.5f * a.y});
    }
    for (int j = 0; j < res; ++j) {
        const std::size_t a = c + 1 + static_cast<std::size_t>(j);
        if (flip)
            w.triangle(c, a + 1, a);
        else
            w.triangle(c, a, a + 1);
    }
}

void meshChain(Writer& w, const skel::Skeleton& s, const std::vector<float>& radius,
               const std::int32_t* nodes, std::size_t m, bool lateral, bool caps,
               const std::vector<glm::vec3>& cs) {
    const int res = static_cast<int>(cs.size()) - 1;
    auto P = [&](std::size_t k) { return s.position[static_cast<std::size_t>(nodes[k])]; };
    // The base ring of a lateral uses the lateral's own radius, never wider than the parent.
    auto R = [&](std::size_t k) {
        if (k == 0 && lateral)
            return std::min(radius[static_cast<std::size_t>(nodes[1])],
                            radius[static_cast<std::size_t>(nodes[0])]);
        return radius[static_cast<std::size_t>(nodes[k])];
    };
    const glm::vec3 frameHeading =
        skel::headingOf(s.orientation[static_cast<std::size_t>(nodes[lateral ? 1 : 0])]);
    auto dir = [&](std::size_t k) { return safeNormalize(P(k + 1) - P(k), frameHeading); };

    glm::vec3 tPrev(0.0f), n(0.0f), pPrev(0.0f);
    glm::vec3 dPrev = dir(0);
    float v = 0.0f;
    const std::size_t ringVerts = static_cast<std::size_t>(res) + 1;
    const std::size_t firstRing = caps && !lateral ? w.v + ringVerts + 1 : w.v;
    std::size_t ringStart = firstRing;
    if (caps && !lateral) w.v = firstRing; // the base cap is written after the first frame
    glm::vec3 n0(0.0f), b0(0.0f), t0(0.0f);

    for (std::size_t k = 0; k < m; ++k) {
        const glm::vec3 p = P(k);
        const glm::vec3 dNext = k + 1 < m ? dir(k) : dPrev;
        const glm::vec3 t = k == 0       ? dNext
                            : k + 1 == m ? dPrev
                                         : safeNormalize(dPrev + dNext, dNext);
        if (k == 0) {
            const glm::quat q = s.orientation[static_cast<std::size_t>(nodes[lateral ? 1 : 0])];
            glm::vec3 up = skel::upOf(q);
            up -= glm::dot(up, t) * t;
            n = glm::dot(up, up) > 1e-6f ? glm::normalize(up) : anyPerpendicular(t);
        } else {
            // Double reflection (Wang et al. 2008): rotation-minimizing frame transport.
            const glm::vec3 v1 = p - pPrev;
            const float c1 = glm::dot(v1, v1);
            glm::vec3 nL = n, tL = tPrev;
            if (c1 > 1e-20f) {
                nL = n - (2.0f / c1) * glm::dot(v1, n) * v1;
                tL = tPrev - (2.0f / c1) * glm::dot(v1, tPrev) * v1;
            }
            const glm::vec3 v2 = t - tL;
            const float c2 = glm::dot(v2, v2);
            if (c2 > 1e-20f) nL -= (2.0f / c2) * glm::dot(v2, nL) * v2;
            nL -= glm::dot(nL, t) * t;
            n = safeNormalize(nL, anyPerpendicular(t));
            const float rAvg = std::max(0.5f * (R(k - 1) + R(k)), 1e-3f);
            v += std::sqrt(c1) / (2.0f * std::numbers::pi_v<float> * rAvg);
        }
        const glm::vec3 b = glm::cross(t, n);
        const float r = R(k);
        w.flex = 1.0f - r * w.invRMax;
        // Taper slope dr/ds tilts the normals towards the thinner end.
        const std::size_t ka = k > 0 ? k - 1 : k, kb = k + 1 < m ? k + 1 : k;
        const float ds = glm::length(P(kb) - P(ka));
        const float slope = ds > 1e-12f ? (R(kb) - R(ka)) / ds : 0.0f;
        const float inv = 1.0f / std::sqrt(1.0f + slope * slope);
        const glm::vec3 tn = -slope * inv * t;
        for (int j = 0; j <= res; ++j) {
            const glm::vec3 a = cs[static_cast<std::size_t>(j)];
            const glm::vec3 radial = a.x * n + a.y * b;
            w.vertex(p + r * radial, radial * inv + tn, {a.z, v});
        }
        if (k > 0) {
            const std::size_t a0 = ringStart - ringVerts;
            for (int j = 0; j < res; ++j) {
                const std::size_t a = a0 + static_cast<std::size_t>(j);
                const std::size_t c = ringStart + static_cast<std::size_t>(j);
                w.triangle(a, a + 1, c + 1);
                w.triangle(a, c + 1, c);
            }
        }
        if (k == 0) {
            n0 = n;
            b0 = b;
            t0 = t;
        }
        ringStart += ringVerts;
        tPrev = t;
        pPrev = p;
        dPrev = dNext;
        if (k + 1 == m && caps) cap(w, p, n, b, t, r, cs, false);
    }
    if (caps && !lateral) {
        const std::size_t end = w.v;
        w.v = firstRing - ringVerts - 1;
        cap(w, P(0), n0, b0, -t0, R(0), cs, true);
        w.v = end;
    }
}

} // namespace

std::vector<float> tubeRadiiReference(const skel::Skeleton& s, const TubeSettings& settings) {
    const std::size_t n = s.size();
    std::vector<float> r(n);
    const auto scale = static_cast<float>(settings.radiusScale);
    if (settings.thickness == ThicknessMode::Skeleton) {
        for (std::size_t i = 0; i < n; ++i)
            r[i] = std::max(s.radius[i] * scale, kMinTubeRadius);
        return r;
    }
    std::vector<std::uint32_t> children(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (s.parent[i] >= 0 && !(s.flags[i] & skel::kHidden))
            ++children[static_cast<std::size_t>(s.parent[i])];
    std::vector<std::uint32_t> forks(n, 0);
    const double base = 0.5 * settings.initialThickness * settings.radiusScale;
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t p = s.parent[i];
        if (p >= 0)
            forks[i] = forks[static_cast<std::size_t>(p)] +
                       (children[static_cast<std::size_t>(p)] > 1 ? 1u : 0u);
        r[i] = std::max(static_cast<float>(base * std::pow(settings.thicknessMultiplier,
                                                           static_cast<double>(forks[i]))),
                        kMinTubeRadius);
    }
    return r;
}

void appendTubesReference(Mesh& out, const skel::Skeleton& s, const TubeSettings& settings,
                          Progress& progress) {
    requireRange("resolution", settings.resolution, 3, 64);
    requireRange("radius_scale", settings.radiusScale, 0.0, 1e3);
    if (settings.thickness == ThicknessMode::Branching) {
        requireRange("initial_thickness", settings.initialThickness, 0.0, 1e3);
        requireRange("thickness_multiplier", settings.thicknessMultiplier, 1e-6, 1.0);
    }
    s.validate();
    const int res = settings.resolution;
    const std::vector<float> radius = tubeRadiiReference(s, settings);
    const Chains chains = buildChains(s, radius, settings.minBranchRadius);
    const std::size_t count = chains.count();

    std::vector<std::size_t> vOff(count + 1), iOff(count + 1);
    vOff[0] = out.positions.size();
    iOff[0] = out.indices.size();
    for (std::size_t c = 0; c < count; ++c) {
        const Layout l = chainLayout(chains.begin[c + 1] - chains.begin[c], chains.lateral[c],
                                     settings.caps, res);
        vOff[c + 1] = vOff[c] + l.vertices;
        iOff[c + 1] = iOff[c] + l.indices;
    }
    if (vOff[count] > std::numeric_limits<std::uint32_t>::max())
        throw LimitExceeded("tube mesh would have " + std::to_string(vOff[count]) +
                            " vertices; the limit of 32-bit indices is 4294967295");

    // Attributes the mesh did not have yet are filled for the existing vertices too.
    out.positions.resize(vOff[count]);
    out.normals.resize(vOff[count], glm::vec3(0, 1, 0));
    out.uvs.resize(vOff[count], glm::vec2(0.0f));
    const bool wind = settings.windAttributes || !out.branchOrder.empty();
    if (wind) {
        out.branchOrder.resize(vOff[count], 0);
        out.flexibility.resize(vOff[count], 1.0f);
    }
    out.indices.resize(iOff[count]);
    if (iOff[count] > iOff[0]) {
        if (out.submeshes.empty() && iOff[0] > 0)
            out.submeshes.push_back({"bark", 0, static_cast<std::uint32_t>(iOff[0])});
        out.submeshes.push_back({"bark", static_cast<std::uint32_t>(iOff[0]),
                                 static_cast<std::uint32_t>(iOff[count] - iOff[0])});
    }

    // cos, sin and u of each ring vertex; the seam repeats the first with u = 1.
    std::vector<glm::vec3> cs(static_cast<std::size_t>(res) + 1);
    for (int j = 0; j < res; ++j) {
        const double a = 2.0 * std::numbers::pi * j / res;
        cs[static_cast<std::size_t>(j)] = {static_cast<float>(std::cos(a)),
                                           static_cast<float>(std::sin(a)),
                                           static_cast<float>(j) / static_cast<float>(res)};
    }
    cs[static_cast<std::size_t>(res)] = {cs[0].x, cs[0].y, 1.0f};
    float rMax = 0.0f;
    for (float r : radius)
        rMax = std::max(rMax, r);
    const float invRMax = rMax > 0.0f ? 1.0f / rMax : 0.0f;

    // Batches keep cancellation responsive; inside a batch the chains are independent and
    // each writes only its own precomputed ranges, so the result is thread-count independent.
    constexpr std::size_t kBatch = 8192;
    for (std::size_t first = 0; first < count; first += kBatch) {
        progress.checkCancelled();
        progress.report(static_cast<double>(first) / static_cast<double>(count), "mesh");
        const auto last = static_cast<std::int64_t>(std::min(count, first + kBatch));
#pragma omp parallel for schedule(dynamic, 256)
        for (std::int64_t ci = static_cast<std::int64_t>(first); ci < last; ++ci) {
            const auto c = static_cast<std::size_t>(ci);
            const std::int32_t* nodes = chains.nodes.data() + chains.begin[c];
            const std::size_t m = chains.begin[c + 1] - chains.begin[c];
            const bool lateral = chains.lateral[c] != 0;
            const auto head = static_cast<std::size_t>(nodes[lateral ? 1 : 0]);
            Writer w{out, wind, vOff[c], iOff[c], s.order[head], invRMax};
            meshChain(w, s, radius, nodes, m, lateral, settings.caps, cs);
        }
    }
    progress.report(1.0, "mesh");
}

} // namespace sylva::mesh::reference
