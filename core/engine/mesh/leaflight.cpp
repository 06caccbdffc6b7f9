#include "engine/mesh/leaflight.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace sylva::mesh {

namespace {

constexpr double kCell = 0.5; // metres: a few leaves' spread, finer than a branch's spray

std::uint64_t cellKey(int x, int y, int z) {
    auto u = [](int v) {
        return static_cast<std::uint64_t>(static_cast<std::uint32_t>(v) & 0x1fffff);
    };
    return (u(x) << 42) | (u(y) << 21) | u(z);
}

glm::ivec3 cellOf(const glm::dvec3& p) {
    return glm::ivec3(glm::floor(p / kCell));
}

// The light a node gathers itself: its record less its children's (a space colonization node's
// own exposure, a self-organizing tip's buds'); where that is nothing (a self-organizing node
// whose buds all grew or were shed), the mean per tip of its subtree.
std::vector<float> ownLight(const skel::Skeleton& s) {
    const std::size_t n = s.size();
    std::vector<double> children(n, 0.0), tips(n, 0.0);
    std::vector<char> hasChild(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        if (s.parent[i] >= 0) hasChild[static_cast<std::size_t>(s.parent[i])] = 1;
    for (std::size_t i = n; i-- > 0;) {
        if (!hasChild[i]) tips[i] += 1.0;
        if (s.parent[i] < 0) continue;
        const auto p = static_cast<std::size_t>(s.parent[i]);
        tips[p] += tips[i];
        children[p] += s.light[i];
    }
    std::vector<float> out(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double own = s.light[i] - children[i];
        out[i] = static_cast<float>(own > 1e-4 * std::max(1.0, static_cast<double>(s.light[i]))
                                        ? own
                                        : s.light[i] / std::max(tips[i], 1.0));
    }
    return out;
}

struct Sum {
    double light = 0.0;
    double count = 0.0;
};

} // namespace

std::vector<float> leafCardLight(const Mesh& mesh, std::size_t firstVertex,
                                 const std::vector<skel::Leaf>& leaves,
                                 const skel::Skeleton& skeleton) {
    const std::size_t n = skeleton.size();
    if (n == 0 || skeleton.light.size() != n || firstVertex >= mesh.positions.size()) return {};
    const std::vector<float> perTip = ownLight(skeleton);
    std::unordered_map<std::uint64_t, Sum> cells;
    Sum all;
    for (const skel::Leaf& leaf : leaves) {
        if (leaf.node < 0 || static_cast<std::size_t>(leaf.node) >= n) continue;
        const double l = perTip[static_cast<std::size_t>(leaf.node)];
        const glm::ivec3 c = cellOf(glm::dvec3(leaf.position));
        Sum& s = cells[cellKey(c.x, c.y, c.z)];
        s.light += l;
        s.count += 1.0;
        all.light += l;
        all.count += 1.0;
    }
    if (all.count == 0.0) return {};
    const std::size_t vertices = mesh.positions.size() - firstVertex;
    std::vector<float> light((vertices + 3) / 4);
    for (std::size_t card = 0; card < light.size(); ++card) {
        const std::size_t v = firstVertex + 4 * card;
        const std::size_t end = std::min(mesh.positions.size(), v + 4);
        glm::dvec3 centre(0.0);
        for (std::size_t k = v; k < end; ++k)
            centre += glm::dvec3(mesh.positions[k]);
        centre /= static_cast<double>(end - v);
        const glm::ivec3 c = cellOf(centre);
        Sum s;
        if (auto it = cells.find(cellKey(c.x, c.y, c.z)); it != cells.end()) s = it->second;
        if (s.count == 0.0)
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dz = -1; dz <= 1; ++dz)
                        if (auto it = cells.find(cellKey(c.x + dx, c.y + dy, c.z + dz));
                            it != cells.end()) {
                            s.light += it->second.light;
                            s.count += it->second.count;
                        }
        if (s.count == 0.0) s = all;
        light[card] = static_cast<float>(s.light / s.count);
    }
    // Spread between the 5th and 50th percentiles: the records' scale depends on the crown's
    // density and the voxel size; what the tint needs is which cards are lit among these. The
    // lit half keeps the texture's brightness, so the crown's outside is no darker than it was
    // (with the 80th, the side views of the oak, beech and maple lost 12-23 % of their
    // brightness; with the 50th, 9-16 %).
    std::vector<float> sorted = light;
    std::sort(sorted.begin(), sorted.end());
    const float lo = sorted[sorted.size() / 20];
    const float hi = sorted[sorted.size() / 2];
    const float span = hi - lo;
    for (float& l : light)
        l = span > 1e-9f ? std::clamp((l - lo) / span, 0.0f, 1.0f) : 1.0f;
    return light;
}

} // namespace sylva::mesh
