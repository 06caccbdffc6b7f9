#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include "ui/generation/treegenerator.h"

namespace sylva::ui {

/// A species or grammar file shown on its own instead of the document (the window's preview
/// mode): generated as `sylva-cli tree` makes it, on a worker, newest run wins. The window
/// decides what to show; this holds the mode, the file, the running job and the last good tree.
class SpeciesPreviewSession : public QObject {
    Q_OBJECT

public:
    explicit SpeciesPreviewSession(QObject* parent = nullptr);
    /// Stops the running job and waits for it (its result is dropped).
    ~SpeciesPreviewSession() override;

    /// Enters the preview of \p path and generates it; a run still going is superseded (its
    /// result dropped).
    void start(const QString& path);
    /// Asks a running job to stop (dropped() follows; nothing does when none runs). The last
    /// good result stays.
    void cancel();
    /// cancel() while the job still runs; a job that already ended hands out its result.
    void cancelIfRunning();
    /// Leaves the preview mode (the document is shown again); a running job goes on.
    void leave() { mActive = false; }
    /// Stops the running job and waits for it, without a signal (the window closes).
    void stop();

    /// Whether the preview is what is shown (from start() to leave()).
    bool isActive() const { return mActive; }
    /// From start() until the last job's result was handed out (generated() or dropped()).
    bool isRunning() const { return mRunning; }
    /// The file previewed (the last one started).
    const QString& path() const { return mPath; }
    /// The last successful run's result.
    const GenerationResult& result() const { return mResult; }

Q_SIGNALS:
    /// The running job's stage (a new name only).
    void progressed(const QString& stage);
    /// A job ended without a result: cancelled, or superseded by a newer one.
    void dropped();
    /// A job ended with \p run: when it is ok() it is result() from now on, otherwise the last
    /// good result stays. Its sources (and their times when read) are listed either way.
    void generated(const GenerationResult& run);

private:
    void onFinished();

    QFutureWatcher<GenerationResult> mWatcher;
    bool mActive = false;
    bool mRunning = false;
    QString mPath;
    GenerationResult mResult;
};

} // namespace sylva::ui
