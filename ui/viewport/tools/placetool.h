#pragma once

#include <string>

#include "ui/viewport/tools/scenetool.h"

namespace sylva::ui {

/// Place: a click drops a tree of the chosen species on the ground, with a fresh seed and a
/// random rotation.
class PlaceTool : public SceneTool {
public:
    using SceneTool::SceneTool;

    void click(QMouseEvent* event) override;

    /// The species dropped (the first species when empty or unknown).
    void setSpecies(const std::string& species) { mSpecies = species; }
    std::string species() const;

private:
    std::string mSpecies;
};

} // namespace sylva::ui
