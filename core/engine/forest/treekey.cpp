#include "engine/forest/treekey.h"

#include "engine/util/random.h"

namespace sylva::forest::build {

std::uint64_t treeKey(std::uint64_t species, const placement::Instance& in,
                      const std::vector<env::CrownVolume>& near, const ForestScene& scene,
                      const ForestOptions& options, double cameraDistance,
                      const std::vector<skel::BranchEdit>* edits) {
    std::uint64_t h = mixSeed(species, options.obstaclesKey);
    auto mix = [&h](const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i)
            h = (h ^ p[i]) * 0x100000001b3ull;
    };
    auto pod = [&mix](const auto& v) { mix(&v, sizeof v); };
    pod(in.id);
    pod(in.position);
    pod(in.rotation);
    pod(in.scale);
    pod(in.growth);
    pod(in.seed);
    pod(in.handPlaced);
    pod(in.season);
    const int season = scene.season ? static_cast<int>(*scene.season) : -1;
    pod(season);
    for (const env::CrownVolume& c : near) {
        pod(c.base);
        pod(c.radius);
        pod(c.bottom);
        pod(c.top);
    }
    pod(scene.lightDirection);
    if (options.useLod) pod(cameraDistance);
    if (edits)
        for (const skel::BranchEdit& e : *edits) {
            mix(e.branch.data(), e.branch.size() + 1);
            const glm::vec3 bend = e.bend.value_or(glm::vec3(0.0f));
            const bool bits[] = {e.prune, e.bend.has_value(), e.lock};
            mix(bits, sizeof bits);
            pod(bend);
            pod(e.length);
            pod(e.radius);
            // Where an anchored edit goes, and what a locked one puts back, are its result too.
            const bool anchored = e.anchor.has_value();
            pod(anchored);
            if (e.anchor) {
                pod(e.anchor->base);
                pod(e.anchor->direction);
                pod(e.anchor->length);
            }
            pod(e.lockedBase);
            for (const skel::LockedNode& n : e.locked) {
                pod(n.parent);
                pod(n.order);
                pod(n.radius);
                pod(n.offset);
                pod(n.orientation);
            }
            for (const skel::LockedLeaf& l : e.lockedLeaves) {
                pod(l.node);
                pod(l.size);
                pod(l.offset);
                pod(l.orientation);
            }
        }
    const bool flags[] = {options.useLod,
                          options.adapt,
                          options.neighbours,
                          options.buildMeshes,
                          scene.obstacles != nullptr,
                          options.windData};
    if (options.keepGrown) h = mixSeed(h, 0x6b67); // cached trees then carry their grown skeleton
    mix(flags, sizeof flags);
    return h;
}

} // namespace sylva::forest::build
