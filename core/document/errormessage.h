#pragma once

#include <exception>
#include <string>

namespace sylva::doc {

/// What an exception from the engine or the document means to a user: the one mapping the CLI,
/// the editor and the Python bindings share, so all three say the same thing.
struct ErrorReport {
    enum class Kind { InvalidInput, LimitExceeded, Io, OutOfMemory, Cancelled, Other };
    Kind kind = Kind::Other;
    /// Without a program name. An InvalidInput with diagnostics gives one
    /// "file:line:col: error: message" line per diagnostic.
    std::string message;
};

/// Describes \p error (a current exception); \p context names what was being done for the
/// messages that carry no file of their own ("generating alder.json").
ErrorReport describeError(std::exception_ptr error, const std::string& context = {});

/// The user's message for the exception being handled (inside a catch block): what the
/// editor's action boundaries show.
inline std::string currentErrorMessage() {
    return describeError(std::current_exception()).message;
}

} // namespace sylva::doc
