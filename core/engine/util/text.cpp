#include "engine/util/text.h"

#include <charconv>

namespace sylva {

std::string lowerAscii(std::string text) {
    for (char& ch : text)
        if (ch >= 'A' && ch <= 'Z') ch = static_cast<char>(ch - 'A' + 'a');
    return text;
}

std::string shortestDecimal(double value) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, r.ptr);
}

std::string shortestDecimal(float value) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, r.ptr);
}

double decimalOf(float value) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, value);
    double out = 0.0;
    std::from_chars(buf, r.ptr, out);
    return out;
}

} // namespace sylva
