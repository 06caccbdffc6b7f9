#include "ui/nodes/nodegraphscene.h"

#include <QCoreApplication>
#include <QGraphicsSceneMouseEvent>
#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <algorithm>
#include <functional>
#include <set>

#include "document/errormessage.h"
#include "document/speciesgraphedit.h"
#include "engine/util/error.h"

namespace sylva::ui {

namespace {

constexpr qreal kPortRadius = 7.0;

QColor categoryColor(const QString& category) {
    if (category == QLatin1String("Generator")) return QColor(70, 120, 70);
    if (category == QLatin1String("Environment")) return QColor(150, 100, 50);
    if (category == QLatin1String("Geometry")) return QColor(60, 100, 150);
    return QColor(90, 90, 90);
}

/// The node's inputs as drawn: a hand-written project may name one by a number, which every
/// edit of the species refuses with its reason; the node is drawn without its edges meanwhile.
std::vector<std::string> drawnInputs(const sylva::Value& node) {
    try {
        return doc::nodeInputs(node);
    } catch (const InvalidInput&) {
        return {};
    }
}

} // namespace

// ---- NodeItem -------------------------------------------------------------------------------

NodeItem::NodeItem(NodeGraphScene& scene, QString id, QString type, QString category,
                   bool takesInput, bool isOutput)
    : mScene(scene), mId(std::move(id)), mType(std::move(type)), mCategory(std::move(category)),
      mTakesInput(takesInput), mIsOutput(isOutput) {
    setFlags(ItemIsMovable | ItemIsSelectable | ItemSendsGeometryChanges);
    setZValue(1);
    setToolTip(QCoreApplication::translate("NodeGraph", "%1 (%2)").arg(mId, mType));
}

QRectF NodeItem::boundingRect() const {
    return QRectF(-kPortRadius - 2, -2, kWidth + 2 * kPortRadius + 4, kHeight + 4);
}

void NodeItem::paint(QPainter* p, const QStyleOptionGraphicsItem* option, QWidget*) {
    p->setRenderHint(QPainter::Antialiasing);
    const QRectF body(0, 0, kWidth, kHeight);
    const bool selected = option->state & QStyle::State_Selected;
    QPen border(mError.isEmpty() ? (selected ? QColor(255, 160, 40) : QColor(30, 30, 30))
                                 : QColor(220, 40, 40),
                selected || !mError.isEmpty() ? 2.5 : 1.0);
    p->setPen(border);
    p->setBrush(QColor(48, 48, 52));
    p->drawRoundedRect(body, 6, 6);
    // Title bar in the category's colour.
    QPainterPath title;
    title.addRoundedRect(QRectF(0, 0, kWidth, 22), 6, 6);
    title.addRect(QRectF(0, 12, kWidth, 10));
    p->fillPath(title.simplified(), categoryColor(mCategory));
    p->setPen(Qt::white);
    QFont f = p->font();
    f.setBold(true);
    p->setFont(f);
    p->drawText(QRectF(8, 0, kWidth - 16, 22), Qt::AlignVCenter | Qt::AlignLeft, mId);
    f.setBold(false);
    p->setFont(f);
    if (mIsOutput)
        p->drawText(QRectF(8, 0, kWidth - 16, 22), Qt::AlignVCenter | Qt::AlignRight,
                    QCoreApplication::translate("NodeGraph", "tree ▶"));
    p->setPen(QColor(200, 200, 200));
    p->drawText(QRectF(8, 24, kWidth - 16, 18), Qt::AlignVCenter | Qt::AlignLeft, mType);
    // The live preview's figure: compute time, "cached", or the error.
    QString status;
    QColor statusColor(150, 210, 150);
    if (!mError.isEmpty()) {
        // The message without its "file:line:col: error:" prefix; the tooltip has it all.
        QString shortError = mError;
        if (const int at = shortError.lastIndexOf(QLatin1String("error: ")); at >= 0)
            shortError = shortError.mid(at + 7);
        status = QCoreApplication::translate("NodeGraph", "✖ %1").arg(shortError);
        statusColor = QColor(255, 110, 110);
    } else if (mMs >= 0.0) {
        status =
            mRan ? QCoreApplication::translate("NodeGraph", "%1 ms").arg(mMs, 0, 'f', 1)
                 : QCoreApplication::translate("NodeGraph", "%1 ms (cached)").arg(mMs, 0, 'f', 1);
        if (!mRan) statusColor = QColor(160, 160, 160);
    }
    p->setPen(statusColor);
    p->drawText(QRectF(8, 42, kWidth - 16, 18), Qt::AlignVCenter | Qt::AlignLeft,
                p->fontMetrics().elidedText(status, Qt::ElideRight, int(kWidth - 16)));
    // Ports.
    p->setPen(QPen(QColor(20, 20, 20), 1));
    p->setBrush(QColor(230, 200, 90));
    p->drawEllipse(QPointF(kWidth, kHeight / 2), kPortRadius, kPortRadius);
    if (mTakesInput) {
        p->setBrush(QColor(120, 190, 240));
        p->drawEllipse(QPointF(0, kHeight / 2), kPortRadius, kPortRadius);
    }
}

bool NodeItem::onOutputPort(const QPointF& scenePos) const {
    return QLineF(scenePos, outputPort()).length() <= kPortRadius + 5;
}

bool NodeItem::onInputPort(const QPointF& scenePos) const {
    return mTakesInput && QLineF(scenePos, inputPort()).length() <= kPortRadius + 5;
}

void NodeItem::setRun(double ms, bool ran, const QString& error) {
    mMs = ms;
    mRan = ran;
    mError = error;
    setToolTip(error.isEmpty() ? QCoreApplication::translate("NodeGraph", "%1 (%2)").arg(mId, mType)
                               : error);
    update();
}

QVariant NodeItem::itemChange(GraphicsItemChange change, const QVariant& value) {
    if (change == ItemPositionHasChanged) mScene.updateEdges();
    return QGraphicsObject::itemChange(change, value);
}

void NodeItem::mousePressEvent(QGraphicsSceneMouseEvent* event) {
    mPressPos = pos();
    QGraphicsObject::mousePressEvent(event);
}

void NodeItem::mouseReleaseEvent(QGraphicsSceneMouseEvent* event) {
    QGraphicsObject::mouseReleaseEvent(event);
    // Queued: the command rebuilds the scene, which must not delete this item inside its own
    // event handler.
    if (pos() != mPressPos)
        QMetaObject::invokeMethod(
            &mScene, [scene = &mScene, id = mId] { scene->nodeMoved(id); }, Qt::QueuedConnection);
}

// ---- EdgeItem -------------------------------------------------------------------------------

EdgeItem::EdgeItem(NodeItem* from, NodeItem* to) : mFrom(from), mTo(to) {
    setFlags(ItemIsSelectable);
    setZValue(0);
    setPen(QPen(QColor(200, 200, 200), 2.0));
    updatePath();
}

void EdgeItem::updatePath() {
    const QPointF a = mFrom->outputPort(), b = mTo->inputPort();
    const qreal dx = std::max<qreal>(40.0, std::abs(b.x() - a.x()) * 0.5);
    QPainterPath path(a);
    path.cubicTo(a + QPointF(dx, 0), b - QPointF(dx, 0), b);
    setPath(path);
    setPen(QPen(isSelected() ? QColor(255, 160, 40) : QColor(200, 200, 200), 2.0));
}

// ---- NodeGraphScene -------------------------------------------------------------------------

NodeGraphScene::NodeGraphScene(doc::Document& document, QObject* parent)
    : QGraphicsScene(parent), mDocument(document) {
    setBackgroundBrush(QColor(36, 36, 40));
    connect(&mDocument, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        if (c.what & doc::DocumentChange::Reset) {
            if (mDocument.speciesIndex(mSpecies.toStdString()) < 0) mSpecies.clear();
            rebuild();
        } else if (c.what & doc::DocumentChange::Species) {
            if (!mSpecies.isEmpty() && mDocument.speciesIndex(mSpecies.toStdString()) < 0)
                mSpecies.clear();
            rebuild();
        }
    });
    connect(this, &QGraphicsScene::selectionChanged, this, [this] {
        if (mRebuilding) return;
        for (EdgeItem* e : mEdges)
            e->updatePath();
        const QStringList ids = selectedNodeIds();
        Q_EMIT nodeSelected(ids.isEmpty() ? QString() : ids.front());
    });
}

NodeGraphScene::~NodeGraphScene() {
    // QGraphicsScene's destructor removes the items and may signal selectionChanged, whose
    // handler reads this class's members: remove them while those still exist.
    mRebuilding = true;
    disconnect(this, nullptr, this, nullptr);
    clear();
    mNodes.clear();
    mEdges.clear();
}

void NodeGraphScene::setSpecies(const QString& species) {
    if (species == mSpecies) return;
    mSpecies = species;
    mRuns.clear();
    mError.clear();
    mErrorNode.clear();
    rebuild();
    Q_EMIT nodeSelected(QString());
}

NodeItem* NodeGraphScene::node(const QString& id) const {
    const auto it = mNodes.find(id);
    return it == mNodes.end() ? nullptr : it->second;
}

QList<NodeItem*> NodeGraphScene::nodes() const {
    QList<NodeItem*> out;
    for (const auto& [id, item] : mNodes)
        out << item;
    return out;
}

QList<EdgeItem*> NodeGraphScene::edges() const {
    return mEdges;
}

QStringList NodeGraphScene::selectedNodeIds() const {
    QStringList out;
    for (QGraphicsItem* item : selectedItems())
        if (auto* n = dynamic_cast<NodeItem*>(item)) out << n->id();
    out.sort();
    return out;
}

void NodeGraphScene::selectNode(const QString& id) {
    clearSelection();
    if (NodeItem* n = node(id)) n->setSelected(true);
}

void NodeGraphScene::rebuild() {
    mRebuilding = true;
    const QStringList selected = selectedNodeIds();
    QStringList before;
    for (const auto& [id, item] : mNodes)
        before << id;
    if (mDragLine) {
        removeItem(mDragLine);
        delete mDragLine;
        mDragLine = nullptr;
    }
    clear();
    mNodes.clear();
    mEdges.clear();
    sylva::Value g;
    if (!mSpecies.isEmpty()) {
        try {
            g = mDocument.speciesGraph(mSpecies.toStdString());
        } catch (...) {
            g = sylva::Value();
        }
    }
    if (g.isObject()) {
        graph::registerBuiltinNodeTypes();
        const graph::NodeRegistry& registry = graph::NodeRegistry::instance();
        const std::string output = g.string("output", "");
        const sylva::Value::Array& nodes = doc::graphNodes(g);
        // Nodes without a stored position are laid out by depth (longest path from a source).
        std::map<std::string, int> depth;
        std::function<int(const std::string&, int)> depthOf = [&](const std::string& id,
                                                                  int guard) -> int {
            if (auto it = depth.find(id); it != depth.end()) return it->second;
            int d = 0;
            for (const sylva::Value& n : nodes)
                if (n.string("id", "") == id && guard < 64)
                    for (const std::string& in : drawnInputs(n))
                        d = std::max(d, depthOf(in, guard + 1) + 1);
            depth[id] = d;
            return d;
        };
        std::map<int, int> rowsAtDepth;
        for (const sylva::Value& n : nodes) {
            const std::string id = n.string("id", "");
            const std::string type = n.string("type", "");
            const graph::NodeType* t = registry.find(type);
            auto* item =
                new NodeItem(*this, QString::fromStdString(id), QString::fromStdString(type),
                             t ? QString::fromStdString(t->category) : QString(),
                             t && t->maxInputs > 0, id == output);
            QPointF at;
            // The position stored in the node (the graph was read once above).
            if (const std::optional<glm::dvec2> p = doc::nodeEditorPosition(n)) {
                at = QPointF(p->x, p->y);
            } else {
                const int d = depthOf(id, 0);
                at = QPointF(d * 230.0, rowsAtDepth[d]++ * 96.0);
            }
            item->setPos(at);
            addItem(item);
            mNodes[item->id()] = item;
        }
        for (const sylva::Value& n : nodes) {
            NodeItem* to = node(QString::fromStdString(n.string("id", "")));
            for (const std::string& in : drawnInputs(n))
                if (NodeItem* from = node(QString::fromStdString(in))) {
                    auto* e = new EdgeItem(from, to);
                    e->setToolTip(QCoreApplication::translate("NodeGraph", "%1 → %2")
                                      .arg(from->id(), to->id()));
                    addItem(e);
                    mEdges << e;
                }
        }
    }
    for (const QString& id : selected)
        if (NodeItem* n = node(id)) n->setSelected(true);
    setRuns(mRuns, mErrorNode, mError);
    mRebuilding = false;
    QStringList after;
    for (const auto& [id, item] : mNodes)
        after << id;
    Q_EMIT rebuilt(after != before);
}

void NodeGraphScene::setRuns(const std::map<std::string, graph::Evaluator::NodeRun>& runs,
                             const QString& errorNode, const QString& error) {
    mRuns = runs;
    mErrorNode = errorNode;
    mError = error;
    for (const auto& [id, item] : mNodes) {
        const auto it = runs.find(id.toStdString());
        const QString nodeError = id == errorNode ? error : QString();
        if (it == runs.end())
            item->setRun(-1.0, false, nodeError);
        else
            item->setRun(it->second.ms, it->second.ran, nodeError);
    }
}

void NodeGraphScene::updateEdges() {
    for (EdgeItem* e : mEdges)
        e->updatePath();
}

bool NodeGraphScene::attempt(const std::function<void()>& edit) {
    try {
        edit();
        return true;
    } catch (...) {
        Q_EMIT refused(QString::fromStdString(
            doc::describeError(std::current_exception(), mSpecies.toStdString()).message));
        rebuild(); // a refused move or drag puts the items back where the document has them
        return false;
    }
}

bool NodeGraphScene::addNode(QString type, QPointF at, const sylva::Value& params) {
    QString made;
    const bool ok = attempt([&] {
        made = QString::fromStdString(
            mDocument.addNode(mSpecies.toStdString(), type.toStdString(),
                              params.isNull() ? sylva::Value(sylva::Value::Object{}) : params, {},
                              glm::vec2(float(at.x()), float(at.y()))));
    });
    if (ok) {
        selectNode(made);
        Q_EMIT acted(tr("Added %1").arg(made));
    }
    return ok;
}

bool NodeGraphScene::connectNodes(QString from, QString to) {
    const bool ok = attempt([&] {
        mDocument.connectNodes(mSpecies.toStdString(), from.toStdString(), to.toStdString());
    });
    if (ok) Q_EMIT acted(tr("Connected %1 to %2").arg(from, to));
    return ok;
}

bool NodeGraphScene::disconnectNodes(QString from, QString to) {
    const bool ok = attempt([&] {
        mDocument.disconnectNodes(mSpecies.toStdString(), from.toStdString(), to.toStdString());
    });
    if (ok) Q_EMIT acted(tr("Disconnected %1 from %2").arg(from, to));
    return ok;
}

bool NodeGraphScene::makeOutput(QString id) {
    return attempt([&] { mDocument.setOutputNode(mSpecies.toStdString(), id.toStdString()); });
}

bool NodeGraphScene::deleteSelection() {
    std::vector<std::pair<std::string, std::string>> edges;
    for (QGraphicsItem* item : selectedItems())
        if (auto* e = dynamic_cast<EdgeItem*>(item))
            edges.emplace_back(e->from()->id().toStdString(), e->to()->id().toStdString());
    const QStringList ids = selectedNodeIds();
    if (edges.empty() && ids.isEmpty()) return false;
    std::vector<std::string> nodeIds;
    for (const QString& id : ids)
        nodeIds.push_back(id.toStdString());
    const bool ok = attempt([&] { mDocument.removeNodes(mSpecies.toStdString(), nodeIds, edges); });
    if (ok)
        Q_EMIT acted(tr("Deleted %1").arg(ids.isEmpty() ? tr("a connection") : ids.join(u", ")));
    return ok;
}

QString NodeGraphScene::copySelection() const {
    const QStringList ids = selectedNodeIds();
    if (ids.isEmpty()) return {};
    sylva::Value g;
    try {
        g = mDocument.speciesGraph(mSpecies.toStdString());
    } catch (...) {
        return {};
    }
    sylva::Value::Array out;
    for (const sylva::Value& n : doc::graphNodes(g)) {
        const QString id = QString::fromStdString(n.string("id", ""));
        if (!ids.contains(id)) continue;
        sylva::Value::Object copy{{"id", n.string("id", "")},
                                  {"type", n.string("type", "")},
                                  {"params", n.find("params")
                                                 ? *n.find("params")
                                                 : sylva::Value(sylva::Value::Object{})}};
        sylva::Value::Array inputs;
        for (const std::string& in : drawnInputs(n))
            if (ids.contains(QString::fromStdString(in))) inputs.emplace_back(in);
        copy["inputs"] = sylva::Value(std::move(inputs));
        if (NodeItem* item = node(id))
            copy["editor_position"] =
                sylva::Value(sylva::Value::Array{item->pos().x(), item->pos().y()});
        out.emplace_back(std::move(copy));
    }
    return QString::fromStdString(
        sylva::Value(sylva::Value::Object{{"sylva_nodes", sylva::Value(std::move(out))}}).toJson());
}

bool NodeGraphScene::paste(const QString& text, const QPointF& at) {
    sylva::Value v;
    try {
        v = sylva::Value::parseJson(text.toStdString());
    } catch (...) {
        return false;
    }
    const sylva::Value* list = v.find("sylva_nodes");
    if (!list || !list->isArray() || list->toArray().empty()) return false;
    QStringList made;
    const bool ok = attempt([&] {
        for (const std::string& id : mDocument.pasteNodes(mSpecies.toStdString(), list->toArray(),
                                                          glm::dvec2(at.x(), at.y())))
            made << QString::fromStdString(id);
    });
    if (!ok) return false;
    clearSelection();
    for (const QString& id : made)
        if (NodeItem* n = node(id)) n->setSelected(true);
    Q_EMIT acted(tr("Pasted %1").arg(made.join(u", ")));
    return true;
}

void NodeGraphScene::nodeMoved(const QString& id) {
    // One command per drag (on release), for each node the drag moved.
    NodeItem* item = node(id);
    if (!item) return;
    QList<NodeItem*> moved;
    for (QGraphicsItem* s : selectedItems())
        if (auto* n = dynamic_cast<NodeItem*>(s)) moved << n;
    if (!moved.contains(item)) moved << item;
    // Ids and positions first: each command rebuilds the scene (and deletes these items).
    std::vector<std::pair<std::string, glm::vec2>> targets;
    for (NodeItem* n : moved)
        targets.emplace_back(n->id().toStdString(),
                             glm::vec2(float(n->pos().x()), float(n->pos().y())));
    attempt([&] { mDocument.moveNodes(mSpecies.toStdString(), targets); });
}

void NodeGraphScene::mousePressEvent(QGraphicsSceneMouseEvent* event) {
    if (event->button() == Qt::LeftButton) {
        for (NodeItem* n : nodes()) {
            if (n->onOutputPort(event->scenePos())) {
                mDragFrom = n->id();
            } else if (n->onInputPort(event->scenePos())) {
                // Pick up the edge arriving here by its end (drop it on empty space: disconnect).
                for (EdgeItem* e : mEdges)
                    if (e->to() == n) {
                        mDragFrom = e->from()->id();
                        mDetachFrom = e->from()->id();
                        mDetachTo = n->id();
                    }
            }
            if (!mDragFrom.isEmpty()) break;
        }
        if (!mDragFrom.isEmpty()) {
            mDragLine = new QGraphicsPathItem;
            mDragLine->setPen(QPen(QColor(255, 200, 80), 2.0, Qt::DashLine));
            mDragLine->setZValue(2);
            addItem(mDragLine);
            mouseMoveEvent(event);
            event->accept();
            return;
        }
    }
    QGraphicsScene::mousePressEvent(event);
}

void NodeGraphScene::mouseMoveEvent(QGraphicsSceneMouseEvent* event) {
    if (mDragLine) {
        const NodeItem* from = node(mDragFrom);
        if (!from) return;
        QPainterPath path(from->outputPort());
        path.lineTo(event->scenePos());
        mDragLine->setPath(path);
        event->accept();
        return;
    }
    QGraphicsScene::mouseMoveEvent(event);
}

void NodeGraphScene::mouseReleaseEvent(QGraphicsSceneMouseEvent* event) {
    if (!mDragLine) {
        QGraphicsScene::mouseReleaseEvent(event);
        return;
    }
    removeItem(mDragLine);
    delete mDragLine;
    mDragLine = nullptr;
    const QString from = mDragFrom, detachFrom = mDetachFrom, detachTo = mDetachTo;
    mDragFrom.clear();
    mDetachFrom.clear();
    mDetachTo.clear();
    NodeItem* target = nullptr;
    for (NodeItem* n : nodes())
        if (n->sceneBoundingRect().contains(event->scenePos()) && n->id() != from) target = n;
    event->accept();
    if (target) {
        if (target->id() != detachTo) connectNodes(from, target->id());
    } else if (!detachTo.isEmpty()) {
        disconnectNodes(detachFrom, detachTo);
    }
}

} // namespace sylva::ui
