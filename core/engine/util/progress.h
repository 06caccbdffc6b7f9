#pragma once

#include <string_view>

#include "engine/util/error.h"

namespace sylva {

/// The one interface through which every stage reports progress and learns that it should stop.
/// The editor implements it over a QFuture/QPromise, the CLI over a progress bar and SIGINT.
class Progress {
public:
    virtual ~Progress() = default;
    /// \param fraction 0..1 of the current stage; \param stage a short name ("expand", "mesh").
    virtual void report(double fraction, std::string_view stage) {
        (void)fraction;
        (void)stage;
    }
    virtual bool isCancelled() const { return false; }
    /// Throws Cancelled if the caller asked to stop. Call it at coarse intervals.
    void checkCancelled() const {
        if (isCancelled()) throw Cancelled();
    }
};

/// A Progress that reports nothing and never cancels.
inline Progress& noProgress() {
    static Progress instance;
    return instance;
}

} // namespace sylva
