#include "ui/generation/documentgenerator.h"

#include <QPromise>
#include <QtConcurrent/QtConcurrentRun>

#include "ui/generation/promiseprogress.h"

namespace sylva::ui {

DocumentGenerator::DocumentGenerator(doc::Document& document, QObject* parent)
    : QObject(parent), mDocument(document) {
    connect(&mWatcher, &QFutureWatcher<GenerationResult>::finished, this,
            &DocumentGenerator::onFinished);
    connect(&mWatcher, &QFutureWatcher<GenerationResult>::progressTextChanged, this,
            &DocumentGenerator::progressed);
}

DocumentGenerator::~DocumentGenerator() {
    mWatcher.disconnect(this);
    mWatcher.cancel();
    mWatcher.waitForFinished();
}

void DocumentGenerator::regenerate() {
    mUserCancelled = false;
    if (mRunning) {
        // Newest edit wins: stop the running build; onFinished() starts the latest state.
        if (!mPending) mPendingEdit.start();
        mPending = true;
        mWatcher.cancel();
        return;
    }
    mSinceEdit.start();
    start();
}

void DocumentGenerator::regenerateAll() {
    if (mRunning) {
        mWatcher.cancel();
        mWatcher.waitForFinished(); // the cache is not cleared under a running build
    }
    mCaches.trees.clear();
    regenerate();
}

void DocumentGenerator::cancel() {
    mUserCancelled = true;
    mPending = false;
    mWatcher.cancel();
}

void DocumentGenerator::start() {
    mPending = false;
    // A snapshot: the worker never sees the document change under it.
    const doc::Project project = mDocument.project();
    const QString path = mDocument.path().isEmpty() ? mDocument.displayName() : mDocument.path();
    SceneCaches* caches = &mCaches;
    mRunning = true;
    Q_EMIT started();
    mWatcher.setFuture(
        QtConcurrent::run([project, path, caches](QPromise<GenerationResult>& promise) {
            PromiseProgress progress(promise);
            promise.addResult(generateProject(project, path, caches, progress));
        }));
}

void DocumentGenerator::onFinished() {
    mRunning = false;
    const QFuture<GenerationResult> future = mWatcher.future();
    const bool gotResult = !future.isCanceled() && future.resultCount() > 0;
    GenerationResult result = gotResult ? future.result() : GenerationResult{};
    if (mPending) { // superseded: build the latest state now
        mSinceEdit = mPendingEdit;
        start();
        return;
    }
    if (!gotResult || result.cancelled) {
        Q_EMIT cancelled();
        return;
    }
    if (!result.ok()) {
        mFailure = result.error.isEmpty() ? tr("the generation failed") : result.error;
        Q_EMIT finished(false, result.error);
        return;
    }
    mEditToResultMs = double(mSinceEdit.nsecsElapsed()) * 1e-6;
    mResultRequest = mSinceEdit;
    mResult = std::move(result);
    mFailure.clear();
    Q_EMIT finished(true, {});
}

} // namespace sylva::ui
