#include "engine/nodes/meshnodes.h"

#include <algorithm>
#include <chrono>

#include "engine/graph/graph.h"
#include "engine/mesh/leafplacement.h"
#include "engine/mesh/lod.h"
#include "engine/nodes/paramspecs.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"
#include "engine/wind/windelements.h"

namespace sylva::mesh {

namespace {

using graph::NodeContext;
using graph::NodeOutput;
using sylva::Value;

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

const skel::Skeleton& inputSkeleton(const NodeContext& ctx) {
    if (ctx.inputs.empty() || !ctx.inputs[0] || !ctx.inputs[0]->skeleton)
        ctx.fail("needs an input node that produces a skeleton");
    return *ctx.inputs[0]->skeleton;
}

// The root flare's defaults: the node's ParamSpec and the reading share them.
constexpr double kDefaultRootFlare = 1.35;
constexpr double kDefaultFlareHeight = 1.0;
constexpr double kDefaultGroundDepth = 0.1;

double ranged(const Value& p, const char* key, double fallback, double lo, double hi) {
    const double v = p.number(key, fallback);
    requireRange(key, v, lo, hi);
    return v;
}

int rangedInt(const Value& p, const char* key, int fallback, int lo, int hi) {
    const double v = p.number(key, fallback);
    requireRange(key, v, lo, hi);
    if (v != static_cast<double>(static_cast<int>(v)))
        throw InvalidInput(std::string(key) + " must be a whole number");
    return static_cast<int>(v);
}

LodSettings lodFromParams(const Value& p) {
    LodSettings lod;
    if (const Value* bands = p.find("lod_bands"); bands && !bands->isNull()) {
        lod.bands.clear();
        for (const Value& b : bands->toArray("lod_bands")) {
            LodBand band;
            if (b.isArray()) {
                const Value::Array& a = b.toArray();
                if (a.size() < 2 || a.size() > 3)
                    throw InvalidInput("lod_bands entries are [distance, resolution] or "
                                       "[distance, resolution, leaf_fraction]");
                band.distance = a[0].toNumber("lod band distance");
                band.resolution = static_cast<int>(a[1].toNumber("lod band resolution"));
                if (a.size() == 3) band.leafFraction = a[2].toNumber("lod band leaf fraction");
            } else {
                band.distance = b.number("distance", 0.0);
                band.resolution = static_cast<int>(b.integer("resolution", 8));
                band.leafFraction = b.number("leaf_fraction", 1.0);
            }
            lod.bands.push_back(band);
        }
    }
    lod.minTwigPixels = ranged(p, "lod_min_twig_pixels", lod.minTwigPixels, 0.0, 1e3);
    lod.simplifyPixels = ranged(p, "lod_simplify_pixels", lod.simplifyPixels, 0.0, 1e3);
    lod.leafClusterPixels = ranged(p, "lod_leaf_cluster_pixels", lod.leafClusterPixels, 0.0, 1e3);
    lod.ribbonPixels = ranged(p, "lod_ribbon_pixels", lod.ribbonPixels, 0.0, 1e3);
    lod.leafyTwigPixels = ranged(p, "lod_leafy_twig_pixels", lod.leafyTwigPixels, 0.0, 1e3);
    lod.screenHeightPx = ranged(p, "lod_screen_height", lod.screenHeightPx, 1.0, 1e5);
    lod.fovYDegrees = ranged(p, "lod_fov", lod.fovYDegrees, 1.0, 179.0);
    validateLod(lod);
    return lod;
}

// A season's leaf colour spread (mesh/leaftint.h): `<prefix>hue_variation` (degrees),
// `<prefix>saturation_variation`, `<prefix>brightness_variation`; unset: none.
LeafColorVariation colorVariation(const Value& p, const std::string& prefix) {
    LeafColorVariation v;
    v.hue = ranged(p, (prefix + "hue_variation").c_str(), 0.0, 0.0, 90.0);
    v.saturation = ranged(p, (prefix + "saturation_variation").c_str(), 0.0, 0.0, 1.0);
    v.brightness = ranged(p, (prefix + "brightness_variation").c_str(), 0.0, 0.0, 1.0);
    return v;
}

} // namespace

TreeMeshSettings treeMeshSettingsFromParams(const Value& p, std::uint64_t seed,
                                            const std::filesystem::path& baseDir) {
    TreeMeshSettings s;
    s.tubes.resolution = rangedInt(p, "resolution", 8, 3, 64);
    s.tubes.caps = p.boolean("caps", true);
    const std::string thickness = p.string("thickness", "skeleton");
    if (thickness == "skeleton")
        s.tubes.thickness = ThicknessMode::Skeleton;
    else if (thickness == "branching")
        s.tubes.thickness = ThicknessMode::Branching;
    else
        throw InvalidInput("thickness must be \"skeleton\" or \"branching\", got \"" + thickness +
                           "\"");
    s.tubes.initialThickness = ranged(p, "initial_thickness", 0.2, 0.0, 1e3);
    s.tubes.thicknessMultiplier = ranged(p, "thickness_multiplier", 0.8, 1e-6, 1.0);
    s.tubes.radiusScale = ranged(p, "radius_scale", 1.0, 0.0, 1e3);
    s.tubes.twigBelowRadius = ranged(p, "twig_radius", 0.0, 0.0, 1e3);
    s.tubes.twigResolution = rangedInt(p, "twig_resolution", 4, 3, 64);
    s.tubes.minBranchRadius = ranged(p, "bare_twig_radius", 0.0, 0.0, 1e3);
    s.tubes.rootFlare = ranged(p, "root_flare", kDefaultRootFlare, 1.0, 4.0);
    s.tubes.flareHeight = ranged(p, "flare_height", kDefaultFlareHeight, 0.0, 100.0);
    s.tubes.groundDepth = ranged(p, "ground_depth", kDefaultGroundDepth, 0.0, 10.0);
    s.tubes.buttressLobes = rangedInt(p, "buttress_lobes", 0, 0, 12);
    s.tubes.buttressDepth = ranged(p, "buttress_depth", s.tubes.buttressDepth, 0.0, 1.0);
    s.tubes.barkRelief = ranged(p, "bark_relief", 0.0, 0.0, 0.5);
    s.tubes.barkPattern = parseBarkPattern(p.string("bark_relief_pattern", "ridges"));
    s.tubes.barkReliefScale = ranged(p, "bark_relief_scale", s.tubes.barkReliefScale, 0.01, 2.0);
    s.tubes.barkReliefRadius =
        ranged(p, "bark_relief_radius", s.tubes.barkReliefRadius, 0.0, 100.0);
    s.tubes.barkReliefSides = rangedInt(p, "bark_relief_sides", s.tubes.barkReliefSides, 3, 128);
    auto color = [&](const char* key, glm::vec3 fallback) {
        const Value* v = p.find(key);
        if (!v || v->isNull()) return fallback;
        const Value::Array& a = v->toArray(key);
        if (a.size() != 3) throw InvalidInput(std::string(key) + " must be [r, g, b]");
        glm::vec3 c;
        for (int k = 0; k < 3; ++k) {
            const double x = a[static_cast<std::size_t>(k)].toNumber(key);
            requireRange(key, x, 0.0, 1.0);
            c[k] = static_cast<float>(x);
        }
        return c;
    };
    s.tubes.barkColorLow = color("bark_color_low", s.tubes.barkColorLow);
    s.tubes.barkColorHigh = color("bark_color_high", s.tubes.barkColorHigh);
    if (const Value* h = p.find("bark_color_heights"); h && !h->isNull()) {
        const Value::Array& a = h->toArray("bark_color_heights");
        if (a.size() != 2) throw InvalidInput("bark_color_heights must be [bottom, top]");
        s.tubes.barkColorBottom = a[0].toNumber("bark_color_heights");
        s.tubes.barkColorTop = a[1].toNumber("bark_color_heights");
        requireRange("bark_color_heights bottom", s.tubes.barkColorBottom, 0.0, 1e3);
        requireRange("bark_color_heights top", s.tubes.barkColorTop, s.tubes.barkColorBottom, 1e3);
    }
    s.tubes.windAttributes = p.boolean("wind_attributes", false);
    s.tubes.nodeIds = p.boolean("node_ids", false) || p.boolean("wind_data", false);
    s.leaves = p.boolean("leaves", true);
    s.leafCards.aspect = ranged(p, "leaf_aspect", 0.5, 1e-6, 4.0);
    s.leafCards.sizeScale = ranged(p, "leaf_scale", 1.0, 1e-6, 100.0);
    const double distance = ranged(p, "lod_distance", -1.0, -1.0, 1e7);
    s.lod = lodFromParams(p);
    // The default bands (8, 5 and 3 sides) are never finer than the species' own tubes: a
    // species of 6 sides had a third more triangles at the camera LOD near the camera than
    // without it. Bands given explicitly are kept as they are.
    if (const Value* bands = p.find("lod_bands"); !bands || bands->isNull())
        for (LodBand& band : s.lod.bands)
            band.resolution = std::min(band.resolution, s.tubes.resolution);
    s.useLod = distance >= 0.0;
    s.cameraDistance = std::max(distance, 0.0);
    s.seed = seed;
    auto texture = [&](const char* key) -> std::string {
        const Value* v = p.find(key);
        if (!v || v->isNull()) return {};
        const std::filesystem::path file(v->toString(key));
        if (file.empty() || file.is_absolute() || baseDir.empty()) return file.string();
        return (baseDir / file).lexically_normal().string();
    };
    s.barkTexture = texture("bark_texture_file");
    s.leafTexture = texture("leaf_texture_file");
    s.season = parseSeason(p.string("season", "summer"));
    s.deciduous = p.boolean("deciduous", false);
    if (const Value* autumn = p.find("autumn_color"); autumn && !autumn->isNull()) {
        // Read by make_textures.py (the autumn leaf texture) and by the autumn leaf tint.
        const Value::Array& a = autumn->toArray("autumn_color");
        if (a.size() != 3) throw InvalidInput("autumn_color must be [r, g, b]");
        for (int k = 0; k < 3; ++k) {
            const double c = a[static_cast<std::size_t>(k)].toNumber("autumn_color");
            requireRange("autumn_color", c, 0.0, 1.0);
            s.leafTint.autumnColor[k] = static_cast<float>(c);
        }
    }
    s.leafTint.summer = colorVariation(p, "leaf_");
    s.leafTint.autumn = colorVariation(p, "leaf_autumn_");
    s.leafTint.patchSize = ranged(p, "leaf_color_patch", s.leafTint.patchSize, 0.0, 1e3);
    s.leafTint.lightShading = ranged(p, "leaf_light_shading", 0.0, 0.0, 1.0);
    s.leafClusterSize = rangedInt(p, "leaf_cluster_size", 0, 0, 64);
    s.leafClusterTexture = texture("leaf_cluster_texture_file");
    s.leafClusterCrossed = p.boolean("leaf_cluster_crossed", false);
    if (s.leafClusterSize > 1 && s.leafClusterTexture.empty())
        throw InvalidInput("leaf_cluster_size " + std::to_string(s.leafClusterSize) +
                           " needs leaf_cluster_texture_file (the species' cluster atlas)");
    return s;
}

namespace {

NodeOutput evaluateTubeMesh(const NodeContext& ctx) {
    const skel::Skeleton& skeleton = inputSkeleton(ctx);
    TreeMeshSettings settings;
    try {
        settings =
            treeMeshSettingsFromParams(ctx.params, mixSeed(ctx.seed, salt::kTreeMesh), ctx.baseDir);
    } catch (const InvalidInput& e) {
        ctx.fail(e.what());
    }
    const auto t0 = std::chrono::steady_clock::now();
    auto mesh = std::make_shared<Mesh>(buildTreeMesh(skeleton, settings, ctx.progress));
    // wind_data: the node ids (set above) are the wind data; the 128 bytes a vertex of the
    // written form (Mesh::wind, wind::addWindData) are derived from them by the wind writer,
    // which keeps generation within 15 % of a tree without wind (docs/perf/wind.md).
    NodeOutput out;
    out.timingsMs["mesh"] = msSince(t0);
    out.skeleton = ctx.inputs[0]->skeleton;
    out.stats["vertices"] = static_cast<double>(mesh->vertexCount());
    out.stats["triangles"] = static_cast<double>(mesh->triangleCount());
    if (settings.useLod)
        out.stats["lod_band"] =
            static_cast<double>(selectLod(settings.lod, settings.cameraDistance).band);
    out.mesh = std::move(mesh);
    return out;
}

Phyllotaxis phyllotaxisFrom(const std::string& s) {
    if (s == "alternate") return Phyllotaxis::Alternate;
    if (s == "opposite") return Phyllotaxis::Opposite;
    if (s == "whorled") return Phyllotaxis::Whorled;
    if (s == "spiral") return Phyllotaxis::Spiral;
    throw InvalidInput("phyllotaxis must be \"alternate\", \"opposite\", \"whorled\" or "
                       "\"spiral\", got \"" +
                       s + "\"");
}

NodeOutput evaluateLeaves(const NodeContext& ctx) {
    const skel::Skeleton& skeleton = inputSkeleton(ctx);
    const Value& p = ctx.params;
    LeafPlacement placement;
    std::vector<skel::Leaf> leaves;
    const auto t0 = std::chrono::steady_clock::now();
    try {
        const std::string where = p.string("placement", "branches_and_tips");
        if (where == "branches") {
            placement.atTips = false;
        } else if (where == "tips") {
            placement.alongBranches = false;
        } else if (where == "grammar") {
            placement.alongBranches = placement.atTips = false;
            placement.keepGrammarLeaves = true;
        } else if (where != "branches_and_tips") {
            throw InvalidInput("placement must be \"branches\", \"tips\", \"branches_and_tips\" "
                               "or \"grammar\", got \"" +
                               where + "\"");
        }
        placement.keepGrammarLeaves = p.boolean("keep_grammar_leaves", placement.keepGrammarLeaves);
        placement.phyllotaxis = phyllotaxisFrom(p.string("phyllotaxis", "spiral"));
        placement.whorlCount = rangedInt(p, "whorl_count", 3, 2, 12);
        placement.size = ranged(p, "size", placement.size, 1e-6, 100.0);
        placement.sizeVariation = ranged(p, "size_variation", placement.sizeVariation, 0.0, 1.0);
        placement.density = ranged(p, "density", placement.density, 0.0, 1000.0);
        placement.tipCount = rangedInt(p, "tip_count", placement.tipCount, 0, 32);
        placement.maxBranchRadius =
            ranged(p, "max_branch_radius", placement.maxBranchRadius, 0.0, 1e3);
        placement.petioleAngle = ranged(p, "petiole_angle", placement.petioleAngle, 0.0, 90.0);
        placement.normalWeight = ranged(p, "normal_weight", placement.normalWeight, 0.0, 1e3);
        placement.upWeight = ranged(p, "up_weight", placement.upWeight, 0.0, 1e3);
        placement.lightWeight = ranged(p, "light_weight", placement.lightWeight, 0.0, 1e3);
        if (const Value* light = p.find("light_direction"); light && !light->isNull()) {
            const Value::Array& a = light->toArray("light_direction");
            if (a.size() != 3) throw InvalidInput("light_direction must be [x, y, z]");
            placement.lightDirection = {a[0].toNumber(), a[1].toNumber(), a[2].toNumber()};
        }
        placement.seed = mixSeed(ctx.seed, salt::kLeafPlacement);
        leaves = placeLeaves(skeleton, placement);
    } catch (const InvalidInput& e) {
        ctx.fail(e.what());
    }
    auto out_skeleton = std::make_shared<skel::Skeleton>(skeleton);
    out_skeleton->leaves = std::move(leaves);
    NodeOutput out;
    if (ctx.inputs[0]->mesh) {
        // Placed after tube_mesh: append the cards of the leaves this node made.
        auto m = std::make_shared<Mesh>(*ctx.inputs[0]->mesh);
        const std::size_t first = placement.keepGrammarLeaves ? skeleton.leaves.size() : 0;
        const std::vector<skel::Leaf> fresh(out_skeleton->leaves.begin() +
                                                static_cast<std::ptrdiff_t>(first),
                                            out_skeleton->leaves.end());
        LeafCardSettings cards;
        cards.aspect = ranged(p, "leaf_aspect", 0.5, 1e-6, 4.0);
        appendLeafCards(*m, fresh, cards, out_skeleton.get());
        // The wind data covers the new cards too (they hang on the same elements).
        if (!m->wind.empty()) wind::addWindData(*m, *out_skeleton);
        out.stats["vertices"] = static_cast<double>(m->vertexCount());
        out.stats["triangles"] = static_cast<double>(m->triangleCount());
        out.mesh = std::move(m);
    }
    out.timingsMs["leaves"] = msSince(t0);
    out.stats["leaves"] = static_cast<double>(out_skeleton->leaves.size());
    out.skeleton = std::move(out_skeleton);
    return out;
}

} // namespace

void registerMeshNodes(graph::NodeRegistry& registry) {
    using namespace sylva::nodes;
    graph::NodeType tube;
    tube.name = "tube_mesh";
    tube.role = graph::NodeRole::Mesher;
    tube.doc = "Meshes the branches as tubes and the leaves as cards";
    tube.category = "Geometry";
    tube.minInputs = tube.maxInputs = 1;
    tube.output = graph::PortKind::Mesh;
    tube.evaluate = evaluateTubeMesh;
    group(tube.params, "Tubes",
          {integer("resolution", 8, 3, 64, "Sides of each branch tube"),
           boolean("caps", true, "Close the tips of the tubes"),
           choice("thickness", "skeleton", {"skeleton", "branching"},
                  "Radii from the skeleton, or by branching (initial × multiplier per level)"),
           number("initial_thickness", 0.2, 0, 1e3, "m", "Trunk radius (thickness: branching)"),
           number("thickness_multiplier", 0.8, 1e-6, 1, "",
                  "Radius factor per branching level (thickness: branching)"),
           number("radius_scale", 1.0, 0, 1e3, "", "Multiplies every radius"),
           number("twig_radius", 0.0, 0, 1e3, "m",
                  "Axes thinner than this at their base get twig_resolution sides; 0: off"),
           integer("twig_resolution", 4, 3, 64, "Sides of the tubes thinner than twig_radius"),
           number("bare_twig_radius", 0.0, 0, 1e3, "m",
                  "Side shoots thinner than this at their base get no bark, their leaf cards "
                  "stay (twigs hidden in needle sprays); 0: off"),
           number("root_flare", kDefaultRootFlare, 1, 4, "",
                  "A root's tube at the ground is this many times its radius, widening "
                  "smoothly over flare_height; 1: no flare"),
           number("flare_height", kDefaultFlareHeight, 0, 100, "m",
                  "Height of the root flare, at most 8 root radii"),
           number("ground_depth", kDefaultGroundDepth, 0, 10, "m",
                  "The trunk's tube goes on this far below the ground (no tree stands on the "
                  "ground like a post)"),
           integer("buttress_lobes", 0, 0, 12,
                   "Buttresses: lobes of the trunk's cross-section near the ground, fading over "
                   "flare_height (the trunk gets at least 3 sides a lobe); 0: round"),
           number("buttress_depth", 0.35, 0, 1, "",
                  "How far the largest buttress stands out at the ground, as a fraction of the "
                  "radius"),
           number("bark_relief", 0.0, 0, 0.5, "",
                  "Bark as geometry at the nearest level: thick axes' surface stands out up to "
                  "this fraction of their radius in bark_relief_pattern; 0: none"),
           choice("bark_relief_pattern", "ridges", {"ridges", "plates"},
                  "Ridges split by furrows (oak, maple) or plates between cracks (pine)"),
           number("bark_relief_scale", 0.08, 0.01, 2, "m", "Width of a ridge or plate"),
           number("bark_relief_radius", 0.08, 0, 100, "m",
                  "Axes thinner than this at their base get no relief (it fades in up to 1.5 "
                  "times this)"),
           integer("bark_relief_sides", 64, 3, 128,
                   "Most ring vertices an axis with relief gets (4 a ridge or plate)"),
           vector("bark_color_low", vec(1, 1, 1), 0, 1, "",
                  "Bark colour factor up to the bottom of bark_color_heights"),
           vector("bark_color_high", vec(1, 1, 1), 0, 1, "",
                  "Bark colour factor from the top of bark_color_heights up"),
           other("bark_color_heights", ParamKind::Object,
                 "[bottom, top] metres above the ground over which the bark's colour blends "
                 "from bark_color_low to bark_color_high (vertex colours); unset: none"),
           boolean("wind_attributes", false, "Write wind weights (game engines' wind shaders)"),
           boolean("node_ids", false, "Write the skeleton node of each vertex"),
           boolean("wind_data", false,
                   "Keep what the wind model needs per vertex (its node; docs/wind.md)")});
    group(tube.params, "Leaves",
          {boolean("leaves", true, "Draw the skeleton's leaves as cards"),
           number("leaf_scale", 1.0, 1e-6, 100, "", "Multiplies every leaf card's length"),
           number("leaf_aspect", 0.5, 1e-6, 4, "", "Leaf card width / length"),
           integer("leaf_cluster_size", 0, 0, 64,
                   "Leaves one card carries on average (needs leaf_cluster_texture_file); "
                   "0: one card a leaf"),
           boolean("leaf_cluster_crossed", false,
                   "Each cluster card crossed by a second at right angles along its centre "
                   "line (tufts of needles round their shoot)")});
    group(tube.params, "Level of detail",
          {number("lod_distance", -1.0, -1, 1e7, "m",
                  "Camera distance the mesh is made for; -1: full detail"),
           other("lod_bands", ParamKind::Object,
                 "[[distance, resolution, leaf_fraction], ...] from near to far; unset: 8, 5 "
                 "and 3 sides from 0, 25 and 60 m, never more than resolution"),
           number("lod_min_twig_pixels", 1.0, 0, 1e3, "px",
                  "Drop a lateral subtree smaller than this on screen (leaves included)"),
           number("lod_leafy_twig_pixels", 4.0, 0, 1e3, "px",
                  "A leafy subtree smaller than this keeps its leaves, loses its bark"),
           number("lod_simplify_pixels", 0.5, 0, 1e3, "px", "Straighten axes within this"),
           number("lod_leaf_cluster_pixels", 2.0, 0, 1e3, "px",
                  "Merge leaves within this into one card of the same area; 0: off"),
           number("lod_ribbon_pixels", 2.0, 0, 1e3, "px",
                  "Axes thinner than this become camera-facing ribbons"),
           number("lod_screen_height", 1080.0, 1, 1e5, "px", "Viewport height the pixels refer to"),
           number("lod_fov", 60.0, 1, 179, "°", "Vertical field of view")});
    group(tube.params, "Textures",
          {other("bark_texture_file", ParamKind::File,
                 "Bark PNG (tiles; u around, v along); none: Sylva's bark.png"),
           other("leaf_texture_file", ParamKind::File,
                 "Leaf card RGBA PNG, stem at the bottom; none: Sylva's leaf.png"),
           other("leaf_cluster_texture_file", ParamKind::File,
                 "Leaf cluster atlas RGBA PNG: 4 x 2 tiles, seven sprays and the single leaf")});
    group(
        tube.params, "Season",
        {choice("season", "summer", {"spring", "summer", "autumn", "winter"},
                "Time of year (a project's or tree's season replaces it)"),
         boolean("deciduous", false,
                 "Sheds its leaves: fewer and smaller in spring, fewer in autumn, none in winter; "
                 "off: the same all year (conifers, evergreens)"),
         vector("autumn_color", vec(0.6, 0.4, 0.1), 0, 1, "",
                "Autumn leaf colour (sRGB 0..1): make_textures.py draws the species' "
                "autumn leaves from it")});
    group(
        tube.params, "Leaf colour",
        {number("leaf_hue_variation", 0.0, 0, 90, "°",
                "Leaf cards' hue turned by up to ± this in spring and summer (an evergreen "
                "all year); 0 with the two below: every card alike"),
         number("leaf_saturation_variation", 0.0, 0, 1, "",
                "Leaf cards' saturation scaled by up to ± this fraction"),
         number("leaf_brightness_variation", 0.0, 0, 1, "",
                "The darkest leaf card's loss of brightness (most keep near the texture's)"),
         number("leaf_autumn_hue_variation", 0.0, 0, 90, "°",
                "The same three in autumn for a deciduous species, around autumn_color"),
         number("leaf_autumn_saturation_variation", 0.0, 0, 1, "", "Autumn: saturation ± fraction"),
         number("leaf_autumn_brightness_variation", 0.0, 0, 1, "",
                "Autumn: the darkest card's loss of brightness"),
         number("leaf_color_patch", 1.5, 0, 1e3, "m",
                "Most of the variation follows patches about this large over the crown, the "
                "rest is each card's own; 0: each card on its own"),
         number("leaf_light_shading", 0.0, 0, 1, "",
                "The most shaded leaf card's loss of brightness by the growth's light records "
                "(outer, sun-facing cards lighter, inner darker); 0: not shown")});
    registry.add(std::move(tube));

    graph::NodeType leaves;
    leaves.name = "leaves";
    leaves.doc = "Places leaves along young branches and at tips, by phyllotaxis";
    leaves.category = "Geometry";
    leaves.minInputs = leaves.maxInputs = 1;
    leaves.accepts = {graph::PortKind::Skeleton, graph::PortKind::Mesh};
    leaves.outputFollowsInput = true;
    leaves.role = graph::NodeRole::Leaves;
    leaves.evaluate = evaluateLeaves;
    group(leaves.params, "Where",
          {choice("placement", "branches_and_tips",
                  {"branches_and_tips", "branches", "tips", "grammar"},
                  "Along young branches, at tips, both, or only the grammar's J leaves"),
           boolean("keep_grammar_leaves", false, "Keep the grammar's J leaves as well"),
           number("density", 8.0, 0, 1000, "1/m", "Leaves per metre of young branch"),
           integer("tip_count", 3, 0, 32, "Leaves per branch tip"),
           number("max_branch_radius", 0.02, 0, 1e3, "m", "Thicker branches carry no leaves")});
    group(leaves.params, "Arrangement",
          {choice("phyllotaxis", "spiral", {"spiral", "alternate", "opposite", "whorled"},
                  "How leaves are arranged around the branch"),
           integer("whorl_count", 3, 2, 12, "Leaves per whorl (phyllotaxis: whorled)"),
           number("petiole_angle", 50.0, 0, 90, "°", "Angle between branch and leaf")});
    group(leaves.params, "Size and orientation",
          {number("size", 0.12, 1e-6, 100, "m", "Leaf card length"),
           number("size_variation", 0.2, 0, 1, "", "Size × (1 ± variation)"),
           number("leaf_aspect", 0.5, 1e-6, 4, "", "Card width / length"),
           number("normal_weight", 0.4, 0, 1e3, "", "Card faces away from the branch"),
           number("up_weight", 0.4, 0, 1e3, "", "Card faces up"),
           number("light_weight", 0.2, 0, 1e3, "", "Card faces the light"),
           vector("light_direction", vec(0.3, 1.0, 0.2), -1e9, 1e9, "",
                  "Towards the light (normalised)")});
    registry.add(std::move(leaves));
}

} // namespace sylva::mesh
