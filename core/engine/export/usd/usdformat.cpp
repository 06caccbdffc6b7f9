#include "engine/export/usd/usdformat.h"

#include "engine/export/obj/objwriter.h"

#include <charconv>

#include <glm/gtc/packing.hpp>

namespace sylva::exporter::usd {

std::string primName(std::string_view name) {
    std::string out;
    out.reserve(name.size() + 1);
    for (char c : name) {
        const auto u = static_cast<unsigned char>(c);
        const bool ok =
            (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z') || (u >= '0' && u <= '9') || u == '_';
        out += ok ? c : '_';
    }
    if (out.empty() || (out[0] >= '0' && out[0] <= '9')) out.insert(out.begin(), '_');
    return out;
}

std::string usdString(std::string_view text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (static_cast<unsigned char>(c) >= 0x20) {
            out += c;
        }
    }
    return out + '"';
}

void appendFloat(std::string& out, float value) {
    char buf[32];
    char* end = std::to_chars(buf, buf + sizeof buf, value).ptr;
    out.append(buf, end);
}

void appendFixed(std::string& out, double value, int decimals) {
    char buf[48];
    out.append(buf, formatFixed(buf, value, decimals));
}

float toHalf(float value) {
    return glm::unpackHalf1x16(glm::packHalf1x16(value));
}

void appendHalf(std::string& out, float value) {
    const glm::uint16 bits = glm::packHalf1x16(value);
    const float exact = glm::unpackHalf1x16(bits);
    char buf[32];
    // A half has 11 significant bits: 5 significant digits always read back; fewer often do.
    for (int digits = 1; digits <= 5; ++digits) {
        const auto r =
            std::to_chars(buf, buf + sizeof buf, exact, std::chars_format::general, digits);
        float back = 0.0f;
        std::from_chars(buf, r.ptr, back); // locale-independent, unlike strtof
        if (glm::packHalf1x16(back) == bits || digits == 5) {
            out.append(buf, r.ptr);
            return;
        }
    }
}

void appendQuath(std::string& out, const glm::quat& q) {
    out += '(';
    appendHalf(out, q.w);
    out += ',';
    appendHalf(out, q.x);
    out += ',';
    appendHalf(out, q.y);
    out += ',';
    appendHalf(out, q.z);
    out += ')';
}

} // namespace sylva::exporter::usd
