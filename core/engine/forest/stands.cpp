#include "engine/forest/stands.h"

#include <map>
#include <string>
#include <utility>

namespace sylva::forest::build {

std::vector<std::shared_ptr<const skel::Skeleton>>
growStands(const ForestScene& scene, const std::vector<SpeciesPlan>& plans,
           std::vector<placement::Instance>& instances, Progress& progress) {
    std::vector<std::shared_ptr<const skel::Skeleton>> grown(instances.size());
    // Stands by their generator's type and key (an order that does not depend on addresses),
    // each with its members in instance order.
    std::map<std::pair<std::string, int>, std::vector<std::size_t>> stands;
    std::vector<graph::StandMember> members(instances.size());
    for (std::size_t i = 0; i < instances.size(); ++i) {
        placement::Instance& in = instances[i];
        const SpeciesPlan& plan = plans[in.species];
        if (!plan.stand) continue;
        const graph::SpeciesGraph& g = scene.species[in.species].graph;
        const graph::NodeDesc& generator = *g.findNode(plan.skeletonNode);
        members[i].params = &generator.params;
        members[i].position = in.position;
        members[i].seed = in.seed;
        in.rotation = 0.0f;
        in.scale = 1.0f;
        in.growth = 1.0f;
        stands[{generator.type, plan.stand->standOf(generator.params)}].push_back(i);
    }
    if (stands.empty()) return grown;
    std::vector<glm::vec3> obstacleTriangles;
    if (scene.obstacles)
        for (const env::ObstacleMesh& m : scene.obstacles->meshes())
            for (const glm::uvec3& t : m.triangles)
                for (int k = 0; k < 3; ++k)
                    obstacleTriangles.push_back(m.vertices[t[k]]);
    for (const auto& stand : stands) {
        const std::vector<std::size_t>& indices = stand.second;
        std::vector<graph::StandMember> trees;
        for (std::size_t i : indices)
            trees.push_back(members[i]);
        const graph::StandGrowth& growth = *plans[instances[indices.front()].species].stand;
        std::vector<skel::Skeleton> skeletons = growth.grow(trees, obstacleTriangles, progress);
        for (std::size_t k = 0; k < indices.size(); ++k)
            grown[indices[k]] = std::make_shared<const skel::Skeleton>(std::move(skeletons[k]));
    }
    return grown;
}

} // namespace sylva::forest::build
