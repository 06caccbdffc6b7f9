#pragma once

// What buildForest's parallel stages (variants, tree batches) share per thread.

#include <chrono>
#include <cstddef>
#include <memory>
#include <vector>

#include "engine/forest/forestbuild.h"

namespace sylva::forest::build {

using Clock = std::chrono::steady_clock;

inline double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

/// One evaluator per thread and species (an evaluator caches, so it is never shared), and each
/// thread's CPU time per stage.
struct Workers {
    Workers(const ForestScene& scene, int threadCount) : threads(threadCount) {
        evaluators.resize(static_cast<std::size_t>(threads));
        for (auto& perThread : evaluators)
            for (const SceneSpecies& s : scene.species)
                perThread.push_back(std::make_unique<graph::Evaluator>(s.graph));
        generateMs.assign(static_cast<std::size_t>(threads), 0.0);
        adaptMs = meshMs = generateMs;
    }
    graph::Evaluator& evaluator(std::size_t thread, std::size_t species) {
        return *evaluators[thread][species];
    }

    int threads = 1;
    std::vector<std::vector<std::unique_ptr<graph::Evaluator>>> evaluators;
    std::vector<double> generateMs, adaptMs, meshMs;
};

} // namespace sylva::forest::build
