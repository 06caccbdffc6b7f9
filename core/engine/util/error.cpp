#include "engine/util/error.h"

#include <cmath>
#include <sstream>

namespace sylva {

std::string Diagnostic::format() const {
    std::string out = file.empty() ? std::string("<input>") : file;
    if (line > 0) {
        out += ':' + std::to_string(line);
        if (column > 0) out += ':' + std::to_string(column);
    }
    out += ": error: ";
    out += message;
    return out;
}

namespace {
std::string joinDiagnostics(const std::vector<Diagnostic>& diagnostics) {
    std::string out;
    for (const Diagnostic& d : diagnostics) {
        if (!out.empty()) out += '\n';
        out += d.format();
    }
    return out.empty() ? std::string("invalid input") : out;
}
} // namespace

InvalidInput::InvalidInput(const std::string& message) : std::invalid_argument(message) {}

InvalidInput::InvalidInput(std::vector<Diagnostic> diagnostics)
    : std::invalid_argument(joinDiagnostics(diagnostics)), mDiagnostics(std::move(diagnostics)) {}

void requireRange(const char* name, double value, double lo, double hi) {
    if (std::isfinite(value) && value >= lo && value <= hi) return;
    std::ostringstream s;
    s << name << " must be in [" << lo << ", " << hi << "], got " << value;
    throw InvalidInput(s.str());
}

} // namespace sylva
