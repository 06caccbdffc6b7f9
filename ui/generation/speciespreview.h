#pragma once

#include <atomic>
#include <map>
#include <memory>
#include <string>

#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include "document/document.h"
#include "engine/graph/graph.h"
#include "ui/generation/vertexdata.h"

namespace sylva::ui {

/// One preview evaluation of a species: its mesh and what each node did.
struct PreviewResult {
    QString species;
    std::shared_ptr<const mesh::Mesh> mesh;
    /// The mesh's vertices as the viewport uploads them (ui/generation/vertexdata.h), made on the
    /// worker.
    std::shared_ptr<const std::vector<ViewVertex>> vertices;
    std::shared_ptr<const skel::Skeleton> skeleton;
    std::map<std::string, graph::Evaluator::NodeRun> runs; ///< per node: time, ran, error
    std::map<std::string, double> stats;
    QString error;           ///< user-facing message; empty on success
    QString errorNode;       ///< the node that failed, when one did
    double evaluateMs = 0.0; ///< the evaluation alone (worker)
    bool cancelled = false;
    std::shared_ptr<graph::Evaluator> evaluator; ///< internal: handed back to the GUI thread
};

/// The species editor's live preview: one long-lived Evaluator per species keeps every node's
/// result, so an edit re-evaluates only the node it touched and what is downstream of it. It runs
/// off the GUI thread; a newer edit cancels an older one (newest wins). The time from the edit
/// to the new mesh on screen is measured by the caller (editToScreenMs()) once it has drawn it.
class SpeciesPreview : public QObject {
    Q_OBJECT

public:
    explicit SpeciesPreview(doc::Document& document, QObject* parent = nullptr);
    ~SpeciesPreview() override;

    /// The species to preview ("" for none); evaluates it at once.
    void setSpecies(const QString& species);
    const QString& species() const { return mSpecies; }
    /// An inactive preview (its editor is hidden) evaluates nothing; activating it catches up.
    void setActive(bool active);
    bool isActive() const { return mActive; }
    /// Seed of the previewed tree.
    void setSeed(std::uint64_t seed);
    /// A preview-only parameter (the grammar editor's generations slider): \p node's \p key
    /// is \p value in the preview, not in the document. A null value removes it.
    void setOverride(const QString& node, const std::string& key, const sylva::Value& value);
    /// Evaluates the species' current graph (after an edit); newest wins.
    void refresh();
    bool isBusy() const { return mRunning || mPending; }
    const PreviewResult& result() const { return mResult; }
    /// The last preview failed (result().error): it has no edit → result or screen time.
    bool failed() const { return !mResult.error.isEmpty(); }
    /// Milliseconds from the edit behind result() to its arrival on the GUI thread.
    double editToResultMs() const { return mEditToResultMs; }
    /// Called by the view once the result is on screen: the edit → mesh-on-screen time.
    void markShown();
    double editToScreenMs() const { return mEditToScreenMs; }
    /// Evaluations (cache misses) per node of the current species, since it was first previewed.
    std::map<std::string, std::size_t> evaluationCounts() const;

Q_SIGNALS:
    void started();
    /// A preview evaluation ended (ok or with an error in result()); not for a superseded one.
    void finished();
    /// Emitted by markShown() with the edit → screen time.
    void shown(double ms);

private:
    struct Job;
    void start();
    void onFinished();

    doc::Document& mDocument;
    QString mSpecies;
    std::uint64_t mSeed = 1;
    std::map<std::pair<QString, std::string>, sylva::Value> mOverrides;
    /// Evaluators by species name; used by one job at a time (the running one owns it).
    std::map<QString, std::shared_ptr<graph::Evaluator>> mEvaluators;
    QFutureWatcher<PreviewResult> mWatcher;
    std::shared_ptr<std::atomic<bool>> mCancel;
    bool mRunning = false;
    bool mPending = false;
    bool mActive = false;
    QElapsedTimer mSinceEdit, mPendingEdit, mResultEdit;
    PreviewResult mResult;
    double mEditToResultMs = 0.0;
    double mEditToScreenMs = 0.0;
    bool mAwaitingScreen = false;
};

} // namespace sylva::ui
