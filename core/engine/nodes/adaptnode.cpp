#include "engine/nodes/adaptnode.h"

#include <chrono>
#include <map>
#include <mutex>
#include <string>
#include <system_error>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/graph/vectorparam.h"
#include "engine/nodes/paramspecs.h"
#include "engine/util/error.h"
#include "engine/util/fileversion.h"

namespace sylva::env {

namespace {

/// Every parameter, in panel order: the one statement of its default and range, which the
/// reading goes through (nodes::ParamReader).
const std::vector<graph::ParamSpec>& adaptSpecs() {
    using namespace sylva::nodes;
    static const std::vector<ParamSpec> table = [] {
        std::vector<ParamSpec> specs;
        group(
            specs, "Bending",
            {number("max_bend", 0.1, 0, 1.5707963267948966, "rad",
                    "Maximum bend: rotation at the root's first branch level (reference 000)"),
             number(
                 "bend_multiplier", 0.9, 0, 1, "",
                 "Bend multiplier per branching level; deeper branches bend less (reference 000)"),
             boolean("return_to_vertical", true,
                     "Let the trunk bend back upright above the obstacles it touched"),
             boolean("recheck_all", true,
                     "Re-check every branch after bending, not only colliders")});
        group(specs, "Pruning",
              {boolean("prune", true, "Hide branches that still collide after bending"),
               boolean("redistribute", true, "Give the pruned length back to the visible branches"),
               vector("light_direction", nullptr, -1e9, 1e9, "",
                      "Direction light travels; redistribution favours branches facing it")});
        group(specs, "Placement (a species on its own)",
              {other("obstacles", ParamKind::Object,
                     "Obstacle meshes [{file, translate, rotate, scale}] (a scene gives its own)"),
               vector("position", nullptr, -1e9, 1e9, "m", "Where the tree stands"),
               number("rotation", 0.0, -1e6, 1e6, "°", "Turn about +Y"),
               number("scale", 1.0, 1e-6, 1e6, "", "Uniform scale")});
        return specs;
    }();
    return table;
}

using graph::NodeContext;
using graph::NodeOutput;
using sylva::Value;

// A vector parameter; a single number means the same value on every axis (uniform scale).
glm::vec3 vec3OrUniform(const Value& v, const std::string& what) {
    if (v.isNumber()) return glm::vec3(static_cast<float>(v.toNumber(what)));
    const glm::vec3 out = graph::vec3Of(v, what);
    for (int k = 0; k < 3; ++k)
        requireRange(what.c_str(), out[k], -1e9, 1e9);
    return out;
}

// The files' versions (one stat() each) and the transforms: another write of a file, or a save
// by rename, gives another key. A file rewritten in place within one tick of its clock with the
// same size would keep its key (see settled()). Unlike parsed grammars, a scene is kept whether
// or not its files are settled: keeping the scene is what keeps the trees adapted to it, and a
// mesh exported twice within a few milliseconds at the same size is not an artist's case.
std::string cacheKey(const std::vector<ObstacleSpec>& specs) {
    std::string key;
    for (const ObstacleSpec& s : specs) {
        std::error_code pathError;
        // One spelling per file (a project saved in another folder names it through another
        // relative path): the same scene, so the trees adapted to it are kept.
        std::filesystem::path file = std::filesystem::weakly_canonical(s.file, pathError);
        if (pathError) file = std::filesystem::absolute(s.file, pathError).lexically_normal();
        const FileVersion v = fileVersionOf(s.file).value_or(FileVersion{});
        key += file.string() + '|' + std::to_string(v.size) + '|' + std::to_string(v.seconds) +
               '.' + std::to_string(v.nanoseconds) + '|' + std::to_string(v.inode) + '|' +
               std::to_string(v.device) + '|';
        const MeshTransform& t = s.transform;
        for (const glm::vec3* v3 : {&t.translate, &t.rotateDeg, &t.scale})
            for (int k = 0; k < 3; ++k)
                key += std::to_string((*v3)[k]) + ',';
        key += '\n';
    }
    return key;
}

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

NodeOutput evaluateAdapt(const NodeContext& ctx) {
    if (ctx.inputs.empty() || !ctx.inputs[0] || !ctx.inputs[0]->skeleton)
        ctx.fail("needs an input node that produces a skeleton");
    const Value& p = ctx.params;
    const AdaptParams params = adaptParamsFromValue(p);
    std::vector<ObstacleSpec> specs;
    if (const Value* list = p.find("obstacles"); list && !list->isNull())
        for (const Value& entry : list->toArray("obstacles"))
            specs.push_back(obstacleSpecFromValue(entry, ctx.baseDir));

    glm::vec3 position(0.0f);
    if (const Value* v = p.find("position"); v && !v->isNull())
        position = vec3OrUniform(*v, "position");
    const nodes::ParamReader read(adaptSpecs(), p);
    const double rotation = read.number("rotation");
    const double scale = read.number("scale");
    glm::mat4 m = glm::translate(glm::mat4(1.0f), position);
    m = glm::rotate(m, glm::radians(static_cast<float>(rotation)), glm::vec3(0, 1, 0));
    m = glm::scale(m, glm::vec3(static_cast<float>(scale)));

    const auto t0 = std::chrono::steady_clock::now();
    std::shared_ptr<const ObstacleScene> scene = loadObstacleScene(specs);
    const double loadMs = msSince(t0);
    const auto t1 = std::chrono::steady_clock::now();
    AdaptResult r;
    if (ctx.tree && ctx.tree->obstacles && specs.empty()) {
        // Growing in a scene: the scene's obstacles, the tree's placement, its neighbours'
        // crowns and the scene's light replace the node's own obstacles and placement.
        AdaptParams sceneParams = params;
        if (!p.contains("light_direction")) sceneParams.lightDirection = ctx.tree->lightDirection;
        sceneParams.leafScale = ctx.tree->leafScale;
        sceneParams.leafAspect = ctx.tree->leafAspect;
        r = adaptTree(*ctx.inputs[0]->skeleton, *ctx.tree->obstacles, ctx.tree->transform,
                      sceneParams,
                      std::span<const CrownVolume>(ctx.tree->neighbours, ctx.tree->neighbourCount));
        scene.reset();
    } else {
        r = adaptTree(*ctx.inputs[0]->skeleton, *scene, m, params);
    }

    NodeOutput out;
    out.timingsMs["obstacles"] = loadMs;
    out.timingsMs["adapt"] = msSince(t1);
    const ObstacleScene& used = scene ? *scene : *ctx.tree->obstacles;
    out.stats["adapt_obstacle_triangles"] = static_cast<double>(used.triangleCount());
    out.stats["adapt_degenerate_triangles"] = static_cast<double>(used.degenerateCount());
    out.stats["adapt_colliding_before"] = static_cast<double>(r.stats.collidingBefore);
    out.stats["adapt_colliding_after"] = static_cast<double>(r.stats.collidingAfter);
    out.stats["adapt_hidden_nodes"] = static_cast<double>(r.stats.hiddenNodes);
    out.stats["adapt_pruned_length_m"] = r.stats.prunedLength;
    out.stats["adapt_redistributed_length_m"] = r.stats.redistributedLength;
    out.stats["adapt_lean_rad"] = r.stats.leanRadians;
    out.skeleton = std::make_shared<const skel::Skeleton>(std::move(r.skeleton));
    return out;
}

} // namespace

std::shared_ptr<const ObstacleScene> loadObstacleScene(const std::vector<ObstacleSpec>& specs,
                                                       bool useCache) {
    static std::mutex mutex;
    static std::map<std::string, std::shared_ptr<const ObstacleScene>> cache;
    std::string key;
    if (useCache) {
        key = cacheKey(specs);
        const std::lock_guard<std::mutex> lock(mutex);
        if (const auto it = cache.find(key); it != cache.end()) return it->second;
    }
    std::vector<ObstacleMesh> meshes;
    meshes.reserve(specs.size());
    for (const ObstacleSpec& s : specs)
        meshes.push_back(loadObstacleMesh(s.file, s.transform));
    auto scene = std::make_shared<const ObstacleScene>(std::move(meshes));
    if (useCache) {
        const std::lock_guard<std::mutex> lock(mutex);
        // A handful of scenes is all an editor session juggles; drop them all past that rather
        // than track recency.
        if (cache.size() >= 8) cache.clear();
        cache.emplace(key, scene);
    }
    return scene;
}

ObstacleSpec obstacleSpecFromValue(const Value& v, const std::filesystem::path& baseDir) {
    const Value::Object& o = v.toObject("obstacle entry");
    for (const auto& [key, value] : o) {
        (void)value;
        if (key != "file" && key != "translate" && key != "rotate" && key != "scale")
            throw InvalidInput("obstacle entry: unknown key '" + key +
                               "' (expected file, translate, rotate, scale)");
    }
    const Value* file = v.find("file");
    if (file == nullptr) throw InvalidInput("obstacle entry needs a 'file'");
    ObstacleSpec spec;
    const std::filesystem::path path(file->toString("obstacle file"));
    spec.file = path.is_absolute() ? path : baseDir / path;
    if (const Value* t = v.find("translate"))
        spec.transform.translate = vec3OrUniform(*t, "translate");
    if (const Value* r = v.find("rotate")) spec.transform.rotateDeg = vec3OrUniform(*r, "rotate");
    if (const Value* s = v.find("scale")) spec.transform.scale = vec3OrUniform(*s, "scale");
    return spec;
}

AdaptParams adaptParamsFromValue(const Value& p) {
    const nodes::ParamReader read(adaptSpecs(), p);
    AdaptParams a;
    a.maxBend = static_cast<float>(read.number("max_bend"));
    a.bendMultiplier = static_cast<float>(read.number("bend_multiplier"));
    a.prune = read.boolean("prune");
    a.redistribute = read.boolean("redistribute");
    a.recheckAll = read.boolean("recheck_all");
    a.returnToVertical = read.boolean("return_to_vertical");
    if (const Value* l = p.find("light_direction"); l && !l->isNull())
        a.lightDirection = vec3OrUniform(*l, "light_direction");
    return a;
}

void registerAdaptNode(graph::NodeRegistry& registry) {
    using namespace sylva::nodes;
    graph::NodeType type;
    type.name = "adapt";
    type.role = graph::NodeRole::Adapt;
    type.doc = "Bends branches away from obstacles, prunes what still collides and regrows it";
    type.category = "Environment";
    type.minInputs = type.maxInputs = 1;
    type.output = graph::PortKind::Skeleton;
    type.evaluate = evaluateAdapt;
    type.params = adaptSpecs();
    registry.add(std::move(type));
}

} // namespace sylva::env
