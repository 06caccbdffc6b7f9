// Opening a project in the editor: the forest merged for the viewport equals what the engine's
// buildForest (the same call as sylva-cli forest) makes, tree for tree, placed in the world,
// with the obstacles after it; bad projects give a message, never an exception.
#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "document/project.h"
#include "document/scenebuild.h"
#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/scene/forestbuild.h"
#include "ui/scenegenerator.h"

using namespace sylva;
using namespace sylva::ui;

namespace {

QString dataFile(const QString& name) {
    return QDir(QStringLiteral(SYLVA_TEST_DATA_DIR)).filePath(name);
}

const mesh::Submesh* findSubmesh(const mesh::Mesh& m, const std::string& material) {
    for (const mesh::Submesh& s : m.submeshes)
        if (s.material == material) return &s;
    return nullptr;
}

} // namespace

class TestSceneGenerator : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void recognisesProjects() {
        QVERIFY(isProjectFile(dataFile("projects/small.sylva")));
        QVERIFY(isProjectFile(dataFile("projects/reference-scene.json"))); // "plants"
        QVERIFY(!isProjectFile(dataFile("projects/adapt-species.json")));  // a species
        QVERIFY(!isProjectFile(dataFile("lsystem/bush.lsys")));
    }

    void forestEqualsTheEnginesBuild() {
        const QString path = dataFile("projects/small.sylva");
        const GenerationResult r = generateScene(path);
        QVERIFY2(r.ok(), qPrintable(r.error));
        QVERIFY(r.skeleton == nullptr);

        // Oracle: the engine's own build of the same project.
        graph::registerBuiltinNodeTypes();
        const scene::ForestScene forest = doc::makeForestScene(doc::loadProject(path));
        std::vector<scene::ForestTree> trees;
        const scene::ForestStats stats = scene::buildForest(
            forest, scene::ForestOptions{}, [&](const std::vector<scene::ForestTree>& batch) {
                trees.insert(trees.end(), batch.begin(), batch.end());
            });
        QCOMPARE(r.stats.at("trees"), double(trees.size()));
        QCOMPARE(r.stats.at("co2_kg"), stats.metrics.co2Kg);
        QCOMPARE(r.stats.at("colliding_trees"), double(stats.collidingTrees));
        QCOMPARE(int(trees.size()), 41); // 25 bushes + 15 shrubs + 1 placed by hand
        std::size_t treeVertices = 0, treeTriangles = 0;
        for (const scene::ForestTree& t : trees) {
            QVERIFY2(t.mesh, t.name.c_str());
            treeVertices += t.mesh->vertexCount();
            treeTriangles += t.mesh->triangleCount();
        }
        const mesh::Mesh& m = *r.mesh;
        const mesh::Submesh* bark = findSubmesh(m, "bark");
        const mesh::Submesh* obstacle = findSubmesh(m, "obstacle");
        QVERIFY(bark && obstacle);
        const mesh::Submesh* leaf = findSubmesh(m, "leaf");
        const std::size_t leafIndices = leaf ? leaf->indexCount : 0;
        QCOMPARE((bark->indexCount + leafIndices) / 3, treeTriangles);
        QCOMPARE(std::size_t(obstacle->indexCount / 3), forest.obstacles->triangleCount());
        QCOMPARE(r.stats.at("obstacle_triangles"), double(forest.obstacles->triangleCount()));
        QCOMPARE(m.vertexCount(), treeVertices + 3 * forest.obstacles->triangleCount());
        QCOMPARE(m.normals.size(), m.vertexCount());

        // Every tree's vertices, in build order, placed by its instance transform (a tree
        // pruned away entirely by the wall has none).
        std::size_t base = 0;
        for (const scene::ForestTree& t : trees) {
            if (t.mesh->empty()) continue;
            const glm::mat4 x = t.instance.transform();
            for (std::size_t v : {std::size_t{0}, t.mesh->vertexCount() - 1}) {
                const glm::vec3 want = glm::vec3(x * glm::vec4(t.mesh->positions[v], 1.0f));
                QVERIFY2(glm::length(m.positions[base + v] - want) < 1e-4f,
                         qPrintable(QString::fromStdString(t.name)));
            }
            base += t.mesh->vertexCount();
        }
        // The obstacle triangles come last, with the wall's corners as loaded.
        const std::uint32_t firstObstacle = m.indices[obstacle->firstIndex];
        QCOMPARE(std::size_t(firstObstacle), treeVertices);
        const env::ObstacleMesh& wall = forest.obstacles->meshes().front();
        QCOMPARE(m.positions[firstObstacle], wall.vertices[wall.triangles.front().x]);
        QVERIFY(r.speciesName.contains(QStringLiteral("41")));
    }

    void badProjectsGiveAMessage() {
        GenerationResult missing = generate(dataFile("projects/does-not-exist.sylva"));
        QVERIFY(!missing.ok());
        QVERIFY2(missing.error.contains(QStringLiteral("does-not-exist.sylva")),
                 qPrintable(missing.error));

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString broken = dir.filePath(QStringLiteral("broken.sylva"));
        QFile file(broken);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(
            "{\n  \"format\": \"sylva-project\",\n  \"format_version\": 1,\n  \"seed\": 02\n}\n");
        file.close();
        const GenerationResult bad = generate(broken);
        QVERIFY(!bad.ok());
        QVERIFY2(bad.error.contains(QStringLiteral("broken.sylva:4:")), qPrintable(bad.error));
        QVERIFY2(bad.error.contains(QStringLiteral("malformed number '02'")),
                 qPrintable(bad.error));
    }
};

QTEST_APPLESS_MAIN(TestSceneGenerator)

#include "test_scenegenerator.moc"
