// The viewport's wind data (ui/generation/windvertexdata.h) against the engine's model: a
// preset grown with node ids, its vertices packed as the viewport uploads them, the frame's
// element rotations made as the viewport makes them, displaced as the shader displaces, and
// held against wind::displace on the engine's own per-vertex data at several times. Also: the
// per-tree loop phase, the shaders' #include.
#include <set>

#include <QDir>
#include <QTest>

#include "document/presetlibrary.h"
#include "document/speciesfile.h"
#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"
#include "engine/wind/windelements.h"
#include "ui/generation/windvertexdata.h"
#include "ui/viewport/shaderprogram.h"

using namespace sylva;

class TestWindVertexData : public QObject {
    Q_OBJECT

private:
    std::shared_ptr<const mesh::Mesh> mMesh;
    std::shared_ptr<const skel::Skeleton> mSkeleton;

private Q_SLOTS:
    void initTestCase() {
        graph::registerBuiltinNodeTypes();
        graph::SpeciesGraph species =
            doc::loadSpecies(QDir(doc::PresetLibrary::directory()).filePath("so-shrub.json"));
        ui::requestNodeIds(species);
        graph::Evaluator evaluator(std::move(species));
        const graph::NodeOutput& out = evaluator.evaluate();
        mMesh = out.mesh;
        mSkeleton = out.skeleton;
        QVERIFY(mMesh && mSkeleton);
        QCOMPARE(mMesh->node.size(), mMesh->positions.size());
    }

    /// Every vertex of the packed data moves as the engine moves it (the bend fraction is 16
    /// bits: well under a millimetre), bark and leaves, in a storm and a breeze.
    void packedDataMovesAsTheEngine() {
        const wind::WindElements elements = wind::buildWindElements(*mSkeleton);
        const std::vector<glm::vec4> texels = ui::windElementTexels(elements);
        QCOMPARE(texels.size(), elements.elements.size());
        const std::vector<ui::ViewWindVertex> packed = ui::windVertices(*mMesh, elements);
        QCOMPARE(packed.size(), mMesh->positions.size());
        mesh::Mesh engine = *mMesh;
        wind::addWindData(engine, *mSkeleton);
        std::size_t leaves = 0;
        for (std::size_t i = 0; i < packed.size(); ++i)
            leaves += engine.wind[i].leaf.y > 0.0f ? 1 : 0;
        QVERIFY2(leaves > 100, "the shrub has fluttering leaf vertices");
        wind::WindSettings storm;
        storm.strength = 2.0f;
        storm.gustiness = 1.0f;
        storm.direction = {0.3f, 0.0f, -1.0f};
        wind::WindSettings breeze;
        breeze.strength = 0.4f;
        breeze.frequency = 1.3f;
        float worst = 0.0f, largest = 0.0f;
        for (const wind::WindSettings& s : {storm, breeze})
            for (double t : {0.0, 0.37, 1.9, 3.3}) {
                const wind::WindFrame frame = wind::windFrame(s, t);
                std::vector<glm::vec4> rotations;
                ui::appendWindRotations(elements, frame, rotations);
                QCOMPARE(rotations.size(), elements.elements.size());
                for (std::size_t i = 0; i < packed.size(); ++i) {
                    const glm::vec3 p = mMesh->positions[i];
                    glm::vec3 na = mMesh->normals.empty() ? glm::vec3(0, 1, 0) : mMesh->normals[i];
                    glm::vec3 nb = na;
                    const glm::vec3 a = wind::displace(engine.wind[i], p, &na, frame);
                    const glm::vec3 b =
                        ui::displacePacked(texels, rotations, packed[i], p, &nb, frame);
                    worst = std::max(worst, glm::length(a - b));
                    largest = std::max(largest, glm::length(a - p));
                }
            }
        QVERIFY2(largest > 0.05f, qPrintable(QString::number(largest)));
        QVERIFY2(worst < 1e-3f, qPrintable(QString::number(worst)));
    }

    /// Leaf stems stay where they hang: the flutter weight is zero at each card's stem.
    void leafStemsDoNotFlutter() {
        const wind::WindElements elements = wind::buildWindElements(*mSkeleton);
        const std::vector<ui::ViewWindVertex> packed = ui::windVertices(*mMesh, elements);
        int cards = 0;
        for (const mesh::Submesh& sm : mMesh->submeshes) {
            if (sm.material != "leaf") continue;
            for (std::uint32_t k = sm.firstIndex; k + 6 <= sm.firstIndex + sm.indexCount; k += 6) {
                const std::uint32_t b = mMesh->indices[k];
                QCOMPARE(packed[b].flutter, std::uint16_t(0));
                QVERIFY(packed[b + 2].flutter != 0);
                ++cards;
            }
        }
        QVERIFY(cards > 10);
    }

    void meshWithoutNodeIdsHasNoWindData() {
        mesh::Mesh m = *mMesh;
        m.node.clear();
        QVERIFY(ui::windVertices(m, wind::buildWindElements(*mSkeleton)).empty());
    }

    /// Each tree plays at its own place in the loop; a species alone (id 0) at the start.
    void treesPlayAtTheirOwnPhase() {
        QCOMPARE(ui::windPhaseOf(0), 0.0f);
        std::set<float> phases;
        for (std::uint64_t id = 1; id <= 200; ++id) {
            const float p = ui::windPhaseOf(id);
            QVERIFY(p >= 0.0f && p < 1.0f);
            QCOMPARE(ui::windPhaseOf(id), p);
            phases.insert(p);
        }
        QVERIFY(phases.size() > 190);
    }

    /// mesh.vert takes the wind law from wind.glsl by #include.
    void windShaderIsIncluded() {
        const QByteArray vertex = ui::expandIncludes(ui::shaderSource(QStringLiteral("mesh.vert")));
        QVERIFY(!vertex.contains("#include"));
        QVERIFY(vertex.contains("void windDisplace("));
        QVERIFY(vertex.startsWith("#version 330 core\n"));
    }
};

QTEST_GUILESS_MAIN(TestWindVertexData)
#include "test_windvertexdata.moc"
