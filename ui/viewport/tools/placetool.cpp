#include "ui/viewport/tools/placetool.h"

#include <cmath>

#include <QCoreApplication>
#include <QMouseEvent>

#include "document/document.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"

namespace sylva::ui {

std::string PlaceTool::species() const {
    const auto& species = mContext.document.project().species;
    if (species.empty()) return {};
    for (const doc::ProjectSpecies& s : species)
        if (s.name == mSpecies) return s.name;
    return species.front().name;
}

void PlaceTool::click(QMouseEvent* event) {
    doc::Document& document = mContext.document;
    const QPoint pos = event->position().toPoint();
    const std::string name = species();
    if (name.empty()) {
        mContext.message(QCoreApplication::translate(
            "sylva::ui::ToolController", "Add a species first (Scene ▸ Add species from file…)"));
        return;
    }
    const auto g = mContext.groundAt(pos);
    if (!g) {
        mContext.noGroundUnderCursor();
        return;
    }
    if (mContext.inObstacleFootprint(*g)) {
        mContext.message(QCoreApplication::translate(
            "sylva::ui::ToolController", "A tree cannot stand inside an obstacle's footprint"));
        return;
    }
    Rng rng(mixSeed(document.project().seed, document.treeIds().size() + salt::kPlaceTool));
    doc::ProjectInstance t;
    t.species = name;
    t.position = *g;
    // Tenths of a degree, as the Properties panel shows and takes them (17 digits before).
    t.rotation = std::round(3600.0 * rng.uniform()) / 10.0;
    t.seed = doc::treeSeed(rng.next());
    document.selectTrees({document.addTree(t)});
}

} // namespace sylva::ui
