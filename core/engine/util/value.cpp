#include "engine/util/value.h"

#include "engine/util/error.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <string_view>

namespace sylva {

namespace {

const char* typeName(const Value& v) {
    if (v.isNull()) return "null";
    if (v.isBool()) return "a boolean";
    if (v.isNumber()) return "a number";
    if (v.isString()) return "a string";
    if (v.isArray()) return "an array";
    return "an object";
}

[[noreturn]] void wrongType(const std::string& what, const char* expected, const Value& v) {
    throw InvalidInput(what + " must be " + expected + ", got " + typeName(v));
}

void appendNumber(std::string& out, double d) {
    if (!std::isfinite(d)) {
        out += "null"; // JSON has no inf/nan; the validators reject them before this point
        return;
    }
    char buf[32];
    auto res = std::to_chars(buf, buf + sizeof buf, d);
    out.append(buf, res.ptr);
}

void appendString(std::string& out, const std::string& s) {
    out += '"';
    for (unsigned char c : s) {
        switch (c) {
        case '"':
            out += "\\\"";
            break;
        case '\\':
            out += "\\\\";
            break;
        case '\n':
            out += "\\n";
            break;
        case '\r':
            out += "\\r";
            break;
        case '\t':
            out += "\\t";
            break;
        default:
            if (c < 0x20) {
                char buf[8];
                std::snprintf(buf, sizeof buf, "\\u%04x", c);
                out += buf;
            } else {
                out += static_cast<char>(c);
            }
        }
    }
    out += '"';
}

void appendJson(std::string& out, const Value& v) {
    if (v.isNull()) {
        out += "null";
    } else if (v.isBool()) {
        out += v.toBool() ? "true" : "false";
    } else if (v.isNumber()) {
        appendNumber(out, v.toNumber());
    } else if (v.isString()) {
        appendString(out, v.toString());
    } else if (v.isArray()) {
        out += '[';
        bool first = true;
        for (const Value& e : v.toArray()) {
            if (!first) out += ',';
            first = false;
            appendJson(out, e);
        }
        out += ']';
    } else {
        out += '{';
        bool first = true;
        for (const auto& [k, e] : v.toObject()) {
            if (!first) out += ',';
            first = false;
            appendString(out, k);
            out += ':';
            appendJson(out, e);
        }
        out += '}';
    }
}

bool isFlat(const Value& v) {
    if (!v.isArray()) return false;
    for (const Value& e : v.toArray())
        if (e.isArray() || e.isObject()) return false;
    return true;
}

void appendPretty(std::string& out, const Value& v, int depth) {
    const std::string pad(static_cast<std::size_t>(depth + 1) * 2, ' ');
    const std::string closePad(static_cast<std::size_t>(depth) * 2, ' ');
    if (v.isArray() && !v.toArray().empty() && !isFlat(v)) {
        out += "[\n";
        bool first = true;
        for (const Value& e : v.toArray()) {
            if (!first) out += ",\n";
            first = false;
            out += pad;
            appendPretty(out, e, depth + 1);
        }
        out += "\n" + closePad + "]";
    } else if (v.isObject() && !v.toObject().empty()) {
        out += "{\n";
        bool first = true;
        for (const auto& [k, e] : v.toObject()) {
            if (!first) out += ",\n";
            first = false;
            out += pad;
            appendString(out, k);
            out += ": ";
            appendPretty(out, e, depth + 1);
        }
        out += "\n" + closePad + "}";
    } else {
        appendJson(out, v);
    }
}

/// Recursive-descent JSON parser that tracks line and column for its diagnostics.
class JsonParser {
public:
    JsonParser(const std::string& text, const std::string& file) : mText(text), mFile(file) {}

    Value parseDocument() {
        skipSpace();
        Value v = parseValue(0);
        skipSpace();
        if (mPos != mText.size()) fail("unexpected text after the JSON value");
        return v;
    }

private:
    [[noreturn]] void fail(const std::string& message) const {
        int line = 1, column = 1;
        for (std::size_t i = 0; i < mPos && i < mText.size(); ++i) {
            if (mText[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        throw InvalidInput(std::vector<Diagnostic>{{mFile, line, column, message}});
    }

    void skipSpace() {
        while (mPos < mText.size() && std::strchr(" \t\r\n", mText[mPos]) && mText[mPos] != 0)
            ++mPos;
    }

    bool consume(const char* word) {
        const std::size_t n = std::strlen(word);
        if (mText.compare(mPos, n, word) == 0) {
            mPos += n;
            return true;
        }
        return false;
    }

    Value parseValue(int depth) {
        if (depth > 256) fail("JSON nested too deeply");
        if (mPos >= mText.size()) fail("unexpected end of JSON");
        const char c = mText[mPos];
        if (c == '{') return parseObject(depth);
        if (c == '[') return parseArray(depth);
        if (c == '"') return Value(parseString());
        if (consume("true")) return Value(true);
        if (consume("false")) return Value(false);
        if (consume("null")) return Value();
        if (c == '-' || (c >= '0' && c <= '9')) return Value(parseNumber());
        fail(std::string("unexpected character '") + c + "'");
    }

    Value parseObject(int depth) {
        ++mPos; // {
        Value::Object obj;
        skipSpace();
        if (mPos < mText.size() && mText[mPos] == '}') {
            ++mPos;
            return Value(std::move(obj));
        }
        for (;;) {
            skipSpace();
            if (mPos >= mText.size() || mText[mPos] != '"') fail("expected a quoted key");
            const std::size_t keyPos = mPos;
            std::string key = parseString();
            if (obj.count(key)) {
                mPos = keyPos;
                fail("duplicate key \"" + key + "\"");
            }
            skipSpace();
            if (mPos >= mText.size() || mText[mPos] != ':') fail("expected ':' after a key");
            ++mPos;
            skipSpace();
            obj.emplace(std::move(key), parseValue(depth + 1));
            skipSpace();
            if (mPos < mText.size() && mText[mPos] == ',') {
                ++mPos;
                continue;
            }
            if (mPos < mText.size() && mText[mPos] == '}') {
                ++mPos;
                return Value(std::move(obj));
            }
            fail("expected ',' or '}' in an object");
        }
    }

    Value parseArray(int depth) {
        ++mPos; // [
        Value::Array arr;
        skipSpace();
        if (mPos < mText.size() && mText[mPos] == ']') {
            ++mPos;
            return Value(std::move(arr));
        }
        for (;;) {
            skipSpace();
            arr.push_back(parseValue(depth + 1));
            skipSpace();
            if (mPos < mText.size() && mText[mPos] == ',') {
                ++mPos;
                continue;
            }
            if (mPos < mText.size() && mText[mPos] == ']') {
                ++mPos;
                return Value(std::move(arr));
            }
            fail("expected ',' or ']' in an array");
        }
    }

    static void appendUtf8(std::string& out, unsigned cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }

    unsigned parseHex4() {
        if (mPos + 4 > mText.size()) fail("incomplete \\u escape");
        unsigned v = 0;
        auto res = std::from_chars(mText.data() + mPos, mText.data() + mPos + 4, v, 16);
        if (res.ptr != mText.data() + mPos + 4) fail("bad \\u escape");
        mPos += 4;
        return v;
    }

    std::string parseString() {
        ++mPos; // opening quote
        std::string out;
        while (mPos < mText.size()) {
            const char c = mText[mPos++];
            if (c == '"') return out;
            if (static_cast<unsigned char>(c) < 0x20) {
                --mPos;
                fail("control character in a string");
            }
            if (c != '\\') {
                out += c;
                continue;
            }
            if (mPos >= mText.size()) break;
            const char e = mText[mPos++];
            switch (e) {
            case '"':
                out += '"';
                break;
            case '\\':
                out += '\\';
                break;
            case '/':
                out += '/';
                break;
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'n':
                out += '\n';
                break;
            case 'r':
                out += '\r';
                break;
            case 't':
                out += '\t';
                break;
            case 'u': {
                unsigned cp = parseHex4();
                if (cp >= 0xD800 && cp < 0xDC00 && mText.compare(mPos, 2, "\\u") == 0) {
                    mPos += 2;
                    const unsigned lo = parseHex4();
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
                }
                appendUtf8(out, cp);
                break;
            }
            default:
                --mPos;
                fail(std::string("unknown escape '\\") + e + "'");
            }
        }
        fail("unterminated string");
    }

    double parseNumber() {
        const std::size_t start = mPos;
        if (mText[mPos] == '-') ++mPos;
        while (mPos < mText.size() && std::strchr("0123456789.eE+-", mText[mPos]) &&
               mText[mPos] != 0)
            ++mPos;
        double d = 0;
        auto res = std::from_chars(mText.data() + start, mText.data() + mPos, d);
        if (res.ec != std::errc() || res.ptr != mText.data() + mPos ||
            !isJsonNumber(std::string_view(mText).substr(start, mPos - start))) {
            const std::string token = mText.substr(start, mPos - start);
            mPos = start;
            if (res.ec == std::errc::result_out_of_range)
                fail("number '" + token + "' is out of range (magnitudes up to 1.8e308)");
            fail("malformed number '" + token +
                 "' (JSON numbers are like 12, -0.5 or 3e-4: no leading zeros, digits on both "
                 "sides of '.')");
        }
        return d;
    }

    // JSON's number grammar: -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
    static bool isJsonNumber(std::string_view t) {
        std::size_t i = 0;
        auto digits = [&] {
            const std::size_t from = i;
            while (i < t.size() && t[i] >= '0' && t[i] <= '9')
                ++i;
            return i - from;
        };
        if (i < t.size() && t[i] == '-') ++i;
        if (i < t.size() && t[i] == '0')
            ++i;
        else if (digits() == 0)
            return false;
        if (i < t.size() && t[i] == '.') {
            ++i;
            if (digits() == 0) return false;
        }
        if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
            ++i;
            if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
            if (digits() == 0) return false;
        }
        return i == t.size();
    }

    const std::string& mText;
    const std::string& mFile;
    std::size_t mPos = 0;
};

} // namespace

bool Value::toBool(const std::string& what) const {
    if (!isBool()) wrongType(what, "true or false", *this);
    return std::get<bool>(mData);
}

double Value::toNumber(const std::string& what) const {
    if (!isNumber()) wrongType(what, "a number", *this);
    return std::get<double>(mData);
}

const std::string& Value::toString(const std::string& what) const {
    if (!isString()) wrongType(what, "a string", *this);
    return std::get<std::string>(mData);
}

const Value::Array& Value::toArray(const std::string& what) const {
    if (!isArray()) wrongType(what, "an array", *this);
    return std::get<Array>(mData);
}

const Value::Object& Value::toObject(const std::string& what) const {
    if (!isObject()) wrongType(what, "an object", *this);
    return std::get<Object>(mData);
}

Value::Object& Value::objectRef() {
    if (isNull()) mData = Object{};
    if (!isObject()) wrongType("value", "an object", *this);
    return std::get<Object>(mData);
}

Value::Array& Value::arrayRef() {
    if (isNull()) mData = Array{};
    if (!isArray()) wrongType("value", "an array", *this);
    return std::get<Array>(mData);
}

const Value* Value::find(const std::string& key) const {
    if (!isObject()) return nullptr;
    const Object& o = std::get<Object>(mData);
    auto it = o.find(key);
    return it == o.end() ? nullptr : &it->second;
}

double Value::number(const std::string& key, double fallback) const {
    const Value* v = find(key);
    if (!v || v->isNull()) return fallback;
    const double d = v->toNumber(key);
    if (!std::isfinite(d)) throw InvalidInput(key + " must be a finite number");
    return d;
}

std::int64_t Value::integer(const std::string& key, std::int64_t fallback) const {
    const Value* v = find(key);
    if (!v || v->isNull()) return fallback;
    const double d = v->toNumber(key);
    if (!std::isfinite(d) || d != std::floor(d) || std::fabs(d) > 9.0e15)
        throw InvalidInput(key + " must be a whole number");
    return static_cast<std::int64_t>(d);
}

bool Value::boolean(const std::string& key, bool fallback) const {
    const Value* v = find(key);
    if (!v || v->isNull()) return fallback;
    return v->toBool(key);
}

std::string Value::string(const std::string& key, const std::string& fallback) const {
    const Value* v = find(key);
    if (!v || v->isNull()) return fallback;
    return v->toString(key);
}

std::string Value::toJson() const {
    std::string out;
    appendJson(out, *this);
    return out;
}

std::string Value::toPrettyJson() const {
    std::string out;
    appendPretty(out, *this, 0);
    return out;
}

Value Value::parseJson(const std::string& text, const std::string& fileName) {
    return JsonParser(text, fileName).parseDocument();
}

Value Value::parseLoose(const std::string& text) {
    try {
        return parseJson(text);
    } catch (const InvalidInput&) {
        return Value(text);
    }
}

std::uint64_t Value::hash() const {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : toJson()) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

} // namespace sylva
