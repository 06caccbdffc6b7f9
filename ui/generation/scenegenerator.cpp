#include "ui/generation/scenegenerator.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include <QFile>
#include <QFileInfo>
#include <QStringList>

#include "document/filerefs.h"
#include "document/project.h"
#include "document/scenebuild.h"
#include "engine/forest/forestbuild.h"
#include "engine/mesh/mesh.h"
#include "engine/util/random.h"
#include "ui/generation/windvertexdata.h"

namespace sylva::ui {

namespace {

/// Smooth value noise in [0, 1] over the integer lattice (trilinear, smoothstep-weighted).
float valueNoise(const glm::vec3& p) {
    const glm::vec3 cell = glm::floor(p);
    const glm::vec3 f = p - cell;
    const glm::vec3 w = f * f * (3.0f - 2.0f * f);
    auto lattice = [&cell](int dx, int dy, int dz) {
        std::uint64_t h = mixSeed(mixSeed(std::uint64_t(std::int64_t(cell.x) + dx),
                                          std::uint64_t(std::int64_t(cell.y) + dy)),
                                  std::uint64_t(std::int64_t(cell.z) + dz));
        return float(h >> 40) / float(1u << 24);
    };
    float v = 0.0f;
    for (int k = 0; k < 8; ++k) {
        const int dx = k & 1, dy = (k >> 1) & 1, dz = (k >> 2) & 1;
        v += (dx ? w.x : 1.0f - w.x) * (dy ? w.y : 1.0f - w.y) * (dz ? w.z : 1.0f - w.z) *
             lattice(dx, dy, dz);
    }
    return v;
}

/// A stone's colour at \p p (linear multipliers of the obstacle colour): grey-brown blotches a
/// metre across, grain a decimetre across, and lichen patches, so a boulder or a wall reads as
/// rock rather than flat grey. Fixed in world space: the same everywhere, every frame.
glm::u8vec4 stoneColor(const glm::vec3& p) {
    const float blotch = valueNoise(p * 0.9f);
    const float grain = valueNoise(p * 7.0f + 31.0f);
    const float lichen = glm::smoothstep(0.62f, 0.78f, valueNoise(p * 0.5f + 97.0f));
    const float shade = 0.62f + 0.28f * blotch + 0.10f * grain;
    glm::vec3 c = shade * glm::vec3(1.0f, 0.95f, 0.88f);
    c = glm::mix(c, glm::vec3(0.80f, 0.86f, 0.55f) * shade, 0.55f * lichen);
    const glm::vec3 u8 = glm::clamp(c, 0.0f, 1.0f) * 255.0f + 0.5f;
    return {std::uint8_t(u8.x), std::uint8_t(u8.y), std::uint8_t(u8.z), 255};
}

/// The obstacle and terrain meshes merged, world space, flat-shaded; obstacles coloured as
/// stone (Mesh::colors, which the viewport multiplies with the material's colour).
mesh::Mesh surfaces(const env::ObstacleScene* obstacles, const env::ObstacleScene* ground) {
    mesh::Mesh out;
    for (auto [scene, material] : {std::pair{obstacles, "obstacle"}, std::pair{ground, "ground"}}) {
        if (!scene) continue;
        const auto first = static_cast<std::uint32_t>(out.indices.size());
        for (const env::ObstacleMesh& m : scene->meshes()) {
            // One colour a mesh vertex (a vertex is in about six triangles), then per corner.
            std::vector<glm::u8vec4> colour(m.vertices.size(), glm::u8vec4(255));
            if (scene == obstacles)
                for (std::size_t v = 0; v < m.vertices.size(); ++v)
                    colour[v] = stoneColor(m.vertices[v]);
            for (const glm::uvec3& t : m.triangles) {
                const glm::vec3 corners[3] = {m.vertices[t.x], m.vertices[t.y], m.vertices[t.z]};
                const glm::vec3 n =
                    glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
                for (int k = 0; k < 3; ++k) {
                    out.indices.push_back(static_cast<std::uint32_t>(out.positions.size()));
                    out.positions.push_back(corners[k]);
                    out.normals.push_back(n);
                    out.colors.push_back(colour[t[k]]);
                }
            }
        }
        const auto count = static_cast<std::uint32_t>(out.indices.size()) - first;
        if (count > 0) out.submeshes.push_back({material, first, count});
    }
    return out;
}

float meshHeight(const mesh::Mesh& m) {
    float lo = 0.0f, hi = 0.0f;
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        lo = i ? std::min(lo, m.positions[i].y) : m.positions[i].y;
        hi = i ? std::max(hi, m.positions[i].y) : m.positions[i].y;
    }
    return hi - lo;
}

/// The variants as the viewport draws them: their levels (the full mesh alone where the
/// forest made none) and heights.
std::vector<std::shared_ptr<const ViewVariant>>
viewVariants(const std::vector<forest::ForestVariant>& variants) {
    // The views made last time, by their full mesh: a regeneration that reuses a variant (the
    // forest's tree cache gives back the same meshes) gives back the same ViewVariant, so the
    // viewport keeps its buffers and impostor atlas (keyed by it) instead of baking them again
    // after every edit. Weak: a variant no generation holds any more is not kept alive.
    static std::mutex made;
    static std::map<const mesh::Mesh*, std::weak_ptr<const ViewVariant>> before;
    const std::lock_guard<std::mutex> lock(made);
    std::erase_if(before, [](const auto& kept) { return kept.second.expired(); });
    std::vector<std::shared_ptr<const ViewVariant>> out;
    for (const forest::ForestVariant& v : variants) {
        auto view = std::make_shared<ViewVariant>();
        view->species = v.species;
        view->levels = v.levels;
        if (view->levels.empty() && v.mesh) view->levels.push_back({0.0, v.mesh});
        if (view->levels.empty() || !view->levels.front().mesh) {
            out.push_back(nullptr);
            continue;
        }
        const mesh::Mesh* full = view->levels.front().mesh.get();
        if (auto kept = before[full].lock();
            kept && kept->species == view->species && kept->levels.size() == view->levels.size() &&
            std::equal(kept->levels.begin(), kept->levels.end(), view->levels.begin(),
                       [](const mesh::DistanceLevel& a, const mesh::DistanceLevel& b) {
                           return a.mesh == b.mesh && a.distance == b.distance;
                       })) {
            out.push_back(std::move(kept));
            continue;
        }
        view->height = meshHeight(*view->levels.front().mesh);
        if (v.meshSettings) {
            view->referenceHeightPx = v.meshSettings->lod.screenHeightPx;
            view->referenceFovYDegrees = v.meshSettings->lod.fovYDegrees;
        }
        before[full] = view;
        out.push_back(std::move(view));
    }
    return out;
}

/// The variant of \p species whose height is nearest \p height (null when it has none).
std::shared_ptr<const ViewVariant>
nearestVariant(const std::vector<std::shared_ptr<const ViewVariant>>& variants,
               std::uint32_t species, float height) {
    std::shared_ptr<const ViewVariant> best;
    for (const auto& v : variants)
        if (v && v->species == species && v->height > 0.0f &&
            (!best || std::abs(v->height - height) < std::abs(best->height - height)))
            best = v;
    return best;
}

std::uint64_t pointerKey(const void* a, const void* b) {
    return mixSeed(reinterpret_cast<std::uintptr_t>(a), reinterpret_cast<std::uintptr_t>(b));
}

} // namespace

GenerationResult generateProject(const doc::Project& project, const QString& path,
                                 SceneCaches* caches, Progress& progress) {
    return runGuarded(path, [&](GenerationResult& result) {
        // Watch every file the project reads, stamped before it is read (a change during the
        // generation is still seen): the species and mesh files, then the files the species'
        // graphs name (grammar files), known once makeForestScene has read the species.
        for (const doc::ProjectSpecies& s : project.species)
            if (!s.file.empty())
                result.sources << QFileInfo(project.resolve(s.file)).absoluteFilePath();
        for (const doc::ProjectObstacle& o : project.obstacles)
            result.sources << QFileInfo(project.resolve(o.file)).absoluteFilePath();
        for (const doc::PlacementDomain& d : project.domains)
            if (!d.terrain.empty())
                result.sources << QFileInfo(project.resolve(d.terrain)).absoluteFilePath();
        result.sources.removeDuplicates();
        stampSources(result);
        forest::ForestScene forest = doc::makeForestScene(project);
        // Node ids: the trees sway in the viewport's wind (windvertexdata.h).
        for (forest::SceneSpecies& s : forest.species)
            requestNodeIds(s.graph);
        for (const forest::SceneSpecies& s : forest.species)
            doc::addSpeciesSourceFiles(s.graph, result.sources);
        stampSources(result); // before buildForest reads the grammar files
        forest::ForestOptions options;
        options.keepGrown = true; // the branches scripts list (doc.branches)
        if (caches) {
            options.cache = &caches->trees;
            options.obstaclesKey = pointerKey(forest.obstacles.get(), forest.ground.get());
            caches->obstacles = forest.obstacles;
            caches->ground = forest.ground;
        }
        // Formats with instancing (glTF) write each variant once: File ▸ Export hands them over.
        // The viewport draws each variant's levels once per frame for all its instances.
        std::vector<std::shared_ptr<const ViewVariant>> variants;
        options.onVariants = [&](const std::vector<forest::ForestVariant>& made) {
            for (const forest::ForestVariant& v : made)
                result.exportVariants.push_back({v.name, v.mesh});
            variants = viewVariants(made);
        };
        double height = 0.0;
        const forest::ForestStats stats = forest::buildForest(
            forest, options,
            [&](const std::vector<forest::ForestTree>& batch) {
                for (const forest::ForestTree& tree : batch) {
                    DrawnTree drawn;
                    drawn.instanceId = tree.instance.id;
                    drawn.species = tree.instance.species;
                    // A hand-placed tree's forest id is its document id (the project keeps it).
                    if (tree.instance.handPlaced)
                        drawn.docId = static_cast<doc::TreeId>(tree.instance.id);
                    drawn.mesh = tree.mesh;
                    drawn.transform = tree.instance.transform();
                    drawn.metrics = tree.metrics;
                    drawn.grown = tree.grown;
                    drawn.orphanedEdits = tree.branchEdits.orphaned;
                    // The viewport's coarser levels (ui/viewport/viewlod.h) start from what the
                    // forest made this mesh with.
                    if (tree.meshSettings && tree.skeleton) {
                        drawn.lod.skeleton = tree.skeleton;
                        drawn.lod.settings = tree.meshSettings;
                        drawn.lod.builtDistance = tree.meshCameraDistance;
                    }
                    // Instances draw their variant's levels; a unique tree far away draws the
                    // impostor of its species' variant nearest its height, scaled to it (one
                    // atlas per variant, not one per unique tree: issue 32).
                    const auto v = static_cast<std::size_t>(tree.variant);
                    if (tree.variant >= 0 && v < variants.size() && variants[v]) {
                        drawn.lod.variant = variants[v];
                        drawn.lod.instance = true;
                    } else if (tree.mesh && !tree.mesh->positions.empty()) {
                        const float h = meshHeight(*tree.mesh);
                        drawn.lod.variant = nearestVariant(variants, tree.instance.species, h);
                        if (drawn.lod.variant)
                            drawn.lod.impostorScale = h / drawn.lod.variant->height;
                    }
                    height = std::max(height, tree.metrics.heightM);
                    result.trees.push_back(std::move(drawn));
                    result.exportTrees.push_back({tree.name, tree.mesh, tree.instance.position,
                                                  tree.instance.rotation,
                                                  tree.instance.scale * tree.instance.growth,
                                                  tree.variant, tree.instance.id});
                }
            },
            progress);
        result.mesh = std::make_shared<const mesh::Mesh>(
            surfaces(forest.obstacles.get(), forest.ground.get()));
        result.obstacles = forest.obstacles;
        result.ground = forest.ground;
        result.compactObj = true; // sylva-cli forest's default
        result.hasCamera = true;
        result.cameraEye = project.cameraPosition;
        result.cameraTarget = project.cameraTarget;
        result.stats["trees"] = static_cast<double>(stats.trees);
        result.stats["obstacle_triangles"] =
            forest.obstacles ? static_cast<double>(forest.obstacles->triangleCount()) : 0.0;
        result.stats["colliding_trees"] = static_cast<double>(stats.collidingTrees);
        result.stats["instanced"] = static_cast<double>(stats.instanced);
        result.stats["unique"] = static_cast<double>(stats.unique);
        result.stats["instanced_by_check"] = static_cast<double>(stats.instancedByCheck);
        result.stats["variants"] = static_cast<double>(stats.variants);
        result.stats["pruned_nodes"] = static_cast<double>(stats.prunedNodes);
        // Branch edits whose branch the grown tree lacks (kept in the project, not applied).
        result.stats["orphaned_edits"] = static_cast<double>(stats.orphanedEdits);
        QStringList warnings;
        for (const std::string& w : stats.warnings)
            warnings << QString::fromStdString(w);
        result.warning = warnings.join(QLatin1Char('\n'));
        result.stats["co2_kg"] = stats.metrics.co2Kg;
        result.stats["wood_m3"] = stats.metrics.woodVolumeM3;
        result.stats["biomass_kg"] = stats.metrics.dryBiomassKg;
        result.stats["mean_dbh_m"] = stats.metrics.meanDbhM;
        result.stats["height"] = height;
        // Trees actually grown: the unique trees the cache did not hold and the variants it
        // did not hold. An instanced tree takes its variant's mesh or level, which costs
        // nothing, so it is not counted (without a cache, everything is grown).
        result.stats["regrown"] =
            static_cast<double>(caches ? caches->trees.misses() + caches->trees.variantMisses()
                                       : stats.unique + stats.variants);
        for (const auto& [stage, ms] : stats.wallMs)
            result.timingsMs[stage] = ms;
        // Inside "trees": the CPU time of growing (or re-applying branch edits), adapting and
        // meshing, summed over the workers.
        for (const auto& [stage, ms] : stats.cpuMs)
            result.timingsMs["trees_" + stage] = ms;
        result.speciesName =
            QObject::tr("%1 (%n trees)", nullptr, int(stats.trees)).arg(result.speciesName);
    });
}

GenerationResult generateScene(const QString& path, Progress& progress) {
    doc::LoadReport report;
    doc::Project project;
    GenerationResult failed = runGuarded(
        path, [&](GenerationResult&) { project = doc::loadProjectOrScene(path, &report); });
    if (!failed.error.isEmpty()) return failed;
    GenerationResult result = generateProject(project, path, nullptr, progress);
    QStringList warnings;
    for (const std::string& w : report.warnings)
        warnings << QString::fromStdString(w);
    if (!result.warning.isEmpty()) warnings << result.warning; // the build's own
    result.warning = warnings.join(QLatin1Char('\n'));
    if (result.ok() && result.trees.empty() && result.mesh->empty())
        result.error = QObject::tr("%1: the project has no trees and no obstacles")
                           .arg(QFileInfo(path).fileName());
    return result;
}

GenerationResult generate(const QString& path, Progress& progress) {
    return isProjectFile(path) ? generateScene(path, progress) : generateTree(path, progress);
}

} // namespace sylva::ui
