// The viewport's draw list (ui/viewport/drawlist.h): frustum culling, hidden trees, nearest
// first, and the level of detail each tree's height on screen asks for. Pure: no GL context.

#include <QTest>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "ui/viewport/drawlist.h"
#include "ui/viewport/viewlod.h"

using sylva::ui::Bounds;
using sylva::ui::buildDrawList;
using sylva::ui::DrawListView;
using sylva::ui::TreeDraw;
using sylva::ui::ViewLod;

namespace {

constexpr float kFov = 0.8f;
constexpr double kPixels = 720.0;

/// A camera at (0, 2, 10) looking down -z at the origin.
DrawListView view() {
    DrawListView v;
    v.eye = {0.0f, 2.0f, 10.0f};
    v.viewProj = glm::perspective(kFov, 4.0f / 3.0f, 0.1f, 5000.0f) *
                 glm::lookAt(v.eye, glm::vec3(0.0f, 2.0f, 0.0f), glm::vec3(0, 1, 0));
    v.fovY = kFov;
    v.viewportHeightPx = kPixels;
    return v;
}

/// A tree 10 m high standing at (x, 0, z).
Bounds tree(float x, float z) {
    Bounds b;
    b.lo = {x - 2.0f, 0.0f, z - 2.0f};
    b.hi = {x + 2.0f, 10.0f, z + 2.0f};
    return b;
}

} // namespace

class TestDrawList : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void cullsWhatIsOutsideTheView() {
        // In front, behind the camera, far to the side, in front again but hidden.
        const std::vector<Bounds> bounds = {tree(0, 0), tree(0, 30), tree(500, 0), tree(1, -5)};
        const std::vector<bool> drawn = {true, true, true, false};
        const std::vector<TreeDraw> list = buildDrawList(view(), drawn, bounds);
        QCOMPARE(list.size(), std::size_t(1));
        QCOMPARE(list[0].index, std::size_t(0));
    }

    void emptyBoxesAreNotDrawn() {
        const std::vector<TreeDraw> list = buildDrawList(view(), {true}, {Bounds{}});
        QVERIFY(list.empty());
    }

    void nearestFirstTiesByIndex() {
        const std::vector<Bounds> bounds = {tree(0, -40), tree(0, 0), tree(0, -10), tree(0, 0)};
        const std::vector<TreeDraw> list = buildDrawList(view(), {true, true, true, true}, bounds);
        QCOMPARE(list.size(), std::size_t(4));
        QCOMPARE(list[0].index, std::size_t(1));
        QCOMPARE(list[1].index, std::size_t(3)); // the same distance: by index
        QCOMPARE(list[2].index, std::size_t(2));
        QCOMPARE(list[3].index, std::size_t(0));
        for (std::size_t k = 1; k < list.size(); ++k)
            QVERIFY(list[k - 1].distance <= list[k].distance);
        QVERIFY(qAbs(list[0].distance - glm::length(glm::vec3(0, 5, 0) - view().eye)) < 1e-4f);
    }

    void levelsFollowTheHeightOnScreen() {
        const std::vector<Bounds> bounds = {tree(0, 0), tree(0, -3000)};
        std::vector<TreeDraw> list = buildDrawList(view(), {true, true}, bounds);
        QCOMPARE(list.size(), std::size_t(2));
        QCOMPARE(list[0].level, 0); // 10 m away: full detail
        const int expected = ViewLod::levelFor(
            ViewLod::equivalentHeights(double(list[1].distance), 10.0, double(kFov), kPixels));
        QCOMPARE(list[1].level, expected);
        QCOMPARE(list[1].level, ViewLod::kImpostorLevel); // a few pixels high: the impostor
        // With the distance LOD off every tree is drawn at full detail.
        DrawListView off = view();
        off.levels = false;
        list = buildDrawList(off, {true, true}, bounds);
        QCOMPARE(list.size(), std::size_t(2));
        QCOMPARE(list[1].level, 0);
    }

    void treesWithoutABoxAreDrawnFirstAtFullDetail() {
        // The trees' boxes lag behind (fewer than trees): drawn, distance 0, level 0.
        const std::vector<TreeDraw> list = buildDrawList(view(), {true, true, false}, {tree(0, 0)});
        QCOMPARE(list.size(), std::size_t(2));
        QCOMPARE(list[0].index, std::size_t(1));
        QCOMPARE(list[0].distance, 0.0f);
        QCOMPARE(list[0].level, 0);
        QCOMPARE(list[1].index, std::size_t(0));
    }

    void frustumPlanesSeeAStraddlingBox() {
        const auto planes = sylva::ui::frustumPlanes(view().viewProj);
        Bounds straddling;
        straddling.lo = {-1000.0f, -1.0f, -5.0f};
        straddling.hi = {1000.0f, 1.0f, -4.0f};
        QVERIFY(sylva::ui::intersectsFrustum(planes, straddling));
        Bounds below;
        below.lo = {-1.0f, -500.0f, 0.0f};
        below.hi = {1.0f, -400.0f, 1.0f};
        QVERIFY(!sylva::ui::intersectsFrustum(planes, below));
    }
};

QTEST_APPLESS_MAIN(TestDrawList)
#include "test_drawlist.moc"
