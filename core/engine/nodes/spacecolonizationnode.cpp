#include "engine/nodes/spacecolonizationnode.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <set>

#include "engine/environment/obstaclemesh.h"
#include "engine/graph/vectorparam.h"
#include "engine/growth/envelope.h"
#include "engine/growth/litattractors.h"
#include "engine/growth/nodelight.h"
#include "engine/growth/spacecolonization.h"
#include "engine/nodes/paramspecs.h"
#include "engine/skeleton/radii.h"
#include "engine/util/error.h"

namespace sylva::growth {

namespace {

using sylva::Value;

glm::vec3 vec3Param(const Value& obj, const std::string& key, const glm::vec3& fallback,
                    const std::string& what) {
    const Value* v = obj.find(key);
    return v == nullptr ? fallback : graph::vec3Of(*v, what);
}

void checkKeys(const Value& obj, const std::set<std::string>& allowed, const std::string& what) {
    for (const auto& [key, value] : obj.toObject(what)) {
        (void)value;
        if (allowed.count(key) == 0) {
            std::string list;
            for (const std::string& k : allowed)
                list += (list.empty() ? "" : ", ") + k;
            throw InvalidInput(what + ": unknown key '" + key + "' (allowed: " + list + ")");
        }
    }
}

float positive(const Value& obj, const std::string& key, double fallback, double hi,
               const std::string& what) {
    const double v = obj.number(key, fallback);
    if (!(v > 0.0) || !(v <= hi))
        throw InvalidInput(what + "." + key + " must be in (0, " + std::to_string(hi) + "], got " +
                           std::to_string(v));
    return static_cast<float>(v);
}

} // namespace

Envelope loadEnvelopeMesh(const std::filesystem::path& file, float scale, const glm::vec3& offset) {
    if (!(scale > 0.0f) || !std::isfinite(scale))
        throw InvalidInput("envelope scale must be a positive number, got " +
                           std::to_string(scale));
    if (!std::isfinite(offset.x) || !std::isfinite(offset.y) || !std::isfinite(offset.z))
        throw InvalidInput("envelope offset must be finite");
    env::MeshTransform transform;
    transform.scale = glm::vec3(scale);
    transform.translate = offset;
    env::ObstacleMesh mesh;
    try {
        mesh = env::loadObstacleMesh(file, transform);
    } catch (const IoError& e) {
        throw IoError(std::string("envelope: ") + e.what());
    } catch (const LimitExceeded& e) {
        throw LimitExceeded(std::string("envelope: ") + e.what());
    } catch (const InvalidInput& e) {
        throw InvalidInput(std::string("envelope: ") + e.what());
    }
    std::vector<std::uint32_t> indices;
    indices.reserve(3 * mesh.triangles.size());
    for (const glm::uvec3& t : mesh.triangles)
        indices.insert(indices.end(), {t.x, t.y, t.z});
    return Envelope::mesh(std::move(mesh.vertices), std::move(indices), file.string());
}

Envelope envelopeFromParams(const Value& env, const graph::NodeContext& ctx) {
    const std::string what = "envelope";
    env.toObject(what);
    const EnvelopeShape shape = envelopeShapeFromName(env.string("shape", "sphere"));
    const glm::vec3 center = vec3Param(env, "center", glm::vec3(0, 6, 0), what + ".center");
    switch (shape) {
    case EnvelopeShape::Sphere:
        checkKeys(env, {"shape", "center", "radius"}, what);
        return Envelope::sphere(center, positive(env, "radius", 4.5, 1000, what));
    case EnvelopeShape::Ellipsoid:
        checkKeys(env, {"shape", "center", "radii"}, what);
        return Envelope::ellipsoid(center,
                                   vec3Param(env, "radii", glm::vec3(4, 3, 4), what + ".radii"));
    case EnvelopeShape::Cone:
        checkKeys(env, {"shape", "center", "radius", "height", "inverted"}, what);
        return Envelope::cone(center, positive(env, "radius", 3, 1000, what),
                              positive(env, "height", 6, 1000, what),
                              env.boolean("inverted", false));
    case EnvelopeShape::Cylinder:
        checkKeys(env, {"shape", "center", "radius", "height"}, what);
        return Envelope::cylinder(center, positive(env, "radius", 2, 1000, what),
                                  positive(env, "height", 6, 1000, what));
    case EnvelopeShape::Hemisphere:
        checkKeys(env, {"shape", "center", "radius"}, what);
        return Envelope::hemisphere(center, positive(env, "radius", 4.5, 1000, what));
    case EnvelopeShape::Profile: {
        checkKeys(env, {"shape", "center", "radius", "height", "profile"}, what);
        const Value* prof = env.find("profile");
        if (prof == nullptr)
            throw InvalidInput("envelope.profile is required for shape 'profile': a list of "
                               "[t, radius] pairs or a Weber-Penn shape name");
        std::vector<glm::vec2> points;
        if (prof->isString()) {
            points = Envelope::weberPennProfile(prof->toString());
        } else {
            for (const Value& p : prof->toArray("envelope.profile")) {
                const Value::Array& pair = p.toArray("envelope.profile point");
                if (pair.size() != 2)
                    throw InvalidInput("envelope.profile points must be [t, radius] pairs");
                points.emplace_back(
                    static_cast<float>(pair[0].toNumber("envelope.profile t")),
                    static_cast<float>(pair[1].toNumber("envelope.profile radius")));
            }
        }
        return Envelope::profile(center, positive(env, "radius", 3, 1000, what),
                                 positive(env, "height", 6, 1000, what), std::move(points));
    }
    case EnvelopeShape::Mesh: {
        checkKeys(env, {"shape", "file", "scale", "offset", "center"}, what);
        const Value* file = env.find("file");
        if (file == nullptr) throw InvalidInput("envelope.file is required for shape 'mesh'");
        const glm::vec3 offset = vec3Param(env, "offset", glm::vec3(0.0f), what + ".offset");
        return loadEnvelopeMesh(ctx.resolve(file->toString("envelope.file")),
                                positive(env, "scale", 1, 1e6, what), offset);
    }
    }
    throw InvalidInput("unknown envelope shape");
}

void registerSpaceColonizationNode(graph::NodeRegistry& registry) {
    graph::NodeType type;
    type.name = "space_colonization";
    type.minInputs = 0;
    type.maxInputs = 1;
    type.doc = "Grows a tree toward attraction points in a crown envelope (Runions et al. 2007)";
    type.category = "Generator";
    type.role = graph::NodeRole::Generator;
    type.accepts = {graph::PortKind::Skeleton};
    type.output = graph::PortKind::Skeleton;
    using namespace sylva::nodes;
    group(type.params, "Attraction points",
          {integer("attractors", 3000, 1, 2'000'000,
                   "N: attraction points sampled in the envelope (more: denser crown)"),
           other("envelope", ParamKind::Object,
                 "Crown envelope: {shape: sphere|ellipsoid|cone|cylinder|hemisphere|profile|mesh, "
                 "center, radius, ...}; default a sphere of 4.5 m at (0, 6, 0)"),
           integer("seed", 1, 0, kMaxSeed, "Seed of the points and of the random directions")});
    group(type.params, "Light",
          {integer("light_clusters", 0, 0, 1000,
                   "K: sunlit foliage clusters the points are kept in (0: the whole envelope)"),
           number("light_cluster_radius", 0.35, 0, 2, "",
                  "Cluster radius as a fraction of the envelope's mean half-extent", true),
           number("light_cluster_spread", 0.5, 0, 1, "",
                  "Spread of the cluster radii: radius x (1 +- spread/2)"),
           number("shaded_fraction", 0.0, 0, 0.99, "",
                  "Drop this fraction of the points, the most shaded by those above"),
           number("light_voxel_size", 0.6, 0, 100, "m", "Edge of a shadow voxel", true),
           integer("light_inner_clusters", 0, 0, 1000,
                   "Clusters in the shaded inside: foliage on the main limbs under the lit shell"),
           number("light_inner_radius", 0.7, 0, 2, "",
                  "Inner cluster radius as a fraction of the lit clusters' radius", true)});
    group(type.params, "Growth",
          {number("influence_distance", 3.0, 0, 1000, "m",
                  "d_i: a point attracts its closest node within this distance", true),
           number("kill_distance", 0.6, 0, 1000, "m",
                  "d_k: a point dies once a node is this close; D < d_k < d_i", true),
           number("segment_length", 0.2, 0, 100, "m", "D: length of every new segment", true),
           number("randomness", 0.147, 0, 1, "", "Weight of a random unit vector per step"),
           vector("tropism", vec(0, 0, 0), -1, 1, "",
                  "g: bias added to each direction (gravity: (0, -g, 0)); |g| <= 1"),
           integer("max_iterations", 1000, 1, 100000, "Growth steps at most")});
    group(type.params, "Trunk and thickness",
          {number("trunk_height", 2.0, 0, 1000, "m", "Straight trunk before colonizing"),
           number("clear_trunk", 0.0, 0, 1000, "m",
                  "A bare bole: no shoot grows from the trunk or the input skeleton, and no "
                  "attraction point stays, lower than this above its base; 0: off"),
           vector("root", vec(0, 0, 0), -1e6, 1e6, "m", "Trunk base (without an input skeleton)"),
           number("pipe_exponent", 2.41, 1, 4, "",
                  "Pipe model exponent: r^e = sum of the children's r^e"),
           number("tip_radius", 0.01, 0, 10, "m", "Radius of branch tips", true), taperParam(),
           junctionSlopeParam()});
    type.evaluate = [specs = type.params](const graph::NodeContext& ctx) -> graph::NodeOutput {
        using Clock = std::chrono::steady_clock;
        const ParamReader read(specs, ctx.params);
        const Value& p = ctx.params;
        ColonizationParams cp;
        std::int64_t count = 0;
        std::uint64_t seed = 0;
        Envelope envelope = Envelope::sphere(glm::vec3(0, 6, 0), 4.5f);
        LightParams light;
        skel::RadiusShaping shaping;
        try {
            count = read.integer("attractors");
            cp.influenceDistance = static_cast<float>(read.number("influence_distance"));
            cp.killDistance = static_cast<float>(read.number("kill_distance"));
            cp.segmentLength = static_cast<float>(read.number("segment_length"));
            cp.randomness = static_cast<float>(read.number("randomness"));
            cp.tropism = read.vector("tropism");
            cp.trunkHeight = static_cast<float>(read.number("trunk_height"));
            cp.root = read.vector("root");
            cp.maxIterations = static_cast<int>(read.integer("max_iterations"));
            cp.pipeExponent = static_cast<float>(read.number("pipe_exponent"));
            cp.tipRadius = static_cast<float>(read.number("tip_radius"));
            cp.clearTrunk = static_cast<float>(read.number("clear_trunk"));
            shaping.taper = static_cast<float>(read.number("taper"));
            shaping.junctionSlope = static_cast<float>(read.number("junction_slope"));
            skel::validate(shaping);
            const std::int64_t s = read.integer("seed");
            seed = ctx.seedOverridden ? ctx.seed : static_cast<std::uint64_t>(s);
            cp.seed = seed;
            validate(cp);
            light.clusters = static_cast<int>(read.integer("light_clusters"));
            light.clusterRadius = static_cast<float>(read.number("light_cluster_radius"));
            light.clusterSpread = static_cast<float>(read.number("light_cluster_spread"));
            light.shadedFraction = static_cast<float>(read.number("shaded_fraction"));
            light.voxelSize = static_cast<float>(read.number("light_voxel_size"));
            light.innerClusters = static_cast<int>(read.integer("light_inner_clusters"));
            light.innerRadius = static_cast<float>(read.number("light_inner_radius"));
            validate(light);
            const Value* env = p.find("envelope");
            if (env != nullptr) envelope = envelopeFromParams(*env, ctx);
        } catch (const InvalidInput& e) {
            ctx.fail(e.what());
        }

        const skel::Skeleton* initial = nullptr;
        if (!ctx.inputs.empty()) {
            if (ctx.inputs[0] == nullptr || !ctx.inputs[0]->skeleton)
                ctx.fail("the input node gives no skeleton to grow from");
            initial = ctx.inputs[0]->skeleton.get();
        }

        graph::NodeOutput out;
        if (!ctx.inputs.empty()) {
            out.stats = ctx.inputs[0]->stats;
            out.timingsMs = ctx.inputs[0]->timingsMs;
        }
        const auto t0 = Clock::now();
        std::vector<glm::vec3> points =
            litAttractors(envelope.sample(static_cast<std::size_t>(count), seed), light, seed);
        if (cp.clearTrunk > 0.0f) {
            // The crown starts above the clear trunk: points lower than it would only pull
            // limbs down into sprays hanging beside the bole.
            float base = cp.root.y;
            if (initial != nullptr && !initial->empty()) {
                base = std::numeric_limits<float>::max();
                for (const glm::vec3& q : initial->position)
                    base = std::min(base, q.y);
            }
            std::erase_if(points, [&](const glm::vec3& q) { return q.y < base + cp.clearTrunk; });
        }
        const auto t1 = Clock::now();
        ColonizationResult r =
            colonize(points, cp, initial, NeighbourSearch::Accelerated, ctx.progress);
        // Lit clusters leave gaps wider than d_i: a crown that stopped with clusters out of reach
        // keeps growing from what it has toward the points left, reaching farther each round
        // (a limb that crosses the gap to the light), at most kReachRounds times.
        constexpr int kReachRounds = 4;
        for (int round = 0;
             round < kReachRounds && light.clusters > 0 &&
             r.stopReason == StopReason::NothingInReach && r.killedCount < points.size();
             ++round) {
            std::vector<glm::vec3> left;
            for (std::size_t i = 0; i < points.size(); ++i)
                if (!r.killed[i]) left.push_back(points[i]);
            ColonizationParams farther = cp;
            farther.influenceDistance = cp.influenceDistance * static_cast<float>(2 << round);
            farther.trunkHeight = 0.0f;
            const std::size_t killedBefore = r.killedCount;
            const skel::Skeleton grown = std::move(r.skeleton);
            ColonizationResult next =
                colonize(left, farther, &grown, NeighbourSearch::Accelerated, ctx.progress);
            std::vector<std::uint8_t> killed = std::move(r.killed);
            std::size_t j = 0;
            for (std::size_t i = 0; i < points.size(); ++i)
                if (!killed[i]) killed[i] = next.killed[j++];
            next.killed = std::move(killed);
            next.killedCount += killedBefore;
            next.iterations += r.iterations;
            next.initialNodes = r.initialNodes;
            r = std::move(next);
        }
        skel::shapeRadii(r.skeleton, shaping);
        // The crown's own shade, for the leaves' tint and the editor's Colour by light.
        recordLight(r.skeleton, light.voxelSize);
        const auto t2 = Clock::now();

        auto ms = [](auto a, auto b) {
            return std::chrono::duration<double, std::milli>(b - a).count();
        };
        out.timingsMs["attractors"] += ms(t0, t1);
        out.timingsMs["grow"] += ms(t1, t2);
        out.stats["segments"] = static_cast<double>(r.skeleton.segmentCount());
        out.stats["nodes"] = static_cast<double>(r.skeleton.size());
        out.stats["attractors"] = static_cast<double>(points.size());
        out.stats["attractors_killed"] = static_cast<double>(r.killedCount);
        out.stats["attractors_left"] = static_cast<double>(points.size() - r.killedCount);
        out.stats["iterations"] = r.iterations;
        out.stats["stop_reason"] = static_cast<double>(static_cast<int>(r.stopReason));
        out.stats["zero_average_fixes"] = static_cast<double>(r.zeroAverageFixes);
        out.stats["oscillation_fixes"] = static_cast<double>(r.oscillationFixes);
        out.skeleton = std::make_shared<const skel::Skeleton>(std::move(r.skeleton));
        return out;
    };
    registry.add(std::move(type));
}

} // namespace sylva::growth
