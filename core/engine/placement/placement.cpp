#include "engine/placement/placement.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

namespace sylva::placement {

glm::mat4 Instance::transform() const {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
    m = glm::rotate(m, rotation, glm::vec3(0, 1, 0));
    return glm::scale(m, glm::vec3(scale * growth));
}

float Instance::radius(const std::vector<SpeciesSpec>& species) const {
    return species.at(this->species).crownRadius * scale * growth;
}

bool insidePolygon(const std::vector<glm::vec2>& polygon, const glm::vec2& p) {
    bool inside = false;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
        const glm::vec2& a = polygon[i];
        const glm::vec2& b = polygon[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

namespace {

constexpr std::size_t kMaxTrees = 50'000'000;

bool finite2(const glm::vec2& v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

void domainBounds(const Domain& d, glm::vec2& lo, glm::vec2& hi) {
    if (d.shape == DomainShape::Rectangle) {
        lo = d.min;
        hi = d.max;
        return;
    }
    lo = glm::vec2(std::numeric_limits<float>::max());
    hi = -lo;
    for (const glm::vec2& p : d.polygon) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
}

double polygonArea(const std::vector<glm::vec2>& poly) {
    double a = 0.0;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        a +=
            static_cast<double>(poly[j].x) * poly[i].y - static_cast<double>(poly[i].x) * poly[j].y;
    return std::abs(a) * 0.5;
}

/// The trees placed so far and the blocking test, with or without the grid.
class Occupancy {
public:
    Occupancy(PlacementMethod method, glm::vec2 lo, glm::vec2 hi, float maxRadius,
              std::size_t expected)
        : mGrid(method == PlacementMethod::Grid && maxRadius > 0.0f), mLo(lo) {
        if (!mGrid) return;
        const glm::vec2 size = glm::max(hi - lo, glm::vec2(1e-3f));
        // A cell at least one radius wide keeps every blocking tree within the 3x3 neighbours;
        // a coarser grid when the radius is tiny keeps the cell array near the tree count.
        const double limit = std::max<double>(4.0 * static_cast<double>(expected), 1024.0);
        mCell = std::max(static_cast<double>(maxRadius),
                         std::sqrt(static_cast<double>(size.x) * size.y / limit));
        mNx = static_cast<int>(std::ceil(size.x / mCell)) + 1;
        mNz = static_cast<int>(std::ceil(size.y / mCell)) + 1;
        mHead.assign(static_cast<std::size_t>(mNx) * static_cast<std::size_t>(mNz), -1);
    }

    void add(const glm::vec2& p, float radius) {
        const auto index = static_cast<std::int32_t>(mPos.size());
        mPos.push_back(p);
        mR2.push_back(radius * radius);
        if (!mGrid) return;
        const std::size_t c = cellIndex(cellX(p.x), cellZ(p.y));
        mNext.push_back(mHead[c]);
        mHead[c] = index;
    }

    /// Whether a tree of radius \p r at \p q and a stored one stand inside each other's
    /// cylinders (either way).
    bool collides(const glm::vec2& q, float r) const {
        const float r2 = r * r;
        auto hit = [&](std::size_t j) { return dist2(q, mPos[j]) < std::max(mR2[j], r2); };
        if (!mGrid) {
            for (std::size_t j = 0; j < mPos.size(); ++j)
                if (hit(j)) return true;
            return false;
        }
        const int cx = cellX(q.x), cz = cellZ(q.y);
        for (int z = std::max(cz - 1, 0); z <= std::min(cz + 1, mNz - 1); ++z)
            for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, mNx - 1); ++x)
                for (std::int32_t j = mHead[cellIndex(x, z)]; j >= 0;
                     j = mNext[static_cast<std::size_t>(j)])
                    if (hit(static_cast<std::size_t>(j))) return true;
        return false;
    }

    bool blocked(const glm::vec2& q) const {
        if (!mGrid) {
            for (std::size_t j = 0; j < mPos.size(); ++j)
                if (dist2(q, mPos[j]) < mR2[j]) return true;
            return false;
        }
        const int cx = cellX(q.x), cz = cellZ(q.y);
        for (int z = std::max(cz - 1, 0); z <= std::min(cz + 1, mNz - 1); ++z)
            for (int x = std::max(cx - 1, 0); x <= std::min(cx + 1, mNx - 1); ++x)
                for (std::int32_t j = mHead[cellIndex(x, z)]; j >= 0;
                     j = mNext[static_cast<std::size_t>(j)])
                    if (dist2(q, mPos[static_cast<std::size_t>(j)]) <
                        mR2[static_cast<std::size_t>(j)])
                        return true;
        return false;
    }

private:
    static float dist2(const glm::vec2& a, const glm::vec2& b) {
        const glm::vec2 d = a - b;
        return d.x * d.x + d.y * d.y;
    }
    int cellX(float x) const {
        return std::clamp(static_cast<int>(std::floor((x - mLo.x) / mCell)), 0, mNx - 1);
    }
    int cellZ(float z) const {
        return std::clamp(static_cast<int>(std::floor((z - mLo.y) / mCell)), 0, mNz - 1);
    }
    std::size_t cellIndex(int x, int z) const {
        return static_cast<std::size_t>(z) * static_cast<std::size_t>(mNx) +
               static_cast<std::size_t>(x);
    }

    bool mGrid;
    glm::vec2 mLo;
    double mCell = 1.0;
    int mNx = 1, mNz = 1;
    std::vector<std::int32_t> mHead, mNext;
    std::vector<glm::vec2> mPos;
    std::vector<float> mR2;
};

} // namespace

PlacementResult placeForest(const std::vector<SpeciesSpec>& species,
                            const std::vector<Domain>& domains,
                            const std::vector<Instance>& handPlaced, const PlacementParams& params,
                            PlacementMethod method) {
    requireRange("max_tries", params.maxTries, 1, 1e6);
    requireRange("scale_variation", params.scaleVariation, 0.0, 0.9);
    requireRange("growth_spread", params.growthSpread, 0.0, 1e6);
    std::map<std::string, std::uint32_t> speciesIndex;
    for (std::size_t i = 0; i < species.size(); ++i) {
        requireRange(("trunk radius of '" + species[i].name + "'").c_str(), species[i].trunkRadius,
                     0.0, 1e3);
        requireRange(("crown radius of '" + species[i].name + "'").c_str(), species[i].crownRadius,
                     0.0, 1e4);
        speciesIndex.emplace(species[i].name, static_cast<std::uint32_t>(i));
    }

    // Validate everything before placing anything.
    std::size_t total = handPlaced.size();
    std::vector<std::vector<std::uint32_t>> slotsPerDomain(domains.size());
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (std::size_t d = 0; d < domains.size(); ++d) {
        const Domain& dom = domains[d];
        const std::string where = "domain " + std::to_string(d + 1);
        if (dom.shape == DomainShape::Rectangle) {
            if (!finite2(dom.min) || !finite2(dom.max) || !(dom.min.x < dom.max.x) ||
                !(dom.min.y < dom.max.y))
                throw InvalidInput(where + ": a rectangle needs min < max in x and z");
        } else {
            if (dom.polygon.size() < 3)
                throw InvalidInput(where + ": a polygon needs at least 3 points");
            for (const glm::vec2& p : dom.polygon)
                if (!finite2(p)) throw InvalidInput(where + ": polygon point is not a number");
            if (polygonArea(dom.polygon) <= 1e-9)
                throw InvalidInput(where + ": the polygon has no area");
        }
        for (const auto& [name, count] : dom.counts) {
            const auto it = speciesIndex.find(name);
            if (it == speciesIndex.end())
                throw InvalidInput(where + ": unknown species '" + name + "' in counts");
            if (count > kMaxTrees || total + count > kMaxTrees)
                throw LimitExceeded("a forest is limited to " + std::to_string(kMaxTrees) +
                                    " trees; lower the domains' counts or split the scene into "
                                    "several projects");
            total += count;
            slotsPerDomain[d].insert(slotsPerDomain[d].end(), count, it->second);
        }
        glm::vec2 dlo, dhi;
        domainBounds(dom, dlo, dhi);
        lo = glm::min(lo, dlo);
        hi = glm::max(hi, dhi);
    }
    std::vector<std::uint64_t> domainIds(domains.size());
    {
        std::map<std::uint64_t, std::size_t> seen;
        for (std::size_t d = 0; d < domains.size(); ++d) {
            domainIds[d] = domains[d].id ? domains[d].id : d + 1;
            if (domainIds[d] > kMaxDomainId)
                throw InvalidInput("domain " + std::to_string(d + 1) + ": id " +
                                   std::to_string(domainIds[d]) + " is not in [1, " +
                                   std::to_string(kMaxDomainId) + "]");
            if (!seen.emplace(domainIds[d], d).second)
                throw InvalidInput("domains " + std::to_string(seen[domainIds[d]] + 1) + " and " +
                                   std::to_string(d + 1) + " have the same id " +
                                   std::to_string(domainIds[d]));
        }
    }
    std::vector<std::uint64_t> handIds(handPlaced.size());
    {
        std::map<std::uint64_t, std::size_t> seen;
        for (std::size_t i = 0; i < handPlaced.size(); ++i) {
            handIds[i] = handPlaced[i].id ? handPlaced[i].id : i + 1;
            if (handIds[i] >= kDomainIdStride)
                throw InvalidInput("hand-placed instance " + std::to_string(i + 1) + ": id " +
                                   std::to_string(handIds[i]) + " is not in [1, " +
                                   std::to_string(kDomainIdStride - 1) + "]");
            if (!seen.emplace(handIds[i], i).second)
                throw InvalidInput("hand-placed instances " + std::to_string(seen[handIds[i]] + 1) +
                                   " and " + std::to_string(i + 1) + " have the same id " +
                                   std::to_string(handIds[i]));
        }
    }
    for (const Instance& inst : handPlaced) {
        if (inst.species >= species.size())
            throw InvalidInput("hand-placed instance " + std::to_string(inst.id) +
                               ": unknown species index " + std::to_string(inst.species));
        lo = glm::min(lo, glm::vec2(inst.position.x, inst.position.z));
        hi = glm::max(hi, glm::vec2(inst.position.x, inst.position.z));
    }

    float maxRadius = 0.0f;
    for (const SpeciesSpec& s : species)
        maxRadius = std::max(maxRadius, s.crownRadius * (1.0f + params.scaleVariation));
    for (const Instance& inst : handPlaced)
        maxRadius = std::max(maxRadius, inst.radius(species));

    PlacementResult result;
    result.instances.reserve(total);
    if (lo.x > hi.x) lo = hi = glm::vec2(0.0f);
    // What stands already: hand-placed trees, then each domain's survivors in turn.
    Occupancy kept(method, lo, hi, maxRadius, total);
    for (std::size_t i = 0; i < handPlaced.size(); ++i) {
        Instance copy = handPlaced[i];
        copy.id = handIds[i];
        copy.handPlaced = true;
        kept.add(glm::vec2(copy.position.x, copy.position.z), copy.radius(species));
        result.instances.push_back(copy);
    }

    for (std::size_t d = 0; d < domains.size(); ++d) {
        const Domain& dom = domains[d];
        std::vector<std::uint32_t>& slots = slotsPerDomain[d];
        Rng rng(mixSeed(mixSeed(params.seed, salt::kDomainSlots), domainIds[d]));
        // Interleave the species so that no species is squeezed into what the others left.
        for (std::size_t i = slots.size(); i > 1; --i)
            std::swap(slots[i - 1], slots[rng.below(i)]);
        glm::vec2 dlo, dhi;
        domainBounds(dom, dlo, dhi);
        Occupancy occupied(method, dlo, dhi, maxRadius, slots.size());
        std::vector<std::size_t> placedPerSpecies(species.size(), 0);
        std::vector<Instance> placed;
        for (std::size_t slot = 0; slot < slots.size(); ++slot) {
            const std::uint32_t sp = slots[slot];
            Instance inst;
            inst.id = domainTreeId(domainIds[d], slot);
            inst.species = sp;
            inst.seed = mixSeed(params.seed, inst.id);
            Rng own(mixSeed(inst.seed, salt::kPlacedTree));
            inst.rotation = own.uniformf(0.0f, glm::two_pi<float>());
            inst.scale = 1.0f + own.uniformf(-params.scaleVariation, params.scaleVariation);
            const float x = own.uniformf(0.0f, params.growthSpread);
            inst.growth = params.growthSpread > 0.0f ? std::min(1.0f, 2.0f * x / (1.0f + x)) : 1.0f;
            const float radius = inst.radius(species);

            bool found = false;
            for (int attempt = 0; attempt < params.maxTries && !found; ++attempt) {
                glm::vec2 q(rng.uniformf(dlo.x, dhi.x), rng.uniformf(dlo.y, dhi.y));
                if (dom.shape == DomainShape::Polygon) {
                    // Rejection from the bounding box; misses do not use up a try unless the
                    // polygon is a sliver of its box.
                    int guard = 0;
                    while (!insidePolygon(dom.polygon, q) && ++guard < 256)
                        q = glm::vec2(rng.uniformf(dlo.x, dhi.x), rng.uniformf(dlo.y, dhi.y));
                    if (guard >= 256) {
                        ++result.rejectedTries;
                        continue;
                    }
                }
                if (occupied.blocked(q)) {
                    ++result.rejectedTries;
                    continue;
                }
                float y = 0.0f;
                if (params.obstacles != nullptr && !params.obstacles->empty()) {
                    const env::Segment vertical{{q.x, params.obstacles->lo().y - 1.0f, q.y},
                                                {q.x, params.obstacles->hi().y + 1.0f, q.y}};
                    const float trunk = species[sp].trunkRadius * inst.scale * inst.growth;
                    if (params.obstacles->touches(vertical, trunk)) {
                        ++result.rejectedTries;
                        continue;
                    }
                }
                if (params.ground != nullptr) {
                    const env::Segment down{{q.x, params.ground->hi().y + 1.0f, q.y},
                                            {q.x, params.ground->lo().y - 1.0f, q.y}};
                    const env::SegmentHit h = params.ground->intersect(down);
                    if (!h.hit) {
                        ++result.rejectedTries;
                        continue;
                    }
                    y = h.point.y;
                }
                inst.position = glm::vec3(q.x, y, q.y);
                found = true;
            }
            if (!found) continue;
            occupied.add(glm::vec2(inst.position.x, inst.position.z), radius);
            ++placedPerSpecies[sp];
            placed.push_back(inst);
        }
        // The domain's trees that a hand-placed tree or an earlier domain's tree stands on.
        std::vector<bool> displaced(placed.size(), false);
        for (std::size_t i = 0; i < placed.size(); ++i)
            displaced[i] = kept.collides(glm::vec2(placed[i].position.x, placed[i].position.z),
                                         placed[i].radius(species));
        for (std::size_t i = 0; i < placed.size(); ++i) {
            if (displaced[i]) {
                ++result.displaced;
                continue;
            }
            kept.add(glm::vec2(placed[i].position.x, placed[i].position.z),
                     placed[i].radius(species));
            result.instances.push_back(placed[i]);
        }
        for (const auto& [name, count] : dom.counts) {
            const std::uint32_t sp = speciesIndex.at(name);
            (void)count;
            // A species may be listed twice in one domain; report it once with the sum.
            bool reported = false;
            for (const Shortfall& s : result.shortfalls)
                reported |= s.domain == d && s.species == sp;
            if (reported) continue;
            std::size_t requested = 0;
            for (const auto& [n2, c2] : dom.counts)
                if (n2 == name) requested += c2;
            if (placedPerSpecies[sp] < requested)
                result.shortfalls.push_back({d, sp, requested, placedPerSpecies[sp]});
        }
    }
    return result;
}

TileGrid makeTileGrid(const std::vector<Domain>& domains, const std::vector<Instance>& handPlaced,
                      int tileCount) {
    requireRange("tile count", tileCount, 1, 1e6);
    TileGrid g;
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const Domain& d : domains) {
        glm::vec2 dlo, dhi;
        domainBounds(d, dlo, dhi);
        lo = glm::min(lo, dlo);
        hi = glm::max(hi, dhi);
    }
    for (const Instance& i : handPlaced) {
        lo = glm::min(lo, glm::vec2(i.position.x, i.position.z));
        hi = glm::max(hi, glm::vec2(i.position.x, i.position.z));
    }
    if (lo.x > hi.x) lo = hi = glm::vec2(0.0f);
    g.lo = lo;
    g.hi = hi;
    int rows = 1;
    for (int r = 1; static_cast<long long>(r) * r <= tileCount; ++r)
        if (tileCount % r == 0) rows = r;
    g.rows = rows;
    g.cols = tileCount / rows;
    // Tiles are as square as the divisors allow: the longer side of the bounds gets the columns.
    if ((hi.x - lo.x) < (hi.y - lo.y)) std::swap(g.rows, g.cols);
    return g;
}

int tileOf(const TileGrid& g, const glm::vec3& p) {
    const glm::vec2 size = glm::max(g.hi - g.lo, glm::vec2(1e-20f));
    const int cx = std::clamp(
        static_cast<int>(std::floor((p.x - g.lo.x) / size.x * static_cast<float>(g.cols))), 0,
        g.cols - 1);
    const int cz = std::clamp(
        static_cast<int>(std::floor((p.z - g.lo.y) / size.y * static_cast<float>(g.rows))), 0,
        g.rows - 1);
    return cz * g.cols + cx;
}

std::vector<Instance> selectTile(const std::vector<Instance>& instances, const TileGrid& grid,
                                 int tile) {
    if (tile < 0 || tile >= grid.count())
        throw InvalidInput("tile " + std::to_string(tile) + " is not in [0, " +
                           std::to_string(grid.count()) + ")");
    std::vector<Instance> out;
    for (const Instance& i : instances)
        if (tileOf(grid, i.position) == tile) out.push_back(i);
    return out;
}

std::pair<int, int> parseTileSpec(const std::string& text) {
    const auto fail = [&text]() -> std::pair<int, int> {
        throw InvalidInput("--tile must be i/N with 1 <= i <= N, got '" + text + "'");
    };
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos || slash == 0 || slash + 1 >= text.size()) return fail();
    const std::string a = text.substr(0, slash), b = text.substr(slash + 1);
    const auto digits = [](const std::string& s) {
        return s.size() <= 7 &&
               std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
    };
    if (!digits(a) || !digits(b)) return fail();
    const int i = std::stoi(a), n = std::stoi(b);
    if (n < 1 || i < 1 || i > n) return fail();
    return {i - 1, n};
}

} // namespace sylva::placement
