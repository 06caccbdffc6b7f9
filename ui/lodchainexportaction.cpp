#include "ui/lodchainexportaction.h"

#include <string_view>

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QProgressDialog>

#include "document/errormessage.h"
#include "ui/filedialogs.h"
#include "ui/workerdialog.h"

namespace sylva::ui {

namespace {

/// Rough shares of the time (english oak: growing 10 %, the levels' search 45 %, the
/// impostor's views 35 %, writing 10 %).
int lodChainPercent(double fraction, std::string_view stage) {
    struct Share {
        std::string_view stage;
        int from, span;
    };
    static constexpr Share kShares[] = {
        {"grow", 0, 10}, {"levels", 10, 45}, {"impostor", 55, 35}, {"writing", 90, 10}};
    for (const Share& s : kShares)
        if (s.stage == stage) return s.from + static_cast<int>(fraction * s.span);
    return -1;
}

} // namespace

LodChainExportAction::LodChainExportAction(QWidget* window, SourceOf source)
    : QObject(window), mWindow(window), mSource(std::move(source)) {
    mAction = new QAction(tr("Export &LOD chain…"), this);
    mAction->setObjectName(QStringLiteral("actionExportLodChain"));
    mAction->setToolTip(tr("Writes the species' or the selected tree's game LOD chain (LOD0 to "
                           "LOD3 and the impostor as glTF, FBX, USD, OBJ and PNG maps) into a "
                           "folder, as sylva-cli lods does"));
    mAction->setEnabled(false);
    connect(mAction, &QAction::triggered, this, &LodChainExportAction::chooseFolder);
}

QProgressDialog* LodChainExportAction::progressDialog() const {
    return mDialog.data();
}

void LodChainExportAction::update() {
    mAction->setEnabled(!mDialog && mSource().has_value());
}

void LodChainExportAction::chooseFolder() {
    const QString dir = QFileDialog::getExistingDirectory(
        mWindow, tr("Export LOD chain into folder"),
        mLastFolder.isEmpty() ? FileDialogs::startFolder(mShown ? mShown() : QString())
                              : mLastFolder);
    if (dir.isEmpty()) return;
    mLastFolder = dir;
    exportTo(dir);
}

bool LodChainExportAction::exportTo(const QString& dir) {
    const std::optional<LodChainSource> source = mSource();
    if (!source) {
        Q_EMIT finished(false, tr("Select one tree, or open a species, to export its LOD chain."));
        return false;
    }
    if (mDialog) return false; // one export at a time
    mAction->setEnabled(false);
    DialogProgress progress(lodChainPercent);
    exporter::GameLodFiles files;
    const std::filesystem::path path = dir.toStdString();
    const WorkerOutcome outcome = runWithProgress(
        mWindow, tr("Export LOD chain"),
        tr("Exporting the LOD chain of %1…").arg(QString::fromStdString(source->name)),
        QStringLiteral("lodChainProgress"), progress,
        [&](Progress& p) { files = exportLodChain(path, *source, p); }, mDialog);
    update();

    if (const std::exception_ptr error = outcome.error) {
        const doc::ErrorReport report = doc::describeError(error);
        Q_EMIT finished(false, outcome.cancelled
                                   ? tr("LOD chain export cancelled: nothing was written.")
                                   : QString::fromStdString(report.message));
        return false;
    }
    mFiles = std::move(files);
    QString message = tr("Exported the LOD chain of %1 (%2 levels and the impostor) to %3")
                          .arg(QString::fromStdString(source->name))
                          .arg(mFiles.levels.size())
                          .arg(QDir::toNativeSeparators(dir));
    // A tree of a few hundred triangles cannot reach the smallest budgets: say why the chain is
    // shorter (the description lists them under dropped_levels).
    if (!mFiles.dropped.empty())
        message += tr("; %n budget(s) left out: the tree has too few triangles for them", "",
                      static_cast<int>(mFiles.dropped.size()));
    Q_EMIT finished(true, message);
    return true;
}

} // namespace sylva::ui
