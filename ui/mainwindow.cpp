#include "ui/mainwindow.h"

#include <algorithm>
#include <string>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDialog>
#include <QDir>
#include <QDockWidget>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QProgressBar>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>
#include <QToolButton>
#include <QTreeView>
#include <QUndoView>

#include "document/autosave.h"
#include "document/errormessage.h"
#include "document/presetlibrary.h"
#include "engine/skeleton/skeleton.h"
#include "ui/document/documentactions.h"
#include "ui/document/messagespanel.h"
#include "ui/document/outlinermodel.h"
#include "ui/document/outlinerview.h"
#include "ui/document/presetbrowser.h"
#include "ui/document/propertiespanel.h"
#include "ui/document/sourcewatcher.h"
#include "ui/document/statspanel.h"
#include "ui/filedialogs.h"
#include "ui/generation/documentgenerator.h"
#include "ui/nodes/nodegraphscene.h"
#include "ui/nodes/parameterpanel.h"
#include "ui/preferencesdialog.h"
#include "ui/recentfilesmenu.h"
#include "ui/scripting/pythonconsole.h"
#include "ui/scripting/pythonhost.h"
#include "ui/speciesworkbench.h"
#include "ui/viewport/colorbymenu.h"
#include "ui/viewport/toolcontroller.h"
#include "ui/viewport/viewport.h"

namespace sylva::ui {

using doc::PresetLibrary;

namespace {
QString errorText() {
    return QString::fromStdString(doc::currentErrorMessage());
}
} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setObjectName(QStringLiteral("SylvaMainWindow"));
    mDocument = new doc::Document(this);
    mAutosave = new doc::Autosave(*mDocument, doc::Autosave::defaultFolder(), this);
    mAutosave->setInterval(
        QSettings().value(QStringLiteral("autosaveIntervalSeconds"), 120).toInt() * 1000);
    mGenerator = new DocumentGenerator(*mDocument, this);

    mViewport = new Viewport(this);
    mViewport->setObjectName(QStringLiteral("viewport"));
    setCentralWidget(mViewport);

    mBusy = new QProgressBar(this);
    mBusy->setRange(0, 0); // indeterminate: stages do not report a common scale
    mBusy->setMaximumWidth(120);
    mBusy->setVisible(false);
    mCancel = new QToolButton(this);
    mCancel->setObjectName(QStringLiteral("cancelButton"));
    mCancel->setText(tr("Cancel"));
    mCancel->setToolTip(tr("Stop the generation; the last result stays"));
    mCancel->setVisible(false);
    connect(mCancel, &QToolButton::clicked, this, [this] {
        if (mPreview.isActive())
            mPreview.cancel();
        else
            mGenerator->cancel();
    });
    statusBar()->addPermanentWidget(mBusy);
    statusBar()->addPermanentWidget(mCancel);
    // A failed generation stays in the status bar (a permanent widget, which the transient
    // lines of later previews and timings do not cover) until a generation succeeds.
    mGenerationError = new QLabel(this);
    mGenerationError->setObjectName(QStringLiteral("generationError"));
    mGenerationError->setStyleSheet(QStringLiteral("color: #ffffff; background: #b03030; "
                                                   "padding: 0 6px"));
    mGenerationError->hide();
    statusBar()->addPermanentWidget(mGenerationError, 1);
    mGlLabel = new QLabel(this);
    statusBar()->addPermanentWidget(mGlLabel);

    createDocks();
    mTools = new ToolController(
        *mDocument, *mViewport,
        [this]() -> const GenerationResult& { return mGenerator->result(); }, this);
    mWorkbench->editBranchesWith(*mTools, *mGenerator); // the Branch tool in its preview
    // The orbit keeps the eye above the terrain and the obstacles under it.
    mViewport->camera().setGround([tools = QPointer<ToolController>(mTools)](float x, float z) {
        return tools ? tools->surfaceHeight(x, z) : 0.0f;
    });
    connect(mTools, &ToolController::treeBranchClicked, this,
            [this](std::uint32_t id, const glm::vec3& local) {
                // With the species editor open, a click on a tree also shows what grew it.
                const auto dock = mDocks.find(QStringLiteral("speciesDock"));
                if (!mWorkbench || dock == mDocks.end() || !dock->second->isVisible() ||
                    mDocument->treeIndex(id) < 0)
                    return;
                const doc::ProjectInstance& t = mDocument->tree(id);
                mWorkbench->showBranchOf(QString::fromStdString(t.species), t.seed, local);
            });
    connect(mTools, &ToolController::message, this, [this](const QString& text) {
        mMessages->add(MessagesPanel::Severity::Warning, text);
        statusBar()->showMessage(text, 10000);
    });
    mSourceWatcher = new SourceWatcher(this);
    createMenus();
    createToolBar();

    // Files of the shown result changed on disk: the policy (reload, or ask first) is ours.
    connect(mSourceWatcher, &SourceWatcher::changed, this, &MainWindow::onSourcesChanged);

    connect(&mPreview, &SpeciesPreviewSession::dropped, this, [this] { setBusy(false); });
    connect(&mPreview, &SpeciesPreviewSession::generated, this, &MainWindow::onPreviewGenerated);
    connect(&mPreview, &SpeciesPreviewSession::progressed, this, [this](const QString& stage) {
        statusBar()->showMessage(tr("Generating: %1").arg(stage));
    });
    connect(mGenerator, &DocumentGenerator::started, this, [this] { setBusy(true); });
    connect(mGenerator, &DocumentGenerator::progressed, this, [this](const QString& stage) {
        statusBar()->showMessage(tr("Regrowing: %1").arg(stage));
    });
    connect(mGenerator, &DocumentGenerator::finished, this, &MainWindow::onDocumentGenerated);
    connect(mGenerator, &DocumentGenerator::cancelled, this, [this] {
        setBusy(false);
        statusBar()->showMessage(tr("Generation cancelled; the last result stays"), 10000);
        Q_EMIT generationFinished(false);
    });
    connect(mDocument, &doc::Document::changed, this, &MainWindow::onDocumentChanged);
    applyWind();
    connect(mDocument, &doc::Document::titleChanged, this, &MainWindow::updateTitle);
    connect(mDocument, &doc::Document::selectionChanged, this, [this] {
        QSet<std::uint32_t> ids;
        for (doc::TreeId id : mDocument->selectedTrees())
            ids.insert(id);
        // A selected branch is drawn over its tree by the Branch tool: the tree is not tinted,
        // so that the branch stands out.
        if (mDocument->selectedBranch()) ids.clear();
        mViewport->setHighlightedTrees(ids);
        mViewport->update();
        mStats->showSelection(*mDocument, mGenerator->result());
    });
    connect(mViewport, &Viewport::frameSwapped, this, [this] {
        if (!mAwaitingFrame) return;
        mAwaitingFrame = false;
        mEditToScreenMs = mGenerator->msSinceResultRequest();
        statusBar()->showMessage(tr("Updated in %1 ms (edit to screen, %2 tree(s) regrown)")
                                     .arg(mEditToScreenMs, 0, 'f', 1)
                                     .arg(mGenerator->result().stats.count("regrown")
                                              ? mGenerator->result().stats.at("regrown")
                                              : 0.0),
                                 10000);
    });
    connect(mAutosave, &doc::Autosave::saved, this, [this](const QString& file) {
        statusBar()->showMessage(tr("Autosaved to %1").arg(QDir::toNativeSeparators(file)), 3000);
    });

    QSettings settings;
    if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray()))
        openAtScreenSize();
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    updateTitle();
}

void MainWindow::openAtScreenSize() {
    // First start: the docks' size hints alone give a small window with a small 3D view; an
    // artist's editor takes most of the screen, centred, leaving the taskbar and a margin.
    const QScreen* screen = QGuiApplication::primaryScreen();
    if (!screen) return;
    const QRect available = screen->availableGeometry();
    const QSize size(available.width() * 9 / 10, available.height() * 9 / 10);
    resize(size);
    move(available.center() - QPoint(size.width() / 2, size.height() / 2));
}

MainWindow::~MainWindow() {
    if (PythonHost::window() == this) PythonHost::setWindow(nullptr);
    // The species editor talks to the document (a grammar burst is committed when its editor
    // loses focus): it goes first, while the document (an older child) still exists.
    for (const QString& name : {QStringLiteral("speciesDock"), QStringLiteral("parametersDock"),
                                QStringLiteral("presetBrowserDock")}) {
        delete mDocks[name];
        mDocks.erase(name);
    }
    mWorkbench = nullptr;
    // The worker only touches its own copies, but stopping it keeps shutdown quick.
    mPreview.disconnect(this);
    mPreview.stop();
    mGenerator->disconnect(this);
}

void MainWindow::createDocks() {
    auto dock = [this](const QString& name, const QString& title, QWidget* widget,
                       Qt::DockWidgetArea area) {
        auto* d = new QDockWidget(title, this);
        d->setObjectName(name);
        d->setWidget(widget);
        addDockWidget(area, d);
        mDocks[name] = d;
        return d;
    };

    mOutlinerModel = new OutlinerModel(*mDocument, this);
    mOutliner = new OutlinerView(*mDocument, mOutlinerModel, this);
    connect(mOutlinerModel, &OutlinerModel::hiddenTreesChanged, mViewport,
            &Viewport::setHiddenTrees);
    connect(mOutlinerModel, &OutlinerModel::editFailed, this, &MainWindow::reportError);
    dock(QStringLiteral("outlinerDock"), tr("Outliner"), mOutliner, Qt::LeftDockWidgetArea);

    mProperties = new PropertiesPanel(*mDocument, this);
    mProperties->setObjectName(QStringLiteral("propertiesPanel"));
    mProperties->setResult([this]() -> const GenerationResult& { return mGenerator->result(); });
    connect(mProperties, &PropertiesPanel::failed, this, &MainWindow::reportError);
    // In a scroll area: a tree's editors are wider than the project's, and the dock (and with
    // it the viewport) must not jump when the selection changes.
    auto* propertiesScroll = new QScrollArea(this);
    propertiesScroll->setWidget(mProperties);
    propertiesScroll->setWidgetResizable(true);
    propertiesScroll->setFrameShape(QFrame::NoFrame);
    propertiesScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff); // editors fit the dock
    propertiesScroll->setMinimumWidth(320); // room for x, y, z with units
    dock(QStringLiteral("propertiesDock"), tr("Properties"), propertiesScroll,
         Qt::LeftDockWidgetArea);

    mStats = new StatsPanel(this);
    dock(QStringLiteral("statsDock"), tr("Statistics"), mStats, Qt::RightDockWidgetArea);

    mUndoView = new QUndoView(mDocument->undoStack(), this);
    mUndoView->setObjectName(QStringLiteral("undoView"));
    mUndoView->setEmptyLabel(tr("<opened>"));
    dock(QStringLiteral("undoDock"), tr("Undo History"), mUndoView, Qt::RightDockWidgetArea);

    // Tuning a species: the graph, the grammar and a live preview below the viewport, the
    // selected node's parameters on the right. Shown by Scene ▸ Edit species… (Ctrl+Shift+E);
    // closed they cost nothing.
    mWorkbench = new SpeciesWorkbench(*mDocument, this);
    mSpeciesRegen = new QTimer(this);
    mSpeciesRegen->setSingleShot(true);
    mSpeciesRegen->setInterval(400);
    connect(mSpeciesRegen, &QTimer::timeout, this, [this] { mGenerator->regenerate(); });
    mWorkbench->setObjectName(QStringLiteral("speciesWorkbench"));
    connect(mWorkbench, &SpeciesWorkbench::status, this,
            [this](const QString& text, int ms) { statusBar()->showMessage(text, ms); });
    connect(mWorkbench, &SpeciesWorkbench::previewFailed, this,
            [this](const QString& where, const QString& message) {
                mMessages->add(MessagesPanel::Severity::Error,
                               tr("Species preview (%1): %2").arg(where, message));
            });
    // A texture drawn without its file, in the scene or in the species preview.
    for (Viewport* view : {mViewport, mWorkbench->previewViewport()})
        connect(view, &Viewport::warning, this, [this](const QString& text) {
            mMessages->add(MessagesPanel::Severity::Warning, text);
            statusBar()->showMessage(text, 15000);
        });
    auto* parametersScroll = new QScrollArea(this);
    parametersScroll->setWidget(mWorkbench->parameters());
    parametersScroll->setWidgetResizable(true);
    parametersScroll->setFrameShape(QFrame::NoFrame);
    parametersScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded); // never cut off
    parametersScroll->setMinimumWidth(340);
    dock(QStringLiteral("speciesDock"), tr("Species Editor"), mWorkbench, Qt::BottomDockWidgetArea)
        ->hide();
    dock(QStringLiteral("parametersDock"), tr("Node Parameters"), parametersScroll,
         Qt::RightDockWidgetArea)
        ->hide();
    mPresetBrowser = new PresetBrowser(*mDocument, this);
    mPresetBrowser->setObjectName(QStringLiteral("presetBrowser"));
    connect(mPresetBrowser, &PresetBrowser::failed, this, &MainWindow::reportError);
    connect(mPresetBrowser, &PresetBrowser::status, this,
            [this](const QString& text, int ms) { statusBar()->showMessage(text, ms); });
    connect(mWorkbench->graphScene(), &NodeGraphScene::nodeSelected, mPresetBrowser,
            [this] { mPresetBrowser->setTargetSpecies(mWorkbench->species()); });
    dock(QStringLiteral("presetBrowserDock"), tr("Preset Browser"), mPresetBrowser,
         Qt::RightDockWidgetArea)
        ->hide();

    mMessages = new MessagesPanel(this);
    dock(QStringLiteral("messagesDock"), tr("Messages"), mMessages, Qt::BottomDockWidgetArea);

    PythonHost::setWindow(this);
    mConsole = new PythonConsole(this);
    mConsole->setObjectName(QStringLiteral("pythonConsole"));
    connect(mConsole, &PythonConsole::quitRequested, this, &QWidget::close);
    dock(QStringLiteral("consoleDock"), tr("Python Console"), mConsole, Qt::BottomDockWidgetArea);
    tabifyDockWidget(mDocks[QStringLiteral("messagesDock")], mDocks[QStringLiteral("consoleDock")]);
    mDocks[QStringLiteral("messagesDock")]->raise();
    // The viewport gets the room; the panels around it start narrow and short.
    resizeDocks({mDocks[QStringLiteral("messagesDock")]}, {140}, Qt::Vertical);
    resizeDocks({mDocks[QStringLiteral("outlinerDock")], mDocks[QStringLiteral("statsDock")]},
                {330, 280}, Qt::Horizontal);
}

void MainWindow::editSpecies(const QString& species) {
    if (species.isEmpty() && mDocument->project().species.empty()) {
        reportError(tr("The project has no species to edit: add one from the Presets menu"));
        return;
    }
    QDockWidget* speciesDock = mDocks[QStringLiteral("speciesDock")];
    QDockWidget* parametersDock = mDocks[QStringLiteral("parametersDock")];
    if (!speciesDock->isVisible()) {
        // The editor takes the bottom's whole width (messages and console become tabs beside
        // it) and the parameters the right's height (statistics and undo history likewise).
        speciesDock->show();
        parametersDock->show();
        for (const char* name : {"messagesDock", "consoleDock"})
            if (QDockWidget* d = mDocks[QLatin1String(name)]; d && !d->isFloating())
                tabifyDockWidget(d, speciesDock);
        for (const char* name : {"statsDock"})
            if (QDockWidget* d = mDocks[QLatin1String(name)]; d && !d->isFloating())
                tabifyDockWidget(d, parametersDock);
        QDockWidget* presets = mDocks[QStringLiteral("presetBrowserDock")];
        presets->show();
        tabifyDockWidget(parametersDock, presets);
        resizeDocks({speciesDock}, {std::max(320, height() * 2 / 5)}, Qt::Vertical);
        resizeDocks({parametersDock}, {360}, Qt::Horizontal);
    }
    speciesDock->raise();
    parametersDock->raise();
    if (!species.isEmpty()) mWorkbench->setSpecies(species);
    mPresetBrowser->setTargetSpecies(mWorkbench->species());
}

void MainWindow::frameSelectionOrAll() {
    const QList<doc::TreeId> ids = mDocument->selectedTrees();
    Bounds box;
    for (std::size_t i = 0; i < mViewport->trees().size(); ++i)
        if (mViewport->trees()[i].id && ids.contains(mViewport->trees()[i].id) &&
            i < mViewport->treeBounds().size() && !mViewport->treeBounds()[i].empty()) {
            box.add(mViewport->treeBounds()[i].lo);
            box.add(mViewport->treeBounds()[i].hi);
        }
    if (box.empty())
        mViewport->frameScene();
    else
        mViewport->frameBox(box.lo, box.hi);
}

void MainWindow::setColorBy(ColorBy mode) {
    mColorBy = mode;
    mColorMenu->setMode(mode);
    applyColoring();
}

void MainWindow::applyColoring() {
    const GenerationResult& result = lastResult();
    const skel::Skeleton* skeleton = mPreview.isActive() ? result.skeleton.get() : nullptr;
    // Attributes this tree has; the others are greyed out. A forest has no one skeleton.
    mColorMenu->enableFor(skeleton, result.mesh != nullptr);
    if (!result.mesh) return;
    if (!skeleton) {
        mViewport->setVertexColors({});
        if (mColorBy != ColorBy::Material)
            statusBar()->showMessage(tr("Colouring by node attributes needs a single tree: the "
                                        "forest is shown in its materials"));
        return;
    }
    AttributeColoring coloring = colorByAttribute(*result.mesh, *skeleton, mColorBy);
    mViewport->setVertexColors(std::move(coloring.colors));
    // The legend names the ramp's range, or says that this tree lacks the attribute.
    if (mColorBy != ColorBy::Material) statusBar()->showMessage(coloring.legend);
}

// --- opening, saving --------------------------------------------------------------------

void MainWindow::openSpecies(const QString& path) {
    if (isProjectFile(path)) {
        if (!openProject(path)) Q_EMIT generationFinished(false);
        return;
    }
    const QString name = QFileInfo(path).fileName();
    mStats->showGenerating(name);
    statusBar()->showMessage(tr("Generating %1…").arg(name));
    setBusy(true);
    mPreview.start(path);
}

bool MainWindow::openProject(const QString& path) {
    if (mDocument->isModified() && !maybeDiscard()) return false;
    try {
        const std::vector<std::string> warnings = mDocument->open(path);
        for (const std::string& w : warnings)
            mMessages->add(MessagesPanel::Severity::Warning, QString::fromStdString(w));
        if (!warnings.empty()) mStats->showWarning(QString::fromStdString(warnings.front()));
    } catch (...) {
        reportError(errorText());
        return false;
    }
    RecentFilesMenu::add(path);
    mMessages->add(MessagesPanel::Severity::Info,
                   tr("Opened %1").arg(QDir::toNativeSeparators(mDocument->path())));
    return true;
}

bool MainWindow::newDocument() {
    if (mDocument->isModified() && !maybeDiscard()) return false;
    mDocument->newProject();
    return true;
}

bool MainWindow::save() {
    if (mDocument->path().isEmpty()) {
        showSaveAsDialog();
        return !mDocument->isModified();
    }
    return saveAs(mDocument->path());
}

bool MainWindow::saveAs(const QString& path) {
    try {
        mDocument->save(path);
    } catch (...) {
        reportError(errorText());
        return false;
    }
    RecentFilesMenu::add(path);
    mAutosave->discard();
    mDocumentStamp = QFileInfo(mDocument->path()).lastModified(); // our own write
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(mDocument->path())),
                             10000);
    return true;
}

bool MainWindow::revert() {
    if (mDocument->path().isEmpty()) return false;
    if (mDocument->isModified() &&
        askUser(tr("Revert to the saved file and lose your edits?"), false) != Answer::Yes)
        return false;
    const QString path = mDocument->path();
    try {
        mDocument->open(path);
    } catch (...) {
        reportError(errorText());
        return false;
    }
    return true;
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
    if (mPreview.isActive()) {
        openSpecies(mPreview.path());
        return;
    }
    mGenerator->regenerateAll();
}

QString MainWindow::currentPath() const {
    return mPreview.isActive() ? mPreview.path() : mDocument->path();
}

const GenerationResult& MainWindow::lastResult() const {
    return mPreview.isActive() ? mPreview.result() : mGenerator->result();
}

QString MainWindow::generationError() const {
    return mGenerationError->isHidden() ? QString() : mGenerationError->text();
}

bool MainWindow::isGenerating() const {
    return mPreview.isRunning() || mGenerator->isBusy() ||
           (mSpeciesRegen != nullptr && mSpeciesRegen->isActive());
}

bool MainWindow::waitForGeneration(int timeoutMs) {
    if (!isGenerating()) return true;
    QEventLoop loop;
    QTimer timeout;
    timeout.setSingleShot(true);
    connect(&timeout, &QTimer::timeout, &loop, &QEventLoop::quit);
    connect(this, &MainWindow::generationFinished, &loop, [this, &loop] {
        if (!isGenerating()) loop.quit();
    });
    timeout.start(timeoutMs);
    loop.exec();
    return !isGenerating();
}

void MainWindow::setBusy(bool busy) {
    mBusy->setVisible(busy);
    mCancel->setVisible(busy);
}

void MainWindow::updateTitle() {
    if (mPreview.isActive()) {
        setWindowTitle(tr("%1 (preview) — Sylva").arg(mPreview.result().speciesName));
        setWindowModified(false);
        return;
    }
    QString name = mDocument->displayName();
    if (!mGenerator->result().trees.empty() || mGenerator->result().mesh)
        name = tr("%1 (%n trees)", nullptr, int(mGenerator->result().trees.size())).arg(name);
    setWindowTitle(tr("%1[*] — Sylva").arg(name));
    setWindowModified(mDocument->isModified());
}

MainWindow::Answer MainWindow::askUser(const QString& question, bool canSave) {
    if (mAsk) return mAsk(question, canSave);
    if (canSave) {
        const auto b = QMessageBox::question(
            this, tr("Sylva"), question,
            QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
        return b == QMessageBox::Save      ? Answer::Save
               : b == QMessageBox::Discard ? Answer::Discard
                                           : Answer::Cancel;
    }
    return QMessageBox::question(this, tr("Sylva"), question) == QMessageBox::Yes ? Answer::Yes
                                                                                  : Answer::No;
}

bool MainWindow::maybeDiscard() {
    const Answer a =
        askUser(tr("%1 has unsaved edits. Save them first?").arg(mDocument->displayName()), true);
    if (a == Answer::Save) return save();
    if (a == Answer::Discard) {
        mAutosave->discard();
        return true;
    }
    return false;
}

bool MainWindow::offerRecovery(bool force) {
    const auto pending = mAutosave->pending();
    if (!pending) return false;
    const QString what = pending->documentPath.isEmpty()
                             ? tr("an untitled project")
                             : QDir::toNativeSeparators(pending->documentPath);
    if (!force &&
        askUser(
            tr("Sylva found edits of %1 autosaved at %2 that were never saved (the editor "
               "did not close normally). Restore them?")
                .arg(what, QLocale().toString(pending->saved.toLocalTime(), QLocale::ShortFormat)),
            false) != Answer::Yes) {
        mAutosave->discard();
        return false;
    }
    try {
        mAutosave->restore();
    } catch (...) {
        reportError(errorText());
        return false;
    }
    mMessages->add(MessagesPanel::Severity::Info,
                   tr("Restored the autosaved edits of %1").arg(what));
    return true;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (mDocument->isModified() && !maybeDiscard()) {
        event->ignore();
        return;
    }
    mAutosave->discard();
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    event->accept();
}

// --- files on disk ----------------------------------------------------------------------

void MainWindow::setViewWind(bool on) {
    mWindAction->setChecked(on);
}

bool MainWindow::viewWind() const {
    return mWindAction->isChecked();
}

void MainWindow::setWindTime(std::optional<double> seconds) {
    for (Viewport* v : {mViewport, mWorkbench ? mWorkbench->previewViewport() : nullptr})
        if (v) v->setWindTime(seconds);
}

void MainWindow::applyWind() {
    const wind::WindSettings w = mDocument->project().wind.value_or(wind::WindSettings{});
    for (Viewport* v : {mViewport, mWorkbench ? mWorkbench->previewViewport() : nullptr})
        if (v) v->setWind(w);
}

void MainWindow::setAutoReload(bool on) {
    mAutoReloadAction->setChecked(on);
}

bool MainWindow::autoReload() const {
    return mAutoReloadAction->isChecked();
}

QStringList MainWindow::watchedFiles() const {
    return mSourceWatcher->files();
}

void MainWindow::reportError(const QString& message) {
    setBusy(isGenerating());
    mLastError = message;
    mStats->showError(message);
    mMessages->add(MessagesPanel::Severity::Error, message);
    // The status bar shows one line; the dock shows the whole message.
    statusBar()->showMessage(message.section(QLatin1Char('\n'), 0, 0));
}

void MainWindow::showOpenDialog() {
    const QString path = FileDialogs::open(this, currentPath());
    if (!path.isEmpty()) openSpecies(path);
}

void MainWindow::showPreferences() {
    PreferencesDialog dialog(mAutosave->interval(), mAutosave->folder(),
                             Viewport::samplesPreference(), this);
    if (dialog.exec() != QDialog::Accepted) return;
    setAutosaveInterval(dialog.autosaveSeconds());
    Viewport::setSamplesPreference(dialog.samples());
}

MainWindow::FrameStats MainWindow::measureFrames(int frames, float orbitDegrees) {
    FrameStats stats = FrameMeter(*mViewport).measure(frames, orbitDegrees);
    if (frames > 0) stats.triangles = lastResult().triangleCount();
    return stats;
}

void MainWindow::setAutosaveInterval(int seconds) {
    mAutosave->setInterval(seconds * 1000);
    QSettings().setValue(QStringLiteral("autosaveIntervalSeconds"), seconds);
}

void MainWindow::showSaveAsDialog() {
    const QString path = FileDialogs::saveProject(this, mDocument->path());
    if (!path.isEmpty()) saveAs(path);
}

} // namespace sylva::ui
