// MainWindow's menus, actions and tool bar (File, Edit, Scene, Presets, View, Help): what each
// action does lives in the main window's other files and the rooms it assembles.
#include "ui/mainwindow.h"

#include <QAction>
#include <QDockWidget>
#include <QKeySequence>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QStatusBar>
#include <QUndoStack>

#include "ui/document/documentactions.h"
#include "ui/document/outlinerview.h"
#include "ui/document/presetsmenu.h"
#include "ui/document/sourcewatcher.h"
#include "ui/generation/documentgenerator.h"
#include "ui/helpmenu.h"
#include "ui/languagemenu.h"
#include "ui/lodchainexportaction.h"
#include "ui/recentfilesmenu.h"
#include "ui/speciesworkbench.h"
#include "ui/viewport/colorbymenu.h"
#include "ui/viewport/toolcontroller.h"
#include "ui/viewport/tooloptionsbar.h"
#include "ui/viewport/viewport.h"

namespace sylva::ui {

void MainWindow::createMenus() {
    mDocumentActions = new DocumentActions(
        *mDocument, [this] { return mViewport->camera().target(); }, this);
    connect(mDocumentActions, &DocumentActions::failed, this, &MainWindow::reportError);
    mDocumentActions->setResult(
        [this]() -> const GenerationResult& { return mGenerator->result(); });
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->setObjectName(QStringLiteral("fileMenu"));
    QAction* newAction = file->addAction(tr("&New project"), this, &MainWindow::newDocument);
    newAction->setObjectName(QStringLiteral("actionNew"));
    newAction->setShortcut(QKeySequence::New);
    QAction* open =
        file->addAction(tr("&Open species or project…"), this, &MainWindow::showOpenDialog);
    open->setObjectName(QStringLiteral("actionOpen"));
    open->setShortcut(QKeySequence::Open);
    auto* recent = new RecentFilesMenu(this);
    connect(recent, &RecentFilesMenu::openRequested, this, &MainWindow::openSpecies);
    file->addMenu(recent);
    QAction* saveAction = file->addAction(tr("&Save"), this, &MainWindow::save);
    saveAction->setObjectName(QStringLiteral("actionSave"));
    saveAction->setShortcut(QKeySequence::Save);
    QAction* saveAsAction = file->addAction(tr("Save &as…"), this, &MainWindow::showSaveAsDialog);
    saveAsAction->setObjectName(QStringLiteral("actionSaveAs"));
    saveAsAction->setShortcut(QKeySequence::SaveAs);
    QAction* revertAction = file->addAction(tr("Re&vert"), this, &MainWindow::revert);
    revertAction->setObjectName(QStringLiteral("actionRevert"));
    file->addSeparator();
    mReloadAction = file->addAction(tr("&Reload"), this, &MainWindow::reload);
    mReloadAction->setShortcuts({QKeySequence(Qt::Key_F5), QKeySequence(tr("Ctrl+R"))});
    mAutoReloadAction = file->addAction(tr("Reload &automatically"));
    mAutoReloadAction->setCheckable(true);
    mAutoReloadAction->setChecked(true);
    connect(mAutoReloadAction, &QAction::toggled, mSourceWatcher, &SourceWatcher::setEnabled);
    mExportAction = file->addAction(tr("&Export…"), this, &MainWindow::showExportDialog);
    mExportAction->setShortcut(QKeySequence(tr("Ctrl+E")));
    mExportAction->setEnabled(false);
    mExportSelectionAction = file->addAction(tr("Export only the selection"));
    mExportSelectionAction->setObjectName(QStringLiteral("actionExportSelection"));
    mExportSelectionAction->setCheckable(true);
    mExportSelectionAction->setToolTip(tr("File ▸ Export writes only the selected trees"));
    mExportViewLodAction = file->addAction(tr("Export with the viewport camera's detail"));
    mExportViewLodAction->setObjectName(QStringLiteral("actionExportViewLod"));
    mExportViewLodAction->setCheckable(true);
    mExportViewLodAction->setToolTip(
        tr("File ▸ Export chooses each tree's level of detail for the viewport's camera instead "
           "of the project's camera"));
    mExportWindAction = file->addAction(tr("Export with the project's wind"));
    mExportWindAction->setObjectName(QStringLiteral("actionExportWind"));
    mExportWindAction->setCheckable(true);
    mExportWindAction->setChecked(true);
    mExportWindAction->setToolTip(
        tr("When the project has a wind, File ▸ Export writes it as sylva-cli forest --wind: a "
           "rig and a looping wind clip per tree (.glb, .gltf, .fbx)"));
    mLodChainExport = new LodChainExportAction(this, [this] {
        return lodChainSource({lastResult(), mPreview.isActive() ? nullptr : mDocument,
                               glm::vec3(0.0f), glm::vec3(0.0f)});
    });
    mLodChainExport->setShownFile([this] { return currentPath(); });
    file->addAction(mLodChainExport->action());
    connect(mLodChainExport, &LodChainExportAction::finished, this,
            [this](bool ok, const QString& message) {
                if (ok)
                    statusBar()->showMessage(message, 10000);
                else
                    reportError(message);
            });
    connect(mDocument, &doc::Document::selectionChanged, mLodChainExport,
            &LodChainExportAction::update);
    QAction* shot =
        file->addAction(tr("Save s&creenshot…"), this, &MainWindow::showScreenshotDialog);
    shot->setShortcut(QKeySequence(tr("Ctrl+Alt+S")));
    file->addSeparator();
    QAction* quit = file->addAction(tr("&Quit"), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->setObjectName(QStringLiteral("editMenu"));
    QAction* undo = mDocument->undoStack()->createUndoAction(this, tr("&Undo"));
    undo->setObjectName(QStringLiteral("actionUndo"));
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = mDocument->undoStack()->createRedoAction(this, tr("&Redo"));
    redo->setObjectName(QStringLiteral("actionRedo"));
    redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    edit->addActions({mDocumentActions->deleteAction(), mDocumentActions->duplicateAction(),
                      mDocumentActions->selectAllAction()});
    mOutliner->addAction(mDocumentActions->deleteAction());
    mOutliner->addAction(mDocumentActions->duplicateAction());
    edit->addSeparator();
    QAction* prefs = edit->addAction(tr("&Preferences…"), this, &MainWindow::showPreferences);
    prefs->setObjectName(QStringLiteral("actionPreferences"));
    prefs->setMenuRole(QAction::PreferencesRole);

    QMenu* scene = menuBar()->addMenu(tr("&Scene"));
    scene->setObjectName(QStringLiteral("sceneMenu"));
    scene->addAction(mDocumentActions->addSpeciesAction());
    QAction* editSpeciesAction = scene->addAction(tr("&Edit species…"), this, [this] {
        // The selected species, else the species of the selected tree, else the shown one.
        QString name;
        for (const doc::ItemRef& item : mDocument->selection()) {
            if (item.kind == doc::ItemRef::Kind::Species &&
                item.id < mDocument->project().species.size())
                name = QString::fromStdString(mDocument->project().species[item.id].name);
        }
        if (name.isEmpty())
            for (doc::TreeId id : mDocument->selectedTrees())
                name = QString::fromStdString(mDocument->tree(id).species);
        editSpecies(name);
    });
    editSpeciesAction->setObjectName(QStringLiteral("actionEditSpecies"));
    editSpeciesAction->setShortcut(QKeySequence(tr("Ctrl+Shift+E")));
    scene->addActions({mDocumentActions->addTreeAction(), mDocumentActions->importObstacleAction(),
                       mDocumentActions->addDomainAction()});

    auto* presets =
        new PresetsMenu([this] { return mPreview.isActive() ? mPreview.path() : QString(); }, this);
    connect(presets, &PresetsMenu::openRequested, this, &MainWindow::openSpecies);
    mPresetsMenu = presets;
    menuBar()->addMenu(presets);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->setObjectName(QStringLiteral("viewMenu"));
    QAction* frame =
        view->addAction(tr("&Frame selection or all"), this, &MainWindow::frameSelectionOrAll);
    frame->setShortcut(QKeySequence(Qt::Key_F));
    frame->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    QAction* grid = view->addAction(tr("Show &grid"));
    grid->setCheckable(true);
    grid->setChecked(true);
    grid->setShortcut(QKeySequence(Qt::Key_G));
    connect(grid, &QAction::toggled, mViewport, &Viewport::setGridVisible);
    // Shortcuts of the View menu act while the viewport has focus, like the F key itself.
    mWindAction = view->addAction(tr("&Wind"));
    mWindAction->setObjectName(QStringLiteral("actionViewWind"));
    mWindAction->setCheckable(true);
    mWindAction->setToolTip(tr("Trees sway in the project's wind (Properties, with nothing "
                               "selected): the wind model the exports carry"));
    mWindAction->setChecked(QSettings().value(QStringLiteral("view/wind"), false).toBool());
    connect(mWindAction, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue(QStringLiteral("view/wind"), on);
        for (Viewport* v : {mViewport, mWorkbench ? mWorkbench->previewViewport() : nullptr})
            if (v) v->setWindEnabled(on);
    });
    for (Viewport* v : {mViewport, mWorkbench ? mWorkbench->previewViewport() : nullptr})
        if (v) v->setWindEnabled(mWindAction->isChecked());
    mViewport->addAction(frame);
    mViewport->addAction(grid);
    mViewport->addAction(mWindAction);
    mColorMenu = new ColorByMenu(mColorBy, this);
    connect(mColorMenu, &ColorByMenu::chosen, this, &MainWindow::setColorBy);
    view->addMenu(mColorMenu);
    view->addSeparator();
    QMenu* docks = view->addMenu(tr("&Panels"));
    docks->setObjectName(QStringLiteral("panelsMenu"));
    for (const auto& [name, d] : mDocks)
        docks->addAction(d->toggleViewAction());
    view->addMenu(new LanguageMenu(this));

    menuBar()->addMenu(new HelpMenu(this));
}

void MainWindow::createToolBar() {
    mToolBar = new ToolOptionsBar(*mTools, *mDocument, this);
    connect(mToolBar, &ToolOptionsBar::failed, this, &MainWindow::reportError);
    addToolBar(mToolBar);
}

} // namespace sylva::ui
