#pragma once

#include <map>
#include <string>

#include <QGraphicsObject>
#include <QGraphicsPathItem>
#include <QGraphicsScene>
#include <QPointer>

#include "document/document.h"
#include "engine/graph/graph.h"

namespace sylva::ui {

class NodeGraphScene;

/// One node of the species graph as drawn: a title (the node's id), its type, its compute time
/// and error state from the live preview, an input port on the left (when the type takes inputs)
/// and an output port on the right. Dragging it moves it; the move is one command on release.
class NodeItem : public QGraphicsObject {
    Q_OBJECT

public:
    static constexpr qreal kWidth = 176.0;
    static constexpr qreal kHeight = 64.0;

    NodeItem(NodeGraphScene& scene, QString id, QString type, QString category, bool takesInput,
             bool isOutput);
    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

    const QString& id() const { return mId; }
    const QString& nodeType() const { return mType; }
    bool takesInput() const { return mTakesInput; }
    /// Port centres in scene coordinates.
    QPointF inputPort() const { return mapToScene(QPointF(0, kHeight / 2)); }
    QPointF outputPort() const { return mapToScene(QPointF(kWidth, kHeight / 2)); }
    /// Whether a scene point is on the output or input port (a little generous for the mouse).
    bool onOutputPort(const QPointF& scenePos) const;
    bool onInputPort(const QPointF& scenePos) const;
    /// The live preview's figures for this node.
    void setRun(double ms, bool ran, const QString& error);

protected:
    QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;
    void mousePressEvent(QGraphicsSceneMouseEvent* event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent* event) override;

private:
    NodeGraphScene& mScene;
    QString mId, mType, mCategory;
    bool mTakesInput = false;
    bool mIsOutput = false;
    double mMs = -1.0;
    bool mRan = false;
    QString mError;
    QPointF mPressPos;
};

/// An edge: from one node's output to another's input.
class EdgeItem : public QGraphicsPathItem {
public:
    EdgeItem(NodeItem* from, NodeItem* to);
    void updatePath();
    NodeItem* from() const { return mFrom; }
    NodeItem* to() const { return mTo; }
    enum { Type = UserType + 2 };
    int type() const override { return Type; }

private:
    NodeItem* mFrom;
    NodeItem* mTo;
};

/// The node editor's scene: an adapter over one species graph of the Document (the graph model
/// lives in the document and the engine, as QtNodes keeps AbstractGraphModel apart from its
/// scene). It rebuilds itself when the document changes; every user action becomes a Document
/// call, i.e. a command in the document's one undo history. Refused edits emit refused() with
/// the engine's reason.
class NodeGraphScene : public QGraphicsScene {
    Q_OBJECT

public:
    explicit NodeGraphScene(doc::Document& document, QObject* parent = nullptr);
    ~NodeGraphScene() override;

    void setSpecies(const QString& species);
    const QString& species() const { return mSpecies; }
    doc::Document& document() { return mDocument; }

    NodeItem* node(const QString& id) const;
    QList<NodeItem*> nodes() const;
    QList<EdgeItem*> edges() const;
    QStringList selectedNodeIds() const;
    void selectNode(const QString& id);

    // Actions (each one Document call; errors are reported through refused()).
    bool addNode(QString type, QPointF at, const sylva::Value& params = {});
    bool connectNodes(QString from, QString to); // copies: the items naming them are rebuilt
    bool disconnectNodes(QString from, QString to);
    /// Deletes the selected nodes and edges as one undo step.
    bool deleteSelection();
    /// The selected nodes (type, params, edges among them) as JSON for the clipboard.
    QString copySelection() const;
    /// Adds the nodes of a copySelection() text at \p at with fresh ids, one undo step.
    bool paste(const QString& text, const QPointF& at);
    bool makeOutput(QString id);

    /// The live preview's per-node results (compute time, error).
    void setRuns(const std::map<std::string, graph::Evaluator::NodeRun>& runs,
                 const QString& errorNode, const QString& error);

    /// Called (queued) by NodeItem when a drag ends: one command per dragged node.
    void nodeMoved(const QString& id);
    void updateEdges();

Q_SIGNALS:
    void nodeSelected(const QString& id); ///< "" when none
    /// The items were made again from the document; \p nodesChanged when nodes came or went.
    void rebuilt(bool nodesChanged);
    void refused(const QString& why);
    void acted(const QString& what); ///< a successful edit, for the status bar

protected:
    void mousePressEvent(QGraphicsSceneMouseEvent* event) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent* event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent* event) override;

private:
    void rebuild();
    bool attempt(const std::function<void()>& edit);

    doc::Document& mDocument;
    QString mSpecies;
    std::map<QString, NodeItem*> mNodes;
    QList<EdgeItem*> mEdges;
    bool mRebuilding = false;
    // A connection being dragged from an output port (or off an input port).
    QGraphicsPathItem* mDragLine = nullptr;
    QString mDragFrom;
    QString mDetachFrom, mDetachTo; ///< the edge picked up by its input end
    std::map<std::string, graph::Evaluator::NodeRun> mRuns;
    QString mErrorNode, mError;
};

} // namespace sylva::ui
