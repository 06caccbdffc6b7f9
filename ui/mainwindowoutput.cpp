// MainWindow's output: screenshots of the viewport or the whole window, and File ▸ Export of
// what is shown (on a worker with progress and Cancel, through exportShown).
#include "ui/mainwindow.h"

#include <string_view>

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QPainter>
#include <QPixmap>
#include <QStatusBar>

#include "document/errormessage.h"
#include "ui/filedialogs.h"
#include "ui/generation/exportshown.h"
#include "ui/viewport/viewport.h"
#include "ui/workerdialog.h"

namespace sylva::ui {

bool MainWindow::saveScreenshot(const QString& path) {
    const QImage image = mViewport->grabSharp();
    if (image.isNull()) {
        reportError(tr("Could not read the viewport's image (no OpenGL context)."));
        return false;
    }
    if (!image.save(path)) {
        reportError(tr("Could not write %1.").arg(QDir::toNativeSeparators(path)));
        return false;
    }
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(path)), 10000);
    return true;
}

bool MainWindow::saveWindowScreenshot(const QString& path) {
    QPixmap image = grab();
    {
        // The 3D views draw into native windows, which a widget grab does not see.
        QPainter painter(&image);
        for (Viewport* view : findChildren<Viewport*>())
            if (view->isVisible() && view->window() == this)
                painter.drawImage(QRect(view->mapTo(this, QPoint(0, 0)), view->size()),
                                  view->grabSharp());
    }
    if (image.isNull() || !image.save(path)) {
        reportError(tr("Could not write %1.").arg(QDir::toNativeSeparators(path)));
        return false;
    }
    return true;
}

bool MainWindow::exportTo(const QString& path) {
    return exportTo(path, {});
}

bool MainWindow::exportTo(const QString& path, const ExportOptions& options) {
    const GenerationResult& shown = lastResult();
    if (shown.exportTrees.empty()) {
        reportError(tr("Nothing to export yet."));
        return false;
    }
    if (mExportDialog) return false; // one export at a time
    // On a worker with progress and Cancel, as Export LOD chain…: a project's export builds its
    // forest as sylva-cli forest does.
    ExportCount count;
    const ShownScene scene{shown, mPreview.isActive() ? nullptr : mDocument,
                           mViewport->camera().eye(), mViewport->camera().target()};
    DialogProgress progress([](double fraction, std::string_view stage) {
        // The forest build reports its trees (grown, adapted, meshed, written batch by batch);
        // the file's last copy is the rest.
        return stage == "trees" ? static_cast<int>(fraction * 95.0) : -1;
    });
    const WorkerOutcome outcome = runWithProgress(
        this, tr("Export"), tr("Exporting to %1…").arg(QFileInfo(path).fileName()),
        QStringLiteral("exportProgress"), progress,
        [&](Progress& p) { count = exportShown(path, scene, options, p); }, mExportDialog);
    if (outcome.error) {
        reportError(outcome.cancelled
                        ? tr("Export cancelled: nothing was written.")
                        : QString::fromStdString(doc::describeError(outcome.error).message));
        return false;
    }
    statusBar()->showMessage(
        (count.wind ? tr("Exported %n tree(s) with the project's wind to %1 (%2 files)", nullptr,
                         int(count.trees))
                    : tr("Exported %n tree(s) to %1 (%2 files)", nullptr, int(count.trees)))
            .arg(QDir::toNativeSeparators(path))
            .arg(count.files),
        10000);
    return true;
}

void MainWindow::showExportDialog() {
    const QString path = FileDialogs::exportFile(this, currentPath());
    if (!path.isEmpty())
        exportTo(path, {mExportSelectionAction->isChecked(), mExportViewLodAction->isChecked(),
                        mExportWindAction->isChecked()});
}

void MainWindow::showScreenshotDialog() {
    const QString path = FileDialogs::screenshot(this, currentPath());
    if (!path.isEmpty()) saveScreenshot(path);
}

} // namespace sylva::ui
