#include "ui/nodes/nodegraphview.h"

#include <QApplication>
#include <QClipboard>
#include <QContextMenuEvent>
#include <QKeyEvent>
#include <QLineEdit>
#include <QMenu>
#include <QScrollBar>
#include <QWheelEvent>
#include <QWidgetAction>

#include "engine/graph/graph.h"

namespace sylva::ui {

NodeGraphView::NodeGraphView(NodeGraphScene* scene, QWidget* parent)
    : QGraphicsView(scene, parent), mScene(scene) {
    setRenderHint(QPainter::Antialiasing);
    setDragMode(QGraphicsView::RubberBandDrag);
    setTransformationAnchor(QGraphicsView::AnchorUnderMouse);
    setViewportUpdateMode(QGraphicsView::FullViewportUpdate);
    setFocusPolicy(Qt::StrongFocus);
    setSceneRect(-5000, -5000, 10000, 10000);
    // A node added or removed stays in view until the user zooms or pans himself.
    connect(scene, &NodeGraphScene::rebuilt, this, [this](bool nodesChanged) {
        if (nodesChanged && !mUserZoomed) frameAll();
    });
    setToolTip(tr("Species graph: drag from a node's right port to another node to connect; Tab "
                  "or right click adds a node; Delete removes; Ctrl+C/Ctrl+V copy and paste; F "
                  "frames all"));
}

void NodeGraphView::frameAll() {
    if (!isVisible() || width() < 50 || height() < 50) return; // framed when shown
    QRectF r = mScene->itemsBoundingRect();
    if (r.isEmpty()) return;
    r.adjust(-40, -40, 40, 40);
    fitInView(r, Qt::KeepAspectRatio);
    // Never zoom in past 1:1: a two-node graph should not fill the screen with giant boxes.
    if (transform().m11() > 1.0) {
        resetTransform();
        centerOn(r.center());
    }
}

QPointF NodeGraphView::cursorScenePos() const {
    const QPoint p = mapFromGlobal(QCursor::pos());
    return rect().contains(p) ? mapToScene(p) : mapToScene(rect().center());
}

QMenu* NodeGraphView::makeAddMenu(const QPointF& scenePos) {
    auto* menu = new QMenu(this);
    menu->setObjectName(QStringLiteral("addNodeMenu"));
    menu->setAttribute(Qt::WA_DeleteOnClose);
    menu->setToolTipsVisible(true);
    auto* search = new QLineEdit(menu);
    search->setObjectName(QStringLiteral("addNodeSearch"));
    search->setPlaceholderText(tr("Search node types…"));
    search->setClearButtonEnabled(true);
    auto* searchAction = new QWidgetAction(menu);
    searchAction->setDefaultWidget(search);
    menu->addAction(searchAction);
    menu->addSeparator();
    graph::registerBuiltinNodeTypes();
    const graph::NodeRegistry& registry = graph::NodeRegistry::instance();
    QList<QAction*> typeActions;
    for (const std::string& name : registry.names()) {
        const graph::NodeType* t = registry.find(name);
        if (t->category.empty()) continue; // test or internal types
        const QString type = QString::fromStdString(name);
        QAction* a =
            menu->addAction(tr("%1  —  %2").arg(type, QString::fromStdString(t->category)));
        a->setData(type);
        a->setToolTip(QString::fromStdString(t->doc));
        connect(a, &QAction::triggered, this,
                [this, type, scenePos] { mScene->addNode(type, scenePos); });
        typeActions << a;
    }
    connect(search, &QLineEdit::textChanged, menu, [typeActions](const QString& text) {
        // Names first; when no name matches, what the types do ("leaf", "obstacle").
        bool byName = false;
        for (QAction* a : typeActions)
            byName = byName || a->text().contains(text, Qt::CaseInsensitive);
        for (QAction* a : typeActions)
            a->setVisible(text.isEmpty() || a->text().contains(text, Qt::CaseInsensitive) ||
                          (!byName && a->toolTip().contains(text, Qt::CaseInsensitive)));
    });
    connect(search, &QLineEdit::returnPressed, menu, [menu, typeActions] {
        for (QAction* a : typeActions)
            if (a->isVisible()) {
                menu->close();
                a->trigger();
                return;
            }
    });
    return menu;
}

bool NodeGraphView::event(QEvent* event) {
    // The editor's keys belong to the graph while it has focus, not to the window's shortcuts
    // (Delete would delete the selected trees, Ctrl+C/V would do nothing).
    if (event->type() == QEvent::ShortcutOverride) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Delete || key->key() == Qt::Key_Backspace ||
            key->key() == Qt::Key_Tab || key->key() == Qt::Key_F || key->key() == Qt::Key_Home ||
            key->matches(QKeySequence::Copy) || key->matches(QKeySequence::Paste)) {
            event->accept();
            return true;
        }
    }
    return QGraphicsView::event(event);
}

bool NodeGraphView::focusNextPrevChild(bool next) {
    // Tab belongs to the node editor (the add-node menu), not to focus navigation.
    if (hasFocus()) return false;
    return QGraphicsView::focusNextPrevChild(next);
}

void NodeGraphView::keyPressEvent(QKeyEvent* event) {
    if (event->key() == Qt::Key_Tab) {
        QMenu* menu = makeAddMenu(cursorScenePos());
        menu->popup(QCursor::pos());
        if (auto* search = menu->findChild<QLineEdit*>(QStringLiteral("addNodeSearch")))
            search->setFocus();
        return;
    }
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        mScene->deleteSelection();
        return;
    }
    if (event->matches(QKeySequence::Copy)) {
        const QString text = mScene->copySelection();
        if (!text.isEmpty()) QApplication::clipboard()->setText(text);
        return;
    }
    if (event->matches(QKeySequence::Paste)) {
        mScene->paste(QApplication::clipboard()->text(), cursorScenePos());
        return;
    }
    if (event->key() == Qt::Key_F || event->key() == Qt::Key_Home) {
        frameAll();
        return;
    }
    QGraphicsView::keyPressEvent(event);
}

void NodeGraphView::showEvent(QShowEvent* event) {
    QGraphicsView::showEvent(event);
    if (!mUserZoomed) frameAll();
}

void NodeGraphView::resizeEvent(QResizeEvent* event) {
    QGraphicsView::resizeEvent(event);
    if (!mUserZoomed) frameAll();
}

void NodeGraphView::wheelEvent(QWheelEvent* event) {
    mUserZoomed = true;
    const double factor = std::pow(1.0015, event->angleDelta().y());
    const double zoom = transform().m11() * factor;
    if (zoom < 0.15 || zoom > 3.0) return;
    scale(factor, factor);
}

void NodeGraphView::contextMenuEvent(QContextMenuEvent* event) {
    const QPointF at = mapToScene(event->pos());
    NodeItem* hit = nullptr;
    for (NodeItem* n : mScene->nodes())
        if (n->sceneBoundingRect().contains(at)) hit = n;
    if (!hit) {
        makeAddMenu(at)->popup(event->globalPos());
        return;
    }
    auto* menu = new QMenu(this);
    menu->setAttribute(Qt::WA_DeleteOnClose);
    const QString id = hit->id();
    menu->addAction(tr("Make it the tree (output)"), this, [this, id] { mScene->makeOutput(id); });
    menu->addAction(tr("Delete"), this, [this, id] {
        mScene->selectNode(id);
        mScene->deleteSelection();
    });
    menu->popup(event->globalPos());
}

void NodeGraphView::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::MiddleButton) {
        mPanning = true;
        mUserZoomed = true;
        mPanLast = event->pos();
        return;
    }
    QGraphicsView::mousePressEvent(event);
}

void NodeGraphView::mouseMoveEvent(QMouseEvent* event) {
    if (mPanning) {
        const QPoint d = event->pos() - mPanLast;
        mPanLast = event->pos();
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() - d.x());
        verticalScrollBar()->setValue(verticalScrollBar()->value() - d.y());
        return;
    }
    QGraphicsView::mouseMoveEvent(event);
}

void NodeGraphView::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() == Qt::MiddleButton) {
        mPanning = false;
        return;
    }
    QGraphicsView::mouseReleaseEvent(event);
}

} // namespace sylva::ui
