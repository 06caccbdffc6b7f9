#pragma once

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QObject>

#include "document/document.h"
#include "ui/generation/scenegenerator.h"

namespace sylva::ui {

/// Regrows the open document off the GUI thread whenever it changes: one generation at a time,
/// the newest edit wins (a running generation is cancelled and the latest state built next),
/// and trees whose inputs did not change are reused from the last build (SceneCaches), so a
/// one-tree edit regrows that tree and the neighbours whose crowns it touches. A cancelled or
/// failed generation leaves the document and the last good result as they were.
class DocumentGenerator : public QObject {
    Q_OBJECT

public:
    explicit DocumentGenerator(doc::Document& document, QObject* parent = nullptr);
    ~DocumentGenerator() override;

    /// Builds the document's current state (after an edit, or a file changed on disk).
    void regenerate();
    /// Forgets every cached tree (a grammar or mesh file changed on disk) and regenerates.
    void regenerateAll();
    /// Stops the running generation; the last good result stays.
    void cancel();
    /// A generation runs, or its result has not been taken yet (the future can be finished
    /// while its finished() signal is still queued), or a newer one waits.
    bool isBusy() const { return mRunning || mPending; }
    /// The last successful generation.
    const GenerationResult& result() const { return mResult; }
    /// Milliseconds from the edit that asked for the last result to its end (the mesh ready).
    double editToResultMs() const { return mEditToResultMs; }
    /// The error of the newest finished generation; empty when it succeeded. result() then
    /// still holds the last good build, which is not the document's current state.
    const QString& failure() const { return mFailure; }
    /// Milliseconds since the edit (or reload) that asked for the last result.
    double msSinceResultRequest() const {
        return mResultRequest.isValid() ? double(mResultRequest.nsecsElapsed()) * 1e-6 : 0.0;
    }

Q_SIGNALS:
    void started();
    void progressed(const QString& stage);
    /// A generation ended: \p ok with a new result(), or an error message; not emitted for a
    /// cancelled or superseded one (cancelled() is).
    void finished(bool ok, const QString& error);
    void cancelled();

private:
    void start();
    void onFinished();

    doc::Document& mDocument;
    SceneCaches mCaches;
    QFutureWatcher<GenerationResult> mWatcher;
    bool mRunning = false;       ///< started, onFinished() not yet run
    bool mPending = false;       ///< an edit arrived while a generation ran
    bool mUserCancelled = false; ///< cancel(): do not restart
    QElapsedTimer mSinceEdit;    ///< started at the edit the running generation builds
    QElapsedTimer mPendingEdit;
    GenerationResult mResult;
    QElapsedTimer mResultRequest; ///< the request behind mResult
    double mEditToResultMs = 0.0;
    QString mFailure;
};

} // namespace sylva::ui
