#include "engine/mesh/tubemesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "engine/util/error.h"
#include "engine/util/hugepages.h"
#include "engine/util/rawvector.h"
#include "engine/util/safenormalize.h"

namespace sylva::mesh {

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

/// Greedy axis simplification: from the last kept node, extend the straight tube as far as
/// every skipped node lies within \p tol of it (distance to the segment, and radius against the
/// linearly interpolated one). The first and last nodes are always kept.
void simplifyChain(std::vector<std::int32_t>& nodes, std::size_t first, const skel::Skeleton& s,
                   const std::vector<float>& radius, double tol) {
    const std::size_t m = nodes.size() - first;
    if (m <= 2 || tol <= 0.0) return;
    auto P = [&](std::size_t k) {
        return glm::dvec3(s.position[static_cast<std::size_t>(nodes[first + k])]);
    };
    auto R = [&](std::size_t k) {
        return static_cast<double>(radius[static_cast<std::size_t>(nodes[first + k])]);
    };
    auto fits = [&](std::size_t a, std::size_t b) {
        const glm::dvec3 pa = P(a), d = P(b) - pa;
        const double len2 = glm::dot(d, d);
        for (std::size_t k = a + 1; k < b; ++k) {
            const double t = len2 > 0.0 ? std::clamp(glm::dot(P(k) - pa, d) / len2, 0.0, 1.0) : 0.0;
            if (glm::length(pa + t * d - P(k)) > tol) return false;
            if (std::abs(R(a) + t * (R(b) - R(a)) - R(k)) > tol) return false;
        }
        return true;
    };
    std::vector<std::int32_t> kept{nodes[first]};
    std::size_t a = 0;
    while (a + 1 < m) {
        std::size_t b = a + 1;
        while (b + 1 < m && fits(a, b + 1))
            ++b;
        kept.push_back(nodes[first + b]);
        a = b;
    }
    nodes.resize(first);
    nodes.insert(nodes.end(), kept.begin(), kept.end());
}

Chains buildChains(const skel::Skeleton& s, const std::vector<float>& radius,
                   double minBranchRadius, double simplifyTolerance) {
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
        simplifyChain(chains.nodes, first, s, radius, simplifyTolerance);
        chains.begin.push_back(static_cast<std::uint32_t>(chains.nodes.size()));
        chains.lateral.push_back(isStart[j] == 2 ? 1 : 0);
    }
    return chains;
}

glm::vec3 anyPerpendicular(const glm::vec3& t) {
    const glm::vec3 a = std::abs(t.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(t, a));
}

/// Tube directions may be very short (tiny segments): only shorter ones than this fall back.
constexpr float kMinDirectionLength = 1e-10f;

/// safeNormalize(v, anyPerpendicular(t), kMinDirectionLength), the fallback (a cross product
/// and a normalization) made only where it is used: every ring of every axis asks.
glm::vec3 normalizeOrPerpendicular(const glm::vec3& v, const glm::vec3& t) {
    const float l = glm::length(v);
    return l > kMinDirectionLength ? v / l : anyPerpendicular(t);
}

struct Layout {
    std::size_t vertices = 0;
    std::size_t indices = 0;
};

Layout chainLayout(std::size_t rings, bool lateral, bool caps, int res, bool ribbon) {
    Layout l;
    if (ribbon) {
        l.vertices = rings * 2;
        l.indices = (rings - 1) * 6;
        return l;
    }
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

/// A ring's place and frame (meshChain's first loop; its second writes the rings).
struct RingFrame {
    glm::vec3 p, t, n, b, tn;
    float r, ds, inv, v;
};

/// \p v with room for \p n elements (grown, not filled, where it is smaller: what it held is
/// then lost), and its data: the thread's scratch arrays, reused from run to run and chain to
/// chain.
template <class T> T* room(RawVector<T>& v, std::size_t n) {
    if (v.size() < n) {
        v.clear();
        v.resize(n);
    }
    return v.data();
}

/// A relief chain's rows (meshChain's second pass), kept by the thread's Scratch from chain to
/// chain: a fresh vector a chain was an allocation and a zero fill of rows that are written
/// before they are read (the few pads that are read are set where the rows are made).
struct ReliefRows {
    RawVector<float> rho;     ///< ρ of each ring vertex (rings × sides+1, then four pads)
    RawVector<float> slopes;  ///< a ring's slopes (barkSlopeRow: ∂ρ/∂θ, then ∂ρ/∂s)
    RawVector<float> csLanes; ///< cs's x, y, then z (sides+1 and three zero pads each)
    RawVector<float> lanes;   ///< a ring's positions and normals by component
};

// Writes one run of chains into a scratch block: vertex v lands at v - base (indices keep
// their absolute values). Raw pointers, so the compiler does not reload vector internals.
struct Writer {
    glm::vec3* pos;
    glm::vec3* nrm;
    glm::vec2* uvs;
    std::uint16_t* orders; ///< null without wind attributes
    float* flexes;
    std::uint32_t* nodeIds; ///< null without node ids
    std::uint32_t* idx;
    std::size_t base;
    std::size_t indexBase;
    std::size_t v;
    std::size_t i;
    std::uint16_t order = 0;
    float invRMax = 0.0f;
    float flex = 0.0f;
    std::uint32_t node = 0;

    void vertex(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
        const std::size_t k = v - base;
        pos[k] = p;
        nrm[k] = n;
        uvs[k] = uv;
        if (orders) {
            orders[k] = order;
            flexes[k] = flex;
        }
        if (nodeIds) nodeIds[k] = node;
        ++v;
    }
    /// The per-vertex attributes but position, normal and uv (order, flex, node) of the \p count
    /// vertices from v, as vertex() writes them; v advanced past them.
    void attributes(std::size_t count) {
        const std::size_t first = v - base;
        if (orders)
            for (std::size_t k = first; k < first + count; ++k) {
                orders[k] = order;
                flexes[k] = flex;
            }
        if (nodeIds)
            for (std::size_t k = first; k < first + count; ++k)
                nodeIds[k] = node;
        v += count;
    }
    /// A round ring's vertices: vertex(p + r * radial, radial * inv + tn, {uTiles * a.z, v})
    /// with radial = a.x * n + a.y * b for each entry a of \p cs (res + 1 of them), bit for
    /// bit: the same products and sums, a vector's three lanes at once where SSE2 is there.
    void ring(const glm::vec3* cs, int res, const glm::vec3& p, float r, const glm::vec3& n,
              const glm::vec3& b, float inv, const glm::vec3& tn, float uTiles, float vCoord) {
#if defined(__SSE2__)
        const __m128 vn = _mm_setr_ps(n.x, n.y, n.z, 0.0f);
        const __m128 vb = _mm_setr_ps(b.x, b.y, b.z, 0.0f);
        const __m128 vp = _mm_setr_ps(p.x, p.y, p.z, 0.0f);
        const __m128 vtn = _mm_setr_ps(tn.x, tn.y, tn.z, 0.0f);
        const __m128 vr = _mm_set1_ps(r), vinv = _mm_set1_ps(inv);
        // The writer's arrays and values in locals: _mm_storel_pi stores through __m64, which may
        // alias anything, so the members were loaded again after every vertex's store.
        const std::size_t first = v - base;
        float* const positions = &pos[first].x;
        float* const normals = &nrm[first].x;
        glm::vec2* const uv = uvs + first;
        std::uint16_t* const ord = orders != nullptr ? orders + first : nullptr;
        float* const flx = orders != nullptr ? flexes + first : nullptr;
        std::uint32_t* const ids = nodeIds != nullptr ? nodeIds + first : nullptr;
        const std::uint16_t o = order;
        const float fl = flex;
        const std::uint32_t id = node;
        for (int j = 0; j <= res; ++j) {
            const glm::vec3& a = cs[j];
            const __m128 radial =
                _mm_add_ps(_mm_mul_ps(_mm_load1_ps(&a.x), vn), _mm_mul_ps(_mm_load1_ps(&a.y), vb));
            const __m128 position = _mm_add_ps(vp, _mm_mul_ps(vr, radial));
            const __m128 normal = _mm_add_ps(_mm_mul_ps(radial, vinv), vtn);
            const auto k = static_cast<std::size_t>(j);
            float* pk = positions + 3 * k;
            float* nk = normals + 3 * k;
            _mm_storel_pi(reinterpret_cast<__m64*>(pk), position);
            _mm_store_ss(pk + 2, _mm_movehl_ps(position, position));
            _mm_storel_pi(reinterpret_cast<__m64*>(nk), normal);
            _mm_store_ss(nk + 2, _mm_movehl_ps(normal, normal));
            uv[k] = {uTiles * a.z, vCoord};
            if (ord) {
                ord[k] = o;
                flx[k] = fl;
            }
            if (ids) ids[k] = id;
        }
        v += static_cast<std::size_t>(res) + 1;
#else
        for (int j = 0; j <= res; ++j) {
            const glm::vec3& a = cs[j];
            const glm::vec3 radial = a.x * n + a.y * b;
            vertex(p + r * radial, radial * inv + tn, {uTiles * a.z, vCoord});
        }
#endif
    }
    void triangle(std::size_t a, std::size_t b, std::size_t c) {
        std::uint32_t* t = idx + (i - indexBase);
        t[0] = static_cast<std::uint32_t>(a);
        t[1] = static_cast<std::uint32_t>(b);
        t[2] = static_cast<std::uint32_t>(c);
        i += 3;
    }
};

// A thread's reusable block of vertices and indices for one run of chains; its contents are
// appended to the mesh in chain order. Generating into a block that stays in cache and then
// appending to reserved (not resized) arrays writes the big arrays once: resize() would first
// zero-fill them (value-initialized glm vectors), a whole extra pass over ~56 bytes a vertex.
// The block itself is RawVectors: every slot of a run is written before it is appended (the
// chains' layout), so a zero fill of the block (~0.5 MB a tree for the English oak: its
// trunk's run of relief rings) would be written over unread; a block too small is made anew,
// not grown (growing would copy the last run's vertices).
struct Scratch {
    RawVector<glm::vec3> pos, nrm;
    RawVector<glm::vec2> uvs;
    RawVector<std::uint16_t> orders;
    RawVector<float> flexes;
    RawVector<std::uint32_t> nodeIds;
    RawVector<std::uint32_t> idx;
    RawVector<RingFrame> frames; ///< a run's rings' frames (meshChain's first pass)
    ReliefRows relief;           ///< a relief chain's rows (meshChain's second pass)

    Writer writer(std::size_t vBegin, std::size_t vCount, std::size_t iBegin, std::size_t iCount,
                  bool wind, bool ids) {
        room(pos, vCount);
        room(nrm, vCount);
        room(uvs, vCount);
        if (wind) {
            room(orders, vCount);
            room(flexes, vCount);
        }
        if (ids) room(nodeIds, vCount);
        room(idx, iCount);
        return Writer{pos.data(),
                      nrm.data(),
                      uvs.data(),
                      wind ? orders.data() : nullptr,
                      wind ? flexes.data() : nullptr,
                      ids ? nodeIds.data() : nullptr,
                      idx.data(),
                      vBegin,
                      iBegin,
                      vBegin,
                      iBegin};
    }
    void appendTo(Mesh& m, std::size_t vCount, std::size_t iCount, bool wind, bool ids) const {
        const auto vn = static_cast<std::ptrdiff_t>(vCount);
        m.positions.insert(m.positions.end(), pos.begin(), pos.begin() + vn);
        m.normals.insert(m.normals.end(), nrm.begin(), nrm.begin() + vn);
        m.uvs.insert(m.uvs.end(), uvs.begin(), uvs.begin() + vn);
        if (wind) {
            m.branchOrder.insert(m.branchOrder.end(), orders.begin(), orders.begin() + vn);
            m.flexibility.insert(m.flexibility.end(), flexes.begin(), flexes.begin() + vn);
        }
        if (ids) m.node.insert(m.node.end(), nodeIds.begin(), nodeIds.begin() + vn);
        m.indices.insert(m.indices.end(), idx.begin(),
                         idx.begin() + static_cast<std::ptrdiff_t>(iCount));
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

/// How many times the bark texture goes round an axis of base radius \p r0 with textures
/// \p width metres wide (TubeSettings::barkTextureWidth; 0: once).
float barkTiles(float r0, float width) {
    if (width <= 0.0f) return 1.0f;
    return std::max(1.0f, std::round(2.0f * std::numbers::pi_v<float> * r0 / width));
}

/// meshChain's two passes: the rings' frames (into \p frames, m of them), then the rings from
/// them. A run's chains take the first pass each before the second: each ring's normal is
/// transported from the last one's, a chain of a square root and divisions, and with rings
/// written between them the processor could not run ahead to the next rings' or chain's.
enum class ChainPass { Frames, Rings };

void meshChain(Writer& w, ChainPass pass, RingFrame* frames, ReliefRows& rows,
               const skel::Skeleton& s, const std::vector<float>& radius, const std::int32_t* nodes,
               std::size_t m, bool lateral, bool caps, const std::vector<glm::vec3>& cs,
               const std::uint32_t* ids = nullptr, const glm::vec2* lobe = nullptr,
               const float* lobeAmp = nullptr, const float* relief = nullptr, float uTiles = 1.0f) {
    auto id = [&](std::size_t k) {
        return ids != nullptr ? ids[k] : static_cast<std::uint32_t>(nodes[k]);
    };
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
    auto dir = [&](std::size_t k) {
        return safeNormalize(P(k + 1) - P(k), frameHeading, kMinDirectionLength);
    };

    if (pass == ChainPass::Frames) {
        glm::vec3 tPrev(0.0f), n(0.0f), pPrev(0.0f);
        glm::vec3 dPrev = dir(0);
        float vAlong = 0.0f; // the bark texture's v at each ring
        // The rings' frames first, in a loop of their own: each ring's normal is transported from
        // the last one's (a chain of a square root and divisions a ring), and with the rings'
        // vertices between them the processor could not run ahead to the next chain's.
        for (std::size_t k = 0; k < m; ++k) {
            const glm::vec3 p = P(k);
            const glm::vec3 dNext = k + 1 < m ? dir(k) : dPrev;
            const glm::vec3 t = k == 0 ? dNext
                                : k + 1 == m
                                    ? dPrev
                                    : safeNormalize(dPrev + dNext, dNext, kMinDirectionLength);
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
                n = normalizeOrPerpendicular(nL, t);
                const float rAvg = std::max(0.5f * (R(k - 1) + R(k)), 1e-3f);
                vAlong += uTiles * std::sqrt(c1) / (2.0f * std::numbers::pi_v<float> * rAvg);
            }
            const glm::vec3 b = glm::cross(t, n);
            const float r = R(k);
            // Taper slope dr/ds tilts the normals towards the thinner end.
            const std::size_t ka = k > 0 ? k - 1 : k, kb = k + 1 < m ? k + 1 : k;
            const float ds = glm::length(P(kb) - P(ka));
            const float slope = ds > 1e-12f ? (R(kb) - R(ka)) / ds : 0.0f;
            const float inv = 1.0f / std::sqrt(1.0f + slope * slope);
            const glm::vec3 tn = -slope * inv * t;
            frames[k] = {p, t, n, b, tn, r, ds, inv, vAlong};
            tPrev = t;
            pPrev = p;
            dPrev = dNext;
        }
        return;
    }
    const std::size_t ringVerts = static_cast<std::size_t>(res) + 1;
    const std::size_t firstRing = caps && !lateral ? w.v + ringVerts + 1 : w.v;
    std::size_t ringStart = firstRing;
    if (caps && !lateral) w.v = firstRing; // the base cap is written after the first frame
    glm::vec3 n0(0.0f), b0(0.0f), t0(0.0f);
    const float* rhoRows = nullptr; // with relief: ρ of each ring vertex (rows.rho)
    float* dTh = nullptr;           // with relief: a ring's slopes (rows.slopes)
    float* dS = nullptr;
    const float* csX = nullptr; // with relief: cs's x, y and z (rows.csLanes)
    const float* csY = nullptr;
    const float* csZ = nullptr;
    float* ringLanes = nullptr; // with relief: a ring's vertices (rows.lanes)
    for (std::size_t k = 0; k < m; ++k) {
        const RingFrame& f = frames[k];
        const glm::vec3 p = f.p, t = f.t, n = f.n, b = f.b, tn = f.tn;
        const float r = f.r, ds = f.ds, inv = f.inv, v = f.v;
        const std::size_t ka = k > 0 ? k - 1 : k, kb = k + 1 < m ? k + 1 : k;
        // A lateral's base ring sits at its parent's node but belongs to the lateral.
        w.node = id(k == 0 && lateral ? 1 : k);
        w.flex = std::max(1.0f - r * w.invRMax, 0.0f); // a flared root is wider than rMax
        const float amp = lobeAmp != nullptr ? lobeAmp[k] : 0.0f;
        if (relief != nullptr) {
            // ρ(k, j) = R(k) (1 + lobe + relief): the normal of the displaced surface,
            // ρ·radial - ∂ρ/∂θ·around - ρ·∂ρ/∂s·t, from differences over the neighbouring
            // vertices (the seam's neighbours across it).
            // ρ of every ring, once (each vertex reads its ring's, its neighbours' and the
            // neighbouring rings'): R(k) (1 + lobe + relief), the lobe's term a product or, on
            // a round section, none (1 + 0 is 1: the same sum).
            if (k == 0) {
                float* rho = room(rows.rho, m * ringVerts + 4);
                for (std::size_t kk = 0; kk < m; ++kk) {
                    const float rk = R(kk);
                    const float* rel = relief + kk * ringVerts;
                    float* row = rho + kk * ringVerts;
                    if (lobe != nullptr) {
                        const float a = lobeAmp[kk];
                        for (std::size_t j = 0; j < ringVerts; ++j)
                            row[j] = rk * (1.0f + a * lobe[j].x + rel[j]);
                    } else {
                        for (std::size_t j = 0; j < ringVerts; ++j)
                            row[j] = rk * (1.0f + rel[j]);
                    }
                }
                for (std::size_t j = 0; j < 4; ++j) // (the last ring read four at a time)
                    rho[m * ringVerts + j] = 0.0f;
                rhoRows = rho;
            }
            const float* rhoK = rhoRows + k * ringVerts;
            const float* rhoA = rhoRows + ka * ringVerts;
            const float* rhoB = rhoRows + kb * ringVerts;
            const float dTheta = 2.0f * std::numbers::pi_v<float> / static_cast<float>(res);
            // The ring's slopes first, four quotients to a division (barkSlopeRow): ∂ρ/∂θ's
            // difference over 2 dθ (the relief's, where the lobes' own is known exactly) and
            // ∂ρ/∂s's over ds, the same quotients as a vertex at a time.
            if (k == 0) {
                dTh = room(rows.slopes, 2 * (ringVerts + 3));
                dS = dTh + ringVerts + 3;
            }
            barkSlopeRow(lobe != nullptr ? relief + k * ringVerts : rhoK, rhoA, rhoB, res,
                         2.0f * dTheta, ds, dTh, dS);
            // The ring's positions and normals (barkReliefVertices: four vertices to an
            // instruction on SSE2, a relief vertex's normal is a square root and three
            // divisions), then written four vertices at a time (barkReliefInterleave).
            const std::size_t stride = ringVerts + 3;
            if (k == 0) {
                float* x = room(rows.csLanes, 3 * stride);
                float* y = x + stride;
                float* z = y + stride;
                for (std::size_t j = 0; j < ringVerts; ++j) {
                    x[j] = cs[j].x;
                    y[j] = cs[j].y;
                    z[j] = cs[j].z;
                }
                for (std::size_t j = ringVerts; j < stride; ++j)
                    x[j] = y[j] = z[j] = 0.0f;
                csX = x;
                csY = y;
                csZ = z;
                ringLanes = room(rows.lanes, 6 * stride);
            }
            if (lobe != nullptr) { // the lobes' own slope is known exactly
                const float rk = R(k);
                for (std::size_t j = 0; j < ringVerts; ++j)
                    dTh[j] = rk * (amp * lobe[j].y + dTh[j]);
            }
            {
                float* o = ringLanes;
                barkReliefVertices(csX, csY, ringVerts, p, n, b, t, rhoK, dTh, dS,
                                   kMinDirectionLength, o, stride);
                const std::size_t first = w.v - w.base;
                barkReliefInterleave(o, stride, ringVerts, csZ, uTiles, v, w.pos + first,
                                     w.nrm + first, w.uvs + first);
                w.attributes(ringVerts);
            }
        }
        if (relief == nullptr && !(amp > 0.0f))
            w.ring(cs.data(), res, p, r, n, b, inv, tn, uTiles, v);
        for (int j = 0; relief == nullptr && amp > 0.0f && j <= res; ++j) {
            const glm::vec3 a = cs[static_cast<std::size_t>(j)];
            const glm::vec3 radial = a.x * n + a.y * b;
            // r(θ) = r (1 + amp · shape(θ)); the normal of the lobed section leans against
            // dr/dθ along the ring's tangent.
            const glm::vec2 sh = lobe[j];
            const glm::vec3 around = -a.y * n + a.x * b;
            const float rr = r * (1.0f + amp * sh.x);
            const glm::vec3 inPlane =
                safeNormalize(rr * radial - r * amp * sh.y * around, radial, kMinDirectionLength);
            w.vertex(p + rr * radial,
                     safeNormalize(inPlane * inv + tn, radial, kMinDirectionLength),
                     {uTiles * a.z, v});
        }
        if (k > 0) {
            const std::size_t a0 = ringStart - ringVerts;
            int j = 0;
#if defined(__SSE2__)
            // Two quads' six triangles (twelve indices) in three stores: the scalar writes' values
            // (modulo 2^32 as their casts), each lane two more every step.
            {
                const auto a = static_cast<std::uint32_t>(a0),
                           c = static_cast<std::uint32_t>(ringStart);
                auto lanes = [](std::uint32_t x, std::uint32_t y, std::uint32_t z,
                                std::uint32_t u) {
                    return _mm_setr_epi32(static_cast<int>(x), static_cast<int>(y),
                                          static_cast<int>(z), static_cast<int>(u));
                };
                __m128i t0 = lanes(a, a + 1, c + 1, a), t1 = lanes(c + 1, c, a + 1, a + 2),
                        t2 = lanes(c + 2, a + 1, c + 2, c + 1);
                const __m128i two = _mm_set1_epi32(2);
                auto* out = reinterpret_cast<__m128i*>(w.idx + (w.i - w.indexBase));
                for (; j + 1 < res; j += 2, out += 3) {
                    _mm_storeu_si128(out, t0);
                    _mm_storeu_si128(out + 1, t1);
                    _mm_storeu_si128(out + 2, t2);
                    t0 = _mm_add_epi32(t0, two);
                    t1 = _mm_add_epi32(t1, two);
                    t2 = _mm_add_epi32(t2, two);
                }
                w.i += 6 * static_cast<std::size_t>(j);
            }
#endif
            for (; j < res; ++j) {
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
        if (k + 1 == m && caps) cap(w, p, n, b, t, r, cs, false);
    }
    if (caps && !lateral) {
        const std::size_t end = w.v;
        w.v = firstRing - ringVerts - 1;
        w.node = id(0);
        cap(w, P(0), n0, b0, -t0, R(0), cs, true);
        w.v = end;
    }
}

/// A root's axis as its own little chain: the skeleton's nodes plus a ring below the ground and
/// rings over the flare's height, each with the radius the flare gives it and the node it
/// belongs to (the nearer node of its segment).
struct FlaredChain {
    skel::Skeleton sub; ///< positions and orientations of the rings only
    std::vector<float> radius;
    std::vector<std::int32_t> nodes; ///< 0, 1, 2, ... into sub
    std::vector<std::uint32_t> ids;  ///< the skeleton node of each ring
    std::vector<glm::vec3> cs;       ///< cos, sin and u of each ring vertex (its own sides)
    std::vector<glm::vec2> lobe;     ///< buttress shape and its dθ per ring vertex; empty: round
    std::vector<float> lobeAmp;      ///< buttress amplitude per ring
    std::vector<float> relief; ///< bark relief per ring vertex (rings × sides+1); empty: none
};

// How far each buttress lobe stands out, relative: a fixed irregular table, the same on every
// platform (lobe i gets entry i).
constexpr float kLobeWeights[] = {1.0f,  0.7f,  0.9f, 0.6f, 0.85f, 0.75f,
                                  0.95f, 0.65f, 0.8f, 0.7f, 0.9f,  0.6f};

FlaredChain flareChain(const skel::Skeleton& s, const std::vector<float>& radius,
                       const std::int32_t* nodes, std::size_t m, const TubeSettings& settings,
                       const std::vector<glm::vec3>& cs) {
    FlaredChain f;
    const int lobes = settings.buttressDepth > 0.0 ? settings.buttressLobes : 0;
    f.cs = cs;
    if (lobes > 0) {
        // Lobe i centred at 2πi/lobes: weight_i · max(0, cos(lobes · θ))², less its mean (the
        // section keeps about its round area), and its derivative in θ.
        const int sides = std::max(static_cast<int>(cs.size()) - 1, 3 * lobes);
        f.cs.resize(static_cast<std::size_t>(sides) + 1);
        f.lobe.resize(static_cast<std::size_t>(sides) + 1);
        double mean = 0.0;
        for (int i = 0; i < lobes; ++i)
            mean += kLobeWeights[i];
        mean *= 0.25 / lobes;
        for (int j = 0; j <= sides; ++j) {
            const double theta = 2.0 * std::numbers::pi * (j % sides) / sides;
            const double t = lobes * theta;
            const auto lobe =
                static_cast<std::size_t>(std::lround(t / (2.0 * std::numbers::pi)) % lobes);
            const double c = std::cos(t), sn = std::sin(t), wt = kLobeWeights[lobe];
            const double shape = c > 0.0 ? wt * c * c : 0.0;
            const double slope = c > 0.0 ? -2.0 * wt * c * sn * lobes : 0.0;
            f.cs[static_cast<std::size_t>(j)] = {static_cast<float>(std::cos(theta)),
                                                 static_cast<float>(std::sin(theta)),
                                                 static_cast<float>(j) / static_cast<float>(sides)};
            f.lobe[static_cast<std::size_t>(j)] = {static_cast<float>(shape - mean),
                                                   static_cast<float>(slope)};
        }
    }
    const auto node0 = static_cast<std::size_t>(nodes[0]);
    const glm::quat q0 = s.orientation[node0];
    const double flare = settings.rootFlare;
    const double height =
        std::min(settings.flareHeight, kMaxFlareRadii * static_cast<double>(radius[node0]));
    auto widen = [&](double along) {
        if (!(height > 0.0) || along >= height) return 1.0;
        const double u = 1.0 - std::max(along, 0.0) / height;
        return 1.0 + (flare - 1.0) * u * u;
    };
    auto buttress = [&](double along) {
        if (lobes == 0 || !(height > 0.0) || along >= height) return 0.0;
        const double u = 1.0 - std::max(along, 0.0) / height;
        return settings.buttressDepth * u * u * u;
    };
    auto ring = [&](const glm::vec3& p, double r, std::uint32_t id, double along) {
        f.lobeAmp.push_back(static_cast<float>(buttress(along)));
        f.sub.position.push_back(p);
        f.sub.orientation.push_back(q0);
        f.radius.push_back(static_cast<float>(r));
        f.nodes.push_back(static_cast<std::int32_t>(f.nodes.size()));
        f.ids.push_back(id);
    };
    auto P = [&](std::size_t k) { return s.position[static_cast<std::size_t>(nodes[k])]; };
    auto R = [&](std::size_t k) {
        return static_cast<double>(radius[static_cast<std::size_t>(nodes[k])]);
    };
    const glm::vec3 down = -safeNormalize(P(1) - P(0), skel::headingOf(q0), kMinDirectionLength);
    if (settings.groundDepth > 0.0)
        ring(P(0) + static_cast<float>(settings.groundDepth) * down, R(0) * widen(0.0),
             static_cast<std::uint32_t>(nodes[0]), 0.0);
    // Rings of the flare where it changes fastest, near the ground.
    constexpr double kFlareRings[] = {0.06, 0.14, 0.25, 0.4, 0.6, 0.8};
    double along = 0.0;
    ring(P(0), R(0) * widen(0.0), static_cast<std::uint32_t>(nodes[0]), 0.0);
    std::size_t next = 0;
    for (std::size_t k = 0; k + 1 < m; ++k) {
        const double len = glm::length(P(k + 1) - P(k));
        for (; next < std::size(kFlareRings) && kFlareRings[next] * height < along + len; ++next) {
            const double at = kFlareRings[next] * height;
            if (at <= along) continue;
            const double t = (at - along) / len;
            ring(P(k) + static_cast<float>(t) * (P(k + 1) - P(k)),
                 (R(k) + t * (R(k + 1) - R(k))) * widen(at),
                 static_cast<std::uint32_t>(nodes[t < 0.5 ? k : k + 1]), at);
        }
        along += len;
        ring(P(k + 1), R(k + 1) * widen(along), static_cast<std::uint32_t>(nodes[k + 1]), along);
    }
    return f;
}

/// Any axis as its own little chain (as flareChain makes a root's), so that bark relief can add
/// rings to it: a lateral's base ring keeps its radius (its own, never wider than its parent's)
/// and every ring the orientation of the axis' own first node (what meshChain's frame reads).
FlaredChain plainChain(const skel::Skeleton& s, const std::vector<float>& radius,
                       const std::int32_t* nodes, std::size_t m, bool lateral,
                       const std::vector<glm::vec3>& cs) {
    FlaredChain f;
    f.cs = cs;
    const glm::quat q = s.orientation[static_cast<std::size_t>(nodes[lateral ? 1 : 0])];
    for (std::size_t k = 0; k < m; ++k) {
        const auto node = static_cast<std::size_t>(nodes[k]);
        float r = radius[node];
        if (k == 0 && lateral) r = std::min(radius[static_cast<std::size_t>(nodes[1])], r);
        f.sub.position.push_back(s.position[node]);
        f.sub.orientation.push_back(q);
        f.radius.push_back(r);
        f.nodes.push_back(static_cast<std::int32_t>(k));
        f.ids.push_back(static_cast<std::uint32_t>(nodes[k == 0 && lateral ? 1 : k]));
        f.lobeAmp.push_back(0.0f);
    }
    return f;
}

/// Bark relief on a chain made by flareChain or plainChain: rings added where the relief shows
/// (every barkRingSpacing columns along the axis) and the relief of each ring vertex.
/// \p columns around, each \p width metres wide at the axis' base; \p parentRadius: a lateral's
/// relief fades in over this distance from its base (0: a root's axis, no fade).
void addBarkRelief(FlaredChain& f, const TubeSettings& settings, int columns, float width,
                   float parentRadius, std::uint32_t seed) {
    const auto depth = static_cast<float>(settings.barkRelief);
    const auto rMin = static_cast<float>(settings.barkReliefRadius);
    auto amplitude = [&](float r, float along) {
        float a = depth * (rMin > 0.0f ? std::clamp((r - rMin) / (0.5f * rMin), 0.0f, 1.0f) : 1.0f);
        if (parentRadius > 0.0f) a *= std::clamp(along / parentRadius, 0.0f, 1.0f);
        return a;
    };
    const float spacing = static_cast<float>(barkRingSpacing(settings.barkPattern)) * width;
    FlaredChain g;
    g.cs = std::move(f.cs);
    g.lobe = std::move(f.lobe);
    std::vector<float> along, amp;
    float at = 0.0f;
    auto push = [&](const glm::vec3& p, const glm::quat& q, float r, std::uint32_t id,
                    float lobeAmp, float s) {
        g.sub.position.push_back(p);
        g.sub.orientation.push_back(q);
        g.radius.push_back(r);
        g.nodes.push_back(static_cast<std::int32_t>(g.nodes.size()));
        g.ids.push_back(id);
        g.lobeAmp.push_back(lobeAmp);
        along.push_back(s);
        amp.push_back(amplitude(r, s));
    };
    const std::size_t m = f.nodes.size();
    push(f.sub.position[0], f.sub.orientation[0], f.radius[0], f.ids[0], f.lobeAmp[0], 0.0f);
    for (std::size_t k = 0; k + 1 < m; ++k) {
        const glm::vec3 a = f.sub.position[k], b = f.sub.position[k + 1];
        const float len = glm::length(b - a);
        const float ra = f.radius[k], rb = f.radius[k + 1];
        const bool shows = amplitude(ra, at) > 0.0f || amplitude(rb, at + len) > 0.0f;
        const int pieces =
            shows && spacing > 0.0f ? std::max(1, static_cast<int>(std::ceil(len / spacing))) : 1;
        for (int i = 1; i < pieces; ++i) {
            const float t = static_cast<float>(i) / static_cast<float>(pieces);
            push(a + t * (b - a), f.sub.orientation[k], ra + t * (rb - ra),
                 f.ids[t < 0.5f ? k : k + 1], f.lobeAmp[k] + t * (f.lobeAmp[k + 1] - f.lobeAmp[k]),
                 at + t * len);
        }
        at += len;
        push(b, f.sub.orientation[k + 1], rb, f.ids[k + 1], f.lobeAmp[k + 1], at);
    }
    const int sides = static_cast<int>(g.cs.size()) - 1;
    const std::size_t ringVerts = static_cast<std::size_t>(sides) + 1;
    g.relief.assign(g.nodes.size() * ringVerts, 0.0f);
    BarkRing ring(settings.barkPattern, columns, sides); // what every ring of the axis shares
    for (std::size_t k = 0; k < g.nodes.size(); ++k) {
        if (!(amp[k] > 0.0f)) continue;
        float* row = g.relief.data() + k * ringVerts;
        barkReliefRow(ring, along[k] / width, seed, amp[k], row);
        row[sides] = row[0];
    }
    f = std::move(g);
}

/// A flat strip along the chain, two vertices a node, facing \p camera.
void meshRibbon(Writer& w, const skel::Skeleton& s, const std::vector<float>& radius,
                const std::int32_t* nodes, std::size_t m, bool lateral, const glm::vec3& camera,
                float widthScale) {
    auto P = [&](std::size_t k) { return s.position[static_cast<std::size_t>(nodes[k])]; };
    auto R = [&](std::size_t k) {
        if (k == 0 && lateral)
            return std::min(radius[static_cast<std::size_t>(nodes[1])],
                            radius[static_cast<std::size_t>(nodes[0])]);
        return radius[static_cast<std::size_t>(nodes[k])];
    };
    const glm::vec3 frameHeading =
        skel::headingOf(s.orientation[static_cast<std::size_t>(nodes[lateral ? 1 : 0])]);
    auto dir = [&](std::size_t k) {
        return safeNormalize(P(k + 1) - P(k), frameHeading, kMinDirectionLength);
    };
    glm::vec3 dPrev = dir(0);
    float v = 0.0f;
    for (std::size_t k = 0; k < m; ++k) {
        w.node = static_cast<std::uint32_t>(nodes[k == 0 && lateral ? 1 : k]);
        const glm::vec3 p = P(k);
        const glm::vec3 dNext = k + 1 < m ? dir(k) : dPrev;
        const glm::vec3 t = k == 0       ? dNext
                            : k + 1 == m ? dPrev
                                         : safeNormalize(dPrev + dNext, dNext, kMinDirectionLength);
        if (k > 0) {
            const float rAvg = std::max(0.5f * (R(k - 1) + R(k)), 1e-3f);
            v += glm::length(p - P(k - 1)) / (2.0f * std::numbers::pi_v<float> * rAvg);
        }
        glm::vec3 view = camera - p;
        view -= glm::dot(view, t) * t;
        const glm::vec3 normal = normalizeOrPerpendicular(view, t);
        const glm::vec3 side = glm::cross(t, normal);
        const float half = R(k) * widthScale;
        w.flex = 1.0f - R(k) * w.invRMax;
        w.vertex(p - half * side, normal, {0.0f, v});
        w.vertex(p + half * side, normal, {1.0f, v});
        if (k > 0) {
            const std::size_t a = w.v - 4;
            w.triangle(a, a + 1, a + 3);
            w.triangle(a, a + 3, a + 2);
        }
        dPrev = dNext;
    }
}

} // namespace

std::vector<float> tubeRadii(const skel::Skeleton& s, const TubeSettings& settings) {
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

void appendTubes(Mesh& out, const skel::Skeleton& s, const TubeSettings& settings,
                 Progress& progress) {
    requireRange("resolution", settings.resolution, 3, 64);
    requireRange("radius_scale", settings.radiusScale, 0.0, 1e3);
    if (settings.thickness == ThicknessMode::Branching) {
        requireRange("initial_thickness", settings.initialThickness, 0.0, 1e3);
        requireRange("thickness_multiplier", settings.thicknessMultiplier, 1e-6, 1.0);
    }
    s.validate();
    const int res = settings.resolution;
    const std::vector<float> radius = tubeRadii(s, settings);
    requireRange("simplify tolerance", settings.simplifyTolerance, 0.0, 1e6);
    const Chains chains =
        buildChains(s, radius, settings.minBranchRadius, settings.simplifyTolerance);
    const std::size_t count = chains.count();
    requireRange("root_flare", settings.rootFlare, 1.0, 4.0);
    requireRange("flare_height", settings.flareHeight, 0.0, 100.0);
    requireRange("ground_depth", settings.groundDepth, 0.0, 10.0);
    requireRange("buttress_lobes", settings.buttressLobes, 0, 12);
    requireRange("buttress_depth", settings.buttressDepth, 0.0, 1.0);
    requireRange("bark_relief", settings.barkRelief, 0.0, 0.5);
    requireRange("bark_relief_scale", settings.barkReliefScale, 0.01, 2.0);
    requireRange("bark_relief_radius", settings.barkReliefRadius, 0.0, 100.0);
    requireRange("bark_relief_sides", settings.barkReliefSides, 3, 128);
    requireRange("bark_texture_width", settings.barkTextureWidth, 0.0, 10.0);

    std::vector<std::size_t> vOff(count + 1), iOff(count + 1);
    vOff[0] = out.positions.size();
    iOff[0] = out.indices.size();
    requireRange("ribbon radius", settings.ribbonBelowRadius, 0.0, 1e6);
    std::vector<std::uint8_t> ribbon(count, 0);
    if (settings.ribbonBelowRadius > 0.0)
        for (std::size_t c = 0; c < count; ++c) {
            const std::int32_t own = chains.nodes[chains.begin[c] + (chains.lateral[c] ? 1 : 0)];
            ribbon[c] = radius[static_cast<std::size_t>(own)] < settings.ribbonBelowRadius;
            if (ribbon[c]) out.cameraRibbons = true;
        }
    requireRange("twig radius", settings.twigBelowRadius, 0.0, 1e6);
    requireRange("twig resolution", settings.twigResolution, 3, 64);
    std::vector<std::uint8_t> twig(count, 0);
    if (settings.twigBelowRadius > 0.0)
        for (std::size_t c = 0; c < count; ++c) {
            const std::int32_t own = chains.nodes[chains.begin[c] + (chains.lateral[c] ? 1 : 0)];
            twig[c] = radius[static_cast<std::size_t>(own)] < settings.twigBelowRadius;
        }
    // cos, sin and u of each ring vertex; the seam repeats the first with u = 1.
    auto ringTable = [](int sides) {
        std::vector<glm::vec3> t(static_cast<std::size_t>(sides) + 1);
        for (int j = 0; j < sides; ++j) {
            const double a = 2.0 * std::numbers::pi * j / sides;
            t[static_cast<std::size_t>(j)] = {static_cast<float>(std::cos(a)),
                                              static_cast<float>(std::sin(a)),
                                              static_cast<float>(j) / static_cast<float>(sides)};
        }
        t[static_cast<std::size_t>(sides)] = {t[0].x, t[0].y, 1.0f};
        return t;
    };
    const std::vector<glm::vec3> cs = ringTable(res);
    const std::vector<glm::vec3> csTwig = ringTable(settings.twigResolution);
    // Roots' axes with their flare (a handful of chains: one a tree).
    const bool flaring =
        ((settings.rootFlare > 1.0 || settings.buttressLobes > 0) && settings.flareHeight > 0.0) ||
        settings.groundDepth > 0.0;
    std::vector<FlaredChain> flared;
    std::vector<std::int32_t> flaredOf(count, -1);
    for (std::size_t c = 0; c < count; ++c) {
        const std::int32_t* nodes = chains.nodes.data() + chains.begin[c];
        const std::size_t m = chains.begin[c + 1] - chains.begin[c];
        const bool lateral = chains.lateral[c] != 0;
        const bool root = !lateral && s.parent[static_cast<std::size_t>(nodes[0])] < 0;
        // Bark relief on thick axes: columns about barkReliefScale wide at the axis' base.
        const std::int32_t own = nodes[lateral ? 1 : 0];
        const float r0 = radius[static_cast<std::size_t>(own)];
        const bool relief =
            settings.barkRelief > 0.0 && !ribbon[c] && !twig[c] && r0 >= settings.barkReliefRadius;
        if (!(flaring && root && !ribbon[c]) && !relief) continue;
        int columns = 0;
        std::vector<glm::vec3> reliefCs;
        if (relief) {
            const double around = 2.0 * std::numbers::pi * r0;
            columns = std::max(3, static_cast<int>(std::lround(around / settings.barkReliefScale)));
            columns =
                std::min(columns, std::max(settings.barkReliefSides / kBarkSidesPerColumn, 1));
            reliefCs = ringTable(std::max(columns * kBarkSidesPerColumn, res));
        }
        const std::vector<glm::vec3>& ring = relief ? reliefCs : twig[c] ? csTwig : cs;
        flaredOf[c] = static_cast<std::int32_t>(flared.size());
        flared.push_back(flaring && root ? flareChain(s, radius, nodes, m, settings, ring)
                                         : plainChain(s, radius, nodes, m, lateral, ring));
        if (relief)
            addBarkRelief(flared.back(), settings, columns,
                          static_cast<float>(2.0 * std::numbers::pi * r0 / columns),
                          lateral ? radius[static_cast<std::size_t>(nodes[0])] : 0.0f,
                          static_cast<std::uint32_t>(own));
    }
    for (std::size_t c = 0; c < count; ++c) {
        std::size_t rings = chains.begin[c + 1] - chains.begin[c];
        int sides = twig[c] ? settings.twigResolution : res;
        if (flaredOf[c] >= 0) {
            const FlaredChain& f = flared[static_cast<std::size_t>(flaredOf[c])];
            rings = f.nodes.size();
            sides = static_cast<int>(f.cs.size()) - 1;
        }
        const Layout l =
            chainLayout(rings, chains.lateral[c], settings.caps, sides, ribbon[c] != 0);
        vOff[c + 1] = vOff[c] + l.vertices;
        iOff[c + 1] = iOff[c] + l.indices;
    }
    if (const std::size_t triangles = (iOff[count] - iOff[0]) / 3;
        triangles > settings.maxTriangles)
        throw LimitExceeded("tube mesh would have " + std::to_string(triangles) +
                            " triangles, more than the limit of " +
                            std::to_string(settings.maxTriangles) +
                            "; lower the tube_mesh resolution or grow a smaller tree (fewer "
                            "generations, cycles or attractors)");
    if (vOff[count] > std::numeric_limits<std::uint32_t>::max())
        throw LimitExceeded("tube mesh would have " + std::to_string(vOff[count]) +
                            " vertices; the limit of 32-bit indices is 4294967295");

    // Attributes the mesh did not have yet are filled for the existing vertices too.
    const std::size_t existing = out.positions.size();
    out.normals.resize(existing, glm::vec3(0, 1, 0));
    out.uvs.resize(existing, glm::vec2(0.0f));
    const bool wind = settings.windAttributes || !out.branchOrder.empty();
    if (wind) {
        out.branchOrder.resize(existing, 0);
        out.flexibility.resize(existing, 1.0f);
    }
    const bool ids = settings.nodeIds || !out.node.empty();
    if (ids) out.node.resize(existing, Mesh::kNoNode);
    auto reserveBig = [](auto& v, std::size_t n) {
        const bool fresh = v.capacity() < n;
        v.reserve(n);
        if (fresh) adviseHugePages(v);
    };
    const std::size_t vRoom = vOff[count] + settings.reserveVertices;
    reserveBig(out.positions, vRoom);
    reserveBig(out.normals, vRoom);
    reserveBig(out.uvs, vRoom);
    if (wind) {
        reserveBig(out.branchOrder, vRoom);
        reserveBig(out.flexibility, vRoom);
    }
    if (ids) reserveBig(out.node, vRoom);
    reserveBig(out.indices, iOff[count] + settings.reserveIndices);
    if (iOff[count] > iOff[0]) {
        if (out.submeshes.empty() && iOff[0] > 0)
            out.submeshes.push_back({"bark", 0, static_cast<std::uint32_t>(iOff[0])});
        out.submeshes.push_back({"bark", static_cast<std::uint32_t>(iOff[0]),
                                 static_cast<std::uint32_t>(iOff[count] - iOff[0])});
    }

    float rMax = 0.0f;
    for (float r : radius)
        rMax = std::max(rMax, r);
    const float invRMax = rMax > 0.0f ? 1.0f / rMax : 0.0f;

    // Runs of consecutive chains of about kRunVertices vertices are meshed in parallel, each
    // into its thread's scratch block, and appended in chain order (omp ordered): the result
    // is the same on any thread count. Cancellation is checked between groups of runs.
    constexpr std::size_t kRunVertices = 4096;
    std::vector<std::size_t> runs{0};
    for (std::size_t c = 0; c < count; ++c)
        if (vOff[c + 1] - vOff[runs.back()] >= kRunVertices || c + 1 == count)
            runs.push_back(c + 1);
    const std::size_t runCount = runs.size() - 1;
    const auto textureWidth = static_cast<float>(settings.barkTextureWidth);
    // One tree's bark (the English oak: 57k vertices, about a millisecond) is meshed on one
    // thread: a parallel region of that size saves a fraction of a millisecond and, under
    // libgomp's default waiting (Python, the editor, Blender), leaves the other threads
    // spinning for milliseconds after it (the oak took 77 ms of CPU on two threads against
    // 39 ms with this region serial). Forests mesh many trees in parallel instead.
    constexpr std::size_t kParallelVertices = 256 * 1024;
    const bool parallel = vOff[count] >= kParallelVertices;
    constexpr std::size_t kRunsPerCheck = 256;
    for (std::size_t first = 0; first < runCount; first += kRunsPerCheck) {
        progress.checkCancelled();
        progress.report(static_cast<double>(first) / static_cast<double>(runCount), "mesh");
        const auto last = static_cast<std::int64_t>(std::min(runCount, first + kRunsPerCheck));
#pragma omp parallel if (parallel)
        {
            Scratch scratch;
#pragma omp for ordered schedule(dynamic, 1)
            for (std::int64_t ri = static_cast<std::int64_t>(first); ri < last; ++ri) {
                const std::size_t c0 = runs[static_cast<std::size_t>(ri)];
                const std::size_t c1 = runs[static_cast<std::size_t>(ri) + 1];
                const std::size_t nv = vOff[c1] - vOff[c0], ni = iOff[c1] - iOff[c0];
                Writer w = scratch.writer(vOff[c0], nv, iOff[c0], ni, wind, ids);
                w.invRMax = invRMax;
                std::size_t rings = 0;
                for (std::size_t c = c0; c < c1; ++c)
                    if (flaredOf[c] >= 0)
                        rings += flared[static_cast<std::size_t>(flaredOf[c])].nodes.size();
                    else if (!ribbon[c])
                        rings += chains.begin[c + 1] - chains.begin[c];
                room(scratch.frames, rings);
                // Every chain's frames first, then the rings (ChainPass).
                for (const ChainPass pass : {ChainPass::Frames, ChainPass::Rings}) {
                    RingFrame* frames = scratch.frames.data();
                    for (std::size_t c = c0; c < c1; ++c) {
                        const std::int32_t* nodes = chains.nodes.data() + chains.begin[c];
                        const std::size_t m = chains.begin[c + 1] - chains.begin[c];
                        const bool lateral = chains.lateral[c] != 0;
                        const std::int32_t own = nodes[lateral ? 1 : 0];
                        w.order = s.order[static_cast<std::size_t>(own)];
                        const float tiles =
                            barkTiles(radius[static_cast<std::size_t>(own)], textureWidth);
                        if (flaredOf[c] >= 0) {
                            const FlaredChain& f = flared[static_cast<std::size_t>(flaredOf[c])];
                            meshChain(w, pass, frames, scratch.relief, f.sub, f.radius,
                                      f.nodes.data(), f.nodes.size(), lateral, settings.caps, f.cs,
                                      f.ids.data(), f.lobe.empty() ? nullptr : f.lobe.data(),
                                      f.lobeAmp.data(),
                                      f.relief.empty() ? nullptr : f.relief.data(), tiles);
                            frames += f.nodes.size();
                        } else if (ribbon[c]) {
                            if (pass == ChainPass::Rings)
                                meshRibbon(w, s, radius, nodes, m, lateral, settings.ribbonCamera,
                                           static_cast<float>(settings.ribbonWidthScale));
                        } else {
                            meshChain(w, pass, frames, scratch.relief, s, radius, nodes, m, lateral,
                                      settings.caps, twig[c] ? csTwig : cs, nullptr, nullptr,
                                      nullptr, nullptr, tiles);
                            frames += m;
                        }
                    }
                }
#pragma omp ordered
                scratch.appendTo(out, nv, ni, wind, ids);
            }
        }
    }
    // Bark is not tinted: white where the mesh carries colours (leaf cards made before).
    if (settings.barkColorTop > settings.barkColorBottom && !s.empty()) {
        // The bark's colour by height: the low colour blending into the high one.
        out.colors.reserve(vRoom);
        out.colors.resize(existing, glm::u8vec4(255));
        const auto ground = static_cast<double>(s.position[0].y);
        const double span = settings.barkColorTop - settings.barkColorBottom;
        auto byte = [](float c) {
            return static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f));
        };
        for (std::size_t k = existing; k < out.positions.size(); ++k) {
            const double u = std::clamp(
                (out.positions[k].y - ground - settings.barkColorBottom) / span, 0.0, 1.0);
            const auto t = static_cast<float>(u * u * (3.0 - 2.0 * u));
            const glm::vec3 c =
                settings.barkColorLow + t * (settings.barkColorHigh - settings.barkColorLow);
            out.colors.push_back({byte(c.x), byte(c.y), byte(c.z), 255});
        }
    }
    if (!out.colors.empty()) out.colors.resize(out.positions.size(), glm::u8vec4(255));
    progress.report(1.0, "mesh");
}

Mesh buildTubeMesh(const skel::Skeleton& skeleton, const TubeSettings& settings,
                   Progress& progress) {
    Mesh mesh;
    appendTubes(mesh, skeleton, settings, progress);
    return mesh;
}

} // namespace sylva::mesh
