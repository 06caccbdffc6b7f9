#pragma once

#include <atomic>
#include <chrono>
#include <string>

#include "engine/util/progress.h"

namespace sylva::cli {

/// A progress bar on stderr when stderr is a terminal (silent otherwise), and Ctrl-C handling:
/// the first SIGINT asks the running stage to stop at its next check (isCancelled()), so the
/// engine unwinds, temporaries are removed and no half-written file is left behind.
class TerminalProgress : public Progress {
public:
    TerminalProgress();
    ~TerminalProgress() override;
    void report(double fraction, std::string_view stage) override;
    bool isCancelled() const override;
    /// Ends the bar's line.
    void finish();

private:
    bool mTerminal = false;
    int mLastPercent = -1;
    std::chrono::steady_clock::time_point mStart;
};

/// Exit status of a run stopped by Ctrl-C (128 + SIGINT, as shells report it).
inline constexpr int kInterrupted = 130;

} // namespace sylva::cli
