#pragma once

#include <QGraphicsView>

#include "ui/nodes/nodegraphscene.h"

class QMenu;

namespace sylva::ui {

/// The node editor's view: zoom with the wheel, pan with the middle button, and the keys of node
/// editors: Tab (or a right click on empty space) opens a searchable menu of node types, Delete
/// removes the selection, Ctrl+C / Ctrl+V copy and paste nodes, F frames all.
class NodeGraphView : public QGraphicsView {
    Q_OBJECT

public:
    explicit NodeGraphView(NodeGraphScene* scene, QWidget* parent = nullptr);
    NodeGraphScene* graphScene() const { return mScene; }
    void frameAll();
    /// The add-node menu at \p scenePos (what Tab opens): a search field, then every node type
    /// matching it, with its one-line doc as tooltip. Returned for tests; shown by the caller.
    QMenu* makeAddMenu(const QPointF& scenePos);

protected:
    bool event(QEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    bool focusNextPrevChild(bool next) override;
    void wheelEvent(QWheelEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void contextMenuEvent(QContextMenuEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;

private:
    QPointF cursorScenePos() const;

    NodeGraphScene* mScene;
    bool mPanning = false;
    bool mUserZoomed = false; ///< the user zoomed or panned: resizing no longer frames all
    QPoint mPanLast;
};

} // namespace sylva::ui
