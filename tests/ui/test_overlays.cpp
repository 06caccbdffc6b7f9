// The bands a tool's wide overlay lines are drawn as (ui/viewport/overlays.h: screenBands):
// as wide on screen as asked whatever the distance, cut at the near plane, none for thin lines.
// Pure: no GL context.

#include <algorithm>
#include <cmath>
#include <vector>

#include <QTest>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "ui/viewport/overlays.h"

using sylva::ui::OverlayLine;
using sylva::ui::screenBands;

namespace {

const glm::vec2 kPixels(800.0f, 600.0f);

glm::mat4 camera() {
    return glm::perspective(0.8f, kPixels.x / kPixels.y, 0.1f, 1000.0f) *
           glm::lookAt(glm::vec3(0.0f, 0.0f, 10.0f), glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

/// The band's vertices in pixels (x, y), six per line.
std::vector<glm::vec2> inPixels(const std::vector<float>& bands) {
    std::vector<glm::vec2> out;
    for (std::size_t i = 0; i + 7 <= bands.size(); i += 7)
        out.push_back((glm::vec2(bands[i], bands[i + 1]) * 0.5f + 0.5f) * kPixels);
    return out;
}

} // namespace

class TestOverlays : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // A vertical line near and one far: both bands are 4 px across and reach 2 px past their
    // ends (square ends close a polyline's joints).
    void widthIsInPixelsAtAnyDistance() {
        for (const float z : {5.0f, -200.0f}) {
            const OverlayLine line{{0.0f, -1.0f, z}, {0.0f, 1.0f, z}, {1, 1, 0, 1}, 4.0f};
            const std::vector<glm::vec2> v = inPixels(screenBands({line}, camera(), kPixels));
            QCOMPARE(v.size(), std::size_t(6));
            float xLo = 1e9f, xHi = -1e9f, yLo = 1e9f, yHi = -1e9f;
            for (const glm::vec2& p : v) {
                xLo = std::min(xLo, p.x);
                xHi = std::max(xHi, p.x);
                yLo = std::min(yLo, p.y);
                yHi = std::max(yHi, p.y);
            }
            QVERIFY2(std::abs((xHi - xLo) - 4.0f) < 1e-3f, qPrintable(QString::number(xHi - xLo)));
            QVERIFY(std::abs((xHi + xLo) * 0.5f - 400.0f) < 1e-3f); // centred on the line
            // The line's own length on screen plus 2 px at either end.
            const glm::vec4 a = camera() * glm::vec4(line.a, 1.0f);
            const glm::vec4 b = camera() * glm::vec4(line.b, 1.0f);
            const float len = (b.y / b.w - a.y / a.w) * 0.5f * kPixels.y;
            QVERIFY2(std::abs((yHi - yLo) - (len + 4.0f)) < 1e-2f,
                     qPrintable(QString("%1 vs %2").arg(yHi - yLo).arg(len + 4.0f)));
        }
    }

    // The colour and depth carried to every vertex; a thin line is left to GL_LINES.
    void carriesColourSkipsThinLines() {
        const OverlayLine wide{{-1, 0, 0}, {1, 0, 0}, {0.2f, 0.4f, 0.6f, 0.8f}, 3.0f};
        const OverlayLine thin{{-1, 1, 0}, {1, 1, 0}, {1, 1, 1, 1}, 1.0f};
        const std::vector<float> bands = screenBands({thin, wide, thin}, camera(), kPixels);
        QCOMPARE(bands.size(), std::size_t(6 * 7));
        for (std::size_t i = 0; i < bands.size(); i += 7) {
            QCOMPARE(bands[i + 3], 0.2f);
            QCOMPARE(bands[i + 6], 0.8f);
            QVERIFY(bands[i + 2] > -1.0f && bands[i + 2] < 1.0f); // inside the depth range
        }
    }

    // Behind the camera: nothing; crossing the near plane: cut there, every vertex finite and
    // in front.
    void nearPlane() {
        const OverlayLine behind{{0, 0, 20}, {0, 1, 30}, {1, 1, 1, 1}, 3.0f};
        QVERIFY(screenBands({behind}, camera(), kPixels).empty());
        const OverlayLine crossing{{0.5f, 0, 20}, {0.5f, 0, 0}, {1, 1, 1, 1}, 3.0f};
        const std::vector<float> bands = screenBands({crossing}, camera(), kPixels);
        QCOMPARE(bands.size(), std::size_t(6 * 7));
        for (std::size_t i = 0; i < bands.size(); i += 7) {
            QVERIFY(std::isfinite(bands[i]) && std::isfinite(bands[i + 1]));
            QVERIFY(bands[i + 2] >= -1.0f - 1e-4f && bands[i + 2] <= 1.0f);
        }
        QVERIFY(screenBands({crossing}, camera(), glm::vec2(0.0f)).empty()); // no view yet
    }
};

QTEST_APPLESS_MAIN(TestOverlays)
#include "test_overlays.moc"
