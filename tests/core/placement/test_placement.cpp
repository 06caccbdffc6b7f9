#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include <omp.h>

#include "engine/placement/placement.h"
#include "engine/util/error.h"
#include "engine/util/random.h"

using namespace sylva;
using namespace sylva::placement;

namespace {

std::vector<SpeciesSpec> twoSpecies() {
    return {{"alder", 2.0f}, {"birch", 1.0f}};
}

Domain rectangle(glm::vec2 lo, glm::vec2 hi, std::size_t alders, std::size_t birches) {
    Domain d;
    d.min = lo;
    d.max = hi;
    d.counts = {{"alder", alders}, {"birch", birches}};
    return d;
}

bool sameInstance(const Instance& a, const Instance& b) {
    return a.id == b.id && a.species == b.species && a.position == b.position &&
           a.rotation == b.rotation && a.scale == b.scale && a.growth == b.growth &&
           a.seed == b.seed && a.handPlaced == b.handPlaced;
}

void expectSame(const PlacementResult& a, const PlacementResult& b) {
    ASSERT_EQ(a.instances.size(), b.instances.size());
    for (std::size_t i = 0; i < a.instances.size(); ++i)
        ASSERT_TRUE(sameInstance(a.instances[i], b.instances[i])) << "instance " << i;
    ASSERT_EQ(a.shortfalls.size(), b.shortfalls.size());
    EXPECT_EQ(a.rejectedTries, b.rejectedTries);
}

/// No tree stands inside the cylinder of a tree placed before it (the reference's rule).
void expectCylindersRespected(const PlacementResult& r, const std::vector<SpeciesSpec>& species) {
    for (std::size_t j = 0; j < r.instances.size(); ++j)
        for (std::size_t i = 0; i < j; ++i) {
            const Instance& a = r.instances[i];
            const Instance& b = r.instances[j];
            if (b.handPlaced) continue;
            const float d =
                glm::length(glm::vec2(a.position.x - b.position.x, a.position.z - b.position.z));
            ASSERT_GE(d, a.radius(species)) << "tree " << j << " inside tree " << i;
        }
}

template <typename F> std::string messageOf(F&& f) {
    try {
        f();
    } catch (const InvalidInput& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InvalidInput";
    return {};
}

} // namespace

TEST(Placement, RespectsCylindersAndTheDomainAndMeetsCounts) {
    const auto species = twoSpecies();
    PlacementParams params;
    params.seed = 7;
    const PlacementResult r =
        placeForest(species, {rectangle({-50, -50}, {50, 50}, 150, 100)}, {}, params);
    ASSERT_EQ(r.instances.size(), 250u);
    EXPECT_TRUE(r.shortfalls.empty());
    std::size_t alders = 0;
    for (const Instance& inst : r.instances) {
        EXPECT_GE(inst.position.x, -50.0f);
        EXPECT_LT(inst.position.x, 50.0f);
        EXPECT_GE(inst.position.z, -50.0f);
        EXPECT_LT(inst.position.z, 50.0f);
        EXPECT_EQ(inst.position.y, 0.0f);
        EXPECT_GE(inst.scale, 0.95f);
        EXPECT_LE(inst.scale, 1.05f);
        EXPECT_GT(inst.growth, 0.0f);
        EXPECT_LE(inst.growth, 1.0f);
        EXPECT_GE(inst.rotation, 0.0f);
        EXPECT_LT(inst.rotation, 6.2832f);
        EXPECT_EQ(inst.seed, mixSeed(7, inst.id));
        alders += inst.species == 0 ? 1 : 0;
    }
    EXPECT_EQ(alders, 150u);
    expectCylindersRespected(r, species);
}

TEST(Placement, ReportsTheShortfallOfAFullDomain) {
    const auto species = twoSpecies();
    PlacementParams params;
    params.seed = 3;
    const PlacementResult r =
        placeForest(species, {rectangle({0, 0}, {10, 10}, 500, 500)}, {}, params);
    ASSERT_FALSE(r.shortfalls.empty());
    std::size_t placed = 0;
    for (const Shortfall& s : r.shortfalls) {
        EXPECT_EQ(s.domain, 0u);
        EXPECT_EQ(s.requested, 500u);
        EXPECT_LT(s.placed, s.requested);
        placed += s.placed;
    }
    EXPECT_EQ(placed, r.instances.size());
    expectCylindersRespected(r, species);
}

TEST(Placement, GridEqualsNaiveUpToTenThousandTrees) {
    const auto species = twoSpecies();
    PlacementParams params;
    params.seed = 11;
    Domain poly;
    poly.shape = DomainShape::Polygon;
    poly.polygon = {{0, 0}, {120, 0}, {120, 60}, {60, 20}, {0, 60}};
    poly.counts = {{"birch", 3000}, {"alder", 1000}};
    Instance hand;
    hand.species = 0;
    hand.position = glm::vec3(30, 0, 30);
    hand.scale = 3.0f;
    const std::vector<Domain> domains = {rectangle({-200, -100}, {0, 100}, 4000, 2000), poly};
    const PlacementResult grid =
        placeForest(species, domains, {hand}, params, PlacementMethod::Grid);
    const PlacementResult naive =
        placeForest(species, domains, {hand}, params, PlacementMethod::Naive);
    EXPECT_GT(grid.rejectedTries, 0u);
    EXPECT_GT(grid.instances.size(), 8000u);
    expectSame(grid, naive);
    for (const Instance& i : grid.instances)
        if (i.id > 0 && i.position.x > 0.0f) {
            EXPECT_TRUE(insidePolygon(poly.polygon, {i.position.x, i.position.z}));
        }
    // A crowded case with many rejections and shortfalls.
    const std::vector<Domain> crowded = {rectangle({0, 0}, {40, 40}, 300, 300)};
    const PlacementResult g2 = placeForest(species, crowded, {}, params, PlacementMethod::Grid);
    expectSame(g2, placeForest(species, crowded, {}, params, PlacementMethod::Naive));
    EXPECT_FALSE(g2.shortfalls.empty());
}

TEST(Placement, DeterministicFromTheSeedOnOneAndTwoThreads) {
    const auto species = twoSpecies();
    PlacementParams params;
    params.seed = 5;
    const std::vector<Domain> domains = {rectangle({0, 0}, {80, 80}, 300, 300)};
    const int saved = omp_get_max_threads();
    omp_set_num_threads(1);
    const PlacementResult one = placeForest(species, domains, {}, params);
    omp_set_num_threads(2);
    const PlacementResult two = placeForest(species, domains, {}, params);
    omp_set_num_threads(saved);
    expectSame(one, two);
    params.seed = 6;
    const PlacementResult other = placeForest(species, domains, {}, params);
    EXPECT_NE(other.instances[0].position, one.instances[0].position);
}

TEST(Placement, GrowthStagesAreMostlyMature) {
    const std::vector<SpeciesSpec> species = {{"tiny", 0.0f}};
    PlacementParams params;
    params.seed = 1;
    Domain d;
    d.min = {0, 0};
    d.max = {100, 100};
    d.counts = {{"tiny", 9000}};
    const PlacementResult r = placeForest(species, {d}, {}, params);
    ASSERT_EQ(r.instances.size(), 9000u);
    std::size_t mature = 0, young = 0;
    for (const Instance& i : r.instances) {
        mature += i.growth == 1.0f ? 1 : 0;
        young += i.growth < 0.5f ? 1 : 0;
    }
    // x uniform in [0, 3]: mature when x >= 1 (2/3), younger than half when x < 1/3 (1/9).
    EXPECT_NEAR(static_cast<double>(mature) / 9000.0, 2.0 / 3.0, 0.03);
    EXPECT_NEAR(static_cast<double>(young) / 9000.0, 1.0 / 9.0, 0.02);
    params.growthSpread = 0.0f;
    for (const Instance& i : placeForest(species, {d}, {}, params).instances)
        ASSERT_EQ(i.growth, 1.0f);
}

TEST(Placement, AvoidsObstacleFootprintsAndStandsOnTheGround) {
    const auto species = twoSpecies();
    const env::ObstacleScene obstacles({env::makeBoxMesh({-10, 0, -5}, {10, 8, 5}, "house")});
    // A sloped terrain y = 0.1·x covering only x in [-40, 40].
    const env::ObstacleScene ground({env::makeObstacleMesh(
        "terrain", {{-40, -4, -50}, {40, 4, -50}, {40, 4, 50}, {-40, -4, 50}},
        {{0, 1, 2}, {0, 2, 3}})});
    PlacementParams params;
    params.seed = 2;
    params.obstacles = &obstacles;
    params.ground = &ground;
    const PlacementResult r =
        placeForest(species, {rectangle({-50, -50}, {50, 50}, 100, 100)}, {}, params);
    EXPECT_GT(r.instances.size(), 150u);
    for (const Instance& i : r.instances) {
        const bool inHouse =
            i.position.x > -10 && i.position.x < 10 && i.position.z > -5 && i.position.z < 5;
        EXPECT_FALSE(inHouse) << i.position.x << ", " << i.position.z;
        EXPECT_GE(i.position.x, -40.0f);
        EXPECT_LE(i.position.x, 40.0f);
        EXPECT_NEAR(i.position.y, 0.1f * i.position.x, 1e-4f);
    }
    expectSame(r, placeForest(species, {rectangle({-50, -50}, {50, 50}, 100, 100)}, {}, params,
                              PlacementMethod::Naive));
}

// A trunk of bark radius r stands at least r (times its scale and growth) from an obstacle, so
// its bark does not start inside one; with no trunk radius only the axis is kept out.
TEST(Placement, TrunksKeepTheirBarkRadiusFromObstacles) {
    auto species = twoSpecies();
    const env::ObstacleScene obstacles({env::makeBoxMesh({-10, 0, -5}, {10, 8, 5}, "house")});
    PlacementParams params;
    params.seed = 5;
    params.obstacles = &obstacles;
    const auto gap = [](const Instance& i) {
        const float dx = std::max({-10.0f - i.position.x, 0.0f, i.position.x - 10.0f});
        const float dz = std::max({-5.0f - i.position.z, 0.0f, i.position.z - 5.0f});
        return std::sqrt(dx * dx + dz * dz);
    };
    const std::vector<Domain> domains = {rectangle({-14, -9}, {14, 9}, 400, 400)};
    float nearest = 1e9f;
    for (const Instance& i : placeForest(species, domains, {}, params).instances)
        nearest = std::min(nearest, gap(i));
    EXPECT_LT(nearest, 0.5f); // without a trunk radius trees stand right at the walls
    for (SpeciesSpec& s : species)
        s.trunkRadius = 0.5f;
    const PlacementResult r = placeForest(species, domains, {}, params);
    EXPECT_GT(r.instances.size(), 20u);
    for (const Instance& i : r.instances)
        EXPECT_GE(gap(i), 0.5f * i.scale * i.growth) << i.position.x << ", " << i.position.z;
    expectSame(r, placeForest(species, domains, {}, params, PlacementMethod::Naive));
    species[0].trunkRadius = -1.0f;
    EXPECT_THROW(placeForest(species, domains, {}, params), InvalidInput);
}

TEST(Placement, HandPlacedInstancesComeFirstAndBlock) {
    const auto species = twoSpecies();
    Instance big;
    big.species = 0;
    big.position = glm::vec3(0, 0, 0);
    big.scale = 5.0f; // a 10 m cylinder in a 30 m square
    big.seed = 99;
    PlacementParams params;
    params.seed = 4;
    const PlacementResult r =
        placeForest(species, {rectangle({-15, -15}, {15, 15}, 20, 20)}, {big}, params);
    ASSERT_GE(r.instances.size(), 2u);
    EXPECT_TRUE(r.instances[0].handPlaced);
    EXPECT_EQ(r.instances[0].id, 1u); // no id given: its index + 1
    EXPECT_EQ(r.instances[0].seed, 99u);
    EXPECT_GT(r.displaced, 0u);
    for (std::size_t i = 1; i < r.instances.size(); ++i) {
        // Domain 1 (no id given: its index + 1), slot ids in slot order.
        EXPECT_GE(r.instances[i].id, domainTreeId(1, 0));
        EXPECT_LT(r.instances[i].id, domainTreeId(1, 40));
        EXPECT_GT(r.instances[i].id, r.instances[i - 1].id);
        EXPECT_GE(glm::length(glm::vec2(r.instances[i].position.x, r.instances[i].position.z)),
                  10.0f);
    }
}

// Issue 30: a hand-placed tree takes no part in the scattering; moving it changes only the
// domain trees it stood on or stands on now, and every other tree keeps its id and place.
TEST(Placement, MovingAHandPlacedTreeMovesNoOtherTree) {
    const auto species = twoSpecies();
    PlacementParams params;
    params.seed = 5;
    const std::vector<Domain> domains = {rectangle({-50, -50}, {50, 50}, 120, 120)};
    Instance hand;
    hand.id = 17;
    hand.species = 0;
    hand.position = glm::vec3(-20, 0, 0);
    hand.scale = 3.0f; // a 6 m cylinder
    const PlacementResult none = placeForest(species, domains, {}, params);
    const PlacementResult before = placeForest(species, domains, {hand}, params);
    hand.position.x += 30.0f;
    const PlacementResult after = placeForest(species, domains, {hand}, params);
    EXPECT_EQ(before.instances[0].id, 17u);
    auto near = [&](const Instance& t, glm::vec3 at) {
        const float d = glm::length(glm::vec2(t.position.x - at.x, t.position.z - at.z));
        return d < std::max(t.radius(species), 6.0f);
    };
    // Every domain tree of the forest without the hand-placed tree is in both forests,
    // unchanged, unless the hand-placed tree stands on it.
    std::map<std::uint64_t, Instance> inBefore, inAfter;
    for (const Instance& t : before.instances)
        inBefore[t.id] = t;
    for (const Instance& t : after.instances)
        inAfter[t.id] = t;
    std::size_t displacedBefore = 0, displacedAfter = 0;
    for (const Instance& t : none.instances) {
        const bool coveredBefore = near(t, glm::vec3(-20, 0, 0));
        const bool coveredAfter = near(t, glm::vec3(10, 0, 0));
        if (coveredBefore) {
            EXPECT_FALSE(inBefore.count(t.id));
            ++displacedBefore;
        } else {
            ASSERT_TRUE(inBefore.count(t.id)) << t.id;
            EXPECT_TRUE(sameInstance(inBefore[t.id], t)) << t.id;
        }
        if (coveredAfter) {
            EXPECT_FALSE(inAfter.count(t.id));
            ++displacedAfter;
        } else {
            ASSERT_TRUE(inAfter.count(t.id)) << t.id;
            EXPECT_TRUE(sameInstance(inAfter[t.id], t)) << t.id;
        }
    }
    EXPECT_EQ(before.displaced, displacedBefore);
    EXPECT_EQ(after.displaced, displacedAfter);
    EXPECT_EQ(none.instances.size(), before.instances.size() - 1 + displacedBefore);
    EXPECT_GT(displacedBefore + displacedAfter, 0u) << "the test must move a tree onto others";
    EXPECT_TRUE(before.shortfalls.empty());
}

// Each domain scatters on its own stream, seeded from its id: the order of the domains in the
// file, and the other domains, do not change its trees (where domains do not overlap).
TEST(Placement, ADomainsTreesFollowItsIdNotItsPlaceInTheList) {
    const auto species = twoSpecies();
    PlacementParams params;
    params.seed = 6;
    Domain a = rectangle({-50, -50}, {0, 50}, 40, 40);
    a.id = 7;
    Domain b = rectangle({10, -50}, {60, 50}, 30, 10);
    b.id = 3;
    const PlacementResult ab = placeForest(species, {a, b}, {}, params);
    const PlacementResult ba = placeForest(species, {b, a}, {}, params);
    const PlacementResult onlyA = placeForest(species, {a}, {}, params);
    std::map<std::uint64_t, Instance> byId;
    for (const Instance& t : ba.instances)
        byId[t.id] = t;
    ASSERT_EQ(ab.instances.size(), ba.instances.size());
    for (const Instance& t : ab.instances)
        EXPECT_TRUE(sameInstance(byId.at(t.id), t)) << t.id;
    for (const Instance& t : onlyA.instances) {
        EXPECT_EQ(t.id / kDomainIdStride, 7u);
        EXPECT_TRUE(sameInstance(byId.at(t.id), t)) << t.id;
    }
    // Overlapping domains: the later one's trees give way to the earlier one's.
    Domain c = rectangle({-50, -50}, {0, 50}, 40, 40);
    c.id = 8;
    const PlacementResult ac = placeForest(species, {a, c}, {}, params);
    EXPECT_GT(ac.displaced, 0u);
    expectCylindersRespected(ac, species);
}

TEST(Placement, IdsAreCheckedAndNeverRepeat) {
    const auto species = twoSpecies();
    PlacementParams params;
    Domain a = rectangle({0, 0}, {10, 10}, 1, 1);
    Domain b = a;
    a.id = b.id = 4;
    EXPECT_NE(messageOf([&] {
                  placeForest(species, {a, b}, {}, params);
              }).find("domains 1 and 2 have the same id 4"),
              std::string::npos);
    a.id = kMaxDomainId + 1;
    EXPECT_NE(messageOf([&] { placeForest(species, {a}, {}, params); }).find("is not in [1, "),
              std::string::npos);
    Instance h1, h2;
    h1.id = h2.id = 9;
    EXPECT_NE(messageOf([&] {
                  placeForest(species, {}, {h1, h2}, params);
              }).find("hand-placed instances 1 and 2 have the same id 9"),
              std::string::npos);
    h1.id = kDomainIdStride;
    EXPECT_NE(messageOf([&] { placeForest(species, {}, {h1}, params); }).find("is not in [1, "),
              std::string::npos);
}

TEST(Placement, BadInputsGetTheirMessages) {
    const auto species = twoSpecies();
    PlacementParams params;
    Domain unknown = rectangle({0, 0}, {10, 10}, 1, 1);
    unknown.counts.push_back({"oak", 3});
    EXPECT_NE(messageOf([&] {
                  placeForest(species, {unknown}, {}, params);
              }).find("unknown species 'oak'"),
              std::string::npos);
    EXPECT_NE(messageOf([&] {
                  placeForest(species, {rectangle({10, 0}, {0, 10}, 1, 1)}, {}, params);
              }).find("min < max"),
              std::string::npos);
    Domain poly;
    poly.shape = DomainShape::Polygon;
    poly.polygon = {{0, 0}, {1, 1}};
    EXPECT_NE(messageOf([&] { placeForest(species, {poly}, {}, params); }).find("at least 3"),
              std::string::npos);
    poly.polygon = {{0, 0}, {1, 1}, {2, 2}};
    EXPECT_NE(messageOf([&] { placeForest(species, {poly}, {}, params); }).find("no area"),
              std::string::npos);
    PlacementParams zero;
    zero.maxTries = 0;
    EXPECT_NE(messageOf([&] { placeForest(species, {}, {}, zero); }).find("max_tries"),
              std::string::npos);
    EXPECT_NE(messageOf([&] {
                  placeForest({{"x", -1.0f}}, {}, {}, params);
              }).find("crown radius"),
              std::string::npos);
    Instance bad;
    bad.species = 7;
    EXPECT_NE(messageOf([&] { placeForest(species, {}, {bad}, params); }).find("unknown species"),
              std::string::npos);
    EXPECT_THROW(placeForest(species, {rectangle({0, 0}, {1, 1}, 60'000'000, 0)}, {}, params),
                 LimitExceeded);
    // The limit of trees per forest names itself and what to do.
    try {
        placeForest(
            species,
            {rectangle({0, 0}, {1, 1}, 30'000'000, 0), rectangle({0, 0}, {1, 1}, 30'000'000, 0)},
            {}, params);
        ADD_FAILURE() << "expected LimitExceeded";
    } catch (const LimitExceeded& e) {
        EXPECT_STREQ(e.what(), "a forest is limited to 50000000 trees; lower the domains' counts "
                               "or split the scene into several projects");
    }
}

TEST(Tiles, UnionOfTheTilesEqualsTheWholeForest) {
    const auto species = twoSpecies();
    PlacementParams params;
    params.seed = 9;
    Instance hand;
    hand.position = glm::vec3(120, 0, -80); // outside the domain: the bounds include it
    const std::vector<Domain> domains = {rectangle({-100, -50}, {100, 50}, 800, 800)};
    const PlacementResult whole = placeForest(species, domains, {hand}, params);
    for (int n : {1, 2, 3, 4, 7, 12}) {
        const TileGrid grid = makeTileGrid(domains, {hand}, n);
        EXPECT_EQ(grid.count(), n);
        std::vector<Instance> united;
        for (int t = 0; t < n; ++t) {
            // Each tile is its own run, as a farm job would do it.
            const PlacementResult run = placeForest(species, domains, {hand}, params);
            const std::vector<Instance> part = selectTile(run.instances, grid, t);
            for (const Instance& i : part)
                EXPECT_EQ(tileOf(grid, i.position), t);
            united.insert(united.end(), part.begin(), part.end());
        }
        std::sort(united.begin(), united.end(),
                  [](const Instance& a, const Instance& b) { return a.id < b.id; });
        ASSERT_EQ(united.size(), whole.instances.size()) << n << " tiles";
        for (std::size_t i = 0; i < united.size(); ++i)
            ASSERT_TRUE(sameInstance(united[i], whole.instances[i]));
    }
    // Tiles are spatial: 3 tiles over the 200 x 100 m area are thirds of the x range; 4 tiles
    // are 2 x 2, numbered row by row (z) then column (x); outside points go to the border tile.
    const TileGrid g3 = makeTileGrid(domains, {}, 3);
    EXPECT_EQ(g3.cols, 3);
    EXPECT_EQ(g3.rows, 1);
    EXPECT_EQ(tileOf(g3, {-99, 0, 0}), 0);
    EXPECT_EQ(tileOf(g3, {-30, 0, 40}), 1);
    EXPECT_EQ(tileOf(g3, {500, 0, 0}), 2);
    const TileGrid g = makeTileGrid(domains, {}, 4);
    EXPECT_EQ(g.cols, 2);
    EXPECT_EQ(g.rows, 2);
    EXPECT_EQ(tileOf(g, {-99, 0, -49}), 0);
    EXPECT_EQ(tileOf(g, {99, 0, -49}), 1);
    EXPECT_EQ(tileOf(g, {-99, 0, 49}), 2);
    EXPECT_EQ(tileOf(g, {99, 0, 49}), 3);
    EXPECT_THROW(selectTile(whole.instances, g, 4), InvalidInput);
    EXPECT_THROW(makeTileGrid(domains, {}, 0), InvalidInput);
}

TEST(Tiles, ParsesTileSpecs) {
    EXPECT_EQ(parseTileSpec("1/4"), std::make_pair(0, 4));
    EXPECT_EQ(parseTileSpec("4/4"), std::make_pair(3, 4));
    for (const char* bad : {"0/4", "5/4", "1/0", "a/4", "1/", "/4", "14", "-1/4", "1/4/2"})
        EXPECT_NE(messageOf([&] { parseTileSpec(bad); }).find(std::string("'") + bad + "'"),
                  std::string::npos)
            << bad;
}
