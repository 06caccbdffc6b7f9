#pragma once

#include <functional>
#include <optional>

#include <QObject>
#include <QPointer>
#include <QString>

#include "ui/generation/exportlodchain.h"

class QAction;
class QProgressDialog;
class QWidget;

namespace sylva::ui {

/// File ▸ Export LOD chain…: a species' or the selected tree's game LOD chain written into a
/// folder as `sylva-cli lods` writes it (exportLodChain on a worker thread), with a progress
/// dialog whose Cancel stops it within a second and leaves no file. The window asks the
/// folder; tests and scripts call exportTo().
class LodChainExportAction : public QObject {
    Q_OBJECT

public:
    /// \p source answers what is shown now (lodChainSource of the window's shown scene).
    using SourceOf = std::function<std::optional<LodChainSource>()>;
    LodChainExportAction(QWidget* window, SourceOf source);

    QAction* action() const { return mAction; }
    /// The file shown (the project or species), whose folder the folder dialog starts in.
    void setShownFile(std::function<QString()> shown) { mShown = std::move(shown); }
    /// Enables the action when there is a chain to export (after a generation, a selection).
    void update();
    /// Writes the chain into \p dir (created when missing), showing the progress dialog and
    /// running the event loop until it ends. True when written; false when cancelled or failed
    /// (failed() says why) or when there is nothing to export.
    bool exportTo(const QString& dir);
    /// The progress dialog while an export runs (null otherwise): tests press its Cancel.
    QProgressDialog* progressDialog() const;
    /// What the last exportTo() wrote.
    const exporter::GameLodFiles& lastFiles() const { return mFiles; }

Q_SIGNALS:
    /// After each export: \p ok, and the message for the status bar or the error to report.
    void finished(bool ok, const QString& message);

private:
    void chooseFolder();

    QWidget* mWindow;
    SourceOf mSource;
    std::function<QString()> mShown;
    QAction* mAction;
    QPointer<QProgressDialog> mDialog;
    exporter::GameLodFiles mFiles;
    QString mLastFolder;
};

} // namespace sylva::ui
