#pragma once

#include <QThreadPool>
#include <QWidget>

#include "document/document.h"

class QLabel;
class QListWidget;
class QListWidgetItem;
class QPushButton;

namespace sylva::ui {

/// The preset browser: every species file of the presets folder and of the user's own presets
/// folder, with a thumbnail rendered by Sylva (grown and drawn off the GUI thread, one at a time,
/// cached on disk), applied to a species of the project (one undo step, a double click or
/// Apply), and the current species saved as a new preset.
class PresetBrowser : public QWidget {
    Q_OBJECT

public:
    static constexpr int kThumbnailSize = 96;

    explicit PresetBrowser(doc::Document& document, QWidget* parent = nullptr);
    ~PresetBrowser() override;

    /// The species Apply replaces (the species editor's, or the selected one).
    void setTargetSpecies(const QString& species);
    QString targetSpecies() const;
    QListWidget* list() const { return mList; }
    /// Applies the selected preset to the target species; false (failed() emitted) on error.
    bool applySelected();
    /// Saves the target species as a preset file; false (failed()) on error.
    bool saveTargetAs(const QString& path);
    /// Lists the presets again (the user's folder may have a new one).
    void refresh();
    /// Thumbnails still to draw.
    int pendingThumbnails() const { return mPending; }
    /// Where the user's own presets are saved.
    static QString userPresetsDirectory();
    static QString thumbnailCacheDirectory();

Q_SIGNALS:
    void failed(const QString& message);
    void status(const QString& message, int timeoutMs);

protected:
    void showEvent(QShowEvent* event) override;

private:
    void startThumbnails();

    doc::Document& mDocument;
    QString mTarget;
    QListWidget* mList;
    QLabel* mTargetLabel;
    QPushButton* mApply;
    QPushButton* mSave;
    QThreadPool mPool; ///< one thumbnail at a time: the editor stays responsive
    int mPending = 0;
    bool mStarted = false;
};

} // namespace sylva::ui
