#include "ui/viewport/tools/movetool.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QCoreApplication>
#include <QLineF>
#include <QMouseEvent>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/util/error.h"
#include "ui/generation/treegenerator.h"
#include "ui/viewport/tools/selecttool.h"

namespace sylva::ui {

namespace {
constexpr float kDegreesPerPixel = 0.5f; ///< Ctrl+drag rotation
constexpr float kScalePerPixel = 0.005f; ///< Shift+drag scale, exponential
constexpr float kHandlePixels = 9.0f;    ///< how near the cursor must be to take a handle
constexpr int kRingSegments = 72;
} // namespace

doc::ProjectInstance MoveTool::draggedInstance(const Dragged& d) const {
    doc::ProjectInstance t = d.start;
    t.position += mDragMove;
    if (mDragMove != glm::vec3(0.0f) && mContext.result().ground)
        t.position.y = mContext.groundHeight(t.position.x, t.position.z); // stays on the terrain
    t.rotation += mDragDegrees;
    t.scale *= mDragScale;
    return t;
}

void MoveTool::dragTo(const QPoint& pos, Qt::KeyboardModifiers modifiers) {
    const QPoint delta = pos - mPress;
    // One gesture does one thing: move, or rotate (the ring, or Ctrl), or scale (the box, or
    // Shift), each tree about its own trunk.
    mDragMode = mDragHandle == Handle::Ring       ? DragMode::Rotate
                : mDragHandle == Handle::Scale    ? DragMode::Scale
                : modifiers & Qt::ControlModifier ? DragMode::Rotate
                : modifiers & Qt::ShiftModifier   ? DragMode::Scale
                                                  : DragMode::Move;
    mDragMove = glm::vec3(0.0f);
    mDragDegrees = 0.0;
    mDragScale = 1.0;
    if (mDragHandle == Handle::Ring) {
        if (const auto angle = ringAngle(pos)) {
            // Unwrapped, so that a drag all the way round turns a full turn.
            double step = *angle - mRingLast;
            step -= 2.0 * M_PI * std::round(step / (2.0 * M_PI));
            mRingTotal += step;
            mRingLast = *angle;
        }
        mDragDegrees = mRingTotal * 180.0 / M_PI;
    } else if (mDragMode == DragMode::Rotate) {
        mDragDegrees = kDegreesPerPixel * delta.x();
    } else if (mDragMode == DragMode::Scale) {
        mDragScale = std::exp(-double(kScalePerPixel) * delta.y()); // up: larger
    } else if (const auto ground = hitPlane(mContext.viewport.rayAt(pos), mDragHeight)) {
        mDragMove = glm::vec3(ground->x - mDragStart.x, 0.0f, ground->z - mDragStart.z);
    }
    for (const Dragged& d : mDragged) {
        glm::mat4 m = d.startTransform;
        const glm::vec3 base = positionOf(m);
        if (mDragMode == DragMode::Rotate) {
            const float angle = glm::radians(float(mDragDegrees));
            m = glm::translate(glm::mat4(1.0f), base) *
                glm::rotate(glm::mat4(1.0f), angle, glm::vec3(0, 1, 0)) *
                glm::translate(glm::mat4(1.0f), -base) * m;
        } else if (mDragMode == DragMode::Scale) {
            const auto k = float(mDragScale);
            m = glm::translate(glm::mat4(1.0f), base) * glm::scale(glm::mat4(1.0f), glm::vec3(k)) *
                glm::translate(glm::mat4(1.0f), -base) * m;
        } else {
            m = glm::translate(glm::mat4(1.0f), mDragMove) * m;
        }
        mContext.viewport.setTreeTransform(d.viewIndex, m); // the mesh follows; nothing regrows
    }
}

std::optional<MoveTool::Handles> MoveTool::handles() const {
    if (mDragHandle != Handle::None) return mDragHandles; // they stay put while dragged
    const QList<doc::TreeId> selected = mContext.document.selectedTrees();
    if (selected.isEmpty()) return std::nullopt;
    const std::vector<ViewTree>& trees = mContext.viewport.trees();
    const std::vector<Bounds>& bounds = mContext.viewport.treeBounds();
    std::vector<std::size_t> shown;
    for (std::size_t i = 0; i < trees.size() && i < bounds.size(); ++i)
        if (trees[i].id != 0 && selected.contains(trees[i].id) && !bounds[i].empty())
            shown.push_back(i);
    if (shown.empty()) return std::nullopt;
    Handles h;
    float top = std::numeric_limits<float>::lowest();
    h.centre = glm::vec3(0.0f);
    float ground = std::numeric_limits<float>::max();
    for (std::size_t i : shown) {
        const glm::vec3 p = positionOf(trees[i].transform);
        h.centre += p / float(shown.size());
        ground = std::min(ground, p.y);
        top = std::max(top, bounds[i].hi.y);
    }
    h.centre.y = ground;
    // Around the crowns: the farthest trunk plus that tree's crown half-width.
    h.radius = 1.0f;
    for (std::size_t i : shown) {
        const glm::vec3 p = positionOf(trees[i].transform);
        const glm::vec3 size = bounds[i].hi - bounds[i].lo;
        const float crown = 0.4f * std::max(size.x, size.z);
        h.radius =
            std::max(h.radius, glm::length(glm::vec2(p.x - h.centre.x, p.z - h.centre.z)) + crown);
    }
    h.scaleHandle = {h.centre.x, top + 0.1f * std::max(top - ground, 1.0f), h.centre.z};
    return h;
}

std::optional<double> MoveTool::ringAngle(const QPoint& pos) const {
    const auto p = hitPlane(mContext.viewport.rayAt(pos), mDragHandles.centre.y);
    if (!p) return std::nullopt;
    return std::atan2(-(p->z - mDragHandles.centre.z), p->x - mDragHandles.centre.x);
}

MoveTool::Handle MoveTool::handleAt(const QPoint& pos) const {
    const auto h = handles();
    if (!h) return Handle::None;
    const QPointF cursor(pos);
    if (const auto box = mContext.viewport.project(h->scaleHandle);
        box && QLineF(*box, cursor).length() <= 1.5 * kHandlePixels)
        return Handle::Scale;
    std::optional<QPointF> previous;
    for (int k = 0; k <= kRingSegments; ++k) {
        const double a = 2.0 * M_PI * k / kRingSegments;
        const auto p = mContext.viewport.project(
            h->centre + h->radius * glm::vec3(std::cos(a), 0.0f, -std::sin(a)));
        if (p && previous) {
            // Distance from the cursor to the segment previous → p.
            const QPointF d = *p - *previous;
            const double len2 = QPointF::dotProduct(d, d);
            const double t =
                len2 > 0 ? std::clamp(QPointF::dotProduct(cursor - *previous, d) / len2, 0.0, 1.0)
                         : 0.0;
            if (QLineF(*previous + t * d, cursor).length() <= kHandlePixels) return Handle::Ring;
        }
        previous = p;
    }
    return Handle::None;
}

std::vector<OverlayLine> MoveTool::handleLines() const {
    const auto h = handles();
    if (!h) return {};
    std::vector<OverlayLine> lines;
    const glm::vec4 ringColor = mDragHandle == Handle::Ring ? glm::vec4(1.0f, 0.95f, 0.4f, 1.0f)
                                                            : glm::vec4(1.0f, 0.70f, 0.1f, 0.95f);
    const glm::vec4 boxColor = mDragHandle == Handle::Scale ? glm::vec4(0.6f, 1.0f, 1.0f, 1.0f)
                                                            : glm::vec4(0.2f, 0.8f, 1.0f, 0.95f);
    // Two rings a little apart read as one thicker line (core profile lines are one pixel).
    for (const float r : {h->radius, 1.015f * h->radius})
        for (int k = 0; k < kRingSegments; ++k) {
            const double a0 = 2.0 * M_PI * k / kRingSegments;
            const double a1 = 2.0 * M_PI * (k + 1) / kRingSegments;
            lines.push_back({h->centre + r * glm::vec3(std::cos(a0), 0.0f, -std::sin(a0)),
                             h->centre + r * glm::vec3(std::cos(a1), 0.0f, -std::sin(a1)),
                             ringColor});
        }
    // The scale box: a stem from the crowns' top and a cube a few pixels wide.
    const float size =
        0.012f * glm::length(mContext.viewport.camera().eye() - h->scaleHandle); // about 10 px
    const glm::vec3 c = h->scaleHandle;
    lines.push_back({glm::vec3(c.x, h->centre.y, c.z), c - glm::vec3(0, size, 0),
                     glm::vec4(boxColor.x, boxColor.y, boxColor.z, 0.5f)});
    for (int axis = 0; axis < 3; ++axis)
        for (int i = 0; i < 4; ++i) {
            glm::vec3 a(0.0f);
            a[(axis + 1) % 3] = (i & 1) ? size : -size;
            a[(axis + 2) % 3] = (i & 2) ? size : -size;
            glm::vec3 b = a;
            a[axis] = -size;
            b[axis] = size;
            lines.push_back({c + a, c + b, boxColor});
        }
    return lines;
}

void MoveTool::nudge(float dx, float dz) {
    const QList<doc::TreeId> ids = mContext.document.selectedTrees();
    if (ids.isEmpty()) return;
    mContext.document.undoStack()->beginMacro(
        ids.size() == 1 ? QCoreApplication::translate("sylva::ui::ToolController", "Move tree")
                        : QCoreApplication::translate("sylva::ui::ToolController", "Move trees"));
    try {
        for (doc::TreeId id : ids) {
            doc::ProjectInstance t = mContext.document.tree(id);
            t.position += glm::vec3(dx, 0.0f, dz);
            if (mContext.result().ground)
                t.position.y = mContext.groundHeight(t.position.x, t.position.z);
            if (mContext.inObstacleFootprint(t.position))
                throw InvalidInput("a tree cannot stand inside an obstacle's footprint");
            mContext.document.setTree(id, t);
        }
    } catch (const std::exception& e) {
        mContext.document.undoStack()->endMacro();
        mContext.document.undoStack()->undo();
        mContext.message(QString::fromUtf8(e.what()));
        return;
    }
    mContext.document.undoStack()->endMacro();
}

bool MoveTool::startDrag(doc::TreeId hit) {
    mDragged.clear();
    for (doc::TreeId id : mContext.document.selectedTrees())
        for (std::size_t i = 0; i < mContext.viewport.trees().size(); ++i)
            if (mContext.viewport.trees()[i].id == id)
                mDragged.push_back(
                    {id, i, mContext.document.tree(id), mContext.viewport.trees()[i].transform});
    mDragHeight = float(mContext.document.tree(hit).position.y);
    const auto start = hitPlane(mContext.viewport.rayAt(mPress), mDragHeight);
    mDragMove = glm::vec3(0.0f);
    mDragDegrees = 0.0;
    mDragScale = 1.0;
    mDragMode = DragMode::Move;
    if (mDragged.empty()) return false;
    // A handle's drag needs no ground point under the press (the box is in the sky).
    mDragStart = start ? *start : glm::vec3(0.0f);
    return start.has_value() || handleAt(mPress) != Handle::None;
}

bool MoveTool::press(QMouseEvent* event) {
    mPress = mLast = event->position().toPoint();
    mDragHandle = Handle::None;
    Handle handle = handleAt(mPress);
    if (handle == Handle::Ring) {
        // The ring lies on the ground: where a selected tree is drawn in front of it (its
        // trunk crosses the ring's far side on screen), the press grabs the tree.
        const TreeHit tree = mContext.viewport.pickAt(mPress);
        const Ray ray = mContext.viewport.rayAt(mPress);
        const auto onRing = hitPlane(ray, handles()->centre.y);
        if (tree.index >= 0 && onRing &&
            mContext.document.selectedTrees().contains(
                mContext.viewport.trees()[std::size_t(tree.index)].id) &&
            tree.t * glm::length(ray.direction) < glm::length(*onRing - ray.origin))
            handle = Handle::None;
    }
    if (handle != Handle::None) {
        mDragHandles = *handles();
        const QList<doc::TreeId> selected = mContext.document.selectedTrees();
        if (selected.isEmpty() || !startDrag(selected.front())) return false;
        if (handle == Handle::Ring) {
            const auto angle = ringAngle(mPress);
            if (!angle) return false;
            mRingLast = *angle;
            mRingTotal = 0.0;
        }
        mDragHandle = handle;
        mContext.viewport.update();
        return true;
    }
    const int index = mContext.viewport.treeAt(mPress);
    if (index < 0 || mContext.viewport.trees()[std::size_t(index)].id == 0) return false;
    const doc::TreeId hit = mContext.viewport.trees()[std::size_t(index)].id;
    if (!mContext.document.selectedTrees().contains(hit)) mContext.document.selectTrees({hit});
    return startDrag(hit);
}

void MoveTool::move(QMouseEvent* event) {
    mLast = event->position().toPoint();
    dragTo(mLast, event->modifiers());
}

void MoveTool::release(QMouseEvent* event) {
    mLast = event->position().toPoint();
    mDragHandle = Handle::None;
    mContext.viewport.update(); // the handles follow the trees again
    std::vector<std::pair<doc::TreeId, doc::ProjectInstance>> moved;
    for (const Dragged& d : mDragged) {
        const doc::ProjectInstance t = draggedInstance(d);
        const bool badScale = t.scale < 0.01 || t.scale > 100;
        if (badScale || mContext.inObstacleFootprint(t.position)) {
            for (const Dragged& back : mDragged)
                mContext.viewport.setTreeTransform(back.viewIndex, back.startTransform);
            mContext.message(
                badScale
                    ? QCoreApplication::translate("sylva::ui::ToolController",
                                                  "A tree's scale must stay between 0.01 and 100: "
                                                  "the change was refused")
                    : QCoreApplication::translate("sylva::ui::ToolController",
                                                  "A tree cannot stand inside an obstacle's "
                                                  "footprint: the move was refused"));
            mDragged.clear();
            return;
        }
        if (!(t == d.start)) moved.emplace_back(d.id, t);
    }
    mDragged.clear();
    if (moved.empty()) return;
    // One undo step; the document then regrows the moved trees and the neighbours whose
    // crowns they now touch, adapted to the obstacles and to each other.
    const bool one = moved.size() == 1;
    mContext.document.undoStack()->beginMacro(
        mDragMode == DragMode::Rotate
            ? (one ? QCoreApplication::translate("sylva::ui::ToolController", "Rotate tree")
                   : QCoreApplication::translate("sylva::ui::ToolController", "Rotate trees"))
        : mDragMode == DragMode::Scale
            ? (one ? QCoreApplication::translate("sylva::ui::ToolController", "Scale tree")
                   : QCoreApplication::translate("sylva::ui::ToolController", "Scale trees"))
            : (one ? QCoreApplication::translate("sylva::ui::ToolController", "Move tree")
                   : QCoreApplication::translate("sylva::ui::ToolController", "Move trees")));
    for (const auto& [id, t] : moved)
        mContext.document.setTree(id, t);
    mContext.document.undoStack()->endMacro();
}

void MoveTool::click(QMouseEvent* event) {
    mSelect.selectAt(event->position().toPoint(), event->modifiers());
}

} // namespace sylva::ui
