// The viewport's lit impostor atlas (ui/viewport/impostorlighting.h): each view's texels lit
// by the key light as the orbit camera has it when it looks at the tree along that view.
#include <QtTest/QtTest>

#include <cmath>

#include "engine/mesh/impostor.h"
#include "ui/viewport/impostorlighting.h"
#include "ui/viewport/orbitcamera.h"

using namespace sylva;

namespace {

// A grid × grid atlas of cell² texels, grey albedo, every texel's normal \p normalOf(view).
mesh::Impostor syntheticAtlas(int grid, int cell,
                              const std::function<glm::vec3(const glm::vec3&)>& normalOf) {
    mesh::Impostor imp;
    imp.settings.grid = grid;
    imp.settings.cellPixels = cell;
    imp.settings.hemisphere = true;
    const int size = grid * cell;
    imp.color = Image(size, size, 4);
    imp.normal = Image(size, size, 3);
    imp.depth = Image(size, size, 1);
    for (int j = 0; j < grid; ++j)
        for (int i = 0; i < grid; ++i) {
            const glm::vec3 view =
                mesh::impostorViewDirection(glm::vec2(float(i), float(j)) / float(grid - 1), true);
            const glm::vec3 n = glm::normalize(normalOf(view));
            for (int y = j * cell; y < (j + 1) * cell; ++y)
                for (int x = i * cell; x < (i + 1) * cell; ++x) {
                    std::uint8_t* c = imp.color.at(x, y);
                    c[0] = c[1] = c[2] = 128;
                    c[3] = std::uint8_t((x + y) % 2 ? 255 : 0);
                    std::uint8_t* nm = imp.normal.at(x, y);
                    for (int k = 0; k < 3; ++k)
                        nm[k] = std::uint8_t(std::lround(127.5f * (n[k] + 1.0f)));
                }
        }
    return imp;
}

float luminance(const std::uint8_t* p) {
    return 0.2126f * float(p[0]) + 0.7152f * float(p[1]) + 0.0722f * float(p[2]);
}

// The light an orbit camera looking at the origin from \p view (toward the viewer) has.
glm::vec3 orbitLight(const glm::vec3& view) {
    ui::OrbitCamera camera;
    camera.lookFrom(10.0f * view, glm::vec3(0.0f));
    return ui::cameraKeyLight(camera.forward(), camera.up(), camera.right());
}

} // namespace

class TestImpostorLighting : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void keepsCoverageAndSize() {
        const mesh::Impostor imp = syntheticAtlas(4, 8, [](const glm::vec3& v) { return v; });
        const Image lit = ui::litImpostorAtlas(imp, 0.8f);
        QCOMPARE(lit.width, imp.color.width);
        QCOMPARE(lit.height, imp.color.height);
        QCOMPARE(lit.channels, 4);
        for (int y = 0; y < lit.height; ++y)
            for (int x = 0; x < lit.width; ++x)
                QCOMPARE(lit.at(x, y)[3], imp.color.at(x, y)[3]);
    }

    // Every view is lit by the light the orbit camera has when it looks along that view: a
    // texel facing that light is the brightest, one facing away from it the darkest, in
    // every cell (the views of the upper hemisphere but the very top, where the orbit
    // camera's pitch stops).
    void eachViewIsLitByTheCamerasKeyLight() {
        const int grid = 6, cell = 4;
        const mesh::Impostor toward =
            syntheticAtlas(grid, cell, [](const glm::vec3& v) { return orbitLight(v); });
        const mesh::Impostor away =
            syntheticAtlas(grid, cell, [](const glm::vec3& v) { return -orbitLight(v); });
        // A normal 60 degrees off the camera's light, toward the viewer.
        const mesh::Impostor aside = syntheticAtlas(grid, cell, [](const glm::vec3& v) {
            const glm::vec3 l = orbitLight(v);
            const glm::vec3 side = glm::normalize(glm::cross(l, glm::vec3(0.0f, 1.0f, 0.0f)));
            return 0.5f * l + 0.866f * side;
        });
        const Image litToward = ui::litImpostorAtlas(toward, 0.8f);
        const Image litAway = ui::litImpostorAtlas(away, 0.8f);
        const Image litAside = ui::litImpostorAtlas(aside, 0.8f);
        int checked = 0;
        for (int j = 0; j < grid; ++j)
            for (int i = 0; i < grid; ++i) {
                const glm::vec3 view = mesh::impostorViewDirection(
                    glm::vec2(float(i), float(j)) / float(grid - 1), true);
                if (view.y > 0.98f) continue;
                const int x = i * cell + 1, y = j * cell + 1;
                const float t = luminance(litToward.at(x, y));
                const float s = luminance(litAside.at(x, y));
                const float a = luminance(litAway.at(x, y));
                QVERIFY2(t > s + 10.0f && s > a + 10.0f,
                         qPrintable(QStringLiteral("cell %1,%2: toward %3, aside %4, away %5")
                                        .arg(i)
                                        .arg(j)
                                        .arg(double(t))
                                        .arg(double(s))
                                        .arg(double(a))));
                ++checked;
            }
        QVERIFY(checked >= grid * grid - 2);
    }

    // The mesh shader's formula (shaders/mesh.frag, the crown's occlusion 0.8 for the per-vertex
    // one): a grey albedo of 128 lit head-on by the key light.
    void matchesTheMeshShadersLighting() {
        const mesh::Impostor imp =
            syntheticAtlas(4, 4, [](const glm::vec3& v) { return orbitLight(v); });
        const Image lit = ui::litImpostorAtlas(imp, 0.8f);
        const float albedo = std::pow(128.0f / 255.0f, 2.0f);
        const std::uint8_t* p = lit.at(1 * 4 + 1, 1 * 4 + 1); // cell (1, 1): uv (1/3, 1/3)
        const glm::vec3 view11 = mesh::impostorViewDirection(glm::vec2(1.0f / 3.0f), true);
        const glm::vec3 n11 = orbitLight(view11);
        const glm::vec3 ambient11 = glm::mix(glm::vec3(0.30f, 0.25f, 0.20f),
                                             glm::vec3(0.62f, 0.70f, 0.85f), 0.5f * n11.y + 0.5f);
        const glm::vec3 expected11 =
            glm::sqrt(albedo * (0.55f * 0.8f * ambient11 +
                                1.35f * glm::vec3(1.0f, 0.96f, 0.90f) * (0.4f + 0.6f * 0.8f)));
        for (int k = 0; k < 3; ++k)
            QVERIFY2(std::abs(float(p[k]) - 255.0f * expected11[k]) <= 2.0f,
                     qPrintable(QStringLiteral("channel %1: %2, expected %3")
                                    .arg(k)
                                    .arg(int(p[k]))
                                    .arg(double(255.0f * expected11[k]))));
    }
};

QTEST_APPLESS_MAIN(TestImpostorLighting)
#include "test_impostorlighting.moc"
