// Colouring a tree by node attributes: the values behind the ramp, computed by hand for a small
// skeleton, and the per-vertex colours the viewport draws.

#include <cmath>

#include <QTest>

#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "ui/generation/vertexdata.h"
#include "ui/viewport/attributecolors.h"

using namespace sylva;
using namespace sylva::ui;

namespace {

// Root 0, trunk 1 -> 2, lateral 3 -> 4 from node 1:
//   metamers per subtree: 1: 4 (1, 2, 3, 4), 2: 1, 3: 2, 4: 1; root 0 carries all 4.
skel::Skeleton fiveNodes() {
    skel::Skeleton s;
    const glm::quat q(1, 0, 0, 0);
    s.addNode({0, 0, 0}, -1, 0.1f, 0, q);
    s.addNode({0, 1, 0}, 0, 0.1f, 0, q);
    s.addNode({0, 2, 0}, 1, 0.1f, 0, q);
    s.addNode({1, 1.5f, 0}, 1, 0.05f, 1, q);
    s.addNode({2, 2, 0}, 3, 0.05f, 1, q);
    s.light = {2.0f, 2.0f, 1.0f, 1.0f, 0.8f};
    s.vigour = {8.0f, 8.0f, 3.0f, 5.0f, 0.0f};
    s.age = {4, 4, 1, 2, 0};
    return s;
}

} // namespace

class TestAttributeColors : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void availability() {
        skel::Skeleton s = fiveNodes();
        for (ColorBy m : {ColorBy::Material, ColorBy::Light, ColorBy::Vigour, ColorBy::Age,
                          ColorBy::BranchOrder})
            QVERIFY(hasAttribute(s, m));
        s.light.clear();
        s.vigour.clear();
        s.age.clear();
        QVERIFY(!hasAttribute(s, ColorBy::Light));
        QVERIFY(!hasAttribute(s, ColorBy::Vigour));
        QVERIFY(!hasAttribute(s, ColorBy::Age));
        QVERIFY(hasAttribute(s, ColorBy::BranchOrder));
        QVERIFY(normalizedAttribute(s, ColorBy::Light).empty());
        QVERIFY(normalizedAttribute(s, ColorBy::Material).empty());
    }

    void lightPerInternodeByHand() {
        // light / metamers in the subtree: 0: 2/4, 1: 2/4, 2: 1/1, 3: 1/2, 4: 0.8/1; max 1.
        const std::vector<float> t = normalizedAttribute(fiveNodes(), ColorBy::Light);
        const std::vector<float> expected = {0.5f, 0.5f, 1.0f, 0.5f, 0.8f};
        QCOMPARE(t.size(), expected.size());
        for (std::size_t i = 0; i < t.size(); ++i)
            QVERIFY2(std::abs(t[i] - expected[i]) < 1e-6f, qPrintable(QString::number(i)));
    }

    void vigourIsLogScaledAgeAndOrderLinear() {
        const skel::Skeleton s = fiveNodes();
        const std::vector<float> v = normalizedAttribute(s, ColorBy::Vigour);
        QCOMPARE(v[0], 1.0f);
        QVERIFY(std::abs(v[2] - std::log1p(3.0f) / std::log1p(8.0f)) < 1e-6f);
        QCOMPARE(v[4], 0.0f);
        const std::vector<float> a = normalizedAttribute(s, ColorBy::Age);
        QCOMPARE(a[0], 1.0f);
        QCOMPARE(a[3], 0.5f);
        const std::vector<float> o = normalizedAttribute(s, ColorBy::BranchOrder);
        QCOMPARE(o[1], 0.0f);
        QCOMPARE(o[4], 1.0f);
    }

    void rampRunsFromDarkBlueToYellowAndBrightens() {
        const glm::vec3 lo = rampColor(0.0f), hi = rampColor(1.0f);
        QVERIFY(lo.z > lo.x && lo.z > lo.y); // blue dominates
        QVERIFY(hi.x > hi.z && hi.y > hi.z); // red and green: yellow
        auto luma = [](glm::vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; };
        float last = -1.0f;
        for (int i = 0; i <= 40; ++i) {
            const float y = luma(rampColor(float(i) / 40.0f));
            QVERIFY2(y >= last, "the ramp gets darker somewhere");
            last = y;
        }
        QCOMPARE(rampColor(-3.0f), lo);
        QCOMPARE(rampColor(std::nanf("")), lo);
    }

    void verticesTakeTheirNodesColour() {
        const skel::Skeleton s = fiveNodes();
        mesh::Mesh m;
        m.positions.resize(4);
        m.node = {2, 4, 0, mesh::Mesh::kNoNode};
        const std::vector<glm::vec3> c = attributeColors(m, s, ColorBy::Light);
        QCOMPARE(c.size(), std::size_t(4));
        QCOMPARE(c[0], rampColor(1.0f));
        QCOMPARE(c[1], rampColor(0.8f));
        QCOMPARE(c[2], rampColor(0.5f));
        QCOMPARE(c[3], rampColor(0.0f));
        QVERIFY(attributeColors(m, s, ColorBy::Material).empty());
        m.node.clear(); // a mesh without node ids cannot be coloured
        QVERIFY(attributeColors(m, s, ColorBy::Light).empty());
    }

    void starvedBranchesAreRedWhenColouredByLight() {
        // The lateral 3 -> 4 falls below a threshold of 0.6 (light per internode 0.5): flagged.
        skel::Skeleton s = fiveNodes();
        s.shedThreshold = 0.6f;
        s.flags[3] |= skel::kStarved;
        s.flags[4] |= skel::kStarved;
        mesh::Mesh m;
        m.positions.resize(3);
        m.node = {2, 4, 3};
        const std::vector<glm::vec3> light = attributeColors(m, s, ColorBy::Light);
        QCOMPARE(light[0], rampColor(1.0f));
        QCOMPARE(light[1], kStarvedColor);
        QCOMPARE(light[2], kStarvedColor);
        // Other modes keep the ramp for the same nodes.
        QCOMPARE(attributeColors(m, s, ColorBy::Age)[1], rampColor(0.0f));
        const QString legend = attributeLegend(s, ColorBy::Light);
        QVERIFY2(legend.contains(QStringLiteral("red: 2 internodes")), qPrintable(legend));
        QVERIFY2(legend.contains(QStringLiteral("0.6")), qPrintable(legend));
        QCOMPARE(colorByAttribute(m, s, ColorBy::Light).legend, legend);
        // A threshold with nothing below it says so; no threshold, no mention.
        s.flags[3] = s.flags[4] = 0;
        QVERIFY(attributeLegend(s, ColorBy::Light).contains(QStringLiteral("no branch")));
        s.shedThreshold = 0.0f;
        QVERIFY(!attributeLegend(s, ColorBy::Light).contains(QStringLiteral("threshold")));
    }

    void legendNamesTheRange() {
        const skel::Skeleton s = fiveNodes();
        QVERIFY(attributeLegend(s, ColorBy::Age).contains(QStringLiteral("4")));
        skel::Skeleton bare = s;
        bare.light.clear();
        QVERIFY(attributeLegend(bare, ColorBy::Light).contains(QStringLiteral("not available")));
    }

    void oneCallGivesColoursAndLegend() {
        const skel::Skeleton s = fiveNodes();
        mesh::Mesh m;
        m.positions.resize(4);
        m.node = {2, 4, 0, mesh::Mesh::kNoNode};
        for (ColorBy mode : {ColorBy::Material, ColorBy::Light, ColorBy::Vigour, ColorBy::Age,
                             ColorBy::BranchOrder}) {
            const AttributeColoring c = colorByAttribute(m, s, mode);
            QVERIFY(c.colors == attributeColors(m, s, mode));
            QCOMPARE(c.legend, attributeLegend(s, mode));
        }
        skel::Skeleton bare = s;
        bare.light.clear();
        const AttributeColoring none = colorByAttribute(m, bare, ColorBy::Light);
        QVERIFY(none.colors.empty());
        QVERIFY(none.legend.contains(QStringLiteral("not available")));
    }

    /// The vertices the viewport uploads (made on the preview's worker): the layout by hand,
    /// smooth normals for a mesh without any, and a triangle with a bad index left out of them.
    void verticesAsTheViewportUploadsThem() {
        mesh::Mesh m;
        m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 3}};
        m.uvs = {{0, 0}, {1, 0}, {0, 1}, {0.5f, 0.25f}};
        // One triangle in the xy plane (area 2, wound for +z) and one in the xz plane (area 3,
        // wound for +y); the third names vertex 9, which does not exist.
        m.indices = {0, 1, 2, 0, 3, 1, 0, 1, 9};
        const std::vector<glm::vec3> colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
        const std::vector<ViewVertex> v = interleaveVertices(m, colors);
        QCOMPARE(v.size(), std::size_t(4));
        // Vertex 1: normal = 4·(0,0,1) + 6·(0,1,0) (the cross products, area-weighted; the
        // shader normalises), its colour, uv and occlusion (1: no leaves, nothing shades it).
        QCOMPARE(v[1].position, glm::vec3(2, 0, 0));
        QCOMPARE(v[1].normal, glm::vec3(0, 6, 4));
        QCOMPARE(v[1].color, glm::vec3(0, 1, 0));
        QCOMPARE(v[1].uv, glm::vec2(1, 0));
        QCOMPARE(v[1].occlusion, 1.0f);
        QCOMPARE(v[2].normal, glm::vec3(0, 0, 4)); // the first triangle only
        QCOMPARE(v[3].uv, glm::vec2(0.5f, 0.25f));
        // Colours that do not match the vertices give white (the material's own colour, which
        // the shader multiplies by it); given normals are kept.
        m.normals.assign(4, glm::vec3(0, 1, 0));
        for (const ViewVertex& p : interleaveVertices(m, {{1, 1, 1}})) {
            QCOMPARE(p.normal, glm::vec3(0, 1, 0));
            QCOMPARE(p.color, glm::vec3(1.0f));
        }
        // Without attribute colours, the mesh's leaf tint (Mesh::colors, linear bytes).
        m.colors = {{255, 255, 255, 255}, {51, 102, 255, 255}, {0, 0, 0, 255}, {255, 0, 0, 255}};
        const std::vector<ViewVertex> tinted = interleaveVertices(m, {});
        QCOMPARE(tinted[1].color, glm::vec3(0.2f, 0.4f, 1.0f));
        QCOMPARE(tinted[3].color, glm::vec3(1.0f, 0.0f, 0.0f));
        // The attribute shown wins over the tint.
        QCOMPARE(interleaveVertices(m, colors)[1].color, glm::vec3(0, 1, 0));
    }
};

QTEST_APPLESS_MAIN(TestAttributeColors)

#include "test_attributecolors.moc"
