// What TreeBuffers decides without a GL context: the materials' colours and the index check
// that keeps a bad mesh from the driver. The uploads themselves are drawn by ui_smoke,
// ui_editor and ui_species.

#include <QTest>

#include "engine/mesh/mesh.h"
#include "ui/viewport/treebuffers.h"

using sylva::ui::TreeBuffers;

class TestTreeBuffers : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void materialColours() {
        QCOMPARE(TreeBuffers::materialColor("leaf"), TreeBuffers::materialColor("foliage"));
        QCOMPARE(TreeBuffers::materialColor("bark"), TreeBuffers::materialColor(""));
        QVERIFY(TreeBuffers::materialColor("leaf") != TreeBuffers::materialColor("bark"));
        QVERIFY(TreeBuffers::materialColor("ground") != TreeBuffers::materialColor("rock"));
        // Linear albedo, darker than mid grey: the shader lights it and outputs sRGB.
        const glm::vec3 leaf = TreeBuffers::materialColor("leaf");
        QVERIFY(leaf.y > leaf.x && leaf.y > leaf.z && leaf.y < 0.5f);
    }

    void indicesInRange() {
        sylva::mesh::Mesh m;
        m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        m.indices = {0, 1, 2};
        QVERIFY(TreeBuffers::indicesInRange(m));
        m.indices = {0, 1, 3};
        QVERIFY(!TreeBuffers::indicesInRange(m));
    }
};

QTEST_APPLESS_MAIN(TestTreeBuffers)
#include "test_treebuffers.moc"
