#include "engine/growth/optimaldirection.h"

#include <algorithm>

#include "engine/growth/shadowgrid.h"
#include "engine/util/safenormalize.h"

namespace sylva::growth {

namespace {

/// The 26 neighbour voxels, ordered by their distance class (6 faces at 1, 12 edges at √2,
/// 8 corners at √3): unit directions as separate x/y/z arrays (so the cone test of all 26
/// vectorizes), integer offsets (so sums over any subset are exact integer sums, per class),
/// and their cells in the neighbourhood array.
struct Neighbours {
    static constexpr int kFaces = 6, kEdges = 12; ///< classes: [0, 6), [6, 18), [18, 26)
    float dx[26], dy[26], dz[26];
    std::int32_t ox[26], oy[26], oz[26];
    int cell[26]; ///< index into the neighbourhood array
    Neighbours() {
        int k = 0;
        for (int cls = 1; cls <= 3; ++cls)
            for (int y = -1; y <= 1; ++y)
                for (int x = -1; x <= 1; ++x)
                    for (int z = -1; z <= 1; ++z) {
                        if (x * x + y * y + z * z != cls) continue;
                        cell[k] = (y + 1) * 9 + (x + 1) * 3 + (z + 1);
                        const glm::vec3 d = glm::normalize(glm::vec3(x, y, z));
                        dx[k] = d.x;
                        dy[k] = d.y;
                        dz[k] = d.z;
                        ox[k] = x;
                        oy[k] = y;
                        oz[k] = z;
                        ++k;
                    }
    }
};
const Neighbours kNeighbours;

} // namespace

glm::vec3 leastShadowedDirection(const std::int32_t (&shadow)[27], const glm::vec3& dir,
                                 float cosHalf) {
    // Branch-free (which neighbours pass is as random as the shadow): every neighbour outside
    // the cone or opaque counts as kOpaque, the least shadow wins, and the directions of all
    // neighbours that tie for it are summed: as integer offsets per distance class (exact, in
    // any order, so the loops vectorize), scaled by 1/|offset| at the end.
    // (Masks instead of ?: so that the compiler cannot turn them back into branches.)
    std::int32_t value[26];
    for (int k = 0; k < 26; ++k) {
        const float d =
            kNeighbours.dx[k] * dir.x + kNeighbours.dy[k] * dir.y + kNeighbours.dz[k] * dir.z;
        const std::int32_t inCone = -static_cast<std::int32_t>(d >= cosHalf);
        value[k] = (shadow[kNeighbours.cell[k]] & inCone) | (ShadowGrid::kOpaque & ~inCone);
    }
    std::int32_t best = ShadowGrid::kOpaque;
    for (int k = 0; k < 26; ++k)
        best = std::min(best, value[k]);
    if (best == ShadowGrid::kOpaque) return dir;
    auto classSum = [&](int from, int to, glm::ivec3& sum) {
        std::int32_t x = 0, y = 0, z = 0;
        for (int k = from; k < to; ++k) {
            const std::int32_t tie = -static_cast<std::int32_t>(value[k] == best);
            x += kNeighbours.ox[k] & tie;
            y += kNeighbours.oy[k] & tie;
            z += kNeighbours.oz[k] & tie;
        }
        sum = {x, y, z};
    };
    constexpr int kEdgesEnd = Neighbours::kFaces + Neighbours::kEdges;
    glm::ivec3 faces, edges, corners;
    classSum(0, Neighbours::kFaces, faces);
    classSum(Neighbours::kFaces, kEdgesEnd, edges);
    classSum(kEdgesEnd, 26, corners);
    const glm::vec3 sum =
        glm::vec3(faces) + glm::vec3(edges) * 0.70710678f + glm::vec3(corners) * 0.57735027f;
    return safeNormalize(sum, dir);
}

} // namespace sylva::growth
