#include "engine/environment/fbxcheck.h"

#include "engine/environment/scenegraphwalk.h"
#include "engine/util/error.h"

#include <cstddef>
#include <cstring>
#include <map>
#include <optional>
#include <vector>

namespace sylva::env {
namespace {

/// What the check needs of an FBX file: its models' ids and its connections.
struct FbxLinks {
    std::vector<std::uint64_t> models;
    struct Connection {
        bool property = false; // "OP": an object-property link, which the converter ignores
        std::uint64_t child = 0, parent = 0;
    };
    std::vector<Connection> connections;
};

LimitExceeded tooDeep(const std::string& where, const std::string& at) {
    return LimitExceeded(where + "FBX scopes nested more than " + std::to_string(kMaxFbxNesting) +
                         " deep (" + at + "); real files nest a handful");
}

/// An ASCII id as Assimp reads it (strtoul10_64: the leading digits); nullopt on overflow,
/// which Assimp refuses.
std::optional<std::uint64_t> asciiId(std::string_view token) {
    std::uint64_t value = 0;
    for (const char c : token) {
        if (c < '0' || c > '9') break;
        const std::uint64_t digit = static_cast<std::uint64_t>(c - '0');
        if (value > (UINT64_MAX - digit) / 10) return std::nullopt;
        value = value * 10 + digit;
    }
    return value;
}

/// ASCII FBX, tokenised as Assimp's Tokenize() does (text up to the first NUL; `;` comments to
/// the line's end; quoted strings; `{`, `}`, `,`; a token followed by `:` is a key).
FbxLinks readAscii(std::string_view text, const std::string& where) {
    text = text.substr(0, text.find('\0'));
    // Elements, read as the tokens come (a file holds millions of numbers; none is kept): a key,
    // its data, and maybe a scope; `Objects { Model: id, … }` and `Connections { C: "OO",
    // child, parent }` at the top level.
    enum class Kind { Key, Data, Open, Close };
    FbxLinks links;
    std::vector<std::string_view> open; // the keys of the open scopes
    std::string_view key;               // the element being read, if any
    std::vector<std::string_view> data; // its first three data tokens
    std::size_t line = 1;
    auto finish = [&] {
        if (key.empty() || open.size() != 1) return;
        if (open[0] == "Objects" && key == "Model" && !data.empty()) {
            if (const auto id = asciiId(data[0])) links.models.push_back(*id);
        } else if (open[0] == "Connections" && key == "C" && data.size() >= 3) {
            const auto child = asciiId(data[1]), parent = asciiId(data[2]);
            if (child && parent)
                links.connections.push_back({data[0] == "\"OP\"", *child, *parent});
        }
    };
    auto token = [&](Kind kind, std::string_view t) {
        switch (kind) {
        case Kind::Key:
            finish();
            key = t;
            data.clear();
            break;
        case Kind::Data:
            if (!key.empty() && data.size() < 3) data.push_back(t);
            break;
        case Kind::Open:
            finish();
            open.push_back(key);
            if (open.size() > kMaxFbxNesting) throw tooDeep(where, "line " + std::to_string(line));
            key = {};
            data.clear();
            break;
        case Kind::Close:
            finish();
            if (!open.empty()) open.pop_back();
            key = {};
            data.clear();
            break;
        }
    };
    const auto lineEnd = [](char c) { return c == '\r' || c == '\n' || c == '\f'; };
    const auto space = [&](char c) { return c == ' ' || c == '\t' || c == '\v' || lineEnd(c); };
    std::size_t begin = std::string_view::npos;
    auto flush = [&](std::size_t end, Kind kind) {
        if (begin != std::string_view::npos) token(kind, text.substr(begin, end - begin));
        begin = std::string_view::npos;
    };
    bool comment = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') ++line;
        if (lineEnd(c)) comment = false;
        if (comment) continue;
        if (c == '"') { // a quoted token, to the next quote (Assimp refuses one mid-token)
            flush(i, Kind::Data);
            const std::size_t close = text.find('"', i + 1);
            const std::size_t end = close == std::string_view::npos ? text.size() : close + 1;
            for (std::size_t k = i; k < end; ++k)
                line += text[k] == '\n';
            token(Kind::Data, text.substr(i, end - i));
            i = end - 1;
            continue;
        }
        if (c == ';') {
            flush(i, Kind::Data);
            comment = true;
        } else if (c == '{' || c == '}') {
            flush(i, Kind::Data);
            token(c == '{' ? Kind::Open : Kind::Close, text.substr(i, 1));
        } else if (c == ',') {
            flush(i, Kind::Data);
        } else if (c == ':') {
            flush(i, Kind::Key);
        } else if (space(c)) {
            if (begin == std::string_view::npos) continue;
            const std::size_t end = i;
            std::size_t peek = i;
            while (peek < text.size() && space(text[peek]))
                ++peek;
            if (peek < text.size() && text[peek] == ':') { // "Key :" is a key too
                for (std::size_t k = i; k < peek; ++k)
                    line += text[k] == '\n';
                i = peek;
                flush(end, Kind::Key);
            } else {
                flush(end, Kind::Data);
            }
        } else if (begin == std::string_view::npos) {
            begin = i;
        }
    }
    flush(text.size(), Kind::Data);
    finish();
    return links;
}

/// Binary FBX, its records read as Assimp's TokenizeBinary() reads them, but without recursion.
FbxLinks readBinary(std::string_view bytes, const std::string& where) {
    auto malformed = [&](std::size_t at, const std::string& what) {
        return InvalidInput(where + "binary FBX record at byte " + std::to_string(at) + ": " +
                            what);
    };
    if (bytes.size() < 27) throw malformed(0, "the file is too short");
    std::uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 23, 4);
    const bool wide = version >= 7500;
    const std::size_t word = wide ? 8 : 4;
    const std::size_t sentinel = 3 * word + 1;
    auto read = [&](std::size_t& at, std::size_t size, std::size_t limit) {
        if (at + size > limit) throw malformed(at, "reads past the end of its scope");
        std::uint64_t v = 0;
        std::memcpy(&v, bytes.data() + at, size); // little-endian, as FBX
        at += size;
        return v;
    };
    struct Scope {
        std::string name;
        std::size_t end;      // the record's end
        std::size_t children; // where its children end (its null record starts)
    };
    std::vector<Scope> open;
    FbxLinks links;
    std::size_t at = 27;
    for (;;) {
        // Close the scopes whose children are all read: a null record, then the scope's end.
        while (!open.empty() && at >= open.back().children) {
            if (at != open.back().children) throw malformed(at, "overruns its parent's end");
            for (std::size_t k = 0; k < sentinel; ++k)
                if (bytes[at + k] != '\0')
                    throw malformed(at, "the null record that closes a list is not null");
            at += sentinel;
            open.pop_back();
        }
        const std::size_t limit = open.empty() ? bytes.size() : open.back().children;
        if (at >= limit) break;
        const std::size_t start = at;
        const std::uint64_t end = read(at, word, limit);
        if (end == 0) {
            if (open.empty()) break; // the footer
            throw malformed(start, "a null record inside a list");
        }
        if (end > limit) throw malformed(start, "ends past its parent or the file");
        if (end < at) throw malformed(start, "ends before it starts");
        const std::uint64_t count = read(at, word, limit);
        const std::uint64_t length = read(at, word, limit);
        const std::size_t nameLength = read(at, 1, limit);
        if (at + nameLength > limit) throw malformed(start, "its name runs past the end");
        std::string name(bytes.substr(at, nameLength));
        at += nameLength;
        const std::size_t properties = at;
        if (length > end - properties) throw malformed(start, "its properties run past its end");
        // Models in Objects, connections in Connections: their first properties.
        if (open.size() == 1) {
            std::size_t p = properties;
            const std::size_t pend = properties + length;
            auto type = [&](char t) { return p < pend && bytes[p] == t; };
            if (open[0].name == "Objects" && name == "Model" && count >= 1 && type('L') &&
                p + 9 <= pend) {
                ++p;
                links.models.push_back(read(p, 8, pend));
            } else if (open[0].name == "Connections" && name == "C" && count >= 3 && type('S') &&
                       p + 5 <= pend) {
                ++p;
                const std::size_t n = read(p, 4, pend);
                if (n <= pend - p) {
                    const std::string_view kind = bytes.substr(p, n);
                    p += n;
                    if (type('L') && p + 9 <= pend) {
                        ++p;
                        const std::uint64_t child = read(p, 8, pend);
                        if (type('L') && p + 9 <= pend) {
                            ++p;
                            links.connections.push_back({kind == "OP", child, read(p, 8, pend)});
                        }
                    }
                }
            }
        }
        at = properties + length;
        if (at < end) { // children, then the null record
            if (end - at < sentinel)
                throw malformed(start, "too short for the null record that closes its list");
            open.push_back({std::move(name), end, end - sentinel});
            if (open.size() > kMaxFbxNesting) throw tooDeep(where, "byte " + std::to_string(start));
        } else if (at != end) {
            throw malformed(start, "its length does not match its properties");
        }
    }
    return links;
}

} // namespace

void checkFbx(std::string_view bytes, const std::string& where) {
    const bool binary = bytes.substr(0, 18) == "Kaydara FBX Binary";
    const FbxLinks links = binary ? readBinary(bytes, where) : readAscii(bytes, where);
    // The converter starts at the root (id 0) and copies every model linked to a node under it.
    std::map<std::uint64_t, std::size_t> index{{0, 0}};
    for (const std::uint64_t id : links.models)
        index.emplace(id, index.size());
    std::vector<std::uint64_t> ids(index.size());
    for (const auto& [id, n] : index)
        ids[n] = id;
    std::vector<std::vector<std::size_t>> next(index.size());
    for (const FbxLinks::Connection& c : links.connections) {
        if (c.property || c.child == 0) continue;
        const auto child = index.find(c.child), parent = index.find(c.parent);
        if (child == index.end() || parent == index.end()) continue; // not a model: not followed
        next[parent->second].push_back(child->second);
    }
    throwSceneGraphProblem(
        walkSceneGraph(next, {0}), where,
        [&](std::size_t n) {
            return n == 0 ? std::string("the FBX scene's root")
                          : "FBX model " + std::to_string(ids[n]);
        },
        "the models with several parents are copied under each");
}

} // namespace sylva::env
