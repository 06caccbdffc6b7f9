#include "ui/generation/speciespreviewsession.h"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>

#include "ui/generation/promiseprogress.h"

namespace sylva::ui {

SpeciesPreviewSession::SpeciesPreviewSession(QObject* parent) : QObject(parent) {
    connect(&mWatcher, &QFutureWatcher<GenerationResult>::finished, this,
            &SpeciesPreviewSession::onFinished);
    connect(&mWatcher, &QFutureWatcher<GenerationResult>::progressTextChanged, this,
            &SpeciesPreviewSession::progressed);
}

SpeciesPreviewSession::~SpeciesPreviewSession() {
    stop();
}

void SpeciesPreviewSession::start(const QString& path) {
    cancelIfRunning(); // superseded; its result is dropped
    mActive = true;
    mPath = path;
    mRunning = true;
    mWatcher.setFuture(QtConcurrent::run([path](QPromise<GenerationResult>& promise) {
        PromiseProgress progress(promise);
        promise.addResult(generateTree(path, progress));
    }));
}

void SpeciesPreviewSession::cancel() {
    mWatcher.cancel();
}

void SpeciesPreviewSession::cancelIfRunning() {
    if (mWatcher.isRunning()) mWatcher.cancel();
}

void SpeciesPreviewSession::stop() {
    // The worker only touches its own copies, but stopping it keeps shutdown quick.
    mWatcher.disconnect(this);
    mWatcher.cancel();
    mWatcher.waitForFinished();
}

void SpeciesPreviewSession::onFinished() {
    const QFuture<GenerationResult> future = mWatcher.future();
    mRunning = mWatcher.isRunning(); // a newer run may already go
    if (future.isCanceled() || future.resultCount() == 0) {
        Q_EMIT dropped(); // superseded by a newer run, or cancelled
        return;
    }
    GenerationResult run = future.result();
    if (run.cancelled) {
        Q_EMIT dropped();
        return;
    }
    if (!run.ok()) {
        Q_EMIT generated(run);
        return;
    }
    mResult = std::move(run);
    Q_EMIT generated(mResult);
}

} // namespace sylva::ui
