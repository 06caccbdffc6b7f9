#include "ui/viewport/tools/branchtool.h"

#include <limits>

#include <QCoreApplication>
#include <QKeyEvent>
#include <QMouseEvent>

#include <glm/gtx/quaternion.hpp>

#include "document/errormessage.h"
#include "ui/generation/treebranches.h"
#include "ui/generation/treegenerator.h"

namespace sylva::ui {

namespace {

float segmentDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? glm::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::length(p - (a + t * ab));
}

glm::vec3 toWorld(const glm::mat4& m, const glm::vec3& p) {
    return glm::vec3(m * glm::vec4(p, 1.0f));
}

} // namespace

const BranchTool::Shown* BranchTool::shown(doc::TreeId tree) const {
    const DrawnTree* drawn = shownTree(mContext.result(), tree);
    if (!drawn || mContext.document.treeIndex(tree) < 0) return nullptr;
    const std::vector<skel::BranchEdit>& edits = mContext.document.branchEdits(tree);
    if (mShown && mShown->tree == tree && mShown->grown == drawn->grown && mShown->edits == edits &&
        mShown->transform == drawn->transform)
        return &*mShown;
    Shown s;
    s.tree = tree;
    s.grown = drawn->grown;
    s.edits = edits;
    s.transform = drawn->transform;
    s.branches = editedBranchesOf(*drawn, edits, &s.edited);
    s.branchOfNode.assign(s.edited.size(), -1);
    for (std::size_t b = 0; b < s.branches.size(); ++b)
        for (std::int32_t k : s.branches[b].nodes)
            s.branchOfNode[std::size_t(k)] = std::int32_t(b);
    mShown = std::move(s);
    return &*mShown;
}

int BranchTool::selectedIndex(const Shown& s) const {
    const auto& selected = mContext.document.selectedBranch();
    if (!selected || selected->tree != s.tree) return -1;
    for (std::size_t b = 0; b < s.branches.size(); ++b)
        if (s.branches[b].id == selected->branch) return int(b);
    return -1;
}

std::optional<doc::Document::BranchRef> BranchTool::branchAt(const QPoint& pos) const {
    Viewport& viewport = mContext.viewport;
    const TreeHit pick = viewport.pickAt(pos);
    if (pick.index < 0) return std::nullopt;
    const doc::TreeId id = viewport.trees()[std::size_t(pick.index)].id;
    if (id == 0) return std::nullopt; // a domain's tree: press() says so
    const Shown* s = shown(id);
    if (!s || s->edited.size() == 0) return std::nullopt;
    const Ray ray = viewport.rayAt(pos);
    const glm::vec3 world = ray.origin + pick.t * ray.direction;
    const glm::vec3 local = glm::vec3(glm::inverse(s->transform) * glm::vec4(world, 1.0f));
    // The segment whose tube surface is nearest the hit: the drawn triangle belongs to it (a
    // leaf card: the twig it hangs from).
    const skel::Skeleton& k = s->edited;
    float best = std::numeric_limits<float>::max();
    std::int32_t bestBranch = -1;
    for (std::size_t i = 0; i < k.size(); ++i) {
        const std::int32_t p = k.parent[i];
        const glm::vec3 a = p >= 0 ? k.position[std::size_t(p)] : k.position[i];
        const float d = segmentDistance(local, a, k.position[i]) - k.radius[i];
        if (d < best && s->branchOfNode[i] >= 0) {
            best = d;
            bestBranch = s->branchOfNode[i];
        }
    }
    if (bestBranch < 0) return std::nullopt;
    return doc::Document::BranchRef{id, s->branches[std::size_t(bestBranch)].id};
}

std::vector<OverlayLine> BranchTool::lines() const {
    const auto& selected = mContext.document.selectedBranch();
    if (!selected) return {};
    const Shown* s = shown(selected->tree);
    if (!s) return {};
    const int b = selectedIndex(*s);
    if (b < 0) return {};
    const skel::Branch& branch = s->branches[std::size_t(b)];
    const skel::Skeleton& k = s->edited;
    const std::int32_t first = branch.nodes.front();
    std::vector<char> in(k.size(), 0), own(k.size(), 0);
    in[std::size_t(first)] = 1;
    for (std::size_t i = std::size_t(first) + 1; i < k.size(); ++i)
        in[i] = k.parent[i] >= first && in[std::size_t(k.parent[i])];
    for (std::int32_t n : branch.nodes)
        own[std::size_t(n)] = 1;
    // While dragging: the subtree turned about its base as the release will bend it.
    glm::mat4 turn(1.0f);
    const glm::vec3 baseWorld = toWorld(s->transform, branch.base);
    if (mDrag && mDrag->direction && mDrag->branch == *selected) {
        const glm::vec3 from = glm::normalize(mDrag->tip - mDrag->base);
        const glm::quat q = glm::rotation(from, glm::normalize(*mDrag->direction));
        turn = glm::translate(glm::mat4(1.0f), baseWorld) * glm::toMat4(q) *
               glm::translate(glm::mat4(1.0f), -baseWorld);
    }
    const glm::mat4 m = turn * s->transform;
    // Bands a few pixels wide over a dark edge, so that the branch reads over leaves, bark and
    // sky alike (a 1-pixel line was lost in the foliage): the edges first, then what it carries,
    // the branch itself on top.
    const glm::vec4 yellow(1.0f, 0.9f, 0.1f, 1.0f), orange(1.0f, 0.5f, 0.05f, 1.0f);
    const glm::vec4 edge(0.05f, 0.03f, 0.0f, 0.75f);
    constexpr float kOwnWidth = 4.0f, kCarriedWidth = 2.5f, kEdge = 2.0f;
    std::vector<OverlayLine> edges, carried, branchOwn;
    for (std::size_t i = std::size_t(first); i < k.size(); ++i) {
        if (!in[i]) continue;
        const std::int32_t p = k.parent[i];
        if (p < 0) continue;
        const glm::vec3 a = toWorld(static_cast<std::int32_t>(i) == first ? s->transform : m,
                                    k.position[std::size_t(p)]);
        const glm::vec3 b = toWorld(m, k.position[i]);
        const float width = own[i] ? kOwnWidth : kCarriedWidth;
        edges.push_back({a, b, edge, width + kEdge});
        (own[i] ? branchOwn : carried).push_back({a, b, own[i] ? yellow : orange, width});
    }
    edges.insert(edges.end(), carried.begin(), carried.end());
    edges.insert(edges.end(), branchOwn.begin(), branchOwn.end()); // the branch itself on top
    return edges;
}

std::optional<glm::vec3> BranchTool::onDragPlane(const QPoint& pos) const {
    const Ray ray = mContext.viewport.rayAt(pos);
    const float denom = glm::dot(ray.direction, mDrag->normal);
    if (std::abs(denom) < 1e-6f) return std::nullopt;
    const float t = glm::dot(mDrag->tip - ray.origin, mDrag->normal) / denom;
    if (t <= 0.0f) return std::nullopt;
    return ray.origin + t * ray.direction;
}

bool BranchTool::press(QMouseEvent* event) {
    if (event->modifiers() != Qt::NoModifier) return false;
    const QPoint pos = event->position().toPoint();
    const auto hit = branchAt(pos);
    if (!hit) {
        const TreeHit pick = mContext.viewport.pickAt(pos);
        if (pick.index >= 0 && mContext.viewport.trees()[std::size_t(pick.index)].id == 0)
            mContext.message(QCoreApplication::translate(
                "sylva::ui::ToolController",
                "Only hand-placed trees take branch edits: this one was scattered by a domain"));
        return false; // the camera orbits; a click lets the branch go
    }
    mContext.document.setSelectedBranch(hit);
    mContext.viewport.update();
    const Shown* s = shown(hit->tree);
    const int b = s ? selectedIndex(*s) : -1;
    if (b < 0) return true;
    const skel::Branch& branch = s->branches[std::size_t(b)];
    Drag d;
    d.branch = *hit;
    d.base = toWorld(s->transform, branch.base);
    d.tip = toWorld(s->transform, branch.tip);
    d.normal = mContext.viewport.camera().forward();
    d.press = pos;
    mDrag = d;
    const auto grab = onDragPlane(pos);
    if (!grab || glm::length(d.tip - d.base) < 1e-6f) {
        mDrag.reset();
        return true;
    }
    mDrag->grab = *grab;
    return true;
}

void BranchTool::move(QMouseEvent* event) {
    if (!mDrag) return;
    const QPoint pos = event->position().toPoint();
    if ((pos - mDrag->press).manhattanLength() <= 4) return;
    const auto p = onDragPlane(pos);
    if (!p) return;
    const glm::vec3 target = mDrag->tip + (*p - mDrag->grab) - mDrag->base;
    if (glm::length(target) > 1e-6f) mDrag->direction = glm::normalize(target);
    mContext.viewport.update();
}

void BranchTool::release(QMouseEvent* event) {
    move(event);
    if (!mDrag) return;
    const Drag d = *mDrag;
    mDrag.reset();
    mContext.viewport.update();
    if (!d.direction) return; // a click: the branch stays selected
    try {
        skel::BranchEdit edit = branchEditOf(mContext.document, d.branch.tree, d.branch.branch);
        if (edit.lock) {
            mContext.message(QCoreApplication::translate(
                                 "sylva::ui::ToolController",
                                 "Branch %1 is locked: unlock it in Properties before bending it")
                                 .arg(QString::fromStdString(d.branch.branch)));
            return;
        }
        // Whole thousandths: the file keeps a short number, the look is the same.
        glm::vec3 dir = *d.direction;
        for (int c = 0; c < 3; ++c)
            dir[c] = std::round(dir[c] * 1000.0f) / 1000.0f;
        if (glm::length(dir) < 1e-3f) return;
        edit.bend = dir;
        applyBranchEdit(mContext.document, shownTree(mContext.result(), d.branch.tree),
                        d.branch.tree, edit);
    } catch (...) {
        mContext.message(QString::fromStdString(doc::currentErrorMessage()));
    }
}

void BranchTool::click(QMouseEvent* event) {
    (void)event;
    // press() took every click on a branch: this one met none.
    mContext.document.setSelection({});
    mContext.viewport.update();
}

bool BranchTool::key(QKeyEvent* event) {
    if (event->key() == Qt::Key_Escape && mContext.document.selectedBranch()) {
        mContext.document.setSelectedBranch(std::nullopt);
        mContext.viewport.update();
        return true;
    }
    if ((event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) &&
        mContext.document.selectedBranch()) {
        try {
            const auto& b = mContext.document.selectedBranch();
            pruneSelectedBranch(mContext.document, shownTree(mContext.result(), b->tree));
        } catch (...) {
            mContext.message(QString::fromStdString(doc::currentErrorMessage()));
        }
        mContext.viewport.update();
        return true;
    }
    return false;
}

} // namespace sylva::ui
