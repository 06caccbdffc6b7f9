#pragma once

#include <string>
#include <string_view>

#include <QPromise>
#include <QString>

#include "engine/util/progress.h"
#include "ui/generation/treegenerator.h"

namespace sylva::ui {

/// Bridges the engine's Progress to a QPromise: the UI sees stage names, and cancelling the
/// future stops the engine at its next checkCancelled().
class PromiseProgress : public Progress {
public:
    explicit PromiseProgress(QPromise<GenerationResult>& promise) : mPromise(promise) {}

    void report(double fraction, std::string_view stage) override {
        (void)fraction;
        // Stages report often; only a new stage name is worth a cross-thread signal.
        if (stage == mStage) return;
        mStage.assign(stage);
        mPromise.setProgressValueAndText(++mTicks,
                                         QString::fromUtf8(stage.data(), qsizetype(stage.size())));
    }
    bool isCancelled() const override { return mPromise.isCanceled(); }

private:
    QPromise<GenerationResult>& mPromise;
    std::string mStage;
    int mTicks = 0;
};

} // namespace sylva::ui
