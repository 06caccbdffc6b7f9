// Fuzzes species-graph evaluation: a species loaded from fuzzed JSON (as the species harness
// does), validated, then evaluated (L-system derivation and turtle, space colonization,
// self-organizing growth, adaptation, leaves, tube meshing). The documented ranges allow
// minutes of work per input (2 million attractors for 100,000 iterations), so before
// evaluating, the parameters that set the amount of work are clamped to small values (the
// table below; the same clamps apply to every input, so a finding reproduces). Any input
// evaluates or throws InvalidInput, LimitExceeded or IoError (a file it names); what
// evaluates is a valid skeleton and a mesh with every index in range and finite positions,
// and evaluating it again from scratch gives the same mesh (determinism).
#include "document/speciesfile.h"
#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/error.h"

#include <QByteArray>
#include <QString>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

struct Clamp {
    const char* type;
    const char* param;
    double lo, hi;
    bool whenAbsent; ///< also set to hi when the node does not name it (its default is larger)
};

// The work a node may ask for, per parameter: values outside [lo, hi] are replaced by the
// nearer bound (so the fuzzer keeps exploring instead of being refused).
constexpr Clamp kClamps[] = {
    {"lsystem", "symbol_limit", 1, 4096, true},
    {"lsystem", "generations", 0, 64, false},
    {"space_colonization", "attractors", 1, 1500, true},
    {"space_colonization", "max_iterations", 1, 150, true},
    {"space_colonization", "segment_length", 0.05, 1e4, false},
    {"self_organizing", "cycles", 1, 6, true},
    {"self_organizing", "markers", 0, 3000, true},
    {"self_organizing", "max_internodes", 1, 3000, true},
    {"self_organizing", "voxel_size", 0.5, 1e4, false}, // 0.25: 13 s, 2 GB (finding 17)
    {"self_organizing", "crown_radius", 1e-3, 8, false},
    {"self_organizing", "crown_top", -1e4, 16, false},
    {"self_organizing", "internode_length", 0.05, 1e4, false},
    {"tube_mesh", "resolution", 3, 8, false},
    {"leaves", "density", 0, 8, false},
    {"leaves", "tip_count", 0, 8, false},
    {"leaves", "whorl_count", 0, 6, false},
};

void clampWork(sylva::graph::SpeciesGraph& species) {
    for (sylva::graph::NodeDesc& node : species.nodes) {
        if (!node.params.isObject()) continue;
        auto& params = node.params.objectRef();
        for (const Clamp& c : kClamps) {
            if (node.type != c.type) continue;
            auto it = params.find(c.param);
            if (it == params.end() && c.whenAbsent) params[c.param] = sylva::Value(c.hi);
            if (it == params.end() || !it->second.isNumber()) continue;
            const double v = it->second.toNumber();
            if (std::isnan(v)) continue; // refused by the node's own check
            if (v < c.lo) it->second = sylva::Value(c.lo);
            if (v > c.hi) it->second = sylva::Value(c.hi);
        }
    }
}

void checkMesh(const sylva::mesh::Mesh& m) {
    if (m.indices.size() % 3 != 0) std::abort();
    for (std::uint32_t i : m.indices)
        if (i >= m.positions.size()) std::abort();
    for (const glm::vec3& p : m.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) std::abort();
    if (!m.normals.empty() && m.normals.size() != m.positions.size()) std::abort();
    if (!m.uvs.empty() && m.uvs.size() != m.positions.size()) std::abort();
    std::size_t covered = 0;
    for (const sylva::mesh::Submesh& s : m.submeshes) {
        if (s.firstIndex != covered) std::abort();
        covered += s.indexCount;
    }
    if (!m.submeshes.empty() && covered != m.indices.size()) std::abort();
}

bool sameMesh(const sylva::mesh::Mesh& a, const sylva::mesh::Mesh& b) {
    return a.positions.size() == b.positions.size() && a.indices == b.indices &&
           std::memcmp(a.positions.data(), b.positions.data(),
                       a.positions.size() * sizeof(glm::vec3)) == 0;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    sylva::graph::registerBuiltinNodeTypes();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const QByteArray bytes(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size));
    // Grammar files named by the seeds (presets/lsystem/...) resolve against the presets.
    const QString baseDir = QStringLiteral(SYLVA_PRESETS_DIR);
    sylva::graph::SpeciesGraph species;
    try {
        species = sylva::doc::parseSpecies(bytes, QStringLiteral("fuzz.json"), baseDir);
        clampWork(species);
        sylva::graph::Evaluator evaluator(species);
        evaluator.validate();
        const sylva::graph::NodeOutput& out = evaluator.evaluate(7);
        if (out.skeleton) out.skeleton->validate();
        if (!out.mesh) return 0;
        checkMesh(*out.mesh);
        sylva::graph::Evaluator again(species);
        const sylva::graph::NodeOutput& second = again.evaluate(7);
        if (!second.mesh || !sameMesh(*out.mesh, *second.mesh)) std::abort();
    } catch (const sylva::InvalidInput&) {
    } catch (const sylva::LimitExceeded&) {
    } catch (const sylva::IoError&) {
    }
    return 0;
}
