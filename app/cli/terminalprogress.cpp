#include "terminalprogress.h"

#include <csignal>
#include <cstdio>
#include <unistd.h>

namespace sylva::cli {

namespace {
volatile std::sig_atomic_t gInterrupted = 0;
extern "C" void onInterrupt(int) {
    gInterrupted = 1;
}
} // namespace

TerminalProgress::TerminalProgress()
    : mTerminal(::isatty(STDERR_FILENO) != 0), mStart(std::chrono::steady_clock::now()) {
    gInterrupted = 0;
    std::signal(SIGINT, onInterrupt);
    std::signal(SIGTERM, onInterrupt);
}

TerminalProgress::~TerminalProgress() {
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
}

bool TerminalProgress::isCancelled() const {
    return gInterrupted != 0;
}

void TerminalProgress::report(double fraction, std::string_view stage) {
    if (!mTerminal) return;
    const int percent = static_cast<int>(fraction * 100.0 + 0.5);
    if (percent == mLastPercent) return;
    mLastPercent = percent;
    const int width = 40;
    const int filled = percent * width / 100;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - mStart).count();
    std::string bar(static_cast<std::size_t>(filled), '#');
    bar.append(static_cast<std::size_t>(width - filled), '.');
    std::fprintf(stderr, "\r%-8.*s [%s] %3d%%  %.1f s", static_cast<int>(stage.size()),
                 stage.data(), bar.c_str(), percent, seconds);
    std::fflush(stderr);
}

void TerminalProgress::finish() {
    if (mTerminal && mLastPercent >= 0) std::fputc('\n', stderr);
    mLastPercent = -1;
}

} // namespace sylva::cli
