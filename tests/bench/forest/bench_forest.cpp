// Forest benchmarks, each with its same-run baseline: Embree against the brute-force
// Möller–Trumbore oracle, grid placement against the O(n²) one, and the reference scenario's
// adaptation stage (1,000 trees of a few thousand segments against two 10k-triangle meshes).
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include <glm/gtc/constants.hpp>

#include "engine/environment/adapt.h"
#include "engine/placement/placement.h"
#include "engine/util/random.h"

using namespace sylva;

namespace {

/// A wavy vertical wall of 2·n·n triangles, `length` long on x, `height` high, around z = z0.
env::ObstacleMesh wavyWall(int n, float length, float height, float z0) {
    std::vector<glm::vec3> v;
    std::vector<glm::uvec3> t;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const float x = -0.5f * length + length * static_cast<float>(i) / static_cast<float>(n);
            const float y = height * static_cast<float>(j) / static_cast<float>(n);
            v.emplace_back(x, y, z0 + 0.8f * std::sin(0.4f * x) + 0.2f * std::sin(1.3f * y));
        }
    const auto at = [n](int i, int j) { return static_cast<unsigned>(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            t.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
            t.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
    return env::makeObstacleMesh("wavy wall", v, t);
}

/// The two ≥ 10k-triangle obstacles of the reference scenario: a wall across the stand and a
/// boulder-like sphere.
std::vector<env::ObstacleMesh> scenarioMeshes() {
    return {wavyWall(72, 80.0f, 6.0f, 10.0f),                           // 10,368 triangles
            env::makeSphereMesh(glm::vec3(-15, 2, -15), 7.0f, 72, 72)}; // 10,224 triangles
}

/// A tree of a few thousand segments: a trunk with three orders of side branches, seeded.
skel::Skeleton makeTree(std::uint64_t seed) {
    Rng rng(seed);
    skel::Skeleton s;
    s.addNode(glm::vec3(0.0f), -1, 0.25f, 0, glm::quat(1, 0, 0, 0));
    struct Axis {
        std::int32_t from;
        glm::vec3 dir;
        int segments;
        float step;
        std::uint16_t order;
    };
    std::vector<Axis> todo = {{0, glm::vec3(0, 1, 0), 40, 0.3f, 0}};
    while (!todo.empty()) {
        const Axis a = todo.back();
        todo.pop_back();
        std::int32_t node = a.from;
        glm::vec3 dir = a.dir;
        for (int i = 0; i < a.segments; ++i) {
            dir = glm::normalize(
                dir + glm::vec3(rng.uniformf(-0.08f, 0.08f), 0.03f, rng.uniformf(-0.08f, 0.08f)));
            const glm::vec3 p = s.position[static_cast<std::size_t>(node)] + a.step * dir;
            const float r = 0.2f * std::pow(0.55f, static_cast<float>(a.order)) *
                            (1.0f - 0.8f * static_cast<float>(i) / static_cast<float>(a.segments));
            node = s.addNode(p, node, r, a.order, glm::quat(1, 0, 0, 0));
            const bool spawn = a.order < 3 && i >= (a.order == 0 ? 10 : 1) && i % 3 == 0;
            if (!spawn) continue;
            for (int k = 0; k < 2; ++k) {
                const float phi = rng.uniformf(0.0f, glm::two_pi<float>());
                const glm::vec3 side(std::cos(phi), 0.35f, std::sin(phi));
                todo.push_back({node, glm::normalize(side), a.segments * 4 / 10 + 2, a.step * 0.8f,
                                static_cast<std::uint16_t>(a.order + 1)});
            }
        }
    }
    s.finalize();
    return s;
}

std::vector<skel::Skeleton>& trees() {
    static std::vector<skel::Skeleton> t = [] {
        std::vector<skel::Skeleton> v;
        for (std::uint64_t i = 0; i < 8; ++i)
            v.push_back(makeTree(i + 1));
        return v;
    }();
    return t;
}

std::vector<env::Segment> branchSegments(std::size_t count) {
    // Branch-sized segments (0.1–0.5 m) scattered over the obstacles' neighbourhood.
    Rng rng(42);
    std::vector<env::Segment> segs(count);
    for (env::Segment& s : segs) {
        s.a = glm::vec3(rng.uniformf(-40, 40), rng.uniformf(0, 8), rng.uniformf(-25, 15));
        const glm::vec3 d(rng.uniformf(-1, 1), rng.uniformf(-1, 1), rng.uniformf(-1, 1));
        s.b = s.a + rng.uniformf(0.1f, 0.5f) * glm::normalize(d + glm::vec3(0, 1e-3f, 0));
    }
    return segs;
}

void segmentQueries(benchmark::State& state, env::CollisionBackend backend) {
    const env::ObstacleScene scene(scenarioMeshes(), backend);
    const std::vector<env::Segment> segs = branchSegments(static_cast<std::size_t>(state.range(0)));
    std::vector<env::SegmentHit> hits(segs.size());
    for (auto _ : state) {
        scene.intersect(segs, hits);
        benchmark::DoNotOptimize(hits.data());
    }
    std::size_t n = 0;
    for (const env::SegmentHit& h : hits)
        n += h.hit ? 1 : 0;
    state.counters["hits"] = static_cast<double>(n);
    state.counters["triangles"] = static_cast<double>(scene.triangleCount());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(segs.size()));
}

void BM_SegmentsEmbree(benchmark::State& state) {
    segmentQueries(state, env::CollisionBackend::Embree);
}
void BM_SegmentsBruteForce(benchmark::State& state) {
    segmentQueries(state, env::CollisionBackend::BruteForce);
}
BENCHMARK(BM_SegmentsEmbree)->Arg(20000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SegmentsBruteForce)->Arg(20000)->Unit(benchmark::kMillisecond);

void BM_SceneBuild(benchmark::State& state) {
    const std::vector<env::ObstacleMesh> meshes = scenarioMeshes();
    for (auto _ : state) {
        env::ObstacleScene scene(meshes);
        benchmark::DoNotOptimize(&scene);
    }
}
BENCHMARK(BM_SceneBuild)->Unit(benchmark::kMillisecond);

void placement(benchmark::State& state, placement::PlacementMethod method) {
    const auto n = static_cast<std::size_t>(state.range(0));
    // Density of a closed stand: about one tree per 40 m², crown radii 2.5 and 1.5 m.
    const float side = std::sqrt(40.0f * static_cast<float>(n));
    placement::Domain d;
    d.min = glm::vec2(-0.5f * side);
    d.max = glm::vec2(0.5f * side);
    d.counts = {{"alder", n / 2}, {"birch", n - n / 2}};
    const std::vector<placement::SpeciesSpec> species = {{"alder", 2.5f}, {"birch", 1.5f}};
    placement::PlacementParams params;
    params.seed = 7;
    std::size_t placed = 0;
    for (auto _ : state) {
        const placement::PlacementResult r =
            placement::placeForest(species, {d}, {}, params, method);
        placed = r.instances.size();
        benchmark::DoNotOptimize(r.instances.data());
    }
    state.counters["placed"] = static_cast<double>(placed);
}

void BM_PlacementGrid(benchmark::State& state) {
    placement(state, placement::PlacementMethod::Grid);
}
void BM_PlacementNaive(benchmark::State& state) {
    placement(state, placement::PlacementMethod::Naive);
}
BENCHMARK(BM_PlacementGrid)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlacementNaive)->Arg(10000)->Unit(benchmark::kMillisecond);

/// 1,000 trees: range(1) == 0 spreads them over a 200 x 200 m stand crossed by the obstacles
/// (the reference scenario); 1 packs all of them around the obstacles so that every tree's
/// bounds overlap a mesh (the worst case: no tree skips the segment queries).
void adaptation(benchmark::State& state, env::CollisionBackend backend) {
    const env::ObstacleScene scene(scenarioMeshes(), backend);
    const auto n = static_cast<std::size_t>(state.range(0));
    const bool packed = state.range(1) != 0;
    Rng rng(3);
    std::vector<const skel::Skeleton*> rest;
    std::vector<glm::mat4> transforms;
    std::size_t segments = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const skel::Skeleton& t = trees()[i % trees().size()];
        rest.push_back(&t);
        segments += t.segmentCount();
        glm::vec3 p;
        if (packed) {
            const bool nearWall = i % 2 == 0;
            p = nearWall
                    ? glm::vec3(rng.uniformf(-38, 38), 0, 10.0f + rng.uniformf(-6, 6))
                    : glm::vec3(-15.0f + rng.uniformf(-12, 12), 0, -15.0f + rng.uniformf(-12, 12));
        } else {
            p = glm::vec3(rng.uniformf(-100, 100), 0, rng.uniformf(-100, 100));
        }
        glm::mat4 m = glm::translate(glm::mat4(1.0f), p);
        m = glm::rotate(m, rng.uniformf(0, 6.28f), glm::vec3(0, 1, 0));
        transforms.push_back(glm::scale(m, glm::vec3(rng.uniformf(0.95f, 1.05f))));
    }
    std::size_t touched = 0, hidden = 0;
    for (auto _ : state) {
        const std::vector<env::AdaptResult> r =
            env::adaptTrees(rest, transforms, scene, env::AdaptParams{});
        touched = hidden = 0;
        for (const env::AdaptResult& a : r) {
            touched += a.stats.collidingBefore > 0 ? 1 : 0;
            hidden += a.stats.hiddenNodes;
        }
        benchmark::DoNotOptimize(r.data());
    }
    state.counters["segments"] = static_cast<double>(segments);
    state.counters["trees_touching"] = static_cast<double>(touched);
    state.counters["hidden_nodes"] = static_cast<double>(hidden);
}

void BM_AdaptEmbree(benchmark::State& state) {
    adaptation(state, env::CollisionBackend::Embree);
}
void BM_AdaptBruteForce(benchmark::State& state) {
    adaptation(state, env::CollisionBackend::BruteForce);
}
BENCHMARK(BM_AdaptEmbree)
    ->Args({1000, 0})
    ->Args({1000, 1})
    ->ArgNames({"trees", "packed"})
    ->Unit(benchmark::kMillisecond);
// The oracle on 20 trees of the packed case (it is some 20-50 times slower per query).
BENCHMARK(BM_AdaptBruteForce)
    ->Args({20, 1})
    ->ArgNames({"trees", "packed"})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

} // namespace
