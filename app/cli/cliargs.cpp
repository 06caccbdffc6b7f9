#include "cliargs.h"

#include <algorithm>
#include <charconv>

namespace sylva::cli {

Args::Args(const std::vector<std::string>& argv, const std::vector<std::string>& valueOptions,
           const std::vector<std::string>& flags) {
    auto isIn = [](const std::vector<std::string>& list, const std::string& s) {
        return std::find(list.begin(), list.end(), s) != list.end();
    };
    // Help wins over any other mistake on the line, as in most tools.
    for (std::size_t i = 0; i < argv.size(); ++i) {
        if (argv[i] == "--help" || argv[i] == "-h") throw HelpRequested();
        if (isIn(valueOptions, argv[i])) ++i; // its value may be anything, even "-h"
    }
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        if (a.size() < 2 || a[0] != '-' || (a[1] >= '0' && a[1] <= '9')) {
            mPositional.push_back(a);
            continue;
        }
        std::string name = a, value;
        bool hasValue = false;
        if (auto eq = a.find('='); eq != std::string::npos && a.rfind("--", 0) == 0) {
            name = a.substr(0, eq);
            value = a.substr(eq + 1);
            hasValue = true;
        }
        if (isIn(flags, name) && !hasValue) {
            mOptions.emplace_back(name, "");
        } else if (isIn(valueOptions, name)) {
            if (!hasValue) {
                if (i + 1 >= argv.size()) throw UsageError("option " + name + " needs a value");
                value = argv[++i];
            }
            mOptions.emplace_back(name, value);
        } else {
            throw UsageError("unknown option " + a);
        }
    }
}

bool Args::flag(const std::string& name) const {
    return std::any_of(mOptions.begin(), mOptions.end(), [&](auto& o) { return o.first == name; });
}

std::optional<std::string> Args::value(const std::string& name) const {
    std::optional<std::string> out;
    for (const auto& [k, v] : mOptions)
        if (k == name) out = v; // the last one wins, as in most tools
    return out;
}

std::vector<std::string> Args::values(const std::string& name) const {
    std::vector<std::string> out;
    for (const auto& [k, v] : mOptions)
        if (k == name) out.push_back(v);
    return out;
}

std::optional<long long> Args::integer(const std::string& name, long long lo, long long hi) const {
    const auto text = value(name);
    if (!text) return std::nullopt;
    long long v = 0;
    auto res = std::from_chars(text->data(), text->data() + text->size(), v);
    if (res.ec != std::errc() || res.ptr != text->data() + text->size() || v < lo || v > hi)
        throw UsageError(name + " must be a whole number in [" + std::to_string(lo) + ", " +
                         std::to_string(hi) + "], got '" + *text + "'");
    return v;
}

} // namespace sylva::cli
