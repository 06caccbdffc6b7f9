#include "ui/mainwindow.h"

#include <string>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QImage>
#include <QKeySequence>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QProgressBar>
#include <QPromise>
#include <QStatusBar>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include "engine/export/treeexport.h"
#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/util/error.h"
#include "ui/presetlibrary.h"
#include "ui/scenegenerator.h"
#include "ui/statspanel.h"
#include "ui/viewport.h"

namespace sylva::ui {

namespace {

/// Bridges the engine's Progress to a QPromise: the UI sees stage names, and cancelling the
/// future stops the engine at its next checkCancelled().
class PromiseProgress : public Progress {
public:
    explicit PromiseProgress(QPromise<GenerationResult>& promise) : mPromise(promise) {}

    void report(double fraction, std::string_view stage) override {
        (void)fraction;
        // Stages report often; only a new stage name is worth a cross-thread signal.
        if (stage == mStage) return;
        mStage.assign(stage);
        mPromise.setProgressValueAndText(++mTicks,
                                         QString::fromUtf8(stage.data(), qsizetype(stage.size())));
    }
    bool isCancelled() const override { return mPromise.isCanceled(); }

private:
    QPromise<GenerationResult>& mPromise;
    std::string mStage;
    int mTicks = 0;
};

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("Sylva"));
    setObjectName(QStringLiteral("SylvaMainWindow"));

    mViewport = new Viewport(this);
    mViewport->setObjectName(QStringLiteral("viewport"));
    setCentralWidget(mViewport);

    mStats = new StatsPanel(this);
    mStatsDock = new QDockWidget(tr("Tree"), this);
    mStatsDock->setObjectName(QStringLiteral("statsDock"));
    mStatsDock->setWidget(mStats);
    mStatsDock->setAllowedAreas(Qt::LeftDockWidgetArea | Qt::RightDockWidgetArea);
    addDockWidget(Qt::RightDockWidgetArea, mStatsDock);

    mBusy = new QProgressBar(this);
    mBusy->setRange(0, 0); // indeterminate: stages do not report a common scale
    mBusy->setMaximumWidth(120);
    mBusy->setVisible(false);
    statusBar()->addPermanentWidget(mBusy);
    mGlLabel = new QLabel(this);
    statusBar()->addPermanentWidget(mGlLabel);

    createMenus();

    // Files of the shown tree: a change (or a save by rename, which shows as a change of the
    // folder) starts a short timer, so that an editor's several writes make one reload.
    mFileWatcher = new QFileSystemWatcher(this);
    mReloadTimer = new QTimer(this);
    mReloadTimer->setSingleShot(true);
    mReloadTimer->setInterval(250);
    connect(mFileWatcher, &QFileSystemWatcher::fileChanged, mReloadTimer,
            qOverload<>(&QTimer::start));
    connect(mFileWatcher, &QFileSystemWatcher::directoryChanged, mReloadTimer,
            qOverload<>(&QTimer::start));
    connect(mReloadTimer, &QTimer::timeout, this, &MainWindow::onSourcesTouched);

    connect(&mWatcher, &QFutureWatcher<GenerationResult>::finished, this,
            &MainWindow::onGenerationFinished);
    connect(&mWatcher, &QFutureWatcher<GenerationResult>::progressTextChanged, this,
            [this](const QString& stage) {
                statusBar()->showMessage(tr("Generating: %1").arg(stage));
            });
}

MainWindow::~MainWindow() {
    // The worker only touches its own copies, but stopping it keeps shutdown quick.
    mWatcher.disconnect(this);
    mWatcher.cancel();
    mWatcher.waitForFinished();
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->setObjectName(QStringLiteral("fileMenu"));
    QAction* open =
        file->addAction(tr("&Open species or project…"), this, &MainWindow::showOpenDialog);
    open->setShortcut(QKeySequence::Open);
    mReloadAction = file->addAction(tr("&Reload"), this, &MainWindow::reload);
    mReloadAction->setShortcuts({QKeySequence(Qt::Key_F5), QKeySequence(tr("Ctrl+R"))});
    mReloadAction->setEnabled(false);
    mAutoReloadAction = file->addAction(tr("Reload &automatically"));
    mAutoReloadAction->setCheckable(true);
    mAutoReloadAction->setChecked(true);
    mExportAction = file->addAction(tr("&Export…"), this, &MainWindow::showExportDialog);
    mExportAction->setShortcut(QKeySequence(tr("Ctrl+E")));
    mExportAction->setEnabled(false);
    QAction* shot =
        file->addAction(tr("Save &screenshot…"), this, &MainWindow::showScreenshotDialog);
    shot->setShortcut(QKeySequence(tr("Ctrl+Shift+S")));
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    mPresetsMenu = menuBar()->addMenu(tr("&Presets"));
    mPresetsMenu->setObjectName(QStringLiteral("presetsMenu"));
    mPresetGroup = new QActionGroup(this);
    connect(mPresetsMenu, &QMenu::aboutToShow, this, &MainWindow::populatePresetsMenu);
    populatePresetsMenu();

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->setObjectName(QStringLiteral("viewMenu"));
    QAction* frame = view->addAction(tr("&Frame tree"), mViewport, &Viewport::frameScene);
    frame->setShortcut(QKeySequence(Qt::Key_F));
    frame->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    QAction* grid = view->addAction(tr("Show &grid"));
    grid->setCheckable(true);
    grid->setChecked(true);
    grid->setShortcut(QKeySequence(Qt::Key_G));
    connect(grid, &QAction::toggled, mViewport, &Viewport::setGridVisible);
    // Shortcuts of the View menu act while the viewport has focus, like the F key itself.
    mViewport->addAction(frame);
    mViewport->addAction(grid);
    QMenu* color = view->addMenu(tr("&Colour by"));
    color->setObjectName(QStringLiteral("colorMenu"));
    mColorGroup = new QActionGroup(this);
    const std::pair<ColorBy, QString> modes[] = {{ColorBy::Material, tr("&Material")},
                                                 {ColorBy::Light, tr("&Light (per internode)")},
                                                 {ColorBy::Vigour, tr("&Vigour")},
                                                 {ColorBy::Age, tr("&Age")},
                                                 {ColorBy::BranchOrder, tr("Branch &order")}};
    for (const auto& [mode, label] : modes) {
        QAction* action = color->addAction(label);
        action->setCheckable(true);
        action->setChecked(mode == mColorBy);
        action->setData(static_cast<int>(mode));
        mColorGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, mode = mode] { setColorBy(mode); });
    }
    view->addSeparator();
    view->addAction(mStatsDock->toggleViewAction());
}

void MainWindow::setColorBy(ColorBy mode) {
    mColorBy = mode;
    for (QAction* action : mColorGroup->actions())
        action->setChecked(action->data().toInt() == static_cast<int>(mode));
    applyColoring();
}

void MainWindow::applyColoring() {
    const skel::Skeleton* skeleton = mResult.skeleton.get();
    // Attributes this tree has; the others are greyed out.
    // A project's forest has no one skeleton: materials only.
    for (QAction* action : mColorGroup->actions()) {
        const auto mode = static_cast<ColorBy>(action->data().toInt());
        action->setEnabled(mode == ColorBy::Material ||
                           (skeleton && hasAttribute(*skeleton, mode)) || !mResult.mesh);
    }
    if (!mResult.mesh) return;
    if (!skeleton) {
        mViewport->setVertexColors({});
        if (mColorBy != ColorBy::Material)
            statusBar()->showMessage(tr("Colouring by node attributes needs a single tree: the "
                                        "forest is shown in its materials"));
        return;
    }
    AttributeColoring coloring = colorByAttribute(*mResult.mesh, *skeleton, mColorBy);
    mViewport->setVertexColors(std::move(coloring.colors));
    // The legend names the ramp's range, or says that this tree lacks the attribute.
    if (mColorBy != ColorBy::Material) statusBar()->showMessage(coloring.legend);
}

void MainWindow::populatePresetsMenu() {
    mPresetsMenu->clear();
    for (QAction* action : mPresetGroup->actions())
        mPresetGroup->removeAction(action);
    const QString dir = PresetLibrary::directory();
    const QList<PresetInfo> presets = PresetLibrary::list(dir);
    if (presets.isEmpty()) {
        QAction* none = mPresetsMenu->addAction(
            dir.isEmpty() ? tr("No presets folder found (set SYLVA_PRESETS_DIR)")
                          : tr("No presets in %1").arg(QDir::toNativeSeparators(dir)));
        none->setEnabled(false);
        return;
    }
    for (const PresetInfo& preset : presets) {
        QAction* action = mPresetsMenu->addAction(preset.name);
        action->setData(preset.path);
        action->setToolTip(preset.path);
        action->setCheckable(true);
        action->setChecked(QFileInfo(preset.path) == QFileInfo(mCurrentPath));
        mPresetGroup->addAction(action);
        connect(action, &QAction::triggered, this,
                [this, path = preset.path] { openSpecies(path); });
    }
}

void MainWindow::openSpecies(const QString& path) {
    if (mWatcher.isRunning()) mWatcher.cancel(); // superseded; its result is dropped
    mCurrentPath = path;
    mReloadAction->setEnabled(!path.isEmpty());
    const QString name = QFileInfo(path).fileName();
    mStats->showGenerating(name);
    statusBar()->showMessage(tr("Generating %1…").arg(name));
    mBusy->setVisible(true);
    mWatcher.setFuture(QtConcurrent::run([path](QPromise<GenerationResult>& promise) {
        PromiseProgress progress(promise);
        promise.addResult(generate(path, progress)); // a species, or a project's forest
    }));
}

bool MainWindow::openDefaultPreset() {
    const QString path = PresetLibrary::defaultPreset();
    if (path.isEmpty()) {
        reportError(tr("No presets folder found: set SYLVA_PRESETS_DIR or open a species file "
                       "with File ▸ Open species…"));
        Q_EMIT generationFinished(false);
        return false;
    }
    openSpecies(path);
    return true;
}

void MainWindow::reload() {
    if (!mCurrentPath.isEmpty()) openSpecies(mCurrentPath);
}

void MainWindow::onGenerationFinished() {
    const QFuture<GenerationResult> future = mWatcher.future();
    if (future.isCanceled() || future.resultCount() == 0) return; // superseded by a newer run
    GenerationResult result = future.result();
    mBusy->setVisible(false);
    if (result.cancelled) return;
    watchSources(result.sources, result.sourceStamps);
    if (!result.ok()) {
        reportError(result.error);
        Q_EMIT generationFinished(false);
        return;
    }
    mLastError.clear();
    mResult = std::move(result);
    if (mResult.hasCamera)
        mViewport->setViewFrom(mResult.cameraEye, mResult.cameraTarget);
    else
        mViewport->clearViewFrom();
    mViewport->setMesh(mResult.mesh, true);
    mExportAction->setEnabled(!mResult.exportTrees.empty());
    mStats->showResult(mResult);
    setWindowTitle(tr("%1 — Sylva").arg(mResult.speciesName));
    statusBar()->showMessage(
        tr("Generated %1 in %2 ms").arg(mResult.speciesName).arg(mResult.elapsedMs, 0, 'f', 1),
        10000);
    applyColoring();
    if (!mResult.warning.isEmpty()) {
        mStats->showWarning(mResult.warning);
        statusBar()->showMessage(mResult.warning.section(QLatin1Char('\n'), 0, 0));
    }
    if (!mViewport->glError().isEmpty()) statusBar()->showMessage(mViewport->glError());
    mGlLabel->setText(mViewport->glInfo());
    Q_EMIT generationFinished(true);
}

void MainWindow::setAutoReload(bool on) {
    mAutoReloadAction->setChecked(on);
}

bool MainWindow::autoReload() const {
    return mAutoReloadAction->isChecked();
}

void MainWindow::watchSources(const QStringList& sources, const QList<QDateTime>& stamps) {
    if (!mFileWatcher->files().isEmpty()) mFileWatcher->removePaths(mFileWatcher->files());
    if (!mFileWatcher->directories().isEmpty())
        mFileWatcher->removePaths(mFileWatcher->directories());
    mSources = sources;
    mStamps.clear();
    QStringList folders;
    bool changedMeanwhile = false;
    for (qsizetype i = 0; i < sources.size(); ++i) {
        const QFileInfo info(sources[i]);
        const QDateTime now = info.exists() ? info.lastModified() : QDateTime();
        // The time the file had when it was read; a file changed since is reloaded at once.
        const QDateTime read = i < stamps.size() ? stamps[i] : now;
        mStamps[sources[i]] = read;
        changedMeanwhile = changedMeanwhile || now != read;
        if (info.exists()) mFileWatcher->addPath(sources[i]);
        if (!folders.contains(info.absolutePath())) folders << info.absolutePath();
    }
    for (const QString& folder : folders)
        if (QFileInfo(folder).isDir()) mFileWatcher->addPath(folder);
    if (changedMeanwhile) mReloadTimer->start();
}

void MainWindow::onSourcesTouched() {
    if (!autoReload() || mCurrentPath.isEmpty()) return;
    // A folder changes for other files too: reload only when one of ours changed, appeared or
    // went (a save by rename replaces the file, and the watch on the old one is gone).
    bool changed = false;
    for (const auto& [file, stamp] : mStamps) {
        const QFileInfo info(file);
        if ((info.exists() ? info.lastModified() : QDateTime()) != stamp) changed = true;
    }
    if (!changed) return;
    // Seen: the next change is compared with the files as they are now.
    for (auto& [file, stamp] : mStamps) {
        const QFileInfo info(file);
        stamp = info.exists() ? info.lastModified() : QDateTime();
        if (info.exists() && !mFileWatcher->files().contains(file)) mFileWatcher->addPath(file);
    }
    reload();
}

void MainWindow::reportError(const QString& message) {
    mBusy->setVisible(false);
    mLastError = message;
    mStats->showError(message);
    // The status bar shows one line; the dock shows the whole message.
    statusBar()->showMessage(message.section(QLatin1Char('\n'), 0, 0));
}

bool MainWindow::saveScreenshot(const QString& path) {
    const QImage image = mViewport->grabFramebuffer();
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

bool MainWindow::exportTo(const QString& path) {
    if (mResult.exportTrees.empty()) {
        reportError(tr("Nothing to export yet."));
        return false;
    }
    QApplication::setOverrideCursor(Qt::WaitCursor);
    QString error;
    std::size_t files = 0;
    try {
        exporter::TreeExporter out(path.toStdString(), {false, mResult.compactObj});
        out.add(mResult.exportTrees);
        files = out.commit().size();
    } catch (const InvalidInput& e) {
        error = QString::fromStdString(e.what());
    } catch (const IoError& e) {
        error = QString::fromStdString(e.what());
    } catch (const std::exception& e) {
        error = tr("Could not export %1: %2")
                    .arg(QDir::toNativeSeparators(path), QString::fromUtf8(e.what()));
    }
    QApplication::restoreOverrideCursor();
    if (!error.isEmpty()) {
        reportError(error);
        return false;
    }
    statusBar()->showMessage(
        tr("Exported %n tree(s) to %1 (%2 files)", nullptr, int(mResult.exportTrees.size()))
            .arg(QDir::toNativeSeparators(path))
            .arg(files),
        10000);
    return true;
}

void MainWindow::showExportDialog() {
    const QString suggested = QFileInfo(mResult.path).completeBaseName() + QStringLiteral(".obj");
    QString filter;
    QString path = QFileDialog::getSaveFileName(
        this, tr("Export"), suggested,
        tr("Wavefront OBJ (*.obj);;glTF binary (*.glb);;glTF (*.gltf);;FBX binary (*.fbx)"),
        &filter);
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) {
        // No extension typed: the chosen filter's.
        const qsizetype star = filter.indexOf(QStringLiteral("*."));
        path += filter.mid(star + 1, filter.indexOf(QLatin1Char(')'), star) - star - 1);
    }
    exportTo(path);
}

void MainWindow::showOpenDialog() {
    QString dir = mCurrentPath.isEmpty() ? PresetLibrary::directory()
                                         : QFileInfo(mCurrentPath).absolutePath();
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open species or project"), dir,
        tr("Species, grammars and projects (*.json *.lsys *.txt *.sylva);;Projects (*.sylva);;"
           "All files (*)"));
    if (!path.isEmpty()) openSpecies(path);
}

void MainWindow::showScreenshotDialog() {
    const QString suggested = mResult.speciesName.isEmpty()
                                  ? QStringLiteral("sylva.png")
                                  : QFileInfo(mResult.path).completeBaseName() + ".png";
    const QString path = QFileDialog::getSaveFileName(this, tr("Save screenshot"), suggested,
                                                      tr("Images (*.png *.jpg *.bmp)"));
    if (!path.isEmpty()) saveScreenshot(path);
}

} // namespace sylva::ui
