#include "ui/viewport/tools/brushtool.h"

#include <algorithm>
#include <cmath>

#include <QCoreApplication>
#include <QMouseEvent>

#include "engine/placement/placement.h"
#include "engine/util/random.h"
#include "engine/util/seedsalts.h"
#include "ui/generation/treegenerator.h"

namespace sylva::ui {

bool BrushTool::press(QMouseEvent* event) {
    const auto g = mContext.groundAt(event->position().toPoint());
    if (!g) {
        mContext.noGroundUnderCursor();
        return false;
    }
    ++mStrokes;
    mStroke.clear();
    dab(*g);
    return true;
}

void BrushTool::move(QMouseEvent* event) {
    if (const auto g = mContext.groundAt(event->position().toPoint());
        g && glm::length(*g - mLastDab) > 0.5f * mContext.brush.radius)
        dab(*g);
}

void BrushTool::release(QMouseEvent*) {
    doc::Document& document = mContext.document;
    std::vector<doc::ProjectInstance> stroke;
    stroke.swap(mStroke);
    mContext.viewport.setPreviewTrees({});
    if (stroke.empty()) return;
    QList<doc::TreeId> added;
    document.undoStack()->beginMacro(QCoreApplication::translate(
        "sylva::ui::ToolController", "Paint %n tree(s)", nullptr, int(stroke.size())));
    for (const doc::ProjectInstance& t : stroke)
        added << document.addTree(t);
    document.undoStack()->endMacro();
    document.selectTrees(added);
}

void BrushTool::dab(const glm::vec3& centre) {
    doc::Document& document = mContext.document;
    mLastDab = centre;
    const auto& species = document.project().species;
    if (species.empty()) {
        mContext.message(QCoreApplication::translate(
            "sylva::ui::ToolController", "Add a species first (Scene ▸ Add species from file…)"));
        return;
    }
    std::vector<std::pair<std::uint32_t, double>> mix;
    double total = 0.0;
    for (const auto& [name, weight] : mContext.brush.mix)
        if (const int i = document.speciesIndex(name); i >= 0 && weight > 0) {
            mix.emplace_back(std::uint32_t(i), weight);
            total += weight;
        }
    if (mix.empty()) {
        for (std::size_t i = 0; i < species.size(); ++i)
            mix.emplace_back(std::uint32_t(i), 1.0);
        total = double(species.size());
    }
    // Deterministic for a given document, stroke and dab: the same gesture paints the same.
    Rng rng(
        mixSeed(mixSeed(document.project().seed, mStrokes), mStroke.size() + salt::kBrushStroke));
    const float area = float(M_PI) * mContext.brush.radius * mContext.brush.radius;
    const int candidates = std::max(1, int(std::lround(mContext.brush.density * area / 100.0f)));

    // Each species' crown radius once (it is a median over the forest's trees).
    std::vector<float> radius(species.size());
    for (std::size_t i = 0; i < species.size(); ++i)
        radius[i] = mContext.crownRadius(std::uint32_t(i));
    auto radiusOf = [&radius](std::size_t s) {
        return s < radius.size() ? radius[s] : ToolContext::kDefaultCrownRadius;
    };
    // Trunks already standing (drawn trees, and this stroke's), each with its crown's radius.
    std::vector<std::pair<glm::vec2, float>> trunks;
    for (const DrawnTree& t : mContext.result().trees) {
        const glm::vec3 p = positionOf(t.transform);
        trunks.emplace_back(glm::vec2(p.x, p.z), radiusOf(t.species));
    }
    std::vector<ViewTree> preview;
    for (const doc::ProjectInstance& t : mStroke)
        trunks.emplace_back(glm::vec2(t.position.x, t.position.z),
                            radiusOf(std::size_t(document.speciesIndex(t.species))) *
                                float(t.scale));
    for (int c = 0; c < candidates; ++c) {
        // The species first, by weight, then up to kTries positions for it (reference 000
        // tries 50): a big-crowned species is not squeezed out by the small ones' leftovers.
        double pickWeight = rng.uniform() * total;
        std::uint32_t s = mix.back().first;
        for (const auto& [index, weight] : mix) {
            if (pickWeight < weight) {
                s = index;
                break;
            }
            pickWeight -= weight;
        }
        doc::ProjectInstance t;
        t.species = species[s].name;
        t.rotation = std::round(3600.0 * rng.uniform()) / 10.0; // tenths, as the panel
        t.scale = 0.95 + 0.1 * rng.uniform();
        t.seed = doc::treeSeed(rng.next());
        constexpr int kTries = 20;
        bool placed = false;
        for (int attempt = 0; attempt < kTries && !placed; ++attempt) {
            const float r =
                mContext.brush.radius * std::sqrt(float(rng.uniform())); // uniform in the disc
            const float a = float(2.0 * M_PI * rng.uniform());
            const glm::vec2 q(centre.x + r * std::cos(a), centre.z + r * std::sin(a));
            t.position = {q.x, mContext.groundHeight(q.x, q.y), q.y};
            // Reference 000's rule: no trunk inside another tree's crown cylinder.
            bool blocked = mContext.inObstacleFootprint(t.position);
            for (const auto& [p, radius] : trunks)
                blocked = blocked || glm::length(q - p) < radius;
            placed = !blocked;
        }
        if (!placed) continue;
        trunks.emplace_back(glm::vec2(t.position.x, t.position.z), radiusOf(s) * float(t.scale));
        mStroke.push_back(t);
    }
    // Preview: each new tree drawn with a grown tree of its species where there is one.
    for (const doc::ProjectInstance& t : mStroke) {
        const auto s = std::uint32_t(document.speciesIndex(t.species));
        for (const DrawnTree& d : mContext.result().trees)
            if (d.species == s && d.mesh && !d.mesh->empty()) {
                placement::Instance in;
                in.position = t.position;
                in.rotation = float(glm::radians(t.rotation));
                in.scale = float(t.scale);
                preview.push_back({0, d.mesh, in.transform(), {}, 0.0f});
                break;
            }
    }
    mContext.viewport.setPreviewTrees(std::move(preview));
}

} // namespace sylva::ui
