#include "engine/nodes/selforganizingnode.h"

#include <chrono>
#include <memory>

#include "engine/nodes/paramspecs.h"
#include "engine/util/error.h"

namespace sylva::growth {

namespace {

using namespace sylva::nodes;

/// Every parameter, in panel order: the one statement of its default and range, which the
/// reading below goes through (ParamReader).
const std::vector<ParamSpec>& selfOrganizingSpecs() {
    static const std::vector<ParamSpec> table = [] {
        std::vector<ParamSpec> specs;
        group(specs, "Growth",
              {integer("cycles", 14, 1, 200, "Growth cycles (years)"),
               integer("seed", 0, 0, kMaxSeed, "Seed of bud directions and markers"),
               number("internode_length", 0.1, 0.001, 10, "m", "Length of one metamer"),
               integer("max_shoot_length", 20, 1, 1000, "Most metamers one bud makes per cycle"),
               number("max_internodes", 1e6, 1, 5e7, "",
                      "Runaway guard: more internodes than this in one tree is an error")});
        group(specs, "Resource allocation",
              {choice("allocation", "borchert_honda", {"borchert_honda", "priority"},
                      "Borchert–Honda (λ) or the priority model (w_min, w_max, κ)"),
               number("alpha", 2.0, 0, 100, "", "α: vigour at the base, v_base = α·Q_base", true),
               number("lambda", 0.5, 0, 1, "", "λ: apical control; > 0.5 favours the main axis"),
               number("w_min", 0.06, 0, 10, "", "Priority model: smallest weight (≤ w_max)"),
               number("w_max", 1.0, 0, 10, "", "Priority model: largest weight", true),
               number("kappa", 0.5, 0, 1, "", "κ: fraction of buds over which the weight falls",
                      true)});
        group(
            specs, "Environment",
            {choice("environment", "shadow_propagation",
                    {"shadow_propagation", "space_colonization"},
                    "How buds find light and space: shadow voxels or markers"),
             number("shadow_a", 1.0, 0, 100, "", "a: shadow a bud casts into its own voxel", true),
             number("shadow_b", 2.0, 1, 100, "", "b: attenuation base, Δs = a·b^(−q)", true),
             integer("shadow_depth", 5, 0, 32, "q_max: voxels a shadow pyramid reaches down"),
             number("full_exposure", 1.0, 0, 100, "", "C: light of an unshaded bud", true),
             number("voxel_size", 1.0, 0.1, 100, "", "Shadow voxel edge, in internode lengths"),
             number("perception_angle", 90.0, 1, 360, "°", "θ: apex angle of a bud's cone"),
             number("perception_radius", 4.0, 0.5, 100, "",
                    "r: reach of a bud's cone, in internode lengths"),
             number("occupancy_radius", 2.0, 0.1, 100, "",
                    "ρ: markers this close to a bud die, in internode lengths (≤ r)"),
             integer("markers", 20000, 0, 5'000'000, "Markers in the crown envelope"),
             number("crown_radius", 3.0, 1e-3, 500, "m", "Half-width of the crown envelope"),
             number("crown_base", 1.0, 0, 500, "m", "Lowest point of the crown envelope"),
             number("crown_top", 7.0, 0, 1000, "m", "Highest point of the crown envelope (> base)",
                    true)});
        group(
            specs, "Shoot direction",
            {number("branch_angle", 45.0, 0, 180, "°", "Angle of a lateral bud from its axis"),
             number("divergence_angle", 137.5, 0, 360, "°", "Phyllotaxis roll between metamers"),
             number("optimal_weight", 0.2, 0, 10, "", "ξ: weight of the optimal growth direction"),
             number("tropism_weight", 0.05, -10, 10, "",
                    "η: tropism (+Y) of the trunk; < 0 droops"),
             number("lateral_tropism_weight", 0.05, -10, 10, "", "η of lateral branches"),
             number("direction_noise", 0.02, 0, 1, "", "Weight of a random unit vector")});
        group(specs, "Shedding, thickness, leaves",
              {number("shedding_threshold", 0.1, 0, 100, "",
                      "Shed lateral branches whose light per internode falls below"),
               number("tip_radius", 0.004, 0, 1, "m", "Radius of a shoot tip", true),
               number("pipe_exponent", 2.5, 1, 4, "", "Pipe model exponent"), taperParam(),
               junctionSlopeParam(),
               number("leaf_size", 0.08, 0, 10, "m", "Leaf card length; 0: no leaves"),
               integer("leaf_age", 2, 0, 200,
                       "Metamers younger than this many cycles carry a leaf")});
        return specs;
    }();
    return table;
}

} // namespace

const std::vector<std::string>& selfOrganizingParamNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const ParamSpec& p : selfOrganizingSpecs())
            n.push_back(p.name);
        return n;
    }();
    return names;
}

SelfOrganizingParams selfOrganizingParamsFrom(const sylva::Value& v) {
    const ParamReader read(selfOrganizingSpecs(), v);
    auto whole = [&read](const char* name) { return static_cast<int>(read.integer(name)); };
    SelfOrganizingParams p;
    p.cycles = whole("cycles");
    p.markers = whole("markers");
    p.shadowDepth = whole("shadow_depth");
    p.maxShootLength = whole("max_shoot_length");
    p.leafAge = whole("leaf_age");
    const std::string env = read.text("environment");
    if (env == "shadow_propagation")
        p.environment = SoEnvironment::ShadowPropagation;
    else if (env == "space_colonization")
        p.environment = SoEnvironment::SpaceColonization;
    else
        throw InvalidInput("environment must be \"space_colonization\" or "
                           "\"shadow_propagation\", got \"" +
                           env + "\"");
    const std::string alloc = read.text("allocation");
    if (alloc == "borchert_honda")
        p.allocation = SoAllocation::BorchertHonda;
    else if (alloc == "priority")
        p.allocation = SoAllocation::Priority;
    else
        throw InvalidInput("allocation must be \"borchert_honda\" or \"priority\", got \"" + alloc +
                           "\"");
    p.alpha = read.number("alpha");
    p.lambda = read.number("lambda");
    p.wMin = read.number("w_min");
    p.wMax = read.number("w_max");
    p.kappa = read.number("kappa");
    p.perceptionAngle = read.number("perception_angle");
    p.perceptionRadius = read.number("perception_radius");
    p.occupancyRadius = read.number("occupancy_radius");
    p.crownRadius = read.number("crown_radius");
    p.crownBase = read.number("crown_base");
    p.crownTop = read.number("crown_top");
    p.shadowA = read.number("shadow_a");
    p.shadowB = read.number("shadow_b");
    p.fullExposure = read.number("full_exposure");
    p.voxelSize = read.number("voxel_size");
    p.internodeLength = read.number("internode_length");
    p.branchAngle = read.number("branch_angle");
    p.divergenceAngle = read.number("divergence_angle");
    p.optimalWeight = read.number("optimal_weight");
    p.tropismWeight = read.number("tropism_weight");
    p.lateralTropismWeight = read.number("lateral_tropism_weight");
    p.directionNoise = read.number("direction_noise");
    p.sheddingThreshold = read.number("shedding_threshold");
    p.tipRadius = read.number("tip_radius");
    p.pipeExponent = read.number("pipe_exponent");
    p.taper = read.number("taper");
    p.junctionSlope = read.number("junction_slope");
    p.leafSize = read.number("leaf_size");
    p.maxInternodes = static_cast<std::int64_t>(read.number("max_internodes"));
    p.validate();
    return p;
}

void registerSelfOrganizingNode(graph::NodeRegistry& registry) {
    graph::NodeType type;
    type.name = "self_organizing";
    type.minInputs = 0;
    type.maxInputs = 0;
    type.doc = "Grows a tree by light and space over yearly cycles (Palubicki et al. 2009)";
    type.category = "Generator";
    type.role = graph::NodeRole::Generator;
    type.output = graph::PortKind::Skeleton;
    type.params = selfOrganizingSpecs();
    // Its trees of one scene grow together, one stand per environment kind (the forest's
    // stand stage): they compete for light and space.
    auto stand = std::make_shared<graph::StandGrowth>();
    stand->standOf = [](const sylva::Value& params) {
        return static_cast<int>(selfOrganizingParamsFrom(params).environment);
    };
    stand->grow = [](const std::vector<graph::StandMember>& members,
                     const std::vector<glm::vec3>& obstacleTriangles, Progress& progress) {
        std::vector<StandTree> trees(members.size());
        for (std::size_t i = 0; i < members.size(); ++i) {
            trees[i].params = selfOrganizingParamsFrom(*members[i].params);
            trees[i].position = members[i].position;
            trees[i].seed = members[i].seed;
        }
        return growStand(trees, obstacleTriangles, progress);
    };
    type.stand = std::move(stand);
    type.evaluate = [](const graph::NodeContext& ctx) {
        SelfOrganizingParams params;
        std::uint64_t seed = 0;
        try {
            params = selfOrganizingParamsFrom(ctx.params);
            const auto s = ParamReader(selfOrganizingSpecs(), ctx.params).integer("seed");
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
        out.stats["starved"] = static_cast<double>(r.starved);
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
