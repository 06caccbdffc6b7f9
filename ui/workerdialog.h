#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <string_view>

#include <QPointer>
#include <QProgressDialog>
#include <QString>

#include "engine/util/progress.h"

namespace sylva::ui {

/// The worker's Progress for runWithProgress(): the percentage the GUI polls (a stage's fraction
/// mapped by the caller's share of the time) and the dialog's Cancel as the flag the engine
/// checks.
class DialogProgress : public Progress {
public:
    /// \p percentOf maps (fraction, stage) to 0..100, or -1 for a stage it does not count.
    explicit DialogProgress(std::function<int(double, std::string_view)> percentOf)
        : mPercentOf(std::move(percentOf)) {}
    void report(double fraction, std::string_view stage) override {
        const int v = mPercentOf ? mPercentOf(fraction, stage) : -1;
        if (v > mPercent.load()) mPercent.store(v);
    }
    bool isCancelled() const override { return mCancel.load(); }
    int percent() const { return mPercent.load(); }
    void cancel() { mCancel.store(true); }

private:
    std::function<int(double, std::string_view)> mPercentOf;
    std::atomic<int> mPercent{0};
    std::atomic<bool> mCancel{false};
};

/// How runWithProgress() ended: the job's exception (none when it succeeded), and whether the
/// user pressed Cancel.
struct WorkerOutcome {
    std::exception_ptr error;
    bool cancelled = false;
};

/// Runs \p job on a worker thread (a plain thread: the engine's exceptions come back as they
/// are) while a window-modal progress dialog over \p parent shows \p progress and offers
/// Cancel; the event loop runs meanwhile, and the job is joined before this returns, cancelled
/// or not. \p dialog holds the dialog while it is shown (tests press its Cancel).
WorkerOutcome runWithProgress(QWidget* parent, const QString& title, const QString& label,
                              const QString& objectName, DialogProgress& progress,
                              const std::function<void(Progress&)>& job,
                              QPointer<QProgressDialog>& dialog);

} // namespace sylva::ui
