#include "ui/viewport/toolcontroller.h"

#include <algorithm>
#include <cmath>

#include <QKeyEvent>
#include <QLineF>
#include <QMouseEvent>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/environment/obstaclescene.h"
#include "engine/forest/placement.h"
#include "engine/util/error.h"
#include "engine/util/random.h"
#include "ui/generation/treegenerator.h"

namespace sylva::ui {

namespace {
constexpr float kNudge = 0.1f;           ///< metres per arrow key (Shift: 10×)
constexpr float kDegreesPerPixel = 0.5f; ///< Ctrl+drag rotation
constexpr float kScalePerPixel = 0.005f; ///< Shift+drag scale, exponential
constexpr float kDefaultCrownRadius = 2.0f;
constexpr float kHandlePixels = 9.0f; ///< how near the cursor must be to take a handle
constexpr int kRingSegments = 72;

glm::vec3 positionOf(const glm::mat4& transform) {
    return glm::vec3(transform[3]);
}
} // namespace

QString ToolController::name(Tool tool) {
    switch (tool) {
    case Tool::Select:
        return QStringLiteral("select");
    case Tool::Move:
        return QStringLiteral("move");
    case Tool::Place:
        return QStringLiteral("place");
    case Tool::Brush:
        return QStringLiteral("brush");
    case Tool::Erase:
        return QStringLiteral("erase");
    }
    return {};
}

bool ToolController::fromName(const QString& text, Tool& tool) {
    for (Tool t : {Tool::Select, Tool::Move, Tool::Place, Tool::Brush, Tool::Erase})
        if (name(t) == text) {
            tool = t;
            return true;
        }
    return false;
}

ToolController::ToolController(doc::Document& document, Viewport& viewport,
                               std::function<const GenerationResult&()> result, QObject* parent)
    : QObject(parent), mDocument(document), mViewport(viewport), mResult(std::move(result)) {
    viewport.setTool(this);
    viewport.setOverlay([this] { return handleLines(); });
}

void ToolController::setTool(Tool tool) {
    if (tool == mTool) return;
    mTool = tool;
    mViewport.setPreviewTrees({});
    mViewport.update(); // the Move tool's handles come or go
    Q_EMIT toolChanged(tool);
}

std::string ToolController::placeSpecies() const {
    const auto& species = mDocument.project().species;
    if (species.empty()) return {};
    for (const doc::ProjectSpecies& s : species)
        if (s.name == mPlaceSpecies) return s.name;
    return species.front().name;
}

void ToolController::setBrush(const Brush& brush) {
    requireRange("brush radius (m)", brush.radius, 0.5, 100);
    requireRange("brush density (trees per 100 m2)", brush.density, 0.01, 50);
    for (const auto& [name, weight] : brush.mix) {
        if (mDocument.speciesIndex(name) < 0) throw InvalidInput("unknown species '" + name + "'");
        requireRange("species weight", weight, 0, 1e6);
    }
    mBrush = brush;
}

std::optional<glm::vec3> ToolController::groundAt(const QPoint& pos) const {
    const Ray ray = mViewport.rayAt(pos);
    if (const auto& ground = mResult().ground; ground && !ground->empty()) {
        // The terrain under the cursor, where trees stand in a terrain project.
        const float reach = 10.0f * mViewport.camera().farPlane();
        const env::SegmentHit hit =
            ground->intersect({ray.origin, ray.origin + reach * ray.direction});
        if (hit.hit) return hit.point;
        return std::nullopt;
    }
    return hitPlane(ray, 0.0f);
}

float ToolController::groundHeight(float x, float z) const {
    const auto& ground = mResult().ground;
    if (!ground || ground->empty()) return 0.0f;
    const env::SegmentHit h =
        ground->intersect({{x, ground->hi().y + 1.0f, z}, {x, ground->lo().y - 1.0f, z}});
    return h.hit ? h.point.y : 0.0f;
}

bool ToolController::inObstacleFootprint(const glm::vec3& p) const {
    const auto& obstacles = mResult().obstacles;
    if (!obstacles || obstacles->empty()) return false;
    // As placement refuses: a vertical line through the trunk meets an obstacle.
    const env::Segment vertical{{p.x, obstacles->lo().y - 1.0f, p.z},
                                {p.x, obstacles->hi().y + 1.0f, p.z}};
    return obstacles->occluded(vertical);
}

float ToolController::crownRadius(std::uint32_t species) const {
    std::vector<double> radii;
    for (const DrawnTree& t : mResult().trees)
        if (t.species == species && t.metrics.crownWidthM > 0)
            radii.push_back(0.5 * t.metrics.crownWidthM);
    if (radii.empty()) return kDefaultCrownRadius;
    std::nth_element(radii.begin(), radii.begin() + std::ptrdiff_t(radii.size() / 2), radii.end());
    return float(radii[radii.size() / 2]);
}

// --- selection ---------------------------------------------------------------------------

void ToolController::selectAt(const QPoint& pos, Qt::KeyboardModifiers modifiers) {
    using K = doc::ItemRef::Kind;
    const Ray ray = mViewport.rayAt(pos);
    const TreeHit pick = mViewport.pickAt(pos);
    const int index = pick.index;
    const float treeT = pick.t; // max() when no tree is hit
    std::optional<doc::ItemRef> item;
    if (index >= 0) {
        const doc::TreeId id = mViewport.trees()[std::size_t(index)].id;
        if (id != 0) {
            item = doc::ItemRef{K::Tree, id};
        } else {
            // A domain's tree: its domain is what can be edited.
            const glm::vec3 p = positionOf(mViewport.trees()[std::size_t(index)].transform);
            const auto& domains = mDocument.project().domains;
            std::uint32_t domain = 0;
            for (std::size_t d = 0; d < domains.size(); ++d)
                if (p.x >= domains[d].min.x && p.x <= domains[d].max.x && p.z >= domains[d].min.y &&
                    p.z <= domains[d].max.y)
                    domain = std::uint32_t(d);
            if (!domains.empty()) {
                item = doc::ItemRef{K::Domain, domain};
                Q_EMIT message(tr("That tree was scattered by domain %1: its counts and extent "
                                  "are in Properties")
                                   .arg(domain + 1));
            }
        }
    }
    if (const auto& obstacles = mResult().obstacles; obstacles && !obstacles->empty()) {
        const float reach = 10.0f * mViewport.camera().farPlane();
        const env::SegmentHit hit =
            obstacles->intersect({ray.origin, ray.origin + reach * ray.direction});
        if (hit.hit && hit.t * reach < treeT && hit.mesh < mDocument.project().obstacles.size())
            item = doc::ItemRef{K::Obstacle, hit.mesh};
    }
    QList<doc::ItemRef> selection = mDocument.selection();
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
    mDocument.setSelection(selection);
    if (!(modifiers & (Qt::ControlModifier | Qt::ShiftModifier)) && item && item->kind == K::Tree) {
        const glm::mat4& transform = mViewport.trees()[std::size_t(index)].transform;
        const glm::vec3 world = ray.origin + treeT * ray.direction;
        Q_EMIT treeBranchClicked(item->id,
                                 glm::vec3(glm::inverse(transform) * glm::vec4(world, 1.0f)));
    }
}

void ToolController::finishRubberBand() {
    mViewport.setBand({});
    const QRect rect = QRect(mPress, mLast).normalized();
    QList<doc::ItemRef> selection = mDocument.selection();
    for (const ViewTree& t : mViewport.trees()) {
        if (t.id == 0) continue;
        const auto screen = mViewport.project(positionOf(t.transform));
        const doc::ItemRef item{doc::ItemRef::Kind::Tree, t.id};
        if (screen && rect.contains(screen->toPoint()) && !selection.contains(item))
            selection << item;
    }
    mDocument.setSelection(selection);
}

void ToolController::stepSelection(int step) {
    const auto& ids = mDocument.treeIds();
    if (ids.empty()) return;
    const QList<doc::TreeId> selected = mDocument.selectedTrees();
    int index = selected.isEmpty() ? (step > 0 ? -1 : 0) : mDocument.treeIndex(selected.last());
    index = (index + step + int(ids.size())) % int(ids.size());
    mDocument.selectTrees({ids[std::size_t(index)]});
}

// --- moving ------------------------------------------------------------------------------

doc::ProjectInstance ToolController::draggedInstance(const Dragged& d) const {
    doc::ProjectInstance t = d.start;
    t.position += mDragMove;
    if (mDragMove != glm::vec3(0.0f) && mResult().ground)
        t.position.y = groundHeight(t.position.x, t.position.z); // stays on the terrain
    t.rotation += mDragDegrees;
    t.scale *= mDragScale;
    return t;
}

void ToolController::dragTo(const QPoint& pos, Qt::KeyboardModifiers modifiers) {
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
    } else if (const auto ground = hitPlane(mViewport.rayAt(pos), mDragHeight)) {
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
        mViewport.setTreeTransform(d.viewIndex, m); // the mesh follows; nothing regrows
    }
}

// --- handles -------------------------------------------------------------------------------

std::optional<ToolController::Handles> ToolController::handles() const {
    if (mTool != Tool::Move) return std::nullopt;
    if (mDragHandle != Handle::None) return mDragHandles; // they stay put while dragged
    const QList<doc::TreeId> selected = mDocument.selectedTrees();
    if (selected.isEmpty()) return std::nullopt;
    const std::vector<ViewTree>& trees = mViewport.trees();
    const std::vector<Bounds>& bounds = mViewport.treeBounds();
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

std::optional<double> ToolController::ringAngle(const QPoint& pos) const {
    const auto p = hitPlane(mViewport.rayAt(pos), mDragHandles.centre.y);
    if (!p) return std::nullopt;
    return std::atan2(-(p->z - mDragHandles.centre.z), p->x - mDragHandles.centre.x);
}

ToolController::Handle ToolController::handleAt(const QPoint& pos) const {
    const auto h = handles();
    if (!h) return Handle::None;
    const QPointF cursor(pos);
    if (const auto box = mViewport.project(h->scaleHandle);
        box && QLineF(*box, cursor).length() <= 1.5 * kHandlePixels)
        return Handle::Scale;
    std::optional<QPointF> previous;
    for (int k = 0; k <= kRingSegments; ++k) {
        const double a = 2.0 * M_PI * k / kRingSegments;
        const auto p =
            mViewport.project(h->centre + h->radius * glm::vec3(std::cos(a), 0.0f, -std::sin(a)));
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

std::vector<OverlayLine> ToolController::handleLines() const {
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
        0.012f * glm::length(mViewport.camera().eye() - h->scaleHandle); // about 10 px
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

void ToolController::nudge(float dx, float dz) {
    const QList<doc::TreeId> ids = mDocument.selectedTrees();
    if (ids.isEmpty()) return;
    mDocument.undoStack()->beginMacro(ids.size() == 1 ? tr("Move tree") : tr("Move trees"));
    try {
        for (doc::TreeId id : ids) {
            doc::ProjectInstance t = mDocument.tree(id);
            t.position += glm::vec3(dx, 0.0f, dz);
            if (mResult().ground) t.position.y = groundHeight(t.position.x, t.position.z);
            if (inObstacleFootprint(t.position))
                throw InvalidInput("a tree cannot stand inside an obstacle's footprint");
            mDocument.setTree(id, t);
        }
    } catch (const std::exception& e) {
        mDocument.undoStack()->endMacro();
        mDocument.undoStack()->undo();
        Q_EMIT message(QString::fromUtf8(e.what()));
        return;
    }
    mDocument.undoStack()->endMacro();
}

// --- brush and eraser ----------------------------------------------------------------------

void ToolController::dab(const glm::vec3& centre) {
    mLastDab = centre;
    const auto& species = mDocument.project().species;
    if (species.empty()) {
        Q_EMIT message(tr("Add a species first (Scene ▸ Add species from file…)"));
        return;
    }
    std::vector<std::pair<std::uint32_t, double>> mix;
    double total = 0.0;
    for (const auto& [name, weight] : mBrush.mix)
        if (const int i = mDocument.speciesIndex(name); i >= 0 && weight > 0) {
            mix.emplace_back(std::uint32_t(i), weight);
            total += weight;
        }
    if (mix.empty()) {
        for (std::size_t i = 0; i < species.size(); ++i)
            mix.emplace_back(std::uint32_t(i), 1.0);
        total = double(species.size());
    }
    // Deterministic for a given document, stroke and dab: the same gesture paints the same.
    Rng rng(mixSeed(mixSeed(mDocument.project().seed, mStrokes), mStroke.size() + 7919));
    const float area = float(M_PI) * mBrush.radius * mBrush.radius;
    const int candidates = std::max(1, int(std::lround(mBrush.density * area / 100.0f)));

    // Each species' crown radius once (it is a median over the forest's trees).
    std::vector<float> radius(species.size());
    for (std::size_t i = 0; i < species.size(); ++i)
        radius[i] = crownRadius(std::uint32_t(i));
    auto radiusOf = [&radius](std::size_t s) {
        return s < radius.size() ? radius[s] : kDefaultCrownRadius;
    };
    // Trunks already standing (drawn trees, and this stroke's), each with its crown's radius.
    std::vector<std::pair<glm::vec2, float>> trunks;
    for (const DrawnTree& t : mResult().trees) {
        const glm::vec3 p = positionOf(t.transform);
        trunks.emplace_back(glm::vec2(p.x, p.z), radiusOf(t.species));
    }
    std::vector<ViewTree> preview;
    for (const doc::ProjectInstance& t : mStroke)
        trunks.emplace_back(glm::vec2(t.position.x, t.position.z),
                            radiusOf(std::size_t(mDocument.speciesIndex(t.species))) *
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
        t.rotation = 360.0 * rng.uniform();
        t.scale = 0.95 + 0.1 * rng.uniform();
        t.seed = rng.next() % 1000000007ull;
        constexpr int kTries = 20;
        bool placed = false;
        for (int attempt = 0; attempt < kTries && !placed; ++attempt) {
            const float r = mBrush.radius * std::sqrt(float(rng.uniform())); // uniform in the disc
            const float a = float(2.0 * M_PI * rng.uniform());
            const glm::vec2 q(centre.x + r * std::cos(a), centre.z + r * std::sin(a));
            t.position = {q.x, groundHeight(q.x, q.y), q.y};
            // Reference 000's rule: no trunk inside another tree's crown cylinder.
            bool blocked = inObstacleFootprint(t.position);
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
        const auto s = std::uint32_t(mDocument.speciesIndex(t.species));
        for (const DrawnTree& d : mResult().trees)
            if (d.species == s && d.mesh && !d.mesh->empty()) {
                forest::Instance in;
                in.position = t.position;
                in.rotation = float(glm::radians(t.rotation));
                in.scale = float(t.scale);
                preview.push_back({0, d.mesh, in.transform(), {}});
                break;
            }
    }
    mViewport.setPreviewTrees(std::move(preview));
}

void ToolController::erase(const glm::vec3& centre) {
    bool changed = false;
    for (const ViewTree& t : mViewport.trees()) {
        if (t.id == 0 || mErased.contains(t.id)) continue;
        const glm::vec3 p = positionOf(t.transform);
        if (glm::length(glm::vec2(p.x - centre.x, p.z - centre.z)) <= mBrush.radius) {
            mErased << t.id;
            changed = true;
        }
    }
    if (changed) {
        QSet<std::uint32_t> hidden(mErased.begin(), mErased.end());
        mViewport.setHiddenTrees(hidden); // the preview: they vanish as the brush passes
    }
}

// --- events ------------------------------------------------------------------------------

bool ToolController::startDrag(doc::TreeId hit) {
    mDragged.clear();
    for (doc::TreeId id : mDocument.selectedTrees())
        for (std::size_t i = 0; i < mViewport.trees().size(); ++i)
            if (mViewport.trees()[i].id == id)
                mDragged.push_back({id, i, mDocument.tree(id), mViewport.trees()[i].transform});
    mDragHeight = float(mDocument.tree(hit).position.y);
    const auto start = hitPlane(mViewport.rayAt(mPress), mDragHeight);
    mDragMove = glm::vec3(0.0f);
    mDragDegrees = 0.0;
    mDragScale = 1.0;
    mDragMode = DragMode::Move;
    if (mDragged.empty()) return false;
    // A handle's drag needs no ground point under the press (the box is in the sky).
    mDragStart = start ? *start : glm::vec3(0.0f);
    return start.has_value() || handleAt(mPress) != Handle::None;
}

bool ToolController::press(QMouseEvent* event) {
    mPress = mLast = event->position().toPoint();
    switch (mTool) {
    case Tool::Select:
        if (!(event->modifiers() & Qt::ControlModifier)) return false;
        mViewport.setBand(QRect(mPress, QSize(1, 1)));
        return true;
    case Tool::Move: {
        mDragHandle = Handle::None;
        Handle handle = handleAt(mPress);
        if (handle == Handle::Ring) {
            // The ring lies on the ground: where a selected tree is drawn in front of it (its
            // trunk crosses the ring's far side on screen), the press grabs the tree.
            const TreeHit tree = mViewport.pickAt(mPress);
            const Ray ray = mViewport.rayAt(mPress);
            const auto onRing = hitPlane(ray, handles()->centre.y);
            if (tree.index >= 0 && onRing &&
                mDocument.selectedTrees().contains(mViewport.trees()[std::size_t(tree.index)].id) &&
                tree.t * glm::length(ray.direction) < glm::length(*onRing - ray.origin))
                handle = Handle::None;
        }
        if (handle != Handle::None) {
            mDragHandles = *handles();
            const QList<doc::TreeId> selected = mDocument.selectedTrees();
            if (selected.isEmpty() || !startDrag(selected.front())) return false;
            if (handle == Handle::Ring) {
                const auto angle = ringAngle(mPress);
                if (!angle) return false;
                mRingLast = *angle;
                mRingTotal = 0.0;
            }
            mDragHandle = handle;
            mViewport.update();
            return true;
        }
        const int index = mViewport.treeAt(mPress);
        if (index < 0 || mViewport.trees()[std::size_t(index)].id == 0) return false;
        const doc::TreeId hit = mViewport.trees()[std::size_t(index)].id;
        if (!mDocument.selectedTrees().contains(hit)) mDocument.selectTrees({hit});
        return startDrag(hit);
    }
    case Tool::Place:
        return false;
    case Tool::Brush: {
        const auto g = groundAt(mPress);
        if (!g) return false;
        ++mStrokes;
        mStroke.clear();
        dab(*g);
        return true;
    }
    case Tool::Erase: {
        const auto g = groundAt(mPress);
        if (!g) return false;
        mErased.clear();
        erase(*g);
        return true;
    }
    }
    return false;
}

void ToolController::move(QMouseEvent* event) {
    mLast = event->position().toPoint();
    switch (mTool) {
    case Tool::Select:
        mViewport.setBand(QRect(mPress, mLast).normalized());
        break;
    case Tool::Move:
        dragTo(mLast, event->modifiers());
        break;
    case Tool::Brush:
        if (const auto g = groundAt(mLast); g && glm::length(*g - mLastDab) > 0.5f * mBrush.radius)
            dab(*g);
        break;
    case Tool::Erase:
        if (const auto g = groundAt(mLast)) erase(*g);
        break;
    case Tool::Place:
        break;
    }
}

void ToolController::release(QMouseEvent* event) {
    mLast = event->position().toPoint();
    switch (mTool) {
    case Tool::Select:
        finishRubberBand();
        break;
    case Tool::Move: {
        mDragHandle = Handle::None;
        mViewport.update(); // the handles follow the trees again
        std::vector<std::pair<doc::TreeId, doc::ProjectInstance>> moved;
        for (const Dragged& d : mDragged) {
            const doc::ProjectInstance t = draggedInstance(d);
            const bool badScale = t.scale < 0.01 || t.scale > 100;
            if (badScale || inObstacleFootprint(t.position)) {
                for (const Dragged& back : mDragged)
                    mViewport.setTreeTransform(back.viewIndex, back.startTransform);
                Q_EMIT message(badScale ? tr("A tree's scale must stay between 0.01 and 100: "
                                             "the change was refused")
                                        : tr("A tree cannot stand inside an obstacle's "
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
        mDocument.undoStack()->beginMacro(
            mDragMode == DragMode::Rotate  ? (one ? tr("Rotate tree") : tr("Rotate trees"))
            : mDragMode == DragMode::Scale ? (one ? tr("Scale tree") : tr("Scale trees"))
                                           : (one ? tr("Move tree") : tr("Move trees")));
        for (const auto& [id, t] : moved)
            mDocument.setTree(id, t);
        mDocument.undoStack()->endMacro();
        break;
    }
    case Tool::Brush: {
        std::vector<doc::ProjectInstance> stroke;
        stroke.swap(mStroke);
        mViewport.setPreviewTrees({});
        if (stroke.empty()) return;
        QList<doc::TreeId> added;
        mDocument.undoStack()->beginMacro(tr("Paint %n tree(s)", nullptr, int(stroke.size())));
        for (const doc::ProjectInstance& t : stroke)
            added << mDocument.addTree(t);
        mDocument.undoStack()->endMacro();
        mDocument.selectTrees(added);
        break;
    }
    case Tool::Erase: {
        const QList<doc::TreeId> erased = mErased;
        mErased.clear();
        mViewport.setHiddenTrees({});
        if (!erased.isEmpty()) mDocument.removeTrees(erased);
        break;
    }
    case Tool::Place:
        break;
    }
}

void ToolController::click(QMouseEvent* event) {
    const QPoint pos = event->position().toPoint();
    if (mTool == Tool::Select || mTool == Tool::Move) {
        selectAt(pos, event->modifiers());
        return;
    }
    if (mTool != Tool::Place) return;
    const std::string species = placeSpecies();
    if (species.empty()) {
        Q_EMIT message(tr("Add a species first (Scene ▸ Add species from file…)"));
        return;
    }
    const auto g = groundAt(pos);
    if (!g) return;
    if (inObstacleFootprint(*g)) {
        Q_EMIT message(tr("A tree cannot stand inside an obstacle's footprint"));
        return;
    }
    Rng rng(mixSeed(mDocument.project().seed, mDocument.treeIds().size() + 104729));
    doc::ProjectInstance t;
    t.species = species;
    t.position = *g;
    t.rotation = 360.0 * rng.uniform();
    t.seed = rng.next() % 1000000007ull;
    mDocument.selectTrees({mDocument.addTree(t)});
}

bool ToolController::key(QKeyEvent* event) {
    const bool shift = event->modifiers() & Qt::ShiftModifier;
    switch (event->key()) {
    case Qt::Key_BracketLeft:
        stepSelection(-1);
        return true;
    case Qt::Key_BracketRight:
        stepSelection(+1);
        return true;
    case Qt::Key_Left:
        nudge(-(shift ? 10 : 1) * kNudge, 0);
        return true;
    case Qt::Key_Right:
        nudge((shift ? 10 : 1) * kNudge, 0);
        return true;
    case Qt::Key_Up:
        nudge(0, -(shift ? 10 : 1) * kNudge);
        return true;
    case Qt::Key_Down:
        nudge(0, (shift ? 10 : 1) * kNudge);
        return true;
    default:
        return false;
    }
}

} // namespace sylva::ui
