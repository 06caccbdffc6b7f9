// Opening a project in the editor: the forest merged for the viewport equals what the engine's
// buildForest (the same call as sylva-cli forest) makes, tree for tree, placed in the world,
// with the obstacles after it; bad projects give a message, never an exception.
#include <algorithm>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include "document/project.h"
#include "document/scenebuild.h"
#include "engine/forest/forestbuild.h"
#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "ui/generation/scenegenerator.h"

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
        const forest::ForestScene forest = doc::makeForestScene(doc::loadProject(path));
        std::vector<forest::ForestTree> trees;
        const forest::ForestStats stats = forest::buildForest(
            forest, forest::ForestOptions{}, [&](const std::vector<forest::ForestTree>& batch) {
                trees.insert(trees.end(), batch.begin(), batch.end());
            });
        QCOMPARE(r.stats.at("trees"), double(trees.size()));
        QCOMPARE(r.stats.at("co2_kg"), stats.metrics.co2Kg);
        QCOMPARE(r.stats.at("colliding_trees"), double(stats.collidingTrees));
        QCOMPARE(int(trees.size()), 41); // 25 bushes + 15 shrubs + 1 placed by hand
        std::size_t treeVertices = 0, treeTriangles = 0;
        for (const forest::ForestTree& t : trees) {
            QVERIFY2(t.mesh, t.name.c_str());
            treeVertices += t.mesh->vertexCount();
            treeTriangles += t.mesh->triangleCount();
        }
        // Every tree on its own, in build order, with its mesh and its instance transform (a
        // tree pruned away entirely by the wall has an empty mesh).
        QCOMPARE(r.trees.size(), trees.size());
        std::size_t drawnVertices = 0, drawnTriangles = 0;
        for (std::size_t i = 0; i < trees.size(); ++i) {
            const DrawnTree& d = r.trees[i];
            QCOMPARE(d.instanceId, trees[i].instance.id);
            QCOMPARE(d.mesh->positions, trees[i].mesh->positions);
            QCOMPARE(d.mesh->indices, trees[i].mesh->indices);
            QVERIFY(d.transform == trees[i].instance.transform());
            // The hand-placed tree carries its document id (its instance's, from the file).
            QCOMPARE(d.docId, trees[i].instance.handPlaced ? doc::TreeId(trees[i].instance.id)
                                                           : doc::TreeId(0));
            drawnVertices += d.mesh->vertexCount();
            drawnTriangles += d.mesh->triangleCount();
        }
        QCOMPARE(drawnVertices, treeVertices);
        QCOMPARE(drawnTriangles, treeTriangles);
        // The obstacles, merged into the static mesh with the wall's corners as loaded.
        const mesh::Mesh& m = *r.mesh;
        const mesh::Submesh* obstacle = findSubmesh(m, "obstacle");
        QVERIFY(obstacle);
        QVERIFY(!findSubmesh(m, "bark"));
        QCOMPARE(std::size_t(obstacle->indexCount / 3), forest.obstacles->triangleCount());
        QCOMPARE(r.stats.at("obstacle_triangles"), double(forest.obstacles->triangleCount()));
        QCOMPARE(m.vertexCount(), 3 * forest.obstacles->triangleCount());
        // Issue #40: the demo's boulder was untextured grey. Obstacles are coloured as stone:
        // one colour a vertex, varying over the surface.
        QCOMPARE(m.colors.size(), m.vertexCount());
        {
            int lo = 255, hi = 0;
            for (std::uint32_t i = obstacle->firstIndex;
                 i < obstacle->firstIndex + obstacle->indexCount; ++i) {
                lo = std::min(lo, int(m.colors[m.indices[i]].x));
                hi = std::max(hi, int(m.colors[m.indices[i]].x));
            }
            QVERIFY2(hi - lo > 40, qPrintable(QStringLiteral("%1..%2").arg(lo).arg(hi)));
        }
        QCOMPARE(m.normals.size(), m.vertexCount());
        const env::ObstacleMesh& wall = forest.obstacles->meshes().front();
        QCOMPARE(m.positions[m.indices[obstacle->firstIndex]],
                 wall.vertices[wall.triangles.front().x]);
        QCOMPARE(r.vertexCount(), treeVertices + m.vertexCount());
        QVERIFY(r.speciesName.contains(QStringLiteral("41")));
    }

    void unchangedTreesAreNotRegrown() {
        const QString path = dataFile("projects/small.sylva");
        doc::Project project = doc::loadProject(path);
        project.instances[0].id = 7;
        SceneCaches caches;
        const GenerationResult first = generateProject(project, path, &caches);
        QVERIFY2(first.ok(), qPrintable(first.error));
        // Grown from nothing: every unique tree and every variant; an instanced tree takes its
        // variant's mesh or level (nothing grown for it), except that those the crown-cylinder
        // test had not cleared were checked by adaptation first (counted as regrown).
        QCOMPARE(first.stats.at("unique") + first.stats.at("instanced"), first.stats.at("trees"));
        QVERIFY(first.stats.at("instanced") > 0.0);
        QCOMPARE(first.stats.at("regrown"), first.stats.at("unique") + first.stats.at("variants") +
                                                first.stats.at("instanced_by_check"));
        QVERIFY(first.stats.at("instanced_by_check") < first.stats.at("instanced"));
        QVERIFY(first.stats.at("regrown") < first.stats.at("trees"));
        const GenerationResult second = generateProject(project, path, &caches);
        QCOMPARE(second.stats.at("regrown"), 0.0);
        // The same meshes, shared: the viewport keeps their GPU buffers.
        for (std::size_t i = 0; i < first.trees.size(); ++i)
            QCOMPARE(second.trees[i].mesh.get(), first.trees[i].mesh.get());
        // And the same variants: the viewport keys their levels' buffers and their impostor
        // atlas by them (a new ViewVariant each time re-baked every atlas after every edit).
        int variants = 0;
        for (std::size_t i = 0; i < first.trees.size(); ++i)
            if (first.trees[i].lod.variant) {
                QCOMPARE(second.trees[i].lod.variant.get(), first.trees[i].lod.variant.get());
                ++variants;
            }
        QVERIFY(variants > 0);
        project.instances[0].seed += 1;
        const GenerationResult third = generateProject(project, path, &caches);
        QCOMPARE(third.stats.at("regrown"), 1.0);
        QCOMPARE(third.trees[0].docId, 7u);
        QVERIFY(third.trees[0].mesh.get() != first.trees[0].mesh.get());
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
