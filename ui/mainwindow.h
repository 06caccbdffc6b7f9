#pragma once

#include <functional>
#include <map>
#include <optional>

#include <QDateTime>
#include <QMainWindow>
#include <QPointer>
#include <QProgressDialog>
#include <QString>

#include "document/document.h"
#include "ui/generation/exportshown.h"
#include "ui/generation/speciespreviewsession.h"
#include "ui/generation/treegenerator.h"
#include "ui/viewport/attributecolors.h"
#include "ui/viewport/framemeter.h"

class QAction;
class QTimer;
class QDockWidget;
class QActionGroup;
class QLabel;
class QMenu;
class QProgressBar;
class QToolButton;
class QTreeView;
class QUndoView;

namespace sylva::doc {
class Autosave;
}

namespace sylva::ui {

class ColorByMenu;
class LodChainExportAction;
class DocumentActions;
class DocumentGenerator;
class MessagesPanel;
class OutlinerModel;
class PropertiesPanel;
class PythonConsole;
class StatsPanel;
class SpeciesWorkbench;
class PresetBrowser;
class SourceWatcher;
class ToolController;
class ToolOptionsBar;
class Viewport;

/// The editor's main window. It only assembles the rooms of `ui/`: the document (core/document:
/// the project, its undo history, autosave) with its views (outliner, properties, undo history,
/// statistics, messages), the generation worker, the viewport with its tool options and frame
/// meter, the preview session, the source watcher, the preferences and the Python console, and
/// holds the policy that joins them (what to show, when to ask, when to reload). Every edit,
/// from a widget, a menu or a script, goes through the document.
///
/// A species or grammar file opens as a preview of that one species (SpeciesPreviewSession, as
/// `sylva-cli tree` makes it); a project opens into the document and is edited there.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Viewport* viewport() const { return mViewport; }
    StatsPanel* statsPanel() const { return mStats; }
    MessagesPanel* messages() const { return mMessages; }
    QMenu* presetsMenu() const { return mPresetsMenu; }
    doc::Document& document() { return *mDocument; }
    doc::Autosave& autosave() { return *mAutosave; }
    DocumentGenerator& generator() { return *mGenerator; }
    QTreeView* outliner() const { return mOutliner; }
    OutlinerModel* outlinerModel() const { return mOutlinerModel; }
    PropertiesPanel* properties() const { return mProperties; }
    PythonConsole* console() const { return mConsole; }
    ToolController& tools() { return *mTools; }
    SpeciesWorkbench* workbench() const { return mWorkbench; }
    PresetBrowser* presetBrowser() const { return mPresetBrowser; }
    /// File ▸ Export LOD chain… (the shown species' or the selected tree's game LOD chain).
    LodChainExportAction* lodChainExport() const { return mLodChainExport; }
    /// Shows the species editor (graph, grammar, live preview, node parameters) on \p species
    /// (the one shown already when empty).
    void editSpecies(const QString& species = {});

    /// Opens a project into the document (openProject) or a species file as a preview;
    /// generationFinished() tells when it is shown. Errors never throw: they go to the status
    /// bar, the Messages dock and the stats dock, and the last good tree stays.
    void openSpecies(const QString& path);
    /// Opens a project into the document. With unsaved edits it asks first (askUser). A file
    /// that cannot be read keeps the open document and says why; false then.
    bool openProject(const QString& path);
    /// File ▸ New: an empty project (asks first with unsaved edits).
    bool newDocument();
    /// File ▸ Save / Save As: atomic; false with a message when writing fails.
    bool save();
    bool saveAs(const QString& path);
    /// File ▸ Revert: the file as saved, dropping the edits (asks first).
    bool revert();
    /// Opens PresetLibrary::defaultPreset() as a preview; false (with a message) when none.
    bool openDefaultPreset();
    /// Generates the shown species or project again (after editing a file on disk).
    void reload();
    /// File ▸ Reload automatically (on by default): regenerate when a file the shown result was
    /// read from changes on disk. A change to the open project's own file with unsaved edits
    /// asks before reloading.
    void setAutoReload(bool on);
    bool autoReload() const;
    /// View ▸ Wind (QSettings "view/wind", off by default): the viewport and the species preview
    /// sway their trees in the project's wind.
    void setViewWind(bool on);
    bool viewWind() const;
    /// Freezes both views' wind clocks at \p seconds, or lets them run again (nullopt).
    void setWindTime(std::optional<double> seconds);
    QStringList watchedFiles() const;
    /// Saves the viewport's current image; false (with a message) on failure.
    bool saveScreenshot(const QString& path);
    /// Saves an image of the whole window, docks and menus included.
    bool saveWindowScreenshot(const QString& path);
    /// Exports what is shown by \p path's extension, exactly as `sylva-cli tree` (a species) or
    /// `sylva-cli forest` (the document's project) writes it.
    bool exportTo(const QString& path);
    /// What File ▸ Export takes from a project (exportShown's options).
    bool exportTo(const QString& path, const ExportOptions& options);

    /// The species file previewed, or the document's file.
    QString currentPath() const;
    /// The last successful generation of what is shown (preview or document).
    const GenerationResult& lastResult() const;
    QString lastError() const { return mLastError; }
    /// The failed generation the status bar shows until one succeeds; empty when none.
    QString generationError() const;
    bool isGenerating() const;
    bool isPreview() const { return mPreview.isActive(); }
    /// Waits (running the event loop) until the current generation ends; false on timeout.
    bool waitForGeneration(int timeoutMs = 600000);
    /// Milliseconds from the last edit to its new meshes drawn on screen.
    double lastEditToScreenMs() const { return mEditToScreenMs; }

    void setColorBy(ColorBy mode);
    ColorBy colorBy() const { return mColorBy; }

    /// What a question to the user answers; tests and scripts replace the dialog.
    enum class Answer { Save, Discard, Cancel, Yes, No };
    using AskHandler = std::function<Answer(const QString& question, bool canSave)>;
    void setAskHandler(AskHandler handler) { mAsk = std::move(handler); }
    /// Offers to restore an autosave left by a crash (askUser); with \p force, restores it
    /// without asking. True when one was restored.
    bool offerRecovery(bool force = false);

    /// Orbits the view by a small step per frame for \p frames frames and measures them
    /// (FrameMeter), with the shown result's triangle count.
    using FrameStats = ui::FrameStats;
    FrameStats measureFrames(int frames, float orbitDegrees = 4.0f);

    /// Edit ▸ Preferences: how often the autosave copy is written (kept in the settings).
    void setAutosaveInterval(int seconds);

    /// Reports an error (status bar, Messages, stats dock).
    void reportError(const QString& message);

Q_SIGNALS:
    /// Emitted on the GUI thread when a generation ends (not when it was superseded).
    void generationFinished(bool ok);

protected:
    void closeEvent(QCloseEvent* event) override;

private:
    void openAtScreenSize();
    void createDocks();
    void createMenus();
    void createToolBar();
    void frameSelectionOrAll();
    void onPreviewGenerated(const GenerationResult& run);
    void onDocumentGenerated(bool ok, const QString& error);
    void onDocumentChanged(const doc::DocumentChange& change);
    void showDocument(bool frame);
    void updateTitle();
    bool maybeDiscard();
    Answer askUser(const QString& question, bool canSave);
    void showOpenDialog();
    void showSaveAsDialog();
    void showPreferences();
    void showScreenshotDialog();
    void showExportDialog();
    void applyColoring();
    void onSourcesChanged(const QStringList& changed);
    void setBusy(bool busy);

    doc::Document* mDocument = nullptr;
    doc::Autosave* mAutosave = nullptr;
    DocumentGenerator* mGenerator = nullptr;
    Viewport* mViewport = nullptr;
    StatsPanel* mStats = nullptr;
    SpeciesWorkbench* mWorkbench = nullptr;
    PresetBrowser* mPresetBrowser = nullptr;
    MessagesPanel* mMessages = nullptr;
    PropertiesPanel* mProperties = nullptr;
    OutlinerModel* mOutlinerModel = nullptr;
    QTreeView* mOutliner = nullptr;
    QUndoView* mUndoView = nullptr;
    PythonConsole* mConsole = nullptr;
    ToolController* mTools = nullptr;
    ToolOptionsBar* mToolBar = nullptr;
    DocumentActions* mDocumentActions = nullptr;
    QAction* mExportSelectionAction = nullptr;
    QAction* mExportViewLodAction = nullptr;
    QAction* mExportWindAction = nullptr;
    std::map<QString, QDockWidget*> mDocks;
    QMenu* mPresetsMenu = nullptr;
    QAction* mReloadAction = nullptr;
    QAction* mExportAction = nullptr;
    LodChainExportAction* mLodChainExport = nullptr;
    QAction* mAutoReloadAction = nullptr;
    QAction* mWindAction = nullptr;
    /// Gives both views the project's wind.
    void applyWind();
    SourceWatcher* mSourceWatcher = nullptr; ///< the files the shown result was read from
    QTimer* mSpeciesRegen = nullptr;         ///< the forest regrows when species edits pause
    QDateTime mDocumentStamp; ///< the project file's time when opened, saved or last seen
    ColorByMenu* mColorMenu = nullptr;
    ColorBy mColorBy = ColorBy::Material;
    QLabel* mGlLabel = nullptr;
    QLabel* mGenerationError = nullptr;
    QPointer<QProgressDialog> mExportDialog; ///< File ▸ Export's, while it runs ///< the newest
                                             ///< generation's error, until one succeeds
    QProgressBar* mBusy = nullptr;
    QToolButton* mCancel = nullptr;

    /// A species file shown instead of the document (a member: it stops before the window's
    /// children go).
    SpeciesPreviewSession mPreview;
    QString mLastError;
    bool mFrameNext = false;    ///< frame (or look from the project camera) at the next result
    QStringList mShownWarnings; ///< the last generation's warnings, already in Messages
    double mEditToScreenMs = 0.0;
    bool mAwaitingFrame = false;
    AskHandler mAsk;
};

} // namespace sylva::ui
