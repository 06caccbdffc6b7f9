#include "engine/growth/selforganizingnode.h"

#include <chrono>
#include <memory>

#include "engine/util/error.h"

namespace sylva::growth {

const std::vector<std::string>& selfOrganizingParamNames() {
    static const std::vector<std::string> names = {"cycles",
                                                   "environment",
                                                   "allocation",
                                                   "alpha",
                                                   "lambda",
                                                   "w_min",
                                                   "w_max",
                                                   "kappa",
                                                   "perception_angle",
                                                   "perception_radius",
                                                   "occupancy_radius",
                                                   "markers",
                                                   "crown_radius",
                                                   "crown_base",
                                                   "crown_top",
                                                   "shadow_a",
                                                   "shadow_b",
                                                   "shadow_depth",
                                                   "full_exposure",
                                                   "voxel_size",
                                                   "internode_length",
                                                   "branch_angle",
                                                   "divergence_angle",
                                                   "optimal_weight",
                                                   "tropism_weight",
                                                   "direction_noise",
                                                   "max_shoot_length",
                                                   "shedding_threshold",
                                                   "tip_radius",
                                                   "pipe_exponent",
                                                   "leaf_size",
                                                   "leaf_age",
                                                   "max_internodes",
                                                   "lateral_tropism_weight",
                                                   "seed"};
    return names;
}

namespace {

int integerIn(const graph::Value& v, const char* key, int fallback, int lo, int hi) {
    const double d = v.number(key, fallback);
    requireRange(key, d, lo, hi);
    if (d != static_cast<double>(static_cast<std::int64_t>(d)))
        throw InvalidInput(std::string(key) + " must be a whole number, got " + std::to_string(d));
    return static_cast<int>(d);
}

} // namespace

SelfOrganizingParams selfOrganizingParamsFrom(const graph::Value& v) {
    SelfOrganizingParams p;
    p.cycles = integerIn(v, "cycles", p.cycles, 1, 200);
    const std::string env = v.string("environment", "shadow_propagation");
    if (env == "shadow_propagation")
        p.environment = SoEnvironment::ShadowPropagation;
    else if (env == "space_colonization")
        p.environment = SoEnvironment::SpaceColonization;
    else
        throw InvalidInput("environment must be \"space_colonization\" or "
                           "\"shadow_propagation\", got \"" +
                           env + "\"");
    const std::string alloc = v.string("allocation", "borchert_honda");
    if (alloc == "borchert_honda")
        p.allocation = SoAllocation::BorchertHonda;
    else if (alloc == "priority")
        p.allocation = SoAllocation::Priority;
    else
        throw InvalidInput("allocation must be \"borchert_honda\" or \"priority\", got \"" + alloc +
                           "\"");
    p.alpha = v.number("alpha", p.alpha);
    p.lambda = v.number("lambda", p.lambda);
    p.wMin = v.number("w_min", p.wMin);
    p.wMax = v.number("w_max", p.wMax);
    p.kappa = v.number("kappa", p.kappa);
    p.perceptionAngle = v.number("perception_angle", p.perceptionAngle);
    p.perceptionRadius = v.number("perception_radius", p.perceptionRadius);
    p.occupancyRadius = v.number("occupancy_radius", p.occupancyRadius);
    p.markers = integerIn(v, "markers", p.markers, 0, 5'000'000);
    p.crownRadius = v.number("crown_radius", p.crownRadius);
    p.crownBase = v.number("crown_base", p.crownBase);
    p.crownTop = v.number("crown_top", p.crownTop);
    p.shadowA = v.number("shadow_a", p.shadowA);
    p.shadowB = v.number("shadow_b", p.shadowB);
    p.shadowDepth = integerIn(v, "shadow_depth", p.shadowDepth, 0, 32);
    p.fullExposure = v.number("full_exposure", p.fullExposure);
    p.voxelSize = v.number("voxel_size", p.voxelSize);
    p.internodeLength = v.number("internode_length", p.internodeLength);
    p.branchAngle = v.number("branch_angle", p.branchAngle);
    p.divergenceAngle = v.number("divergence_angle", p.divergenceAngle);
    p.optimalWeight = v.number("optimal_weight", p.optimalWeight);
    p.tropismWeight = v.number("tropism_weight", p.tropismWeight);
    p.lateralTropismWeight = v.number("lateral_tropism_weight", p.lateralTropismWeight);
    p.directionNoise = v.number("direction_noise", p.directionNoise);
    p.maxShootLength = integerIn(v, "max_shoot_length", p.maxShootLength, 1, 1000);
    p.sheddingThreshold = v.number("shedding_threshold", p.sheddingThreshold);
    p.tipRadius = v.number("tip_radius", p.tipRadius);
    p.pipeExponent = v.number("pipe_exponent", p.pipeExponent);
    p.leafSize = v.number("leaf_size", p.leafSize);
    p.leafAge = integerIn(v, "leaf_age", p.leafAge, 0, 200);
    const double maxInternodes = v.number("max_internodes", static_cast<double>(p.maxInternodes));
    requireRange("max_internodes", maxInternodes, 1, 50'000'000);
    p.maxInternodes = static_cast<std::int64_t>(maxInternodes);
    p.validate();
    return p;
}

void registerSelfOrganizingNode(graph::NodeRegistry& registry) {
    graph::NodeType type;
    type.name = "self_organizing";
    type.minInputs = 0;
    type.maxInputs = 0;
    type.knownParams = selfOrganizingParamNames();
    type.evaluate = [](const graph::NodeContext& ctx) {
        SelfOrganizingParams params;
        std::uint64_t seed = 0;
        try {
            params = selfOrganizingParamsFrom(ctx.params);
            const double s = ctx.params.number("seed", 0.0);
            requireRange("seed", s, 0, 9007199254740992.0);
            seed = ctx.seedOverridden ? ctx.seed : static_cast<std::uint64_t>(s);
        } catch (const InvalidInput& e) {
            ctx.fail(e.what());
        }
        const auto start = std::chrono::steady_clock::now();
        SelfOrganizingResult r;
        try {
            r = growSelfOrganizingDetailed(params, seed, ctx.progress);
        } catch (const LimitExceeded& e) {
            throw LimitExceeded(ctx.sourceFile + (ctx.sourceFile.empty() ? "" : ": ") + "node '" +
                                ctx.node.id + "': " + e.what());
        }
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        graph::NodeOutput out;
        out.stats["internodes"] = static_cast<double>(r.internodes);
        out.stats["cycles"] = r.cycles;
        out.stats["shed"] = static_cast<double>(r.shed);
        out.stats["nodes"] = static_cast<double>(r.skeleton.size());
        out.stats["segments"] = static_cast<double>(r.skeleton.segmentCount());
        out.stats["leaves"] = static_cast<double>(r.skeleton.leaves.size());
        out.timingsMs["grow"] = ms;
        r.skeleton.light = std::move(r.light);
        r.skeleton.vigour = std::move(r.vigour);
        r.skeleton.age = std::move(r.age);
        r.skeleton.validate();
        out.skeleton = std::make_shared<const skel::Skeleton>(std::move(r.skeleton));
        return out;
    };
    registry.add(std::move(type));
}

} // namespace sylva::growth
