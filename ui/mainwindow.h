#pragma once

#include <map>

#include <QDateTime>
#include <QFutureWatcher>
#include <QMainWindow>
#include <QString>

#include "ui/attributecolors.h"
#include "ui/treegenerator.h"

class QAction;
class QFileSystemWatcher;
class QTimer;
class QDockWidget;
class QActionGroup;
class QLabel;
class QMenu;
class QProgressBar;

namespace sylva::ui {

class StatsPanel;
class Viewport;

/// The editor's main window: the 3D viewport in the middle, a dock with the tree's statistics,
/// File / Presets / View menus. Species are generated on a worker thread (QtConcurrent); the
/// window stays responsive and a newer request cancels an older one.
class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Viewport* viewport() const { return mViewport; }
    StatsPanel* statsPanel() const { return mStats; }
    QMenu* presetsMenu() const { return mPresetsMenu; }

    /// Starts generating the species file at \p path, or a project's whole forest with its
    /// obstacles (isProjectFile(): `.sylva`, built as `sylva-cli forest` builds it);
    /// generationFinished() tells when it is done. Errors never throw: they go to the status bar
    /// and the stats dock, and the last good tree stays.
    void openSpecies(const QString& path);
    /// Opens PresetLibrary::defaultPreset(); false (with a message) when there is none.
    bool openDefaultPreset();
    /// Generates the current species file again (after editing it on disk).
    void reload();
    /// File ▸ Reload automatically (on by default): regenerate when a file the shown result was
    /// read from changes on disk (GenerationResult::sources: the species or project, its grammar
    /// files, a project's species and obstacle meshes), also when an editor saves by writing a
    /// new file and renaming it over the old one. Changes within 250 ms are one reload.
    void setAutoReload(bool on);
    bool autoReload() const;
    /// The files watched for automatic reloading (absolute paths).
    QStringList watchedFiles() const { return mSources; }
    /// Saves the viewport's current image; false (with a message) on failure.
    bool saveScreenshot(const QString& path);
    /// Exports what is shown (File ▸ Export…) by \p path's extension, exactly as `sylva-cli
    /// tree` (a species) or `sylva-cli forest` (a project) writes it: `.obj` (+ `.mtl` and
    /// textures), `.glb`, `.gltf` or `.fbx`. False, with a message, when there is nothing to
    /// export or writing fails (nothing half-written is left at \p path).
    bool exportTo(const QString& path);

    /// The species file shown (or being generated).
    QString currentPath() const { return mCurrentPath; }
    /// The last successful generation (empty result before the first).
    const GenerationResult& lastResult() const { return mResult; }
    /// The message of the last failed generation; cleared by a successful one.
    QString lastError() const { return mLastError; }
    bool isGenerating() const { return mWatcher.isRunning(); }

    /// Colours the tree by its materials or a node attribute (View ▸ Colour by); modes the tree
    /// lacks (light, vigour and age come from self-organizing growth) fall back to materials.
    void setColorBy(ColorBy mode);
    ColorBy colorBy() const { return mColorBy; }

Q_SIGNALS:
    /// Emitted on the GUI thread when a generation ends (not when it was superseded).
    void generationFinished(bool ok);

private:
    void createMenus();
    void populatePresetsMenu();
    void onGenerationFinished();
    void showOpenDialog();
    void showScreenshotDialog();
    void showExportDialog();
    void reportError(const QString& message);
    void applyColoring();
    void watchSources(const QStringList& sources, const QList<QDateTime>& stamps);
    void onSourcesTouched();

    Viewport* mViewport = nullptr;
    StatsPanel* mStats = nullptr;
    QDockWidget* mStatsDock = nullptr;
    QMenu* mPresetsMenu = nullptr;
    QActionGroup* mPresetGroup = nullptr;
    QAction* mReloadAction = nullptr;
    QAction* mExportAction = nullptr;
    QAction* mAutoReloadAction = nullptr;
    QFileSystemWatcher* mFileWatcher = nullptr;
    QTimer* mReloadTimer = nullptr;
    QStringList mSources;                 ///< files of the shown (or failed) result
    std::map<QString, QDateTime> mStamps; ///< their modification times when watched
    QActionGroup* mColorGroup = nullptr;
    ColorBy mColorBy = ColorBy::Material;
    QLabel* mGlLabel = nullptr;
    QProgressBar* mBusy = nullptr;

    QFutureWatcher<GenerationResult> mWatcher;
    QString mCurrentPath;
    QString mLastError;
    GenerationResult mResult;
};

} // namespace sylva::ui
