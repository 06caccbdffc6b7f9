// The orbit camera's math, checked against hand-computed positions and projections.

#include <cmath>

#include <QTest>

#include <glm/glm.hpp>
#include <glm/gtc/constants.hpp>

#include "ui/viewport/orbitcamera.h"

using sylva::ui::OrbitCamera;

namespace {

bool near(float a, float b, float tolerance = 1e-4f) {
    return std::abs(a - b) <= tolerance;
}

bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-4f) {
    return glm::length(a - b) <= tolerance;
}

/// Pixel position of a world point in a width x height viewport (y down, like Qt).
glm::vec2 toScreen(const OrbitCamera& camera, const glm::vec3& p, float width, float height) {
    const glm::vec4 clip =
        camera.projectionMatrix(width / height) * camera.viewMatrix() * glm::vec4(p, 1.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x * 0.5f + 0.5f) * width, (0.5f - ndc.y * 0.5f) * height};
}

} // namespace

class TestOrbitCamera : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void eyeAtKnownAngles() {
        OrbitCamera camera;
        camera.setTarget({1.0f, 2.0f, 3.0f});
        camera.setDistance(5.0f);
        camera.setYaw(0.0f);
        camera.setPitch(0.0f);
        QVERIFY(near(camera.eye(), {1.0f, 2.0f, 8.0f}));
        QVERIFY(near(camera.forward(), {0.0f, 0.0f, -1.0f}));
        QVERIFY(near(camera.right(), {1.0f, 0.0f, 0.0f}));
        QVERIFY(near(camera.up(), {0.0f, 1.0f, 0.0f}));

        camera.setYaw(glm::half_pi<float>());
        QVERIFY(near(camera.eye(), {6.0f, 2.0f, 3.0f}));
        QVERIFY(near(camera.right(), {0.0f, 0.0f, -1.0f}));

        // 30 degrees up: eye rises by d sin 30 = 2.5 and comes in to d cos 30.
        camera.setYaw(0.0f);
        camera.setPitch(glm::radians(30.0f));
        QVERIFY(near(camera.eye(), {1.0f, 4.5f, 3.0f + 5.0f * std::sqrt(3.0f) / 2.0f}));
    }

    void looksFromAProjectsCamera() {
        OrbitCamera camera;
        camera.setDistanceLimits(0.1f, 1000.0f);
        // The demo project's camera: from (0, 25, 70) at (0, 5, 0).
        camera.lookFrom({0.0f, 25.0f, 70.0f}, {0.0f, 5.0f, 0.0f});
        QVERIFY(near(camera.eye(), {0.0f, 25.0f, 70.0f}));
        QVERIFY(near(camera.target(), {0.0f, 5.0f, 0.0f}));
        QVERIFY(near(camera.pitch(), std::atan2(20.0f, 70.0f)));
        QVERIFY(near(camera.forward(), glm::normalize(glm::vec3(0.0f, -20.0f, -70.0f))));
        // From -X, below the target, and from straight above (clamped short of the pole).
        camera.lookFrom({-3.0f, -1.0f, 0.0f}, {1.0f, 2.0f, 0.0f});
        QVERIFY(near(camera.eye(), {-3.0f, -1.0f, 0.0f}));
        QVERIFY(near(camera.yaw(), -glm::half_pi<float>()));
        camera.lookFrom({0.0f, 10.0f, 0.0f}, {0.0f, 0.0f, 0.0f});
        QCOMPARE(camera.pitch(), OrbitCamera::kMaxPitch);
        QVERIFY(near(camera.distance(), 10.0f));
        // An eye on the target keeps the angles; the distance limits clamp a far eye.
        const float yaw = camera.yaw();
        camera.lookFrom({2.0f, 2.0f, 2.0f}, {2.0f, 2.0f, 2.0f});
        QCOMPARE(camera.yaw(), yaw);
        camera.lookFrom({0.0f, 0.0f, 5000.0f}, {0.0f, 0.0f, 0.0f});
        QCOMPARE(camera.distance(), 1000.0f);
    }

    void pitchIsClampedShortOfThePole() {
        OrbitCamera camera;
        camera.setPitch(glm::radians(120.0f));
        QCOMPARE(camera.pitch(), OrbitCamera::kMaxPitch);
        camera.setPitch(-10.0f);
        QCOMPARE(camera.pitch(), -OrbitCamera::kMaxPitch);
        // Near the pole the frame is still orthonormal (no flip, no NaN).
        QVERIFY(near(glm::dot(camera.up(), camera.forward()), 0.0f));
        QVERIFY(near(glm::length(camera.up()), 1.0f));
        QVERIFY(camera.up().y > 0.0f);
    }

    void viewMatrixPutsTargetOnTheAxis() {
        OrbitCamera camera;
        camera.setTarget({-2.0f, 0.5f, 4.0f});
        camera.setDistance(7.0f);
        camera.setYaw(0.7f);
        camera.setPitch(-0.3f);
        const glm::vec4 t = camera.viewMatrix() * glm::vec4(camera.target(), 1.0f);
        QVERIFY(near(glm::vec3(t), {0.0f, 0.0f, -7.0f}));
        const glm::vec4 e = camera.viewMatrix() * glm::vec4(camera.eye(), 1.0f);
        QVERIFY(near(glm::vec3(e), {0.0f, 0.0f, 0.0f}));
    }

    void orbitTurnsByPixels() {
        OrbitCamera camera;
        camera.setYaw(0.0f);
        camera.setPitch(0.0f);
        camera.orbit(100.0f, 0.0f);
        QVERIFY(near(camera.yaw(), -100.0f * OrbitCamera::kRadiansPerPixel));
        QVERIFY(near(camera.pitch(), 0.0f));
        camera.orbit(0.0f, 30.0f);
        QVERIFY(near(camera.pitch(), 30.0f * OrbitCamera::kRadiansPerPixel));
        camera.orbit(0.0f, 1.0e4f);
        QCOMPARE(camera.pitch(), OrbitCamera::kMaxPitch);
        // Dragging right moves the eye to the left around the target: from +Z towards -X.
        camera.setPitch(0.0f);
        camera.setYaw(0.0f);
        camera.orbit(10.0f, 0.0f);
        QVERIFY(camera.eye().x < camera.target().x);
        // Yaw wraps instead of growing without bound.
        camera.setYaw(0.0f);
        for (int i = 0; i < 100; ++i)
            camera.orbit(1000.0f, 0.0f);
        QVERIFY(std::abs(camera.yaw()) <= glm::pi<float>() + 1e-5f);
        QVERIFY(near(camera.yaw(), std::remainder(-1000.0f, glm::two_pi<float>()), 1e-2f));
    }

    void panMovesTheTargetWithTheCursor() {
        OrbitCamera camera;
        camera.setTarget({0.0f, 3.0f, 0.0f});
        camera.setDistance(12.0f);
        camera.setYaw(0.4f);
        camera.setPitch(0.2f);
        const float width = 800.0f, height = 600.0f;
        const glm::vec3 point = camera.target();
        const glm::vec2 before = toScreen(camera, point, width, height);
        QVERIFY(near(before.x, 400.0f, 1e-2f) && near(before.y, 300.0f, 1e-2f));
        camera.pan(50.0f, -20.0f, height);
        // The world point that was under the cursor is still under it.
        const glm::vec2 after = toScreen(camera, point, width, height);
        QVERIFY2(near(after.x, before.x + 50.0f, 0.05f), qPrintable(QString::number(after.x)));
        QVERIFY2(near(after.y, before.y - 20.0f, 0.05f), qPrintable(QString::number(after.y)));
        // Panning keeps the distance and the viewing direction.
        QVERIFY(near(camera.distance(), 12.0f));
        QVERIFY(near(camera.eye() - camera.target(), -12.0f * camera.forward()));
    }

    void zoomScalesAndClamps() {
        OrbitCamera camera;
        camera.setDistanceLimits(1.0f, 100.0f);
        camera.setDistance(10.0f);
        camera.zoom(1.0f);
        QVERIFY(near(camera.distance(), 10.0f * OrbitCamera::kZoomPerStep));
        camera.zoom(-2.0f);
        QVERIFY(near(camera.distance(), 10.0f / OrbitCamera::kZoomPerStep));
        camera.zoom(1000.0f);
        QCOMPARE(camera.distance(), 1.0f);
        camera.zoom(-1000.0f);
        QCOMPARE(camera.distance(), 100.0f);
    }

    void frameFitsTheBox_data() {
        QTest::addColumn<float>("aspect");
        QTest::addColumn<float>("sx");
        QTest::addColumn<float>("sy");
        QTest::addColumn<float>("sz");
        QTest::newRow("tall tree, landscape") << 4.0f / 3.0f << 3.0f << 10.0f << 3.0f;
        QTest::newRow("wide crown, portrait") << 0.5f << 20.0f << 6.0f << 18.0f;
        QTest::newRow("tiny seedling, square") << 1.0f << 0.02f << 0.1f << 0.02f;
    }

    void frameFitsTheBox() {
        QFETCH(float, aspect);
        QFETCH(float, sx);
        QFETCH(float, sy);
        QFETCH(float, sz);
        const glm::vec3 lo(-0.5f * sx + 1.0f, 0.0f, -0.5f * sz - 2.0f);
        const glm::vec3 hi = lo + glm::vec3(sx, sy, sz);
        for (float yaw : {0.0f, 1.0f, 2.5f, -2.0f}) {
            for (float pitch : {-0.5f, 0.0f, 0.3f, 1.2f}) {
                OrbitCamera camera;
                camera.setYaw(yaw);
                camera.setPitch(pitch);
                camera.frame(lo, hi, aspect);
                QVERIFY(near(camera.target(), 0.5f * (lo + hi)));
                const glm::mat4 vp = camera.projectionMatrix(aspect) * camera.viewMatrix();
                float largest = 0.0f;
                for (int corner = 0; corner < 8; ++corner) {
                    const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                                      (corner & 4) ? hi.z : lo.z);
                    const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
                    QVERIFY(clip.w > 0.0f);
                    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
                    // Every corner is on screen and between the near and far planes.
                    QVERIFY2(std::abs(ndc.x) < 1.0f && std::abs(ndc.y) < 1.0f,
                             qPrintable(QStringLiteral("corner %1 at %2, %3")
                                            .arg(corner)
                                            .arg(ndc.x)
                                            .arg(ndc.y)));
                    QVERIFY(ndc.z > -1.0f && ndc.z < 1.0f);
                    largest = std::max({largest, std::abs(ndc.x), std::abs(ndc.y)});
                }
                // ...and the box is not lost in the middle.
                QVERIFY2(largest > 0.85f, qPrintable(QString::number(largest)));
            }
        }
    }

    void frameIsTight() {
        // The tightest corner touches the frame margin exactly: the box fills the view.
        const glm::vec3 lo(-1.0f, 0.0f, -1.5f), hi(2.0f, 9.0f, 1.0f);
        for (float aspect : {0.5f, 1.0f, 1.6f}) {
            OrbitCamera camera;
            camera.setYaw(0.6f);
            camera.setPitch(0.25f);
            camera.frame(lo, hi, aspect);
            const glm::mat4 vp = camera.projectionMatrix(aspect) * camera.viewMatrix();
            float largest = 0.0f;
            for (int corner = 0; corner < 8; ++corner) {
                const glm::vec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y,
                                  (corner & 4) ? hi.z : lo.z);
                const glm::vec4 clip = vp * glm::vec4(p, 1.0f);
                largest = std::max({largest, std::abs(clip.x / clip.w), std::abs(clip.y / clip.w)});
            }
            QVERIFY2(near(largest, OrbitCamera::kFrameFill, 1e-3f),
                     qPrintable(QString::number(largest)));
            QVERIFY(camera.minDistance() < camera.distance());
            QVERIFY(camera.maxDistance() > camera.distance());
        }
        // Head-on (yaw = pitch = 0) on a 2 x 4 x 2 box in a square view the height limits: the
        // near top corners are 2 above and 1 in front of the target, so d = 2 / (0.9 tan 20°) + 1.
        OrbitCamera camera;
        camera.setYaw(0.0f);
        camera.setPitch(0.0f);
        camera.frame({-1.0f, 0.0f, -1.0f}, {1.0f, 4.0f, 1.0f}, 1.0f);
        const float expected =
            2.0f / (OrbitCamera::kFrameFill * std::tan(0.5f * camera.fovY())) + 1.0f;
        QVERIFY2(near(camera.distance(), expected, 1e-4f),
                 qPrintable(QStringLiteral("%1 vs %2").arg(camera.distance()).arg(expected)));
        QVERIFY(near(camera.target(), {0.0f, 2.0f, 0.0f}));
    }
};

QTEST_APPLESS_MAIN(TestOrbitCamera)
#include "test_orbitcamera.moc"
