#include "engine/environment/scenegraphwalk.h"

#include "engine/util/error.h"

#include <algorithm>
#include <utility>

namespace sylva::env {

SceneGraphProblem walkSceneGraph(const std::vector<std::vector<std::size_t>>& next,
                                 const std::vector<std::size_t>& roots, std::uint64_t maxNodes,
                                 std::uint64_t maxDepth) {
    enum class State : std::uint8_t { New, Open, Done };
    std::vector<State> state(next.size(), State::New);
    std::vector<std::uint64_t> size(next.size(), 0), depth(next.size(), 0);
    for (const std::size_t root : roots) {
        if (root >= next.size() || state[root] != State::New) continue;
        std::vector<std::pair<std::size_t, std::size_t>> stack{{root, 0}}; // node, next edge
        state[root] = State::Open;
        while (!stack.empty()) {
            const std::size_t n = stack.back().first;
            if (stack.back().second < next[n].size()) {
                const std::size_t m = next[n][stack.back().second++];
                if (m >= next.size()) continue;
                if (state[m] == State::Open) return {SceneGraphProblem::Kind::Loop, m, n};
                if (state[m] == State::New) {
                    state[m] = State::Open;
                    stack.emplace_back(m, 0);
                }
                continue;
            }
            // Post-order: every node below is done. Sizes saturate just above the limit.
            std::uint64_t total = 1, deepest = 0;
            for (const std::size_t m : next[n]) {
                if (m >= next.size()) continue;
                total = std::min(total + size[m], maxNodes + 1);
                deepest = std::max(deepest, depth[m]);
            }
            size[n] = total;
            depth[n] = deepest + 1;
            state[n] = State::Done;
            if (total > maxNodes) return {SceneGraphProblem::Kind::TooManyNodes, n, n};
            if (depth[n] > maxDepth) return {SceneGraphProblem::Kind::TooDeep, n, n};
            stack.pop_back();
        }
    }
    return {};
}

void throwSceneGraphProblem(const SceneGraphProblem& problem, const std::string& where,
                            const std::function<std::string(std::size_t)>& name,
                            const std::string& copies) {
    switch (problem.kind) {
    case SceneGraphProblem::Kind::None:
        return;
    case SceneGraphProblem::Kind::Loop:
        throw InvalidInput(where + name(problem.node) + " is its own ancestor (through " +
                           name(problem.from) + "): the scene graph must not loop");
    case SceneGraphProblem::Kind::TooManyNodes:
        throw LimitExceeded(where + name(problem.node) + " holds more than " +
                            std::to_string(kMaxSceneNodes) + " nodes once " + copies +
                            "; an obstacle needs its geometry, not a scene of that size");
    case SceneGraphProblem::Kind::TooDeep:
        throw LimitExceeded(where + name(problem.node) + " starts a hierarchy more than " +
                            std::to_string(kMaxSceneDepth) +
                            " deep; flatten the obstacle's hierarchy");
    }
}

} // namespace sylva::env
