#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace sylva {

/// A message about a position in a user-supplied text (grammar, species, project).
/// Line and column are 1-based; 0 means "unknown / whole file".
struct Diagnostic {
    std::string file;
    int line = 0;
    int column = 0;
    std::string message;

    /// "file:line:col: error: message" (the compiler-style form the CLI prints).
    std::string format() const;
};

/// The input (a grammar, a parameter, a file's content) is wrong; the user can fix it.
/// Carries the individual diagnostics when there are positions to report.
class InvalidInput : public std::invalid_argument {
public:
    explicit InvalidInput(const std::string& message);
    explicit InvalidInput(std::vector<Diagnostic> diagnostics);
    const std::vector<Diagnostic>& diagnostics() const noexcept { return mDiagnostics; }

private:
    std::vector<Diagnostic> mDiagnostics;
};

/// A file could not be read or written.
class IoError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// A documented size limit (symbols, internodes, ...) would be exceeded.
class LimitExceeded : public std::length_error {
public:
    using std::length_error::length_error;
};

/// The caller asked a running stage to stop (Progress::isCancelled()).
class Cancelled : public std::runtime_error {
public:
    Cancelled() : std::runtime_error("cancelled") {}
};

/// Throws InvalidInput "<name> must be in [lo, hi], got <value>" unless lo <= value <= hi
/// and value is finite.
void requireRange(const char* name, double value, double lo, double hi);

} // namespace sylva
