#include "ui/viewport/tools/selecttool.h"

#include <QCoreApplication>
#include <QMouseEvent>

#include "document/document.h"
#include "engine/environment/obstaclescene.h"
#include "ui/generation/treegenerator.h"

namespace sylva::ui {

bool SelectTool::press(QMouseEvent* event) {
    mPress = mLast = event->position().toPoint();
    if (!(event->modifiers() & Qt::ControlModifier)) return false;
    mContext.viewport.setBand(QRect(mPress, QSize(1, 1)));
    return true;
}

void SelectTool::move(QMouseEvent* event) {
    mLast = event->position().toPoint();
    mContext.viewport.setBand(QRect(mPress, mLast).normalized());
}

void SelectTool::release(QMouseEvent* event) {
    mLast = event->position().toPoint();
    finishRubberBand();
}

void SelectTool::click(QMouseEvent* event) {
    selectAt(event->position().toPoint(), event->modifiers());
}

void SelectTool::selectAt(const QPoint& pos, Qt::KeyboardModifiers modifiers) {
    using K = doc::ItemRef::Kind;
    doc::Document& document = mContext.document;
    Viewport& viewport = mContext.viewport;
    const Ray ray = viewport.rayAt(pos);
    const TreeHit pick = viewport.pickAt(pos);
    const int index = pick.index;
    const float treeT = pick.t; // max() when no tree is hit
    std::optional<doc::ItemRef> item;
    if (index >= 0) {
        const doc::TreeId id = viewport.trees()[std::size_t(index)].id;
        if (id != 0) {
            item = doc::ItemRef{K::Tree, id};
        } else {
            // A domain's tree: its domain is what can be edited.
            const glm::vec3 p = positionOf(viewport.trees()[std::size_t(index)].transform);
            const auto& domains = document.project().domains;
            std::uint32_t domain = 0;
            for (std::size_t d = 0; d < domains.size(); ++d)
                if (p.x >= domains[d].min.x && p.x <= domains[d].max.x && p.z >= domains[d].min.y &&
                    p.z <= domains[d].max.y)
                    domain = std::uint32_t(d);
            if (!domains.empty()) {
                item = doc::ItemRef{K::Domain, domain};
                mContext.message(QCoreApplication::translate(
                                     "sylva::ui::ToolController",
                                     "That tree was scattered by domain %1: its counts and extent "
                                     "are in Properties")
                                     .arg(domain + 1));
            }
        }
    }
    if (const auto& obstacles = mContext.result().obstacles; obstacles && !obstacles->empty()) {
        const float reach = 10.0f * viewport.camera().farPlane();
        const env::SegmentHit hit =
            obstacles->intersect({ray.origin, ray.origin + reach * ray.direction});
        if (hit.hit && hit.t * reach < treeT && hit.mesh < document.project().obstacles.size())
            item = doc::ItemRef{K::Obstacle, hit.mesh};
    }
    QList<doc::ItemRef> selection = document.selection();
    if (modifiers & Qt::ControlModifier) {
        if (item && selection.contains(*item))
            selection.removeAll(*item);
        else if (item)
            selection << *item;
    } else if (modifiers & Qt::ShiftModifier) {
        if (item && !selection.contains(*item)) selection << *item;
    } else {
        selection.clear();
        if (item) selection << *item;
    }
    document.setSelection(selection);
    if (!(modifiers & (Qt::ControlModifier | Qt::ShiftModifier)) && item && item->kind == K::Tree) {
        const glm::mat4& transform = viewport.trees()[std::size_t(index)].transform;
        const glm::vec3 world = ray.origin + treeT * ray.direction;
        mContext.treeBranchClicked(item->id,
                                   glm::vec3(glm::inverse(transform) * glm::vec4(world, 1.0f)));
    }
}

void SelectTool::finishRubberBand() {
    Viewport& viewport = mContext.viewport;
    viewport.setBand({});
    const QRect rect = QRect(mPress, mLast).normalized();
    QList<doc::ItemRef> selection = mContext.document.selection();
    for (const ViewTree& t : viewport.trees()) {
        if (t.id == 0) continue;
        const auto screen = viewport.project(positionOf(t.transform));
        const doc::ItemRef item{doc::ItemRef::Kind::Tree, t.id};
        if (screen && rect.contains(screen->toPoint()) && !selection.contains(item))
            selection << item;
    }
    mContext.document.setSelection(selection);
}

void SelectTool::stepSelection(int step) {
    doc::Document& document = mContext.document;
    const auto& ids = document.treeIds();
    if (ids.empty()) return;
    const QList<doc::TreeId> selected = document.selectedTrees();
    int index = selected.isEmpty() ? (step > 0 ? -1 : 0) : document.treeIndex(selected.last());
    index = (index + step + int(ids.size())) % int(ids.size());
    document.selectTrees({ids[std::size_t(index)]});
}

} // namespace sylva::ui
