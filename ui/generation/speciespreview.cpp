#include "ui/generation/speciespreview.h"
#include "ui/generation/windvertexdata.h"

#include <QtConcurrent/QtConcurrentRun>

#include <omp.h>

#include "document/errormessage.h"
#include "engine/util/error.h"
#include "engine/util/progress.h"

namespace sylva::ui {

namespace {

/// One OpenMP thread for the preview's evaluation (restored after): the editor's 2-core budget
/// is shared with the forest's regrowth and the drawing, and two spinning OpenMP threads on a
/// busy machine took 12 ms where one takes 3 (docs/perf/editor.md).
class SingleThreaded {
public:
    SingleThreaded() : mPrevious(omp_get_max_threads()) { omp_set_num_threads(1); }
    ~SingleThreaded() { omp_set_num_threads(mPrevious); }
    SingleThreaded(const SingleThreaded&) = delete;
    SingleThreaded& operator=(const SingleThreaded&) = delete;

private:
    int mPrevious;
};

class FlagProgress : public Progress {
public:
    explicit FlagProgress(std::shared_ptr<std::atomic<bool>> flag) : mFlag(std::move(flag)) {}
    bool isCancelled() const override { return mFlag->load(std::memory_order_relaxed); }

private:
    std::shared_ptr<std::atomic<bool>> mFlag;
};

} // namespace

SpeciesPreview::SpeciesPreview(doc::Document& document, QObject* parent)
    : QObject(parent), mDocument(document) {
    connect(&mWatcher, &QFutureWatcher<PreviewResult>::finished, this, &SpeciesPreview::onFinished);
    connect(&mDocument, &doc::Document::changed, this, [this](const doc::DocumentChange& c) {
        // Any species change: the previewed one may have been renamed, removed or edited.
        if (c.what & (doc::DocumentChange::Species | doc::DocumentChange::Reset)) {
            if (c.what & doc::DocumentChange::Reset) mEvaluators.clear();
            if (!mSpecies.isEmpty() && mDocument.speciesIndex(mSpecies.toStdString()) < 0)
                setSpecies({});
            else
                refresh();
        }
    });
}

SpeciesPreview::~SpeciesPreview() {
    if (mCancel) mCancel->store(true);
    mWatcher.waitForFinished();
}

void SpeciesPreview::setSpecies(const QString& species) {
    if (species == mSpecies) return;
    mSpecies = species;
    mOverrides.clear();
    mResult = {};
    mResult.species = species;
    refresh();
}

void SpeciesPreview::setSeed(std::uint64_t seed) {
    if (seed == mSeed) return;
    mSeed = seed;
    refresh();
}

void SpeciesPreview::setOverride(const QString& node, const std::string& key,
                                 const sylva::Value& value) {
    const auto k = std::make_pair(node, key);
    if (value.isNull())
        mOverrides.erase(k);
    else
        mOverrides[k] = value;
    refresh();
}

void SpeciesPreview::setActive(bool active) {
    if (active == mActive) return;
    mActive = active;
    if (mActive) refresh();
}

void SpeciesPreview::refresh() {
    if (mSpecies.isEmpty() || !mActive) return;
    if (mRunning) {
        // Newest wins: stop the running evaluation, start again when it has returned.
        if (!mPending) mPendingEdit.start();
        mPending = true;
        if (mCancel) mCancel->store(true);
        return;
    }
    mSinceEdit.start();
    start();
}

void SpeciesPreview::start() {
    graph::SpeciesGraph species;
    PreviewResult failed;
    failed.species = mSpecies;
    try {
        species = mDocument.engineSpecies(mSpecies.toStdString());
        for (const auto& [key, value] : mOverrides)
            if (graph::NodeDesc* n = species.findNode(key.first.toStdString()))
                n->params.objectRef()[key.second] = value;
        // Node ids: the preview sways in the wind (windvertexdata.h) and picks nodes by them.
        requestNodeIds(species);
    } catch (...) {
        failed.error = QString::fromStdString(
            doc::describeError(std::current_exception(), mSpecies.toStdString()).message);
    }
    if (!failed.error.isEmpty()) {
        mResult = failed;
        mEditToResultMs = mEditToScreenMs = 0.0;
        mAwaitingScreen = false;
        Q_EMIT finished();
        return;
    }
    // The job owns the evaluator while it runs; onFinished() stores it back.
    std::shared_ptr<graph::Evaluator> evaluator = mEvaluators[mSpecies];
    mEvaluators.erase(mSpecies);
    mCancel = std::make_shared<std::atomic<bool>>(false);
    mRunning = true;
    Q_EMIT started();
    const std::uint64_t seed = mSeed;
    const QString name = mSpecies;
    auto cancel = mCancel;
    mWatcher.setFuture(QtConcurrent::run([evaluator, species = std::move(species), seed, name,
                                          cancel]() mutable {
        PreviewResult r;
        r.species = name;
        QElapsedTimer timer;
        timer.start();
        std::shared_ptr<graph::Evaluator> ev = evaluator;
        const SingleThreaded oneThread;
        try {
            graph::registerBuiltinNodeTypes();
            // The long-lived evaluator keeps every node's result: setGraph() drops only what
            // the edit changed.
            if (ev)
                ev->setGraph(std::move(species));
            else
                ev = std::make_shared<graph::Evaluator>(std::move(species));
            // Rule lines per branch, for the editor's click-to-rule.
            ev->setTraceSources(true);
            FlagProgress progress(cancel);
            const graph::NodeOutput& o = ev->evaluate(seed, progress);
            r.mesh = o.mesh;
            r.skeleton = o.skeleton;
            r.stats = o.stats;
        } catch (...) {
            const doc::ErrorReport report =
                doc::describeError(std::current_exception(), name.toStdString());
            if (report.kind == doc::ErrorReport::Kind::Cancelled)
                r.cancelled = true;
            else
                r.error = QString::fromStdString(report.message);
        }
        if (ev) {
            r.runs = ev->runs();
            for (const auto& [id, run] : r.runs)
                if (!run.error.empty()) r.errorNode = QString::fromStdString(id);
        }
        r.evaluateMs = double(timer.nsecsElapsed()) * 1e-6;
        // The vertices as the viewport uploads them, made here rather than on the GUI
        // thread (6 ms for a 300k-triangle tree): the GUI thread only copies them.
        if (r.mesh && !cancel->load())
            r.vertices =
                std::make_shared<const std::vector<ViewVertex>>(interleaveVertices(*r.mesh, {}));
        r.evaluator = std::move(ev); // handed back: the GUI thread keeps it for the next edit
        return r;
    }));
}

void SpeciesPreview::onFinished() {
    mRunning = false;
    PreviewResult r = mWatcher.result();
    if (r.evaluator) mEvaluators[r.species] = r.evaluator;
    r.evaluator.reset();
    if (mPending) {
        mPending = false;
        mSinceEdit = mPendingEdit;
        start();
        return;
    }
    if (r.cancelled) return;
    if (r.species != mSpecies) return; // the user moved to another species meanwhile
    if (!r.error.isEmpty() && r.mesh == nullptr && mResult.mesh && mResult.species == r.species) {
        // Keep showing the last good tree; the error is reported beside it.
        r.mesh = mResult.mesh;
        r.vertices = mResult.vertices;
        r.skeleton = mResult.skeleton;
    }
    mResult = std::move(r);
    if (!mResult.error.isEmpty()) {
        // A failed preview is not a fresh one: no timing reads as if it were.
        mEditToResultMs = mEditToScreenMs = 0.0;
        mAwaitingScreen = false;
        Q_EMIT finished();
        return;
    }
    mEditToResultMs = double(mSinceEdit.nsecsElapsed()) * 1e-6;
    mEditToScreenMs = 0.0;
    mResultEdit = mSinceEdit;
    mAwaitingScreen = true;
    Q_EMIT finished();
}

void SpeciesPreview::markShown() {
    if (!mAwaitingScreen) return;
    mAwaitingScreen = false;
    mEditToScreenMs = double(mResultEdit.nsecsElapsed()) * 1e-6;
    Q_EMIT shown(mEditToScreenMs);
}

std::map<std::string, std::size_t> SpeciesPreview::evaluationCounts() const {
    std::map<std::string, std::size_t> out;
    for (const auto& [id, run] : mResult.runs)
        out[id] = run.evaluations;
    return out;
}

} // namespace sylva::ui
