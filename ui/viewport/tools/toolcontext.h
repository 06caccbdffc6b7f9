#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <QPoint>
#include <QString>

#include <glm/glm.hpp>

namespace sylva::doc {
class Document;
}

namespace sylva::ui {

class Viewport;
struct GenerationResult;

/// The brush of the Brush and Erase tools.
struct BrushSettings {
    float radius = 6.0f;                             ///< metres, 0.5 to 100
    float density = 1.5f;                            ///< trees per 100 m², 0.01 to 50
    std::vector<std::pair<std::string, double>> mix; ///< species and weight; empty: all alike
};

/// What every tool works with: the document it edits, the viewport it reads and previews in,
/// the last generation (obstacles, terrain, the grown trees), the brush, and the
/// ToolController's signals. The questions several tools ask about the ground are answered here.
class ToolContext {
public:
    ToolContext(doc::Document& document, Viewport& viewport,
                std::function<const GenerationResult&()> result)
        : document(document), viewport(viewport), result(std::move(result)) {}

    doc::Document& document;
    Viewport& viewport;
    std::function<const GenerationResult&()> result;
    BrushSettings brush;
    /// Something the user should read (ToolController::message).
    std::function<void(const QString&)> message;
    /// ToolController::treeBranchClicked.
    std::function<void(std::uint32_t id, const glm::vec3& local)> treeBranchClicked;

    /// The ground under \p pos (widget pixels): the terrain where there is one, else y = 0.
    std::optional<glm::vec3> groundAt(const QPoint& pos) const;
    /// Says that a click met no ground (the sky, beyond the far plane): nothing was planted.
    void noGroundUnderCursor() const;
    /// The terrain's height at (x, z), or 0 without terrain.
    float groundHeight(float x, float z) const;
    /// The highest surface at (x, z): the terrain (or y = 0) and the obstacles standing on it;
    /// the camera's eye stays above it.
    float surfaceHeight(float x, float z) const;
    /// Whether a trunk at \p position stands in an obstacle's footprint (what placement
    /// refuses), from the last generation's obstacles.
    bool inObstacleFootprint(const glm::vec3& position) const;
    /// The crown radius the spacing rules use for a species: the median of its grown trees'
    /// half crown widths in the last generation (kDefaultCrownRadius when it has none yet).
    float crownRadius(std::uint32_t species) const;
    static constexpr float kDefaultCrownRadius = 2.0f;
};

/// The position of a tree's transform.
inline glm::vec3 positionOf(const glm::mat4& transform) {
    return glm::vec3(transform[3]);
}

} // namespace sylva::ui
