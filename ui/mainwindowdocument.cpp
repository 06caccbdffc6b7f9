// MainWindow's handling of what is shown changing: a preview or the document generated, the
// document changed (what to regrow), files changed on disk (what to reload or regrow), and the
// generated forest put into the viewport, the outliner, Statistics and Messages.
#include "ui/mainwindow.h"

#include <algorithm>
#include <string>

#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QStatusBar>
#include <QTimer>

#include "document/errormessage.h"
#include "document/filerefs.h"
#include "document/projectsettings.h"
#include "ui/document/messagespanel.h"
#include "ui/document/outlinermodel.h"
#include "ui/document/sourcewatcher.h"
#include "ui/document/statspanel.h"
#include "ui/generation/documentgenerator.h"
#include "ui/generation/windvertexdata.h"
#include "ui/lodchainexportaction.h"
#include "ui/speciesworkbench.h"
#include "ui/viewport/viewport.h"

namespace sylva::ui {

void MainWindow::onPreviewGenerated(const GenerationResult& run) {
    setBusy(false);
    mSourceWatcher->watch(run.sources, run.sourceStamps);
    if (!run.ok()) {
        reportError(run.error);
        Q_EMIT generationFinished(false);
        return;
    }
    mLastError.clear();
    const GenerationResult& result = mPreview.result();
    mViewport->clearViewFrom();
    mViewport->setTrees({});
    mViewport->setMesh(result.mesh, true, nullptr, result.skeleton);
    mExportAction->setEnabled(!result.exportTrees.empty());
    mLodChainExport->update();
    mStats->showResult(result);
    updateTitle();
    statusBar()->showMessage(
        tr("Generated %1 in %2 ms").arg(result.speciesName).arg(result.elapsedMs, 0, 'f', 1),
        10000);
    applyColoring();
    if (!mViewport->glError().isEmpty()) statusBar()->showMessage(mViewport->glError());
    mGlLabel->setText(mViewport->glInfo());
    Q_EMIT generationFinished(true);
}

void MainWindow::onDocumentChanged(const doc::DocumentChange& change) {
    const QString wind = QString::fromLatin1(doc::settingChange::kWind);
    if (change.what & doc::DocumentChange::Reset || change.settings.contains(wind)) applyWind();
    // The wind only moves what is drawn: nothing to regrow when nothing else changed.
    if (change.what == doc::DocumentChange::Settings &&
        std::all_of(change.settings.begin(), change.settings.end(),
                    [&wind](const QString& s) { return s == wind; }))
        return;
    if (change.what & doc::DocumentChange::Reset) {
        const QFileInfo own(mDocument->path());
        mDocumentStamp =
            !mDocument->path().isEmpty() && own.exists() ? own.lastModified() : QDateTime();
        mPreview.cancelIfRunning();
        mPreview.leave();
        mFrameNext = true;
        mStats->showGenerating(mDocument->displayName());
        updateTitle();
    } else if (mPreview.isActive()) {
        // An edit of the document (a script adding a tree to a new project): show it.
        mPreview.leave();
        mFrameNext = true;
    } else if (change.what == doc::DocumentChange::Species && !change.species.isEmpty()) {
        // A species edit: nothing to regrow when no tree grows from it; while the species
        // editor is open, its preview goes first and the forest follows when the edits pause.
        if (!mDocument->project().usesSpecies(change.species.toStdString())) return;
        if (mWorkbench && mWorkbench->isVisible()) {
            mSpeciesRegen->start();
            return;
        }
    }
    mGenerator->regenerate();
}

void MainWindow::onDocumentGenerated(bool ok, const QString& error) {
    setBusy(false);
    if (mPreview.isActive()) return;
    const GenerationResult& result = mGenerator->result();
    if (!ok) {
        QStringList sources = doc::projectSourceFiles(mDocument->project());
        QList<QDateTime> stamps = modificationTimes(sources);
        if (!mDocument->path().isEmpty()) {
            sources << mDocument->path();
            stamps << mDocumentStamp;
        }
        mSourceWatcher->watch(sources, stamps);
        reportError(error);
        const QString line = error.section(QLatin1Char('\n'), 0, 0);
        mGenerationError->setText(tr("Generation failed: %1").arg(line));
        mGenerationError->setToolTip(error);
        mGenerationError->show();
        Q_EMIT generationFinished(false);
        return;
    }
    QStringList sources = result.sources;
    QList<QDateTime> stamps = result.sourceStamps;
    if (!mDocument->path().isEmpty()) // stamped when opened or saved, not by the generation
        listProjectFileLast(sources, stamps, QFileInfo(mDocument->path()).absoluteFilePath(),
                            mDocumentStamp);
    mSourceWatcher->watch(sources, stamps);
    mLastError.clear();
    mGenerationError->hide();
    mGenerationError->clear();
    showDocument(mFrameNext);
    mFrameNext = false;
    Q_EMIT generationFinished(true);
}

void MainWindow::showDocument(bool frame) {
    const GenerationResult& result = mGenerator->result();
    std::vector<ViewTree> trees;
    trees.reserve(result.trees.size());
    for (const DrawnTree& t : result.trees)
        trees.push_back({t.docId, t.mesh, t.transform, t.lod, windPhaseOf(t.instanceId)});
    if (frame) {
        mViewport->setViewFrom(result.cameraEye, result.cameraTarget);
    }
    mViewport->setVertexColors({});
    mViewport->setTrees(std::move(trees), false);
    mViewport->setMesh(result.mesh, frame);
    mAwaitingFrame = true;
    mViewport->update();
    mExportAction->setEnabled(!result.exportTrees.empty());
    mLodChainExport->update();
    mStats->showResult(result);
    mStats->showSelection(*mDocument, result);
    QHash<doc::TreeId, QSet<QString>> orphans;
    for (const DrawnTree& t : result.trees)
        for (const std::string& id : t.orphanedEdits)
            orphans[t.docId].insert(QString::fromStdString(id));
    mOutlinerModel->setOrphanedEdits(orphans);
    // The generation's warnings (orphaned branch edits among them) in Messages, each once
    // while it lasts, not again at every regeneration.
    const QStringList warnings = result.warning.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (const QString& w : warnings)
        if (!mShownWarnings.contains(w)) mMessages->add(MessagesPanel::Severity::Warning, w);
    mShownWarnings = warnings;
    updateTitle();
    applyColoring();
    mGlLabel->setText(mViewport->glInfo());
}

// The policy for files changed on disk (SourceWatcher says which): a preview is generated again,
// the project's own file reloads (asking first when there are unsaved edits), and any other
// source regrows the forest.
void MainWindow::onSourcesChanged(const QStringList& changed) {
    if (mPreview.isActive()) {
        reload();
        return;
    }
    const QString own = QFileInfo(mDocument->path()).absoluteFilePath();
    if (!mDocument->path().isEmpty() && changed.contains(own)) {
        // The project file itself: never throw unsaved edits away without asking. Our own save,
        // reported after later edits (its bytes no longer the document's), is no change.
        const QDateTime onDisk =
            QFileInfo::exists(own) ? QFileInfo(own).lastModified() : QDateTime();
        if (onDisk.isValid() && onDisk == mDocumentStamp) return;
        mDocumentStamp = onDisk;
        QFile file(own);
        if (file.open(QIODevice::ReadOnly) && file.readAll() == mDocument->serialized())
            return; // what the document holds: our own save (a script's doc.save, say)
        if (QFileInfo::exists(own) &&
            (!mDocument->isModified() ||
             askUser(tr("%1 changed on disk. Reload it and lose your unsaved edits?")
                         .arg(mDocument->displayName()),
                     false) == Answer::Yes)) {
            try {
                mDocument->open(own);
            } catch (...) {
                reportError(QString::fromStdString(doc::currentErrorMessage()));
            }
        }
        return;
    }
    mGenerator->regenerateAll(); // a species, grammar or mesh file: regrow everything
}

} // namespace sylva::ui
