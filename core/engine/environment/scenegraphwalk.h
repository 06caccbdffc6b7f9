#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace sylva::env {

/// Most nodes of an obstacle file's scene once the nodes it instances (or parents more than
/// once) are copied in, as Assimp copies them: Collada `<instance_node>`, FBX models with
/// several parents. About 1.1 KB of Assimp's nodes each.
inline constexpr std::uint64_t kMaxSceneNodes = 100'000;
/// The deepest such hierarchy: Assimp builds it recursively (20,000 nested Collada nodes
/// overflowed the stack, 5,000 did not).
inline constexpr std::uint64_t kMaxSceneDepth = 1'000;

/// What walking a scene graph found: a loop (`node` reached again from `from` while it was being
/// copied), a node whose copied subtree is too large or too deep, or nothing.
struct SceneGraphProblem {
    enum class Kind { None, Loop, TooManyNodes, TooDeep } kind = Kind::None;
    std::size_t node = 0;
    std::size_t from = 0;
};

/// Walks the graph \p next (node -> the nodes copied under it: its children and the nodes it
/// instances) from each of \p roots, as an importer that copies every subtree it meets
/// recursively would, without recursing itself (files can hold long chains). Finds the first
/// loop, or the first node whose copied subtree holds more than \p maxNodes nodes or is more
/// than \p maxDepth deep. Linear in the nodes and edges reached.
SceneGraphProblem walkSceneGraph(const std::vector<std::vector<std::size_t>>& next,
                                 const std::vector<std::size_t>& roots,
                                 std::uint64_t maxNodes = kMaxSceneNodes,
                                 std::uint64_t maxDepth = kMaxSceneDepth);

/// Throws the error for \p problem, nothing for Kind::None: InvalidInput for a loop,
/// LimitExceeded for the limits. \p where starts the message, \p name names a node ("<node> at
/// line 12", "nodes[3]"), \p copies says what is copied ("its <instance_node>s are copied in").
void throwSceneGraphProblem(const SceneGraphProblem& problem, const std::string& where,
                            const std::function<std::string(std::size_t)>& name,
                            const std::string& copies);

} // namespace sylva::env
