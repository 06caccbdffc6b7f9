#include "ui/viewport/orbitcamera.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace sylva::ui {

OrbitCamera::OrbitCamera() = default;

void OrbitCamera::setDistance(float distance) {
    mDistance = std::clamp(distance, mMinDistance, mMaxDistance);
}

void OrbitCamera::setYaw(float radians) {
    // Keep yaw in (-pi, pi] so that it does not lose precision after long drags.
    const float twoPi = 2.0f * glm::pi<float>();
    mYaw = std::remainder(radians, twoPi);
}

void OrbitCamera::setPitch(float radians) {
    mPitch = std::clamp(radians, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::lookFrom(const glm::vec3& eye, const glm::vec3& target) {
    mTarget = target;
    const glm::vec3 d = eye - target;
    const float length = glm::length(d);
    if (!(length > 0.0f)) return;
    setYaw(std::atan2(d.x, d.z));
    setPitch(std::asin(std::clamp(d.y / length, -1.0f, 1.0f)));
    setDistance(length);
    keepAboveGround();
}

void OrbitCamera::setDistanceLimits(float minDistance, float maxDistance) {
    mMinDistance = std::max(minDistance, 1.0e-6f);
    mMaxDistance = std::max(maxDistance, mMinDistance);
    setDistance(mDistance);
}

glm::vec3 OrbitCamera::eye() const {
    return mTarget - forward() * mDistance;
}

glm::vec3 OrbitCamera::forward() const {
    const float cp = std::cos(mPitch);
    return -glm::vec3(cp * std::sin(mYaw), std::sin(mPitch), cp * std::cos(mYaw));
}

glm::vec3 OrbitCamera::right() const {
    // Horizontal by construction: the turntable never rolls.
    return glm::vec3(std::cos(mYaw), 0.0f, -std::sin(mYaw));
}

glm::vec3 OrbitCamera::up() const {
    return glm::cross(right(), forward());
}

glm::mat4 OrbitCamera::viewMatrix() const {
    return glm::lookAt(eye(), mTarget, up());
}

float OrbitCamera::nearPlane() const {
    return std::max(1.0e-4f, 0.01f * mDistance);
}

float OrbitCamera::farPlane() const {
    // Far enough for the scene and the ground grid (which extends a few radii around it).
    return 4.0f * mDistance + 12.0f * mSceneRadius;
}

glm::mat4 OrbitCamera::projectionMatrix(float aspect) const {
    return glm::perspective(mFovY, std::max(aspect, 1.0e-3f), nearPlane(), farPlane());
}

void OrbitCamera::orbit(float dxPixels, float dyPixels) {
    setYaw(mYaw - dxPixels * kRadiansPerPixel);
    setPitch(mPitch + dyPixels * kRadiansPerPixel);
    keepAboveGround();
}

void OrbitCamera::setGround(GroundHeight ground) {
    mGround = std::move(ground);
    keepAboveGround();
}

void OrbitCamera::keepAboveGround() {
    if (!mGround) return;
    // The ground under the eye changes as the eye rises (a slope, an obstacle's edge): a few
    // rounds settle it.
    for (int round = 0; round < 4; ++round) {
        const glm::vec3 e = eye();
        const float floorY = mGround(e.x, e.z) + kGroundClearance;
        if (!(e.y < floorY - 1e-4f)) return;
        const float s = (floorY - mTarget.y) / mDistance;
        if (s < std::sin(kMaxPitch)) {
            setPitch(std::max(mPitch, std::asin(std::max(s, -1.0f))));
        } else {
            mTarget.y += floorY - e.y; // the target itself is under the ground
        }
    }
}

void OrbitCamera::pan(float dxPixels, float dyPixels, float viewportHeight) {
    if (viewportHeight <= 0.0f) return;
    const float worldPerPixel = 2.0f * mDistance * std::tan(0.5f * mFovY) / viewportHeight;
    mTarget += (-dxPixels * right() + dyPixels * up()) * worldPerPixel;
    keepAboveGround();
}

void OrbitCamera::zoom(float steps) {
    setDistance(mDistance * std::pow(kZoomPerStep, steps));
    keepAboveGround();
}

void OrbitCamera::frame(const glm::vec3& lo, const glm::vec3& hi, float aspect) {
    std::array<glm::vec3, 8> corners;
    for (int corner = 0; corner < 8; ++corner)
        corners[std::size_t(corner)] = glm::vec3(
            (corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
    framePoints(corners, aspect);
}

void OrbitCamera::framePoints(std::span<const glm::vec3> points, float aspect) {
    if (points.empty()) {
        frame(glm::vec3(-0.5f, 0.0f, -0.5f), glm::vec3(0.5f, 1.0f, 0.5f), aspect);
        return;
    }
    glm::vec3 lo = points.front(), hi = points.front();
    for (const glm::vec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    mSceneRadius = std::max(0.5f * glm::length(hi - lo), 1.0e-3f);
    mTarget = 0.5f * (lo + hi);
    // Back off until every point projects inside kFrameFill of the half-width and half-height.
    // A point at view-space offset (x, y, z) from the target (z towards the viewer) sits at
    // depth d - z, so it fits when d >= |x| / tanX + z (and the same for y).
    const float tanY = kFrameFill * std::tan(0.5f * mFovY);
    const float tanX = tanY * std::max(aspect, 1.0e-3f);
    const glm::vec3 r = right(), u = up(), toEye = -forward();
    float fit = 0.0f;
    for (const glm::vec3& p : points) {
        const glm::vec3 offset = p - mTarget;
        const float z = glm::dot(offset, toEye);
        fit = std::max({fit, std::abs(glm::dot(offset, r)) / tanX + z,
                        std::abs(glm::dot(offset, u)) / tanY + z});
    }
    // A flat or tiny scene still needs a sensible distance in front of the near plane.
    fit = std::max(fit, 0.5f * mSceneRadius);
    mMinDistance = 0.01f * mSceneRadius;
    mMaxDistance = std::max(20.0f * std::max(fit, mSceneRadius), mMinDistance);
    setDistance(fit);
    keepAboveGround();
}

} // namespace sylva::ui
