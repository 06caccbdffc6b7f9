#include "engine/wind/windmodel.h"

#include <algorithm>
#include <cmath>

#include "engine/util/error.h"

namespace sylva::wind {

namespace {

constexpr float kTwoPi = 6.28318530717958647692f;

// Half-up rounding, written the way the shader writes it (GLSL's round() may go either way on
// .5), so that CPU and GPU agree on every whole number of cycles.
float roundCycles(float x) {
    return std::max(1.0f, std::floor(x + 0.5f));
}

} // namespace

void validate(const WindSettings& s) {
    requireRange("wind strength", s.strength, kStrengthRange.lo, kStrengthRange.hi);
    requireRange("wind gustiness", s.gustiness, kGustinessRange.lo, kGustinessRange.hi);
    requireRange("wind frequency", s.frequency, kFrequencyRange.lo, kFrequencyRange.hi);
    requireRange("wind period", s.period, kPeriodRange.lo, kPeriodRange.hi);
    if (!std::isfinite(s.direction.x) || !std::isfinite(s.direction.y) ||
        !std::isfinite(s.direction.z))
        throw InvalidInput("wind direction must be three finite numbers");
}

glm::vec3 horizontalDirection(const WindSettings& s) {
    const glm::vec3 d(s.direction.x, 0.0f, s.direction.z);
    const float len = glm::length(d);
    return len > 1e-6f ? d / len : glm::vec3(1, 0, 0);
}

WindFrame windFrame(const WindSettings& s, double seconds) {
    WindFrame f;
    f.direction = horizontalDirection(s);
    f.strength = s.strength;
    f.gustiness = s.gustiness;
    const double period = s.period;
    double t = std::fmod(seconds, period);
    if (t < 0.0) t += period;
    f.time = static_cast<float>(t);
    f.omega = static_cast<float>(6.283185307179586 / period);
    f.baseCycles = roundCycles(s.frequency * s.period);
    return f;
}

float elementStiffness(int level, float radius, float length) {
    static constexpr float kLevel[3] = {15.0f, 6.0f, 3.5f};
    const float slenderness = std::clamp(60.0f * radius / std::max(length, 1e-4f), 0.33f, 3.0f);
    return kLevel[std::clamp(level, 0, 2)] * slenderness;
}

glm::vec3 rotate(const glm::vec3& r, const glm::vec3& v) {
    const float angle = glm::length(r);
    if (angle < 1e-8f) return v + glm::cross(r, v);
    const glm::vec3 k = r / angle;
    const float c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * (glm::dot(k, v) * (1.0f - c));
}

glm::vec3 elementRotation(const WindFrame& f, const glm::vec3& dir, float stiffness, float phase,
                          int level, float treePhase) {
    if (stiffness <= 0.0f || f.strength <= 0.0f) return glm::vec3(0.0f);
    const float t = f.time, w = f.omega, S = f.strength;
    // Gusts: two slow waves per tree (the pressure never drops below S²(1 − G) ≥ 0).
    const float g1 = roundCycles(0.5f * f.baseCycles);
    const float gust = 0.6f * std::sin(w * g1 * t + kTwoPi * treePhase) +
                       0.4f * std::sin(w * (g1 + 1.0f) * t + kTwoPi * (1.7f * treePhase + 0.3f));
    const float pressure = S * S * (1.0f + f.gustiness * gust);
    // Each element sways at a frequency of its own, higher for smaller elements.
    const float n = roundCycles(f.baseCycles * (1.0f + 0.6f * static_cast<float>(level)) *
                                (0.85f + 0.3f * phase));
    const float along = std::sin(w * n * t + kTwoPi * phase);
    const float across = std::sin(w * (n + 1.0f) * t + kTwoPi * (phase + 0.25f));
    const glm::vec3 drag = glm::cross(dir, f.direction); // bends down-wind, 0 along the wind
    const glm::vec3 side = glm::cross(dir, drag);        // sways across the wind
    glm::vec3 r = ((pressure + 0.35f * S * along) * drag + 0.25f * S * across * side) / stiffness;
    // Saturation: stronger wind bends more, but never past a limit (the trunk less than limbs).
    const float limit = level == 0 ? 0.3f : 0.6f;
    const float angle = glm::length(r);
    if (angle > 1e-8f) r *= limit * std::tanh(angle / limit) / angle;
    return r;
}

glm::vec3 displace(const mesh::WindVertex& v, const glm::vec3& position, glm::vec3* normal,
                   const WindFrame& f) {
    glm::vec3 p = position;
    glm::vec3 n = normal ? *normal : glm::vec3(0.0f);
    if (v.leaf.y > 0.0f && f.strength > 0.0f) {
        const float len = glm::length(n);
        if (len > 1e-12f) {
            const float cycles = roundCycles(f.baseCycles * 6.0f * (0.8f + 0.4f * v.phase.w));
            const float flutter = v.leaf.y * f.strength * (0.2f + 0.15f * f.gustiness) *
                                  std::sin(f.omega * cycles * f.time + kTwoPi * v.phase.w);
            p += n * (flutter / len);
        }
    }
    for (int level = 2; level >= 0; --level) {
        const glm::vec4& b = v.branch[level];
        if (b.w <= 0.0f) continue;
        const glm::vec3 r =
            elementRotation(f, glm::vec3(b), b.w, v.phase[level], level, v.phase.x) *
            bendProfile(v.pivot[level].w);
        const glm::vec3 pivot(v.pivot[level]);
        p = pivot + rotate(r, p - pivot);
        n = rotate(r, n);
    }
    p.y = std::max(p.y, std::min(position.y, v.pivot[0].y));
    if (normal) *normal = n;
    return p;
}

} // namespace sylva::wind
