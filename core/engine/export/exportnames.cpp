#include "engine/export/exportnames.h"

#include <cctype>

namespace sylva::exporter {

std::string objectNameFor(const std::string& speciesName) {
    std::string out;
    for (char c : speciesName)
        out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-') ? c : '_';
    return out.empty() ? std::string("tree") : out;
}

std::string fileSafeName(const std::string& name) {
    std::string s = name;
    for (char& c : s) {
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '-' || c == '_';
        if (!ok) c = '_';
    }
    return s;
}

} // namespace sylva::exporter
