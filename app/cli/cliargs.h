#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace sylva::cli {

/// Exit statuses: documented in docs/cli.md.
enum ExitCode { kOk = 0, kBadInput = 1, kBadUsage = 2 };

/// Wrong command-line usage (unknown option, missing value): exit status 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// `--help` or `-h` among a command's options: main() prints that command's help, exit status 0.
class HelpRequested {};

/// A tiny argument reader: positional arguments plus options that may repeat.
class Args {
public:
    /// \p valueOptions take a value ("-o out.obj" or "--seed=3"); \p flags take none.
    /// \throw HelpRequested when `--help` or `-h` is an option (not another option's value),
    /// wherever it is; UsageError for an unknown option or a missing value.
    Args(const std::vector<std::string>& argv, const std::vector<std::string>& valueOptions,
         const std::vector<std::string>& flags);

    const std::vector<std::string>& positional() const { return mPositional; }
    bool flag(const std::string& name) const;
    std::optional<std::string> value(const std::string& name) const;
    std::vector<std::string> values(const std::string& name) const;
    std::optional<long long> integer(const std::string& name, long long lo, long long hi) const;

private:
    std::vector<std::string> mPositional;
    std::vector<std::pair<std::string, std::string>> mOptions;
};

} // namespace sylva::cli
