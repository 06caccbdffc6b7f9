#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "engine/environment/obstaclescene.h"

namespace sylva::placement {

/// What placement needs to know about a species.
struct SpeciesSpec {
    std::string name;
    float crownRadius = 2.0f; ///< metres at scale 1 and full growth: the bounding cylinder
    /// The trunk's bark radius at its base, metres at scale 1 and full growth: a tree stands no
    /// nearer to an obstacle than this (times its scale and growth), so its bark does not start
    /// inside one. 0: only the trunk's axis is kept out of obstacles.
    float trunkRadius = 0.0f;
};

enum class DomainShape { Rectangle, Polygon };

/// Tree ids: a hand-placed tree's id is its own (the project file keeps it), in [1,
/// kDomainIdStride); a domain's tree has id domain id · kDomainIdStride + its slot in the domain
/// (0-based), so ids never collide and survive any edit that leaves the domain alone.
inline constexpr std::uint64_t kDomainIdStride = 1'000'000'000ull;
/// Largest domain id (its trees' ids stay below 2^63, exact in USD's int64 and glTF's extras).
inline constexpr std::uint64_t kMaxDomainId = 9'000'000'000ull;
constexpr std::uint64_t domainTreeId(std::uint64_t domainId, std::uint64_t slot) {
    return domainId * kDomainIdStride + slot;
}

/// An area on the ground (x, z) that receives a number of trees of each species.
struct Domain {
    /// Stable id (the project file keeps it), 1..kMaxDomainId; it seeds the domain's own random
    /// stream and names its trees. 0: the domain's index + 1.
    std::uint64_t id = 0;
    DomainShape shape = DomainShape::Rectangle;
    glm::vec2 min{0.0f};            ///< rectangle: smallest (x, z), metres
    glm::vec2 max{0.0f};            ///< rectangle: largest (x, z), metres
    std::vector<glm::vec2> polygon; ///< polygon: (x, z) corners of a simple polygon, >= 3
    /// (species name, count) in file order; a name must be one of the SpeciesSpec names.
    std::vector<std::pair<std::string, std::size_t>> counts;
};

/// One tree of the forest: hand-placed instances first (in their order), then each domain's.
/// `id` is stable (see kDomainIdStride); `seed` is mixSeed(project seed, id) for placed trees.
struct Instance {
    std::uint64_t id = 0;
    std::uint32_t species = 0; ///< index into the SpeciesSpec list
    glm::vec3 position{0.0f};  ///< metres; y is the ground height under the tree
    float rotation = 0.0f;     ///< radians about +Y, [0, 2·pi)
    float scale = 1.0f;        ///< size variation factor (1 ± scaleVariation)
    float growth = 1.0f;       ///< growth stage (0, 1]; 1 is a mature tree
    std::uint64_t seed = 0;    ///< the tree's own seed (generation, adaptation)
    bool handPlaced = false;
    /// The tree's own season (mesh::Season's value), -1: the scene's (ForestScene::season).
    std::int8_t season = -1;

    /// Local tree frame to world: translate · rotateY(rotation) · uniform scale(scale · growth).
    glm::mat4 transform() const;
    /// The bounding cylinder's radius: crownRadius · scale · growth.
    float radius(const std::vector<SpeciesSpec>& species) const;
};

struct PlacementParams {
    std::uint64_t seed = 0;       ///< the project seed
    int maxTries = 50;            ///< positions tried per tree before giving up, >= 1
    float scaleVariation = 0.05f; ///< scale uniform in [1 - v, 1 + v], v in [0, 0.9]
    /// Growth stage g = min(1, 2x / (1 + x)) with x uniform in [0, growthSpread]. With the
    /// default 3, two thirds of the trees are mature and the rest spread over younger stages
    /// (the reference's "mostly fully grown, a few mid growth, fewer adolescent"); 0 turns the
    /// variation off (every tree mature).
    float growthSpread = 3.0f;
    /// Ground or terrain: trees stand where a ray straight down first meets it, and positions
    /// where it misses are rejected. nullptr: flat ground at y = 0.
    const env::ObstacleScene* ground = nullptr;
    /// Obstacles whose footprints are avoided: a position is rejected when the vertical line
    /// through it comes nearer to an obstacle triangle than the tree's trunk radius
    /// (SpeciesSpec::trunkRadius · scale · growth). nullptr: none.
    const env::ObstacleScene* obstacles = nullptr;
};

/// A species of a domain that did not get all its trees (the domain was full).
struct Shortfall {
    std::size_t domain = 0;
    std::uint32_t species = 0;
    std::size_t requested = 0;
    std::size_t placed = 0;
};

struct PlacementResult {
    std::vector<Instance> instances;
    std::vector<Shortfall> shortfalls; ///< empty when every count was met
    std::size_t rejectedTries = 0;     ///< positions rejected in all (for statistics)
    std::size_t displaced = 0; ///< domain trees removed because a hand-placed tree stands there
};

/// Grid: a uniform grid of cells at least one bounding radius wide, O(1) per test. Naive: the
/// O(n²) test against every placed tree (the oracle; identical results).
enum class PlacementMethod { Grid, Naive };

/// Scatters trees over the domains after the reference (§4.2): per domain, its trees (species
/// interleaved by a seeded shuffle) take random positions; a position inside the bounding
/// cylinder of one of the domain's trees (or an obstacle footprint, or off the terrain) is
/// rejected and retried up to maxTries times; each tree gets a random rotation, scale and growth
/// stage from its own seed. Each domain is scattered alone, from its own stream (project seed +
/// domain id); then hand-placed trees, and the trees of earlier domains where domains overlap,
/// remove the domain trees they collide with (either trunk inside the other's bounding
/// cylinder; counted in `displaced`, not as a shortfall). So moving, adding or removing a
/// hand-placed tree, or editing a domain, changes only the trees around it. Deterministic
/// whatever the thread count.
/// \throw InvalidInput for an unknown species, a degenerate domain, duplicate or out-of-range
/// ids, or parameters out of range. \throw LimitExceeded above 50 million trees.
PlacementResult placeForest(const std::vector<SpeciesSpec>& species,
                            const std::vector<Domain>& domains,
                            const std::vector<Instance>& handPlaced, const PlacementParams& params,
                            PlacementMethod method = PlacementMethod::Grid);

/// Even-odd point-in-polygon test on the ground plane.
bool insidePolygon(const std::vector<glm::vec2>& polygon, const glm::vec2& p);

/// N spatial tiles over fixed bounds: rows x cols cells (rows the largest divisor of N not
/// above sqrt(N)). Every position belongs to exactly one tile; positions outside the bounds go
/// to the nearest border tile.
struct TileGrid {
    glm::vec2 lo{0.0f}, hi{0.0f}; ///< (x, z) bounds, metres
    int cols = 1, rows = 1;
    int count() const { return cols * rows; }
};

/// Tiles over the union of the domains' bounds and the hand-placed positions.
/// \throw InvalidInput unless 1 <= tileCount <= 1,000,000.
TileGrid makeTileGrid(const std::vector<Domain>& domains, const std::vector<Instance>& handPlaced,
                      int tileCount);
/// The 0-based tile of a position.
int tileOf(const TileGrid& grid, const glm::vec3& position);
/// The instances of tile \p tile (0-based), in their original order.
std::vector<Instance> selectTile(const std::vector<Instance>& instances, const TileGrid& grid,
                                 int tile);
/// Parses a command line's "i/N" (1 <= i <= N) into a 0-based tile index and the tile count.
/// \throw InvalidInput "--tile must be i/N with 1 <= i <= N, got '<text>'".
std::pair<int, int> parseTileSpec(const std::string& text);

} // namespace sylva::placement
