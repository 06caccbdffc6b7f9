#include "engine/nodes/selforganizingnode.h"

#include <chrono>
#include <memory>

#include "engine/nodes/paramspecs.h"
#include "engine/util/error.h"

namespace sylva::growth {

namespace {

using P = SelfOrganizingParams;

// The numeric parameters, by name: one table gives both the node's known parameter names and
// the reading (ranges are checked by SelfOrganizingParams::validate()).
struct RealParam {
    const char* name;
    double P::*member;
};
constexpr RealParam kReals[] = {
    {"alpha", &P::alpha},
    {"lambda", &P::lambda},
    {"w_min", &P::wMin},
    {"w_max", &P::wMax},
    {"kappa", &P::kappa},
    {"perception_angle", &P::perceptionAngle},
    {"perception_radius", &P::perceptionRadius},
    {"occupancy_radius", &P::occupancyRadius},
    {"crown_radius", &P::crownRadius},
    {"crown_base", &P::crownBase},
    {"crown_top", &P::crownTop},
    {"shadow_a", &P::shadowA},
    {"shadow_b", &P::shadowB},
    {"full_exposure", &P::fullExposure},
    {"voxel_size", &P::voxelSize},
    {"internode_length", &P::internodeLength},
    {"branch_angle", &P::branchAngle},
    {"divergence_angle", &P::divergenceAngle},
    {"optimal_weight", &P::optimalWeight},
    {"tropism_weight", &P::tropismWeight},
    {"lateral_tropism_weight", &P::lateralTropismWeight},
    {"direction_noise", &P::directionNoise},
    {"shedding_threshold", &P::sheddingThreshold},
    {"tip_radius", &P::tipRadius},
    {"pipe_exponent", &P::pipeExponent},
    {"taper", &P::taper},
    {"junction_slope", &P::junctionSlope},
    {"leaf_size", &P::leafSize},
};

// Whole-number parameters with their range (checked here: a fraction is an error too).
struct IntegerParam {
    const char* name;
    int P::*member;
    int lo, hi;
};
constexpr IntegerParam kIntegers[] = {
    {"cycles", &P::cycles, 1, 200},           {"markers", &P::markers, 0, 5'000'000},
    {"shadow_depth", &P::shadowDepth, 0, 32}, {"max_shoot_length", &P::maxShootLength, 1, 1000},
    {"leaf_age", &P::leafAge, 0, 200},
};

int integerIn(const sylva::Value& v, const char* key, int fallback, int lo, int hi) {
    const double d = v.number(key, fallback);
    requireRange(key, d, lo, hi);
    if (d != static_cast<double>(static_cast<std::int64_t>(d)))
        throw InvalidInput(std::string(key) + " must be a whole number, got " + std::to_string(d));
    return static_cast<int>(d);
}

} // namespace

const std::vector<std::string>& selfOrganizingParamNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n = {"environment", "allocation", "max_internodes", "seed"};
        for (const IntegerParam& i : kIntegers)
            n.emplace_back(i.name);
        for (const RealParam& r : kReals)
            n.emplace_back(r.name);
        return n;
    }();
    return names;
}

SelfOrganizingParams selfOrganizingParamsFrom(const sylva::Value& v) {
    SelfOrganizingParams p;
    for (const IntegerParam& i : kIntegers)
        p.*i.member = integerIn(v, i.name, p.*i.member, i.lo, i.hi);
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
    for (const RealParam& r : kReals)
        p.*r.member = v.number(r.name, p.*r.member);
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
    type.doc = "Grows a tree by light and space over yearly cycles (Palubicki et al. 2009)";
    type.category = "Generator";
    type.role = graph::NodeRole::Generator;
    type.output = graph::PortKind::Skeleton;
    using namespace sylva::nodes;
    group(type.params, "Growth",
          {integer("cycles", 14, 1, 200, "Growth cycles (years)"),
           integer("seed", 0, 0, kMaxSeed, "Seed of bud directions and markers"),
           number("internode_length", 0.1, 0.001, 10, "m", "Length of one metamer"),
           integer("max_shoot_length", 20, 1, 1000, "Most metamers one bud makes per cycle"),
           number("max_internodes", 1e6, 1, 5e7, "",
                  "Runaway guard: more internodes than this in one tree is an error")});
    group(
        type.params, "Resource allocation",
        {choice("allocation", "borchert_honda", {"borchert_honda", "priority"},
                "Borchert–Honda (λ) or the priority model (w_min, w_max, κ)"),
         number("alpha", 2.0, 0, 100, "", "α: vigour at the base, v_base = α·Q_base", true),
         number("lambda", 0.5, 0, 1, "", "λ: apical control; > 0.5 favours the main axis"),
         number("w_min", 0.06, 0, 10, "", "Priority model: smallest weight (≤ w_max)"),
         number("w_max", 1.0, 0, 10, "", "Priority model: largest weight", true),
         number("kappa", 0.5, 0, 1, "", "κ: fraction of buds over which the weight falls", true)});
    group(type.params, "Environment",
          {choice("environment", "shadow_propagation", {"shadow_propagation", "space_colonization"},
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
    group(type.params, "Shoot direction",
          {number("branch_angle", 45.0, 0, 180, "°", "Angle of a lateral bud from its axis"),
           number("divergence_angle", 137.5, 0, 360, "°", "Phyllotaxis roll between metamers"),
           number("optimal_weight", 0.2, 0, 10, "", "ξ: weight of the optimal growth direction"),
           number("tropism_weight", 0.05, -10, 10, "", "η: tropism (+Y) of the trunk; < 0 droops"),
           number("lateral_tropism_weight", 0.05, -10, 10, "", "η of lateral branches"),
           number("direction_noise", 0.02, 0, 1, "", "Weight of a random unit vector")});
    group(type.params, "Shedding, thickness, leaves",
          {number("shedding_threshold", 0.1, 0, 100, "",
                  "Shed lateral branches whose light per internode falls below"),
           number("tip_radius", 0.004, 0, 1, "m", "Radius of a shoot tip", true),
           number("pipe_exponent", 2.5, 1, 4, "", "Pipe model exponent"), taperParam(),
           junctionSlopeParam(),
           number("leaf_size", 0.08, 0, 10, "m", "Leaf card length; 0: no leaves"),
           integer("leaf_age", 2, 0, 200, "Metamers younger than this many cycles carry a leaf")});
    // Kept in step with the reading table above (a test compares them).
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
