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
#include "ui/viewport/viewport.h"

namespace sylva::ui {

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
    {
        // Without multisampling: under a software rasteriser (Mesa llvmpipe) 4× MSAA made the
        // preview's edit → screen time 2.7× longer (docs/performance.md); the preview is
        // small and is there to follow edits.
        QSurfaceFormat format = mPreviewView->format();
        format.setSamples(0);
        mPreviewView->setFormat(format);
    }

    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(mView);
    split->addWidget(mGrammar);
    split->addWidget(mPreviewView);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 3);
    split->setStretchFactor(2, 2);
    layout->addWidget(split, 1);

    connect(mSpeciesCombo, &QComboBox::currentTextChanged, this,
            [this](const QString& s) { setSpecies(s); });
    connect(&mDocument, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        if (c.what & (doc::DocumentChange::Species | doc::DocumentChange::Reset)) refillSpecies();
    });
    connect(mScene, &NodeGraphScene::nodeSelected, this, [this](const QString& id) {
        mParameters->setNode(species(), id);
        QString type;
        if (NodeItem* n = mScene->node(id)) type = n->nodeType();
        if (type == QLatin1String("lsystem")) mGrammar->setNode(species(), id);
    });
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
                                      generations < 0 ? graph::Value() : graph::Value(generations));
            });
    connect(mPreview, &SpeciesPreview::finished, this, &SpeciesWorkbench::onPreviewFinished);
    connect(mPreviewView, &QOpenGLWidget::frameSwapped, mPreview, &SpeciesPreview::markShown);
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
        if (n->nodeType() == QLatin1String("lsystem")) {
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

void SpeciesWorkbench::onPreviewFinished() {
    const PreviewResult& r = mPreview->result();
    mScene->setRuns(r.runs, r.errorNode, r.error);
    if (r.mesh) {
        mPreviewView->setMesh(r.mesh, !mFramed);
        mFramed = true;
    }
    if (!r.error.isEmpty()) {
        mPreviewLabel->setText(tr("Preview failed"));
        mPreviewLabel->setToolTip(r.error);
        Q_EMIT status(r.error, 8000);
    } else {
        mPreviewLabel->setToolTip(tr("Evaluation %1 ms").arg(r.evaluateMs, 0, 'f', 1));
    }
    mPreviewView->update();
}

} // namespace sylva::ui
