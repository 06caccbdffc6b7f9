#include "ui/speciesworkbench.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSplitter>
#include <QTimer>
#include <QVBoxLayout>

#include "ui/generation/speciespreview.h"
#include "ui/grammar/grammareditor.h"
#include "ui/nodes/nodegraphscene.h"
#include "ui/nodes/nodegraphview.h"
#include "ui/nodes/parameterpanel.h"
#include "ui/speciesbranchediting.h"
#include "ui/viewport/picking.h"
#include "ui/viewport/viewport.h"

#include <QMouseEvent>
#include <limits>

#include "engine/graph/graph.h"
#include "engine/mesh/mesh.h"

namespace sylva::ui {

namespace {

/// Whether the grammar editor edits nodes of this type: the type declares a text `grammar`.
bool takesGrammar(const QString& type) {
    const graph::NodeType* t = graph::findType(type.toStdString());
    const graph::ParamSpec* p = t ? t->findParam("grammar") : nullptr;
    return p && p->kind == graph::ParamKind::Text;
}

} // namespace

SpeciesWorkbench::SpeciesWorkbench(doc::Document& document, QWidget* parent)
    : QWidget(parent), mDocument(document) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Species:"), this));
    mSpeciesCombo = new QComboBox(this);
    mSpeciesCombo->setObjectName(QStringLiteral("workbenchSpecies"));
    mSpeciesCombo->setMinimumWidth(160);
    top->addWidget(mSpeciesCombo);
    mRefusal = new QLabel(this);
    mRefusal->setObjectName(QStringLiteral("graphRefusal"));
    mRefusal->setStyleSheet(QStringLiteral("color: #e05050"));
    mRefusal->setWordWrap(true);
    top->addWidget(mRefusal, 1);
    mPreviewLabel = new QLabel(this);
    mPreviewLabel->setObjectName(QStringLiteral("previewTime"));
    top->addWidget(mPreviewLabel);
    layout->addLayout(top);

    mScene = new NodeGraphScene(document, this);
    mView = new NodeGraphView(mScene, this);
    mView->setObjectName(QStringLiteral("nodeGraph"));
    mParameters = new ParameterPanel(document);
    mParameters->setObjectName(QStringLiteral("parameterPanel"));
    mGrammar = new GrammarEditor(document, this);
    mGrammar->setObjectName(QStringLiteral("grammarEditor"));
    mPreview = new SpeciesPreview(document, this);
    mPreviewView = new Viewport(this);
    mPreviewView->setObjectName(QStringLiteral("speciesPreview"));
    mPreviewView->setMinimumSize(200, 160);
    mPreviewView->setToolTip(tr("Click a branch or a leaf to select the node that grew it"));
    mPreviewView->installEventFilter(this);
    {
        // Without multisampling: under a software rasteriser (Mesa llvmpipe) 4× MSAA made the
        // preview's edit → screen time 2.7× longer (docs/perf/editor.md); the preview is
        // small and is there to follow edits.
        QSurfaceFormat format = mPreviewView->format();
        format.setSamples(0);
        mPreviewView->setFormat(format);
    }

    // Each pane says what it is and how to use it, for someone who has never seen it.
    auto captioned = [this](const QString& caption, QWidget* widget) {
        auto* pane = new QWidget(this);
        auto* l = new QVBoxLayout(pane);
        l->setContentsMargins(0, 0, 0, 0);
        l->setSpacing(2);
        auto* label = new QLabel(caption, pane);
        label->setWordWrap(true);
        label->setStyleSheet(QStringLiteral("color: #707070"));
        l->addWidget(label);
        l->addWidget(widget, 1);
        return pane;
    };
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(captioned(tr("<b>Graph</b> — how the species grows: Tab adds a node, drag "
                                  "from a right port to a node to connect, Delete removes"),
                               mView));
    split->addWidget(mGrammar);
    // A failed preview says so on its own pane, above an emptied view (never a stale tree).
    mPreviewError = new QLabel(this);
    mPreviewError->setObjectName(QStringLiteral("previewError"));
    mPreviewError->setStyleSheet(
        QStringLiteral("color: #ffffff; background: #b03030; padding: 4px; font-weight: bold"));
    mPreviewError->setWordWrap(true);
    mPreviewError->setTextInteractionFlags(Qt::TextSelectableByMouse);
    mPreviewError->hide();
    auto* previewPane = new QWidget(this);
    {
        auto* l = new QVBoxLayout(previewPane);
        l->setContentsMargins(0, 0, 0, 0);
        l->setSpacing(2);
        l->addWidget(mPreviewError);
        l->addWidget(mPreviewView, 1);
    }
    split->addWidget(captioned(tr("<b>Preview</b> — one tree; click a branch to select the node "
                                  "that grew it and see its grammar rule"),
                               previewPane));
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 3);
    split->setStretchFactor(2, 2);
    layout->addWidget(split, 1);

    connect(mSpeciesCombo, &QComboBox::currentTextChanged, this,
            [this](const QString& s) { setSpecies(s); });
    connect(&mDocument, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        if (c.what & (doc::DocumentChange::Species | doc::DocumentChange::Reset)) refillSpecies();
        // A reset (open, save under a new name, revert) empties the panels, which handled it
        // first; the graph keeps its selection when its species is still there, so show it.
        if (c.what & doc::DocumentChange::Reset) showSelectionInPanels();
    });
    connect(mScene, &NodeGraphScene::nodeSelected, this, [this] { showSelectionInPanels(); });
    connect(mScene, &NodeGraphScene::refused, this, [this](const QString& why) {
        mRefusal->setText(why);
        Q_EMIT status(why, 8000);
    });
    connect(mScene, &NodeGraphScene::acted, this, [this](const QString& what) {
        mRefusal->clear();
        Q_EMIT status(what, 3000);
    });
    connect(mParameters, &ParameterPanel::editGrammarRequested, this,
            [this](const QString& s, const QString& node) {
                mGrammar->setNode(s, node);
                mGrammar->textEdit()->setFocus();
            });
    connect(mGrammar, &GrammarEditor::stepChanged, this,
            [this](const QString&, const QString& node, int generations) {
                mPreview->setOverride(node, "generations",
                                      generations < 0 ? sylva::Value() : sylva::Value(generations));
            });
    connect(mPreview, &SpeciesPreview::finished, this, &SpeciesWorkbench::onPreviewFinished);
    connect(mPreviewView, &Viewport::frameSwapped, mPreview, &SpeciesPreview::markShown);
    connect(mPreview, &SpeciesPreview::shown, this, [this](double ms) {
        mPreviewLabel->setText(tr("Preview: %1 ms from the edit").arg(ms, 0, 'f', 0));
        Q_EMIT status(
            tr("Species preview: %1 ms from the edit to the new tree on screen").arg(ms, 0, 'f', 1),
            4000);
    });
    refillSpecies();
}

QString SpeciesWorkbench::species() const {
    return mScene->species();
}

bool SpeciesWorkbench::eventFilter(QObject* watched, QEvent* event) {
    if (watched == mPreviewView && event->type() == QEvent::MouseButtonPress) {
        mPressAt = static_cast<QMouseEvent*>(event)->position().toPoint();
    } else if (watched == mPreviewView && event->type() == QEvent::MouseButtonRelease &&
               !mShowingTree) {
        auto* m = static_cast<QMouseEvent*>(event);
        // A click, not the end of an orbit drag.
        if (m->button() == Qt::LeftButton &&
            (m->position().toPoint() - mPressAt).manhattanLength() <= 3)
            selectNodeAt(m->position());
    }
    return QWidget::eventFilter(watched, event);
}

std::pair<QString, QString> SpeciesWorkbench::growingNodes() const {
    // Walk from the output up its inputs: the first leaves node for a leaf card, and the
    // generator (the node without inputs) for a branch or a grammar's own leaf.
    QString leavesNode, generator;
    try {
        const graph::SpeciesGraph g = mDocument.engineSpecies(species().toStdString());
        const graph::NodeDesc* n = g.findNode(g.output);
        while (n) {
            if (graph::roleOf(n->type) == graph::NodeRole::Leaves && leavesNode.isEmpty())
                leavesNode = QString::fromStdString(n->id);
            if (n->inputs.empty()) {
                generator = QString::fromStdString(n->id);
                break;
            }
            n = g.findNode(n->inputs.front());
        }
    } catch (...) {
        return {};
    }
    return {leavesNode, generator};
}

void SpeciesWorkbench::showBranchOf(const QString& species, std::uint64_t seed,
                                    const glm::vec3& local) {
    setSpecies(species);
    mPendingBranch = local;
    mPreview->setSeed(seed); // the preview grows that very tree
    if (!mPreview->isBusy()) resolvePendingBranch();
}

void SpeciesWorkbench::resolvePendingBranch() {
    if (!mPendingBranch) return;
    const glm::vec3 point = *mPendingBranch;
    mPendingBranch.reset();
    const QString generator = growingNodes().second;
    if (generator.isEmpty()) return;
    mScene->selectNode(generator);
    const int line = sourceLineAt(point);
    if (line > 0 && generator == mGrammar->node()) {
        mGrammar->highlightLine(line);
        Q_EMIT status(
            tr("A branch of the clicked tree, grown by node %1: the rule on line %2 (the preview "
               "shows that tree, before adaptation)")
                .arg(generator)
                .arg(line),
            6000);
    }
}

int SpeciesWorkbench::sourceLineAt(const glm::vec3& point) const {
    const std::shared_ptr<const skel::Skeleton> sk = mPreview->result().skeleton;
    if (!sk || sk->sourceLine.size() != sk->size()) return 0;
    // The drawn segment whose tube surface is closest to the point (the point lies on a tube:
    // its distance to the axis minus the radius is about zero there).
    float best = std::numeric_limits<float>::max();
    int line = 0;
    for (std::size_t i = 0; i < sk->size(); ++i) {
        const std::int32_t p = sk->parent[i];
        if (p < 0 || (sk->flags[i] & skel::kHidden)) continue;
        const glm::vec3 a = sk->position[static_cast<std::size_t>(p)], b = sk->position[i];
        const glm::vec3 ab = b - a;
        const float len2 = glm::dot(ab, ab);
        const float t = len2 > 0.0f ? std::clamp(glm::dot(point - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
        const float radius = glm::mix(sk->radius[static_cast<std::size_t>(p)], sk->radius[i], t);
        const float d = std::abs(glm::length(point - (a + t * ab)) - radius);
        if (d < best) {
            best = d;
            line = sk->sourceLine[i];
        }
    }
    return line;
}

QString SpeciesWorkbench::selectNodeAt(const QPointF& pos) {
    const std::shared_ptr<const mesh::Mesh> mesh = mPreview->result().mesh;
    if (!mesh) return {};
    const Ray ray = mPreviewView->rayAt(pos);
    float best = std::numeric_limits<float>::max();
    std::size_t hit = mesh->triangleCount();
    for (std::size_t t = 0; t < mesh->triangleCount(); ++t) {
        const auto d = intersect(ray, mesh->positions[mesh->indices[3 * t]],
                                 mesh->positions[mesh->indices[3 * t + 1]],
                                 mesh->positions[mesh->indices[3 * t + 2]]);
        if (d && *d < best) {
            best = *d;
            hit = t;
        }
    }
    if (hit == mesh->triangleCount()) return {};
    bool leaf = false;
    for (const mesh::Submesh& s : mesh->submeshes)
        if (3 * hit >= s.firstIndex && 3 * hit < s.firstIndex + s.indexCount)
            leaf = s.material.find("leaf") != std::string::npos;
    const auto [leavesNode, generator] = growingNodes();
    const QString node = leaf && !leavesNode.isEmpty() ? leavesNode : generator;
    if (node.isEmpty()) return {};
    mScene->selectNode(node);
    // A branch of an L-system: the rule that wrote it (the preview traces rule lines).
    const int line = leaf ? 0 : sourceLineAt(ray.origin + best * ray.direction);
    if (line > 0 && node == mGrammar->node()) {
        mGrammar->highlightLine(line);
        Q_EMIT status(tr("A branch, grown by node %1: the rule on line %2").arg(node).arg(line),
                      6000);
    } else {
        Q_EMIT status(leaf ? tr("A leaf card, grown by node %1").arg(node)
                           : tr("A branch, grown by node %1").arg(node),
                      4000);
    }
    return node;
}

void SpeciesWorkbench::showSelectionInPanels() {
    const QStringList ids = mScene->selectedNodeIds();
    const QString id = ids.isEmpty() ? QString() : ids.front();
    mParameters->setNode(species(), id);
    NodeItem* n = mScene->node(id);
    if (n && takesGrammar(n->nodeType())) mGrammar->setNode(species(), id);
}

void SpeciesWorkbench::showEvent(QShowEvent* event) {
    QWidget::showEvent(event);
    mPreview->setActive(true);
}

void SpeciesWorkbench::hideEvent(QHideEvent* event) {
    QWidget::hideEvent(event);
    mPreview->setActive(false);
}

void SpeciesWorkbench::setSpecies(const QString& species) {
    if (species == mScene->species()) return;
    mFramed = false;
    mScene->setSpecies(species);
    mParameters->setNode(species, {});
    mGrammar->setNode({}, {});
    mPreview->setSpecies(species);
    {
        const QSignalBlocker b(mSpeciesCombo);
        mSpeciesCombo->setCurrentText(species);
    }
    // Select the generator (first node), so the panels show something useful at once.
    const QList<NodeItem*> nodes = mScene->nodes();
    for (NodeItem* n : nodes)
        if (takesGrammar(n->nodeType())) {
            mScene->selectNode(n->id());
            break;
        }
    QTimer::singleShot(0, mView, [this] { mView->frameAll(); });
}

void SpeciesWorkbench::refillSpecies() {
    const QString current = mScene->species();
    QStringList names;
    for (const doc::ProjectSpecies& s : mDocument.project().species)
        names << QString::fromStdString(s.name);
    {
        const QSignalBlocker b(mSpeciesCombo);
        mSpeciesCombo->clear();
        mSpeciesCombo->addItems(names);
        mSpeciesCombo->setCurrentText(current);
    }
    if (!names.contains(current)) setSpecies(names.isEmpty() ? QString() : names.front());
}

void SpeciesWorkbench::editBranchesWith(ToolController& tools, DocumentGenerator& generator) {
    if (!mBranchEditing)
        mBranchEditing = new SpeciesBranchEditing(mDocument, *this, tools, generator);
}

void SpeciesWorkbench::showTree(const ViewTree* tree, bool frame) {
    if (tree) {
        if (!mShowingTree) mPreviewView->setMesh(nullptr, false);
        mShowingTree = true;
        mPreviewView->setTrees({*tree}, frame);
        mPreviewView->setToolTip(tr("Branch tool: click a branch of the tree to select it, drag it "
                                    "to bend it, Delete prunes it"));
        return;
    }
    if (!mShowingTree) return;
    mShowingTree = false;
    mPreviewView->setTrees({}, false);
    mPreviewView->setToolTip(tr("Click a branch or a leaf to select the node that grew it"));
    mFramed = false; // the species' tree framed again
    onPreviewFinished();
}

void SpeciesWorkbench::onPreviewFinished() {
    const PreviewResult& r = mPreview->result();
    mScene->setRuns(r.runs, r.errorNode, r.error);
    if (r.mesh && !mShowingTree) {
        // Frame the first tree of a species, and again when an edit (a preset, a larger crown)
        // makes the tree outgrow what was framed; a smaller tree (the generations slider
        // stepping back) keeps the view, so stepping does not jump.
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (const glm::vec3& p : r.mesh->positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const bool outgrown =
            !r.mesh->positions.empty() &&
            (glm::any(glm::lessThan(lo, mFramedLo - 0.25f * (mFramedHi - mFramedLo))) ||
             glm::any(glm::greaterThan(hi, mFramedHi + 0.25f * (mFramedHi - mFramedLo))));
        const bool frame = !mFramed || outgrown;
        mPreviewView->setMesh(r.mesh, frame, r.vertices, r.skeleton);
        if (frame && !r.mesh->positions.empty()) {
            mFramedLo = lo;
            mFramedHi = hi;
        }
        mFramed = true;
    }
    if (!r.error.isEmpty()) {
        const QString where =
            r.errorNode.isEmpty() ? r.species : tr("%1, node '%2'").arg(r.species, r.errorNode);
        if (r.mesh) {
            // The same species' last good tree stays while an edit fails; the pane says so.
            mPreviewError->setText(
                tr("Preview failed (%1) — showing the last good tree: %2").arg(where, r.error));
        } else {
            // Another species' tree must not stand in for this one.
            if (!mShowingTree) mPreviewView->setMesh(nullptr, false);
            mPreviewError->setText(tr("Preview failed (%1): %2").arg(where, r.error));
        }
        mPreviewError->show();
        mPreviewLabel->setText(tr("Preview failed"));
        mPreviewLabel->setToolTip(r.error);
        Q_EMIT status(r.error, 8000);
        Q_EMIT previewFailed(where, r.error);
    } else {
        mPreviewError->hide();
        mPreviewError->clear();
        mPreviewLabel->setToolTip(tr("Evaluation %1 ms").arg(r.evaluateMs, 0, 'f', 1));
    }
    mPreviewView->update();
    if (!mPreview->isBusy()) resolvePendingBranch();
}

} // namespace sylva::ui
