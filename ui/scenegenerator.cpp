#include "ui/scenegenerator.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include <QFile>
#include <QFileInfo>
#include <QStringList>

#include <glm/gtc/matrix_inverse.hpp>

#include "document/project.h"
#include "document/scenebuild.h"
#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/scene/forestbuild.h"

namespace sylva::ui {

namespace {

bool isLeafMaterial(const std::string& m) {
    return m == "leaf" || m == "leaves" || m == "foliage";
}

/// The merged scene: triangles collected per material, vertices shared in one array.
class SceneMesh {
public:
    /// Appends \p m transformed by \p transform (a rotation, uniform scale and translation).
    void addTree(const mesh::Mesh& m, const glm::mat4& transform) {
        const auto base = static_cast<std::uint32_t>(mOut.positions.size());
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(transform));
        const bool hasNormals = m.normals.size() == m.positions.size();
        for (std::size_t v = 0; v < m.positions.size(); ++v) {
            mOut.positions.push_back(glm::vec3(transform * glm::vec4(m.positions[v], 1.0f)));
            mOut.normals.push_back(hasNormals ? glm::normalize(normalMatrix * m.normals[v])
                                              : glm::vec3(0, 1, 0));
        }
        if (m.submeshes.empty()) {
            append(mBark, m.indices, 0, static_cast<std::uint32_t>(m.indices.size()), base);
            return;
        }
        for (const mesh::Submesh& s : m.submeshes)
            append(isLeafMaterial(s.material) ? mLeaf : mBark, m.indices, s.firstIndex,
                   s.indexCount, base);
    }

    /// Appends an obstacle (or, with \p ground, terrain) mesh: world space, flat-shaded.
    void addSurface(const env::ObstacleMesh& m, bool ground) {
        std::vector<std::uint32_t>& into = ground ? mGround : mObstacle;
        for (const glm::uvec3& t : m.triangles) {
            const glm::vec3 corners[3] = {m.vertices[t.x], m.vertices[t.y], m.vertices[t.z]};
            const glm::vec3 n =
                glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
            for (const glm::vec3& p : corners) {
                into.push_back(static_cast<std::uint32_t>(mOut.positions.size()));
                mOut.positions.push_back(p);
                mOut.normals.push_back(n);
            }
        }
    }

    mesh::Mesh finish() {
        for (auto [material, indices] :
             {std::pair{"bark", &mBark}, std::pair{"leaf", &mLeaf},
              std::pair{"obstacle", &mObstacle}, std::pair{"ground", &mGround}}) {
            if (indices->empty()) continue;
            mOut.submeshes.push_back({material, static_cast<std::uint32_t>(mOut.indices.size()),
                                      static_cast<std::uint32_t>(indices->size())});
            mOut.indices.insert(mOut.indices.end(), indices->begin(), indices->end());
        }
        return std::move(mOut);
    }

private:
    static void append(std::vector<std::uint32_t>& into, const std::vector<std::uint32_t>& from,
                       std::uint32_t first, std::uint32_t count, std::uint32_t base) {
        const std::size_t end = std::min<std::size_t>(from.size(), std::size_t{first} + count);
        for (std::size_t i = first; i < end; ++i)
            into.push_back(from[i] + base);
    }

    mesh::Mesh mOut;
    std::vector<std::uint32_t> mBark, mLeaf, mObstacle, mGround;
};

} // namespace

bool isProjectFile(const QString& path) {
    if (path.endsWith(QStringLiteral(".sylva"), Qt::CaseInsensitive)) return true;
    if (!path.endsWith(QStringLiteral(".json"), Qt::CaseInsensitive)) return false;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return false;
    const QByteArray head = file.read(1 << 16);
    return head.contains("\"sylva-project\"") ||
           (!head.contains("\"format\"") && head.contains("\"plants\""));
}

GenerationResult generateScene(const QString& path, Progress& progress) {
    return runGuarded(path, [&](GenerationResult& result) {
        doc::LoadReport report;
        const doc::Project project = doc::loadProjectOrScene(path, &report);
        const auto stamped = [&] {
            result.sources.removeDuplicates();
            stampSources(result);
        };
        QStringList warnings;
        for (const std::string& w : report.warnings)
            warnings << QString::fromStdString(w);
        result.warning = warnings.join(QLatin1Char('\n'));
        for (const doc::ProjectSpecies& s : project.species)
            if (!s.file.empty())
                result.sources << QFileInfo(project.resolve(s.file)).absoluteFilePath();
        for (const doc::ProjectObstacle& o : project.obstacles)
            result.sources << QFileInfo(project.resolve(o.file)).absoluteFilePath();
        stamped(); // before makeForestScene reads the species files and meshes
        const scene::ForestScene forest = doc::makeForestScene(project);
        for (const scene::SceneSpecies& s : forest.species)
            addSourceFiles(s.graph, result.sources);
        stamped(); // before buildForest reads the grammar files
        SceneMesh merged;
        const scene::ForestStats stats = scene::buildForest(
            forest, scene::ForestOptions{},
            [&](const std::vector<scene::ForestTree>& batch) {
                for (const scene::ForestTree& tree : batch) {
                    if (tree.mesh) merged.addTree(*tree.mesh, tree.instance.transform());
                    result.exportTrees.push_back({tree.name, tree.mesh, tree.instance.position,
                                                  tree.instance.rotation,
                                                  tree.instance.scale * tree.instance.growth});
                }
            },
            progress);
        if (forest.obstacles)
            for (const env::ObstacleMesh& m : forest.obstacles->meshes())
                merged.addSurface(m, false);
        if (forest.ground)
            for (const env::ObstacleMesh& m : forest.ground->meshes())
                merged.addSurface(m, true);
        result.mesh = std::make_shared<const mesh::Mesh>(merged.finish());
        result.compactObj = true; // sylva-cli forest's default
        result.hasCamera = true;
        result.cameraEye = project.cameraPosition;
        result.cameraTarget = project.cameraTarget;
        result.stats["trees"] = static_cast<double>(stats.trees);
        result.stats["obstacle_triangles"] =
            forest.obstacles ? static_cast<double>(forest.obstacles->triangleCount()) : 0.0;
        result.stats["colliding_trees"] = static_cast<double>(stats.collidingTrees);
        result.stats["pruned_nodes"] = static_cast<double>(stats.prunedNodes);
        result.stats["co2_kg"] = stats.metrics.co2Kg;
        for (const auto& [stage, ms] : stats.wallMs)
            result.timingsMs[stage] = ms;
        result.speciesName =
            QObject::tr("%1 (%n trees)", nullptr, int(stats.trees)).arg(result.speciesName);
        if (result.mesh->empty())
            result.error = QObject::tr("%1: the project has no trees and no obstacles")
                               .arg(QFileInfo(path).fileName());
    });
}

GenerationResult generate(const QString& path, Progress& progress) {
    return isProjectFile(path) ? generateScene(path, progress) : generateTree(path, progress);
}

} // namespace sylva::ui
