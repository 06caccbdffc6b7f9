// The viewport's draw list (ui/viewport/drawlist.h): frustum culling, hidden trees, nearest
// first, and the level of detail each tree's height on screen asks for. Pure: no GL context.

#include <QTest>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/mesh/mesh.h"
#include "ui/viewport/drawlist.h"
#include "ui/viewport/impostors.h"
#include "ui/viewport/viewlod.h"

using sylva::ui::Bounds;
using sylva::ui::buildDrawList;
using sylva::ui::DrawListView;
using sylva::ui::InstanceOf;
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

/// A mesh of \p triangles degenerate triangles (only their count matters here).
std::shared_ptr<const sylva::mesh::Mesh> meshOf(std::size_t triangles) {
    auto m = std::make_shared<sylva::mesh::Mesh>();
    m->positions.assign(3, glm::vec3(0.0f));
    for (std::size_t t = 0; t < triangles; ++t)
        m->indices.insert(m->indices.end(), {0u, 1u, 2u});
    return m;
}

/// A 10 m variant with levels for 0, 25, 50 and 100 m on the reference view (1080 px, 60°).
std::shared_ptr<sylva::ui::ViewVariant> variant() {
    auto v = std::make_shared<sylva::ui::ViewVariant>();
    v->height = 10.0f;
    v->levels = {
        {0.0, meshOf(1000)}, {25.0, meshOf(500)}, {50.0, meshOf(200)}, {100.0, meshOf(50)}};
    return v;
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

    /// While the view moves, a tree is drawn as if the target were motionBias times smaller:
    /// never finer than at rest, and between the two switches an impostor where the sharp
    /// frame draws a mesh, unless it is higher than maxImpostorPx on the target (then the
    /// coarsest mesh: no atlas view magnified into blocks).
    void movingFramesDrawAsIfFarther() {
        DrawListView moving = view();
        moving.viewportHeightPx = 0.5 * kPixels;
        moving.motionBias = 1.5;
        moving.maxImpostorPx = 60.0; // 120 px at rest: above the rest switch, as in the viewport
        DrawListView rest = view();
        const auto levelAt = [](double distance, double pixels) {
            return ViewLod::levelFor(
                ViewLod::equivalentHeights(distance, 10.0, double(kFov), pixels));
        };
        int band = 0, capped = 0;
        for (float z = -20.0f; z > -3000.0f; z *= 1.05f) {
            const std::vector<TreeDraw> m = buildDrawList(moving, {true}, {tree(0, z)});
            const std::vector<TreeDraw> r = buildDrawList(rest, {true}, {tree(0, z)});
            QCOMPARE(m.size(), std::size_t(1));
            QCOMPARE(r.size(), std::size_t(1));
            const double d = double(m[0].distance);
            const double onTarget = 10.0 * 0.5 * kPixels / (2.0 * d * std::tan(0.5 * double(kFov)));
            const int biased = levelAt(d, 0.5 * kPixels / 1.5);
            if (biased == ViewLod::kImpostorLevel && onTarget > 60.0) {
                QCOMPARE(m[0].level, ViewLod::kImpostorLevel - 1);
                ++capped;
            } else {
                QCOMPARE(m[0].level, biased);
            }
            QVERIFY(m[0].level >= r[0].level);
            if (m[0].level == ViewLod::kImpostorLevel && r[0].level != ViewLod::kImpostorLevel)
                ++band;
        }
        QVERIFY(band > 0);   // the band between the two switches was crossed
        QVERIFY(capped > 0); // and trees too large for an impostor stayed meshes
    }

    /// ViewLod::impostorHeightPx() is where levelFor() hands a tree to the impostor, on any
    /// viewport (the viewport keeps swaying trees as meshes above it while the view moves).
    void impostorHeightIsTheSwitch() {
        const double px = ViewLod::impostorHeightPx();
        QVERIFY(px > 50.0 && px < 150.0);
        for (double viewport : {450.0, 720.0, 1080.0, 2160.0}) {
            // A tree 10 m high spanning h pixels of this viewport stands at this distance.
            const auto levelAtPx = [&](double h) {
                const double d = 10.0 * viewport / (2.0 * h * std::tan(0.5 * double(kFov)));
                return ViewLod::levelFor(
                    ViewLod::equivalentHeights(d, 10.0, double(kFov), viewport));
            };
            QCOMPARE(levelAtPx(0.99 * px), ViewLod::kImpostorLevel);
            QVERIFY(levelAtPx(1.01 * px) < ViewLod::kImpostorLevel);
        }
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

    /// Instances of a variant draw the variant's level for their size on screen: farther, or
    /// smaller (scale), is coarser, never finer; a view that moves draws coarser levels; with the
    /// distance LOD off every instance is at the variant's full mesh.
    void instancesTakeTheirVariantsLevelBySize() {
        const auto v = variant();
        // The reference view: a distance d there is the level for d.
        const double refFov = 60.0 * 3.14159265358979323846 / 180.0;
        QCOMPARE(sylva::ui::variantLevelFor(*v, 10.0, 1.0, refFov, 1080.0), std::size_t(0));
        QCOMPARE(sylva::ui::variantLevelFor(*v, 30.0, 1.0, refFov, 1080.0), std::size_t(1));
        QCOMPARE(sylva::ui::variantLevelFor(*v, 60.0, 1.0, refFov, 1080.0), std::size_t(2));
        // Half the scale looks as small as twice the distance; half the pixels too.
        QCOMPARE(sylva::ui::variantLevelFor(*v, 30.0, 0.5, refFov, 1080.0), std::size_t(2));
        QCOMPARE(sylva::ui::variantLevelFor(*v, 30.0, 1.0, refFov, 540.0), std::size_t(2));
        QCOMPARE(sylva::ui::variantLevelFor(*v, 30.0, 1.0, refFov, 1080.0, 4.0), std::size_t(3));

        // Trees along -z: the triangles drawn never grow with the distance, and fall.
        std::vector<Bounds> bounds;
        std::vector<InstanceOf> instances;
        for (int k = 0; k < 40; ++k) {
            bounds.push_back(tree(0.0f, -3.0f * float(k)));
            instances.push_back({v.get(), 1.0f});
        }
        const std::vector<bool> drawn(bounds.size(), true);
        std::vector<TreeDraw> list = buildDrawList(view(), drawn, bounds, instances);
        QCOMPARE(list.size(), bounds.size());
        std::size_t previous = 1000, nearTriangles = 0, farTriangles = 0;
        for (std::size_t i = 0; i < list.size(); ++i) {
            const TreeDraw& d = list[i];
            if (d.level == ViewLod::kImpostorLevel) {
                QCOMPARE(d.variantLevel, -1); // the impostor, not a level
                previous = 0;
                continue;
            }
            QVERIFY(d.variantLevel >= 0);
            const std::size_t t = v->levels[std::size_t(d.variantLevel)].mesh->triangleCount();
            QVERIFY(t <= previous);
            previous = t;
            (i < 10 ? nearTriangles : farTriangles) += i < 10 || i >= 30 ? t : 0;
        }
        QVERIFY2(2 * farTriangles <= nearTriangles,
                 qPrintable(QStringLiteral("%1 vs %2").arg(farTriangles).arg(nearTriangles)));

        // Moving: coarser levels, marked as motion.
        DrawListView moving = view();
        moving.variantFactor = 3.0;
        const std::vector<TreeDraw> coarse = buildDrawList(moving, drawn, bounds, instances);
        bool anyMotion = false;
        for (std::size_t i = 0; i < coarse.size(); ++i) {
            QVERIFY(coarse[i].variantLevel >= list[i].variantLevel);
            QCOMPARE(coarse[i].motion, coarse[i].variantLevel > list[i].variantLevel);
            anyMotion = anyMotion || coarse[i].motion;
        }
        QVERIFY(anyMotion);

        DrawListView off = view();
        off.levels = false;
        for (const TreeDraw& d : buildDrawList(off, drawn, bounds, instances))
            QCOMPARE(d.variantLevel, 0);
        // Trees that are no instance have no variant level.
        for (const TreeDraw& d : buildDrawList(view(), drawn, bounds))
            QCOMPARE(d.variantLevel, -1);
    }

    /// An impostor's card is read at one mipmap level (a uniform, issue 32): the level where a
    /// texel of its view's cell is about a pixel, so a card half the cell's size reads level 1.
    void impostorLevelFollowsTheCardsSize() {
        using sylva::ui::Impostors;
        const float fullSize = 0.5f * float(Impostors::kCell); // radius: the cell's texels
        QCOMPARE(Impostors::levelFor(fullSize), 0);
        QCOMPARE(Impostors::levelFor(4.0f * fullSize), 0); // magnified: the base level
        QCOMPARE(Impostors::levelFor(fullSize / 2.0f), 1);
        QCOMPARE(Impostors::levelFor(fullSize / 4.0f), 2);
        QCOMPARE(Impostors::levelFor(fullSize / 8.0f), 3);
        QCOMPARE(Impostors::levelFor(0.5f), Impostors::kMaxLevel); // the coarsest kept
        QCOMPARE(Impostors::levelFor(0.0f), Impostors::kMaxLevel);
        // Rounded: 1.4 texels a pixel is still level 0, 1.5 and more level 1.
        QCOMPARE(Impostors::levelFor(fullSize / 1.4f), 0);
        QCOMPARE(Impostors::levelFor(fullSize / 1.5f), 1);
        int last = 0;
        for (float r = 200.0f; r > 0.25f; r *= 0.9f) {
            const int level = Impostors::levelFor(r);
            QVERIFY(level >= last);
            last = level;
        }
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
