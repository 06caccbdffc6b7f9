#pragma once

#include <QWidget>

#include <optional>
#include <utility>

#include <glm/glm.hpp>

#include "document/document.h"

class QComboBox;
class QLabel;
class QSplitter;

namespace sylva::ui {

class GrammarEditor;
class NodeGraphScene;
class NodeGraphView;
class ParameterPanel;
class DocumentGenerator;
class SpeciesBranchEditing;
class SpeciesPreview;
class ToolController;
class Viewport;
struct ViewTree;

/// Where a species is tuned: its node graph, the grammar of the selected lsystem node, and a live
/// preview of one tree with each node's compute time; the selected node's parameters are in a
/// ParameterPanel the window docks beside it. Every widget edits the one Document (one undo
/// history with the scene); the preview re-evaluates only the nodes an edit touched.
class SpeciesWorkbench : public QWidget {
    Q_OBJECT

public:
    explicit SpeciesWorkbench(doc::Document& document, QWidget* parent = nullptr);

    void setSpecies(const QString& species);
    QString species() const;
    /// What a click on the preview at \p pos (widget pixels) hits: the node that grew it is
    /// selected (a leaf card: the leaves node when there is one, else the generator; a branch:
    /// the generator). Returns that node's id, "" for a miss.
    /// For an L-system branch, the grammar editor also highlights the rule that wrote it.
    QString selectNodeAt(const QPointF& pos);
    /// The source line (an L-system rule's) of the drawn branch nearest \p point, in the preview's
    /// world space; 0 when the preview's skeleton carries no source lines.
    int sourceLineAt(const glm::vec3& point) const;
    /// A branch of a tree of the scene was clicked at \p local (the tree's own coordinates): the
    /// preview grows that tree (\p species, \p seed) and, once it has, the generator is selected
    /// and, for an L-system, the rule behind the nearest branch is marked. The scene's tree may be
    /// adapted to obstacles; the preview's is not, so a bent branch is matched where it grew.
    void showBranchOf(const QString& species, std::uint64_t seed, const glm::vec3& local);

    /// Lets the window's Branch tool edit a hand-placed tree in the preview (SpeciesBranchEditing:
    /// the tools' current tool, the document's generation for the tree as drawn).
    void editBranchesWith(ToolController& tools, DocumentGenerator& generator);
    SpeciesBranchEditing* branchEditing() const { return mBranchEditing; }
    /// Shows \p tree (a project's tree as the scene draws it, in its place) in the preview
    /// instead of the species' tree, framed when \p frame; null: the species' tree again.
    /// Clicks then belong to the preview's tool, not to node picking.
    void showTree(const ViewTree* tree, bool frame);
    bool showsTree() const { return mShowingTree; }

    NodeGraphScene* graphScene() const { return mScene; }
    NodeGraphView* graphView() const { return mView; }
    ParameterPanel* parameters() const { return mParameters; }
    GrammarEditor* grammar() const { return mGrammar; }
    SpeciesPreview* preview() const { return mPreview; }
    Viewport* previewViewport() const { return mPreviewView; }

Q_SIGNALS:
    /// A line for the status bar ("Preview 23 ms", a refused connection's reason).
    void status(const QString& text, int timeoutMs);
    /// The species preview failed: \p where names the species and the failing node.
    void previewFailed(const QString& where, const QString& message);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void refillSpecies();
    /// Shows the graph's selected node in the parameter panel (and an L-system's grammar).
    void showSelectionInPanels();
    void onPreviewFinished();
    /// The leaves node and the generator the output is grown from ("" where there is none).
    std::pair<QString, QString> growingNodes() const;
    void resolvePendingBranch();

    doc::Document& mDocument;
    QComboBox* mSpeciesCombo;
    QLabel* mPreviewLabel;
    QLabel* mPreviewError;
    QLabel* mRefusal;
    NodeGraphScene* mScene;
    NodeGraphView* mView;
    ParameterPanel* mParameters;
    GrammarEditor* mGrammar;
    SpeciesPreview* mPreview;
    Viewport* mPreviewView;
    bool mFramed = false;
    glm::vec3 mFramedLo{0.0f}, mFramedHi{0.0f}; ///< the bounds the preview was last framed on
    QPoint mPressAt; ///< where a click on the preview began (a drag orbits instead)
    std::optional<glm::vec3> mPendingBranch; ///< a scene click waiting for its tree's preview
    SpeciesBranchEditing* mBranchEditing = nullptr;
    bool mShowingTree = false; ///< showTree(): a project's tree, not the species' preview
};

} // namespace sylva::ui
