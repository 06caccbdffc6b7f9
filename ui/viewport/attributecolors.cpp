#include "ui/viewport/attributecolors.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <QCoreApplication>

#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"

namespace sylva::ui {

namespace {

// Light per internode and the largest raw value of the attribute (for the legend).
struct Raw {
    std::vector<float> value;
    float max = 0.0f;
    std::size_t starved = 0; ///< Light: metamers flagged kStarved
    float threshold = 0.0f;  ///< Light: the skeleton's shedding threshold
};

Raw rawAttribute(const skel::Skeleton& s, ColorBy mode) {
    const std::size_t n = s.size();
    Raw raw;
    if (!hasAttribute(s, mode) || mode == ColorBy::Material) return raw;
    raw.value.resize(n);
    switch (mode) {
    case ColorBy::Light: {
        // Metamers (nodes with a parent) in each subtree, children after parents.
        std::vector<float> count(n, 0.0f);
        for (std::size_t i = n; i-- > 0;) {
            if (s.parent[i] < 0) continue;
            count[i] += 1.0f;
            count[static_cast<std::size_t>(s.parent[i])] += count[i];
        }
        for (std::size_t i = 0; i < n; ++i) {
            raw.value[i] = count[i] > 0.0f ? s.light[i] / count[i] : s.light[i];
            raw.starved += s.parent[i] >= 0 && (s.flags[i] & skel::kStarved) ? 1 : 0;
        }
        raw.threshold = s.shedThreshold;
        break;
    }
    case ColorBy::Vigour:
        for (std::size_t i = 0; i < n; ++i)
            raw.value[i] = std::max(s.vigour[i], 0.0f);
        break;
    case ColorBy::Age:
        for (std::size_t i = 0; i < n; ++i)
            raw.value[i] = static_cast<float>(s.age[i]);
        break;
    case ColorBy::BranchOrder:
        for (std::size_t i = 0; i < n; ++i)
            raw.value[i] = static_cast<float>(s.order[i]);
        break;
    case ColorBy::Material:
        break;
    }
    for (float v : raw.value)
        if (std::isfinite(v)) raw.max = std::max(raw.max, v);
    return raw;
}

QString attributeName(ColorBy mode) {
    switch (mode) {
    case ColorBy::Light:
        return QCoreApplication::translate("AttributeColors", "Light per internode");
    case ColorBy::Vigour:
        return QCoreApplication::translate("AttributeColors", "Vigour (log scale)");
    case ColorBy::Age:
        return QCoreApplication::translate("AttributeColors", "Age in cycles");
    case ColorBy::BranchOrder:
        return QCoreApplication::translate("AttributeColors", "Branch order");
    case ColorBy::Material:
        break;
    }
    return QCoreApplication::translate("AttributeColors", "Materials");
}

// The raw values scaled to 0..1 for the ramp (see normalizedAttribute()).
std::vector<float> normalized(Raw raw, ColorBy mode) {
    if (raw.value.empty()) return {};
    if (mode == ColorBy::Vigour) {
        const float scale = raw.max > 0.0f ? 1.0f / std::log1p(raw.max) : 0.0f;
        for (float& v : raw.value)
            v = std::log1p(v) * scale;
    } else {
        const float scale = raw.max > 0.0f ? 1.0f / raw.max : 0.0f;
        for (float& v : raw.value)
            v *= scale;
    }
    for (float& v : raw.value)
        v = std::isfinite(v) ? std::clamp(v, 0.0f, 1.0f) : 0.0f;
    return std::move(raw.value);
}

QString legendOf(const Raw& raw, ColorBy mode) {
    if (mode == ColorBy::Material) return attributeName(mode);
    if (raw.value.empty())
        return QCoreApplication::translate("AttributeColors", "%1: not available for this tree")
            .arg(attributeName(mode));
    QString legend = QCoreApplication::translate("AttributeColors", "%1: 0 (blue) – %2 (yellow)")
                         .arg(attributeName(mode))
                         .arg(double(raw.max), 0, 'g', 3);
    if (mode == ColorBy::Light && raw.threshold > 0.0f) {
        legend += raw.starved > 0
                      ? QCoreApplication::translate(
                            "AttributeColors",
                            "; red: %1 internodes in branches below the shedding threshold %2, "
                            "shed at the next cycle")
                            .arg(qulonglong(raw.starved))
                            .arg(double(raw.threshold), 0, 'g', 3)
                      : QCoreApplication::translate(
                            "AttributeColors", "; no branch is below the shedding threshold %1")
                            .arg(double(raw.threshold), 0, 'g', 3);
    }
    return legend;
}

// One ramp colour per vertex from its node's 0..1 value (Light: kStarvedColor for starved
// nodes); empty without node ids or values.
std::vector<glm::vec3> vertexColors(const mesh::Mesh& mesh, const skel::Skeleton& s, ColorBy mode,
                                    const std::vector<float>& t) {
    if (t.empty() || mesh.node.size() != mesh.positions.size()) return {};
    const bool markStarved = mode == ColorBy::Light && s.flags.size() == t.size();
    std::vector<glm::vec3> colors(mesh.positions.size());
    for (std::size_t v = 0; v < colors.size(); ++v) {
        const std::uint32_t node = mesh.node[v];
        if (node < t.size() && markStarved && (s.flags[node] & skel::kStarved))
            colors[v] = kStarvedColor;
        else
            colors[v] = rampColor(node < t.size() ? t[node] : 0.0f);
    }
    return colors;
}

} // namespace

bool hasAttribute(const skel::Skeleton& s, ColorBy mode) {
    switch (mode) {
    case ColorBy::Material:
    case ColorBy::BranchOrder:
        return true;
    case ColorBy::Light:
        return !s.light.empty() && s.light.size() == s.size();
    case ColorBy::Vigour:
        return !s.vigour.empty() && s.vigour.size() == s.size();
    case ColorBy::Age:
        return !s.age.empty() && s.age.size() == s.size();
    }
    return false;
}

std::vector<float> normalizedAttribute(const skel::Skeleton& s, ColorBy mode) {
    return normalized(rawAttribute(s, mode), mode);
}

glm::vec3 rampColor(float t) {
    // Five stops, roughly viridis in linear RGB.
    static constexpr std::array<glm::vec3, 5> kStops = {
        glm::vec3(0.040f, 0.010f, 0.120f), glm::vec3(0.030f, 0.120f, 0.330f),
        glm::vec3(0.015f, 0.330f, 0.300f), glm::vec3(0.200f, 0.600f, 0.060f),
        glm::vec3(0.950f, 0.850f, 0.020f)};
    const float x = std::clamp(std::isfinite(t) ? t : 0.0f, 0.0f, 1.0f) * 4.0f;
    const auto i = std::min(static_cast<std::size_t>(x), std::size_t{3});
    return glm::mix(kStops[i], kStops[i + 1], x - static_cast<float>(i));
}

std::vector<glm::vec3> attributeColors(const mesh::Mesh& mesh, const skel::Skeleton& skeleton,
                                       ColorBy mode) {
    if (mode == ColorBy::Material) return {};
    return vertexColors(mesh, skeleton, mode, normalizedAttribute(skeleton, mode));
}

QString attributeLegend(const skel::Skeleton& skeleton, ColorBy mode) {
    return legendOf(rawAttribute(skeleton, mode), mode);
}

AttributeColoring colorByAttribute(const mesh::Mesh& mesh, const skel::Skeleton& skeleton,
                                   ColorBy mode) {
    Raw raw = rawAttribute(skeleton, mode); // one pass over the skeleton for both
    AttributeColoring out;
    out.legend = legendOf(raw, mode);
    if (mode != ColorBy::Material)
        out.colors = vertexColors(mesh, skeleton, mode, normalized(std::move(raw), mode));
    return out;
}

} // namespace sylva::ui
