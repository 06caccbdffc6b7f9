#pragma once

#include <cmath>

#include "engine/mesh/treemesh.h"
#include "engine/skeleton/skeleton.h"

namespace sylva::windtest {

/// A small tree for the wind tests: a 10 m trunk, four limbs (one drooping low, 0.6 m above the
/// ground), each with two branches, a twig (level 3) on one, and leaves on the branches.
inline skel::Skeleton windTree() {
    skel::Skeleton s;
    const glm::quat up(1, 0, 0, 0);
    std::int32_t prev = s.addNode({0, 0, 0}, -1, 0.3f, 0, up);
    std::vector<std::int32_t> trunk{prev};
    for (int i = 1; i <= 10; ++i) {
        prev = s.addNode({0, static_cast<float>(i), 0}, prev, 0.3f - 0.025f * i, 0, up);
        trunk.push_back(prev);
    }
    const glm::vec3 dirs[4] = {{1, -0.12f, 0}, {0, 0.5f, 1}, {-1, 0.6f, 0}, {0, 0.7f, -1}};
    const int at[4] = {1, 4, 6, 8};
    for (int l = 0; l < 4; ++l) {
        const glm::vec3 d = glm::normalize(dirs[l]);
        std::int32_t p = trunk[static_cast<std::size_t>(at[l])];
        std::int32_t mid = -1;
        for (int k = 1; k <= 4; ++k) {
            p = s.addNode(s.position[static_cast<std::size_t>(p)] + d, p, 0.08f - 0.015f * k, 1,
                          up);
            if (k == 2) mid = p;
        }
        for (std::int32_t base : {mid, p}) {
            const glm::vec3 bd = glm::normalize(d + glm::vec3(0, 0.8f, 0.3f));
            std::int32_t q = base;
            for (int k = 1; k <= 3; ++k) {
                q = s.addNode(s.position[static_cast<std::size_t>(q)] + 0.5f * bd, q,
                              0.02f - 0.005f * k, 2, up);
                s.leaves.push_back({s.position[static_cast<std::size_t>(q)], up, 0.2f, q});
            }
            if (l == 1 && base == mid) {
                const std::int32_t twig =
                    s.addNode(s.position[static_cast<std::size_t>(q)] + glm::vec3(0.3f, 0.1f, 0), q,
                              0.005f, 3, up);
                s.leaves.push_back({s.position[static_cast<std::size_t>(twig)], up, 0.2f, twig});
            }
        }
    }
    s.finalize();
    return s;
}

inline mesh::Mesh windTreeMesh(const skel::Skeleton& s) {
    mesh::TreeMeshSettings settings;
    settings.tubes.nodeIds = true;
    return mesh::buildTreeMesh(s, settings);
}

} // namespace sylva::windtest
