#include "engine/nodes/meshnodes.h"

#include <algorithm>
#include <chrono>

#include "engine/graph/graph.h"
#include "engine/mesh/leafplacement.h"
#include "engine/mesh/treemesh.h"
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

// tube_mesh's parameters: the one statement of each one's default and range, read through
// ParamReader by treeMeshSettingsFromParams and shown by the parameter panel and docs.
const std::vector<graph::ParamSpec>& tubeMeshParams() {
    static const std::vector<graph::ParamSpec> params = [] {
        using namespace sylva::nodes;
        std::vector<graph::ParamSpec> params;
        group(
            params, "Tubes",
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
             number("root_flare", 1.35, 1, 4, "",
                    "A root's tube at the ground is this many times its radius, widening "
                    "smoothly over flare_height; 1: no flare"),
             number("flare_height", 1.0, 0, 100, "m",
                    "Height of the root flare, at most 8 root radii"),
             number("ground_depth", 0.1, 0, 10, "m",
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
             number("bark_texture_width", 0, 0, 10, "m",
                    "Width of the bark texture in metres: a thick axis gets it as many times "
                    "around as its girth holds, so bark features keep their size from trunk to "
                    "twig; 0: once around each axis"),
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
        group(params, "Leaves",
              {boolean("leaves", true, "Draw the skeleton's leaves as cards"),
               number("leaf_scale", 1.0, 1e-6, 100, "", "Multiplies every leaf card's length"),
               number("leaf_aspect", 0.5, 1e-6, 4, "", "Leaf card width / length"),
               integer("leaf_cluster_size", 0, 0, 64,
                       "Leaves one card carries on average (needs leaf_cluster_texture_file); "
                       "0: one card a leaf"),
               boolean("leaf_cluster_crossed", false,
                       "Each cluster card crossed by a second at right angles along its centre "
                       "line (tufts of needles round their shoot)")});
        group(params, "Level of detail",
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
               number("lod_screen_height", 1080.0, 1, 1e5, "px",
                      "Viewport height the pixels refer to"),
               number("lod_fov", 60.0, 1, 179, "°", "Vertical field of view")});
        group(
            params, "Textures",
            {other("bark_texture_file", ParamKind::File,
                   "Bark PNG (tiles; u around, v along); none: Sylva's bark.png"),
             other("leaf_texture_file", ParamKind::File,
                   "Leaf card RGBA PNG, stem at the bottom; none: Sylva's leaf.png"),
             other("leaf_cluster_texture_file", ParamKind::File,
                   "Leaf cluster atlas RGBA PNG: 4 x 2 tiles, seven sprays and the single leaf")});
        group(
            params, "Season",
            {choice("season", "summer", {"spring", "summer", "autumn", "winter"},
                    "Time of year (a project's or tree's season replaces it)"),
             boolean(
                 "deciduous", false,
                 "Sheds its leaves: fewer and smaller in spring, fewer in autumn, none in winter; "
                 "off: the same all year (conifers, evergreens)"),
             vector("autumn_color", vec(0.6, 0.4, 0.1), 0, 1, "",
                    "Autumn leaf colour (sRGB 0..1): make_textures.py draws the species' "
                    "autumn leaves from it")});
        group(
            params, "Leaf colour",
            {number("leaf_hue_variation", 0.0, 0, 90, "°",
                    "Leaf cards' hue turned by up to ± this in spring and summer (an evergreen "
                    "all year); 0 with the two below: every card alike"),
             number("leaf_saturation_variation", 0.0, 0, 1, "",
                    "Leaf cards' saturation scaled by up to ± this fraction"),
             number("leaf_brightness_variation", 0.0, 0, 1, "",
                    "The darkest leaf card's loss of brightness (most keep near the texture's)"),
             number("leaf_autumn_hue_variation", 0.0, 0, 90, "°",
                    "The same three in autumn for a deciduous species, around autumn_color"),
             number("leaf_autumn_saturation_variation", 0.0, 0, 1, "",
                    "Autumn: saturation ± fraction"),
             number("leaf_autumn_brightness_variation", 0.0, 0, 1, "",
                    "Autumn: the darkest card's loss of brightness"),
             number("leaf_color_patch", 1.5, 0, 1e3, "m",
                    "Most of the variation follows patches about this large over the crown, the "
                    "rest is each card's own; 0: each card on its own"),
             number("leaf_light_shading", 0.0, 0, 1, "",
                    "The most shaded leaf card's loss of brightness by the growth's light records "
                    "(outer, sun-facing cards lighter, inner darker); 0: not shown")});
        return params;
    }();
    return params;
}

const std::vector<graph::ParamSpec>& leavesParams() {
    static const std::vector<graph::ParamSpec> params = [] {
        using namespace sylva::nodes;
        std::vector<graph::ParamSpec> params;
        group(params, "Where",
              {choice("placement", "branches_and_tips",
                      {"branches_and_tips", "branches", "tips", "grammar"},
                      "Along young branches, at tips, both, or only the grammar's J leaves"),
               boolean("keep_grammar_leaves", false, "Keep the grammar's J leaves as well"),
               number("density", 8.0, 0, 1000, "1/m", "Leaves per metre of young branch"),
               integer("tip_count", 3, 0, 32, "Leaves per branch tip"),
               number("max_branch_radius", 0.02, 0, 1e3, "m", "Thicker branches carry no leaves")});
        group(params, "Arrangement",
              {choice("phyllotaxis", "spiral", {"spiral", "alternate", "opposite", "whorled"},
                      "How leaves are arranged around the branch"),
               integer("whorl_count", 3, 2, 12, "Leaves per whorl (phyllotaxis: whorled)"),
               number("petiole_angle", 50.0, 0, 90, "°", "Angle between branch and leaf")});
        group(params, "Size and orientation",
              {number("size", 0.12, 1e-6, 100, "m", "Leaf card length"),
               number("size_variation", 0.2, 0, 1, "", "Size × (1 ± variation)"),
               number("leaf_aspect", 0.5, 1e-6, 4, "", "Card width / length"),
               number("normal_weight", 0.4, 0, 1e3, "", "Card faces away from the branch"),
               number("up_weight", 0.4, 0, 1e3, "", "Card faces up"),
               number("light_weight", 0.2, 0, 1e3, "", "Card faces the light"),
               vector("light_direction", vec(0.3, 1.0, 0.2), -1e9, 1e9, "",
                      "Towards the light (normalised)")});
        return params;
    }();
    return params;
}

int whole(const nodes::ParamReader& r, const char* key) {
    return static_cast<int>(r.integer(key));
}

LodSettings lodFromParams(const nodes::ParamReader& r) {
    LodSettings lod;
    if (const Value* bands = r.given("lod_bands")) {
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
    lod.minTwigPixels = r.number("lod_min_twig_pixels");
    lod.simplifyPixels = r.number("lod_simplify_pixels");
    lod.leafClusterPixels = r.number("lod_leaf_cluster_pixels");
    lod.ribbonPixels = r.number("lod_ribbon_pixels");
    lod.leafyTwigPixels = r.number("lod_leafy_twig_pixels");
    lod.screenHeightPx = r.number("lod_screen_height");
    lod.fovYDegrees = r.number("lod_fov");
    validateLod(lod);
    return lod;
}

// A season's leaf colour spread (mesh/leaftint.h): `<prefix>hue_variation` (degrees),
// `<prefix>saturation_variation`, `<prefix>brightness_variation`; unset: none.
LeafColorVariation colorVariation(const nodes::ParamReader& r, const std::string& prefix) {
    LeafColorVariation v;
    v.hue = r.number(prefix + "hue_variation");
    v.saturation = r.number(prefix + "saturation_variation");
    v.brightness = r.number(prefix + "brightness_variation");
    return v;
}

} // namespace

TreeMeshSettings treeMeshSettingsFromParams(const Value& p, std::uint64_t seed,
                                            const std::filesystem::path& baseDir) {
    // Every default and range is tube_mesh's table's (tubeMeshParams), stated once.
    const nodes::ParamReader r(tubeMeshParams(), p);
    TreeMeshSettings s;
    s.tubes.resolution = whole(r, "resolution");
    s.tubes.caps = r.boolean("caps");
    s.tubes.thickness =
        r.text("thickness") == "skeleton" ? ThicknessMode::Skeleton : ThicknessMode::Branching;
    s.tubes.initialThickness = r.number("initial_thickness");
    s.tubes.thicknessMultiplier = r.number("thickness_multiplier");
    s.tubes.radiusScale = r.number("radius_scale");
    s.tubes.twigBelowRadius = r.number("twig_radius");
    s.tubes.twigResolution = whole(r, "twig_resolution");
    s.tubes.minBranchRadius = r.number("bare_twig_radius");
    s.tubes.rootFlare = r.number("root_flare");
    s.tubes.flareHeight = r.number("flare_height");
    s.tubes.groundDepth = r.number("ground_depth");
    s.tubes.buttressLobes = whole(r, "buttress_lobes");
    s.tubes.buttressDepth = r.number("buttress_depth");
    s.tubes.barkRelief = r.number("bark_relief");
    s.tubes.barkPattern = parseBarkPattern(r.text("bark_relief_pattern"));
    s.tubes.barkReliefScale = r.number("bark_relief_scale");
    s.tubes.barkReliefRadius = r.number("bark_relief_radius");
    s.tubes.barkReliefSides = whole(r, "bark_relief_sides");
    s.tubes.barkTextureWidth = r.number("bark_texture_width");
    s.tubes.barkColorLow = r.vector("bark_color_low");
    s.tubes.barkColorHigh = r.vector("bark_color_high");
    if (const Value* h = r.given("bark_color_heights")) {
        const Value::Array& a = h->toArray("bark_color_heights");
        if (a.size() != 2) throw InvalidInput("bark_color_heights must be [bottom, top]");
        s.tubes.barkColorBottom = a[0].toNumber("bark_color_heights");
        s.tubes.barkColorTop = a[1].toNumber("bark_color_heights");
        requireRange("bark_color_heights bottom", s.tubes.barkColorBottom, 0.0, 1e3);
        requireRange("bark_color_heights top", s.tubes.barkColorTop, s.tubes.barkColorBottom, 1e3);
    }
    s.tubes.windAttributes = r.boolean("wind_attributes");
    s.tubes.nodeIds = r.boolean("node_ids") || r.boolean("wind_data");
    s.leaves = r.boolean("leaves");
    s.leafCards.aspect = r.number("leaf_aspect");
    s.leafCards.sizeScale = r.number("leaf_scale");
    const double distance = r.number("lod_distance");
    s.lod = lodFromParams(r);
    // The default bands (8, 5 and 3 sides) are never finer than the species' own tubes: a
    // species of 6 sides had a third more triangles at the camera LOD near the camera than
    // without it. Bands given explicitly are kept as they are.
    if (!r.given("lod_bands"))
        for (LodBand& band : s.lod.bands)
            band.resolution = std::min(band.resolution, s.tubes.resolution);
    s.useLod = distance >= 0.0;
    s.cameraDistance = std::max(distance, 0.0);
    s.seed = seed;
    auto texture = [&](const char* key) -> std::string {
        const Value* v = r.given(key);
        if (!v) return {};
        const std::filesystem::path file(v->toString(key));
        if (file.empty() || file.is_absolute() || baseDir.empty()) return file.string();
        return (baseDir / file).lexically_normal().string();
    };
    s.barkTexture = texture("bark_texture_file");
    s.leafTexture = texture("leaf_texture_file");
    s.season = parseSeason(r.text("season"));
    s.deciduous = r.boolean("deciduous");
    // Read by make_textures.py (the autumn leaf texture) and by the autumn leaf tint.
    s.leafTint.autumnColor = r.vector("autumn_color");
    s.leafTint.summer = colorVariation(r, "leaf_");
    s.leafTint.autumn = colorVariation(r, "leaf_autumn_");
    s.leafTint.patchSize = r.number("leaf_color_patch");
    s.leafTint.lightShading = r.number("leaf_light_shading");
    s.leafClusterSize = whole(r, "leaf_cluster_size");
    s.leafClusterTexture = texture("leaf_cluster_texture_file");
    s.leafClusterCrossed = r.boolean("leaf_cluster_crossed");
    if (s.leafClusterSize > 1 && s.leafClusterTexture.empty())
        throw InvalidInput("leaf_cluster_size " + std::to_string(s.leafClusterSize) +
                           " needs leaf_cluster_texture_file (the species' cluster atlas)");
    return s;
}

namespace {

/// treeMeshSettingsFromParams(params, seed, baseDir), read again only when the parameters or
/// the folder differ from the last tube_mesh this thread evaluated: a species grown with one seed
/// after another reads the same parameters every time (~15 us for the English oak: dozens of
/// checked reads and the texture paths normalised). The seed is the only input that changes.
TreeMeshSettings settingsFor(const Value& params, std::uint64_t seed,
                             const std::filesystem::path& baseDir) {
    struct Memo {
        bool valid = false;
        Value params;
        std::filesystem::path baseDir;
        TreeMeshSettings settings;
    };
    thread_local Memo memo;
    if (!memo.valid || memo.baseDir != baseDir || !(memo.params == params)) {
        memo.valid = false;
        memo.settings = treeMeshSettingsFromParams(params, 0, baseDir); // throws: stays invalid
        memo.params = params;
        memo.baseDir = baseDir;
        memo.valid = true;
    }
    TreeMeshSettings s = memo.settings;
    s.seed = seed; // what treeMeshSettingsFromParams does with its seed, and all it does
    return s;
}

NodeOutput evaluateTubeMesh(const NodeContext& ctx) {
    const skel::Skeleton& skeleton = inputSkeleton(ctx);
    TreeMeshSettings settings;
    try {
        settings = settingsFor(ctx.params, mixSeed(ctx.seed, salt::kTreeMesh), ctx.baseDir);
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
    return Phyllotaxis::Spiral; // the table's choices, checked by ParamReader::text
}

NodeOutput evaluateLeaves(const NodeContext& ctx) {
    const skel::Skeleton& skeleton = inputSkeleton(ctx);
    // Every default and range is the leaves node's table's (leavesParams), stated once.
    const nodes::ParamReader r(leavesParams(), ctx.params);
    LeafPlacement placement;
    std::vector<skel::Leaf> leaves;
    const auto t0 = std::chrono::steady_clock::now();
    try {
        const std::string where = r.text("placement");
        if (where == "branches") {
            placement.atTips = false;
        } else if (where == "tips") {
            placement.alongBranches = false;
        } else if (where == "grammar") {
            placement.alongBranches = placement.atTips = false;
            placement.keepGrammarLeaves = true;
        }
        if (r.given("keep_grammar_leaves"))
            placement.keepGrammarLeaves = r.boolean("keep_grammar_leaves");
        placement.phyllotaxis = phyllotaxisFrom(r.text("phyllotaxis"));
        placement.whorlCount = whole(r, "whorl_count");
        placement.size = r.number("size");
        placement.sizeVariation = r.number("size_variation");
        placement.density = r.number("density");
        placement.tipCount = whole(r, "tip_count");
        placement.maxBranchRadius = r.number("max_branch_radius");
        placement.petioleAngle = r.number("petiole_angle");
        placement.normalWeight = r.number("normal_weight");
        placement.upWeight = r.number("up_weight");
        placement.lightWeight = r.number("light_weight");
        placement.lightDirection = r.vector("light_direction");
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
        cards.aspect = r.number("leaf_aspect");
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
    tube.params = tubeMeshParams();
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
    leaves.params = leavesParams();
    registry.add(std::move(leaves));
}

} // namespace sylva::mesh
