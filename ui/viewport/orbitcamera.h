#pragma once

#include <functional>
#include <span>

#include <glm/glm.hpp>

namespace sylva::ui {

/// A turntable camera that orbits a target point. Pure math (no GL, no Qt) so that it is
/// testable without a display. Y is up; yaw turns around +Y, pitch tilts towards +Y.
///
/// The eye sits at target + distance * (cos(pitch) sin(yaw), sin(pitch), cos(pitch) cos(yaw)),
/// so yaw = pitch = 0 looks from +Z towards -Z.
class OrbitCamera {
public:
    /// Radians of yaw/pitch per pixel of mouse drag.
    static constexpr float kRadiansPerPixel = 0.01f;
    /// Distance factor per wheel step (one notch = 120 eighths of a degree).
    static constexpr float kZoomPerStep = 0.85f;
    /// Pitch stays inside +-kMaxPitch so that the view never flips over the pole.
    static constexpr float kMaxPitch = glm::radians(89.0f);
    /// frame() leaves this fraction of the half-width and half-height to the framed box.
    static constexpr float kFrameFill = 0.9f;

    OrbitCamera();

    glm::vec3 target() const { return mTarget; }
    float distance() const { return mDistance; }
    float yaw() const { return mYaw; }
    float pitch() const { return mPitch; }
    /// Vertical field of view in radians.
    float fovY() const { return mFovY; }

    void setTarget(const glm::vec3& target) { mTarget = target; }
    /// Clamped to [minDistance, maxDistance].
    void setDistance(float distance);
    void setYaw(float radians);
    /// Clamped to [-kMaxPitch, kMaxPitch].
    void setPitch(float radians);
    void setDistanceLimits(float minDistance, float maxDistance);
    float minDistance() const { return mMinDistance; }
    float maxDistance() const { return mMaxDistance; }

    /// World-space eye position.
    glm::vec3 eye() const;
    /// Unit vectors of the view: forward (eye -> target), right and up on screen.
    glm::vec3 forward() const;
    glm::vec3 right() const;
    glm::vec3 up() const;

    glm::mat4 viewMatrix() const;
    /// Perspective projection for a viewport of the given aspect ratio (width / height); near
    /// and far planes follow the distance and the framed radius so depth precision stays good.
    glm::mat4 projectionMatrix(float aspect) const;
    float nearPlane() const;
    float farPlane() const;

    /// Looks from \p eye at \p target (a project's camera): target, yaw, pitch and distance
    /// such that eye() == \p eye, unless the pitch or distance limits clamp it. An eye on the
    /// target keeps the current angles.
    void lookFrom(const glm::vec3& eye, const glm::vec3& target);

    /// Drag to orbit: dx/dy are mouse deltas in pixels (right/down positive). Dragging right
    /// turns the scene right (the eye moves left), dragging down tilts the eye upward.
    void orbit(float dxPixels, float dyPixels);
    /// Drag to pan: the point under the cursor at the target's depth follows the mouse.
    /// \param viewportHeight in pixels (> 0).
    void pan(float dxPixels, float dyPixels, float viewportHeight);
    /// Wheel zoom: positive steps move closer (distance *= kZoomPerStep^steps).
    void zoom(float steps);

    /// Aims at the centre of the box [lo, hi] and backs off until all eight corners project
    /// inside kFrameFill of the view of the given aspect ratio (so the tree is never clipped and
    /// fills the view). Keeps yaw and pitch. Also sets the distance limits so that the user can
    /// zoom from 1/100 of the box's radius to 20 times the framing distance.
    void frame(const glm::vec3& lo, const glm::vec3& hi, float aspect);
    /// Like frame(), but fits the points themselves rather than their bounding box, which
    /// frames a dome-shaped crown much tighter. The target is still the bounds' centre so
    /// that orbiting turns around the middle of the tree.
    void framePoints(std::span<const glm::vec3> points, float aspect);

    /// Radius of the last framed bounds (metres); 1 before any frame().
    float sceneRadius() const { return mSceneRadius; }

    /// The height of the ground (terrain, obstacles) under a point (x, z) of the world.
    using GroundHeight = std::function<float(float x, float z)>;
    /// With a ground, orbit(), pan(), zoom(), lookFrom() and frame() keep the eye at least
    /// kGroundClearance above it, as DCC viewports and game editors do: the pitch stops where
    /// the eye would go under (or, when no pitch can, the target rises). Without one (the
    /// default), the camera goes anywhere.
    void setGround(GroundHeight ground);
    static constexpr float kGroundClearance = 0.3f;

private:
    glm::vec3 mTarget{0.0f, 1.0f, 0.0f};
    float mDistance = 5.0f;
    float mYaw = glm::radians(30.0f);
    float mPitch = glm::radians(12.0f);
    float mFovY = glm::radians(40.0f);
    float mMinDistance = 0.01f;
    float mMaxDistance = 1.0e5f;
    float mSceneRadius = 1.0f;
    GroundHeight mGround;

    void keepAboveGround();
};

} // namespace sylva::ui
