#include "engine/environment/meshfilecheck.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "engine/environment/fbxcheck.h"
#include "engine/environment/scenegraphwalk.h"
#include "engine/util/error.h"
#include "engine/util/text.h"
#include "engine/util/value.h"

namespace sylva::env {

namespace {

/// The whole file from its start, in one read (a stream iterator takes ~30 ns a byte).
std::string readAll(std::ifstream& in) {
    in.clear();
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0);
    std::string bytes(size > 0 ? static_cast<std::size_t>(size) : 0, '\0');
    in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    bytes.resize(static_cast<std::size_t>(in.gcount()));
    return bytes;
}

constexpr std::size_t kMaxPlyHeaderBytes = 1 << 20;

/// Bytes of a PLY scalar type, 0 for an unknown name.
std::uint64_t plyTypeSize(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" ||
        t == "float32")
        return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::uint64_t minBytes = 0; ///< scalars plus the count of each list (lists may be empty)
    bool hasProperties = false;
};

void checkPly(const std::filesystem::path& file, std::ifstream& in, std::uintmax_t fileSize,
              std::size_t maxItems) {
    const std::string where = "obstacle mesh '" + file.string() + "': cannot read it: PLY ";
    auto fail = [&](const std::string& what) { throw InvalidInput(where + what); };
    std::vector<PlyElement> elements;
    bool binary = false, haveFormat = false;
    std::string line;
    for (int lineNo = 1;; ++lineNo) {
        if (!std::getline(in, line)) fail("header has no end_header line");
        // tellg() fails once getline() reached the end of the file (a last line without '\n').
        const std::uintmax_t read = in.eof() ? fileSize : static_cast<std::uintmax_t>(in.tellg());
        if (read > kMaxPlyHeaderBytes) fail("header is longer than 1 MiB");
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::string at = "header line " + std::to_string(lineNo) + ": ";
        // Assimp also ends a header line at \r, \0 and \f, so such a byte could hide a line from
        // this check (an element inside a comment): a header is text, these bytes are refused.
        for (const char ch : line)
            if (static_cast<unsigned char>(ch) < 0x20 && ch != '\t') {
                char hex[8];
                std::snprintf(hex, sizeof hex, "0x%02x", static_cast<unsigned>(ch));
                fail(at + "holds the control character " + hex + "; the header must be text");
            }
        std::istringstream words(line);
        std::string key, a, b, c, extra;
        words >> key;
        if (lineNo == 1) {
            if (key != "ply" || (words >> extra)) fail("file does not start with a 'ply' line");
        } else if (key == "end_header") {
            break;
        } else if (key == "comment" || key == "obj_info") {
            continue;
        } else if (key == "format") {
            words >> a >> b;
            if (haveFormat || b.empty() ||
                (a != "ascii" && a != "binary_little_endian" && a != "binary_big_endian"))
                fail(at + "expected one 'format ascii|binary_little_endian|binary_big_endian "
                          "1.0' line");
            haveFormat = true;
            binary = a != "ascii";
        } else if (key == "element") {
            words >> a >> b;
            PlyElement e;
            e.name = a;
            const auto res = std::from_chars(b.data(), b.data() + b.size(), e.count);
            if (a.empty() || b.empty() || res.ec != std::errc() || res.ptr != b.data() + b.size())
                fail(at + "expected 'element <name> <count>'");
            if (e.count > maxItems)
                throw LimitExceeded(where + "element '" + e.name + "' declares " + b +
                                    " items, more than the limit of " + std::to_string(maxItems) +
                                    "; decimate the mesh");
            // Assimp sizes its vertex (face) arrays by the first vertex (face or tristrips)
            // element and writes the items of a later one at their index, past the arrays of a
            // smaller first one (fuzz finding 24: heap metadata overwritten).
            const auto faces = [](const std::string& name) {
                return name == "face" || name == "tristrips";
            };
            for (const PlyElement& earlier : elements)
                if ((e.name == "vertex" && earlier.name == "vertex") ||
                    (faces(e.name) && faces(earlier.name)))
                    fail(at + "a second " + (e.name == "vertex" ? "vertex" : "face") +
                         " element ('" + earlier.name + "' came first); a mesh has one " +
                         "vertex element and one face or tristrips element");
            elements.push_back(e);
        } else if (key == "property") {
            if (elements.empty()) fail(at + "a property before any element");
            words >> a >> b;
            if (a == "list") {
                words >> c;
                if (plyTypeSize(b) == 0 || plyTypeSize(c) == 0 || c.empty() || !(words >> extra) ||
                    extra.empty())
                    fail(at + "expected 'property list <count type> <item type> <name>'");
                elements.back().minBytes += plyTypeSize(b);
            } else {
                if (plyTypeSize(a) == 0 || b.empty())
                    fail(at + "expected 'property <type> <name>' with a PLY type");
                elements.back().minBytes += plyTypeSize(a);
            }
            elements.back().hasProperties = true;
        } else {
            fail(at + "unknown header keyword '" + key + "'");
        }
    }
    if (!haveFormat) fail("header has no format line");

    const std::uintmax_t headerBytes =
        in.eof() ? fileSize : static_cast<std::uintmax_t>(in.tellg());
    const std::uintmax_t body = fileSize - headerBytes;
    if (binary) {
        std::uintmax_t need = 0;
        for (const PlyElement& e : elements)
            need += e.count * e.minBytes; // both <= 1e7 * 1e6: no overflow
        if (body < need)
            fail("data is truncated: the header declares at least " + std::to_string(need) +
                 " bytes, the file has " + std::to_string(body));
    } else {
        std::uintmax_t need = 0; // one line per item of an element with properties
        for (const PlyElement& e : elements)
            if (e.hasProperties) need += e.count;
        std::uintmax_t lines = 0;
        for (std::string l; lines < need && std::getline(in, l);)
            if (l.find_first_not_of(" \t\r") != std::string::npos) ++lines;
        if (lines < need)
            fail("data is truncated: the header declares " + std::to_string(need) +
                 " lines of items, the file has " + std::to_string(lines));
    }
}

/// Most values in one vertex of a Collada index list (an `<input>`'s offset is below it).
constexpr std::uint64_t kMaxColladaInputOffsets = 64;

/// Collada accessors (fuzz finding 25): Debian's Assimp 5.2.5 reads an accessor's items
/// (`offset + index × stride + param`) from its data array without comparing them with the
/// array's length: an `offset` mutated to 400000000 read far past it (SEGV), a longer accessor
/// read past the end, and one naming a `Name_array` read its empty number array (SEGV). The
/// element tags are read as XML writes them (quotes of either kind, spaces around `=`), comments
/// skipped. Obstacles are static geometry: skins (`<controller>`) and animations, the only users
/// of name arrays, are refused with the name arrays themselves; every accessor naming a
/// `float_array` of the file must fit in it. The primitives' index lists hold whole numbers only,
/// and each comes after its primitive's VERTEX input (and a polylist's `<vcount>`), as Assimp
/// needs them when it reads the list.
void checkColladaElements(const std::string& text, const std::string& where,
                          const std::function<std::string(std::size_t)>& lineOf,
                          std::uint64_t maxCount) {
    struct Tag {
        std::string name;
        std::vector<std::pair<std::string, std::string>> attributes;
        std::size_t at = 0;  // its '<'
        std::size_t end = 0; // just after its '>'
        bool closing = false, selfClosing = false;
        const std::string* attribute(const char* key) const {
            for (const auto& [k, v] : attributes)
                if (k == key) return &v;
            return nullptr;
        }
    };
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    std::vector<Tag> tags;
    for (std::size_t i = text.find('<'); i != std::string::npos; i = text.find('<', i)) {
        if (text.compare(i, 4, "<!--") == 0) { // comments, and CDATA, hold no elements
            const std::size_t end = text.find("-->", i + 4);
            i = end == std::string::npos ? text.size() : end + 3;
            continue;
        }
        if (text.compare(i, 9, "<![CDATA[") == 0) {
            const std::size_t end = text.find("]]>", i + 9);
            i = end == std::string::npos ? text.size() : end + 3;
            continue;
        }
        Tag tag;
        tag.at = i++;
        if (i < text.size() && text[i] == '/') {
            tag.closing = true;
            ++i;
        }
        while (i < text.size() && !space(text[i]) && text[i] != '>' && text[i] != '/' &&
               text[i] != '<')
            tag.name += text[i++];
        for (;;) { // attributes: name [spaces] = [spaces] 'value' or "value"
            while (i < text.size() && space(text[i]))
                ++i;
            if (i >= text.size() || text[i] == '>' || text[i] == '<') break;
            if (text[i] == '/') {
                tag.selfClosing = true;
                ++i;
                continue;
            }
            std::string key;
            while (i < text.size() && !space(text[i]) && text[i] != '=' && text[i] != '>' &&
                   text[i] != '/' && text[i] != '<')
                key += text[i++];
            while (i < text.size() && space(text[i]))
                ++i;
            if (i >= text.size() || text[i] != '=') {
                if (key.empty()) ++i; // a stray byte
                continue;
            }
            ++i;
            while (i < text.size() && space(text[i]))
                ++i;
            if (i >= text.size() || (text[i] != '"' && text[i] != '\'')) continue;
            const std::size_t close = text.find(text[i], i + 1);
            if (close == std::string::npos) break;
            tag.attributes.emplace_back(key, text.substr(i + 1, close - i - 1));
            i = close + 1;
        }
        tag.end = i < text.size() && text[i] == '>' ? i + 1 : i;
        tags.push_back(std::move(tag));
    }

    // An attribute's value as a whole number from `least` to `most`, or `fallback` when absent.
    auto whole = [&](const Tag& tag, const char* key, std::uint64_t least, std::uint64_t most,
                     std::uint64_t fallback) {
        const std::string* value = tag.attribute(key);
        if (!value) return fallback;
        std::uint64_t n = 0;
        const auto [ptr, ec] = std::from_chars(value->data(), value->data() + value->size(), n);
        if (value->empty() || ec != std::errc() || ptr != value->data() + value->size() ||
            n < least || n > most)
            throw InvalidInput(where + "<" + tag.name + "> at line " + lineOf(tag.at) + ": " + key +
                               "=\"" + value->substr(0, 32) + "\" is not a whole number from " +
                               std::to_string(least) + " to " + std::to_string(most));
        return n;
    };
    std::map<std::string, std::uint64_t> arrays; // float_array id -> its count (the least)
    for (const Tag& tag : tags) {
        if (tag.closing) continue;
        if (tag.name == "controller" || tag.name == "animation" || tag.name == "Name_array" ||
            tag.name == "IDREF_array")
            throw InvalidInput(where + "<" + tag.name + "> at line " + lineOf(tag.at) +
                               ": obstacles are static geometry; export the obstacle without "
                               "its skin and animations");
        if (tag.name == "accessor")
            whole(tag, "count", 1, maxCount, 0); // the scan above read count="…" only
        // An input's offset picks its index in each vertex's tuple of the index list: Assimp
        // reads it as a signed number (-1 read before the list) and reserves the list times
        // (offset + 1) (offset="100000000": out of memory). Exporters use a handful.
        if (tag.name == "input") whole(tag, "offset", 0, kMaxColladaInputOffsets - 1, 0);
        if (tag.name == "float_array") {
            const std::string* id = tag.attribute("id");
            const std::uint64_t count = whole(tag, "count", 1, maxCount, 0);
            const std::string key = id ? *id : std::string();
            const auto [it, fresh] = arrays.emplace(key, count);
            if (!fresh) it->second = std::min(it->second, count);
        }
    }
    // Each accessor with its params (Assimp counts every <param> below it, at any depth).
    std::vector<std::pair<const Tag*, std::uint64_t>> open; // accessors not closed yet
    auto check = [&](const Tag& accessor, std::uint64_t params) {
        const std::string* source = accessor.attribute("source");
        if (!source || source->empty() || (*source)[0] != '#') return; // Assimp refuses it
        const auto array = arrays.find(source->substr(1));
        if (array == arrays.end()) return; // Assimp refuses a source it cannot resolve
        const std::uint64_t count = whole(accessor, "count", 1, maxCount, 0);
        const std::uint64_t offset = whole(accessor, "offset", 0, maxCount, 0);
        const std::uint64_t stride = whole(accessor, "stride", 0, maxCount, 1);
        if (count == 0) return; // Assimp reads no item of it
        // All at most 9·10^7: no overflow in 64 bits.
        const std::uint64_t end =
            offset + (count - 1) * stride + std::max<std::uint64_t>(params, 1);
        if (end > array->second)
            throw InvalidInput(where + "<accessor> at line " + lineOf(accessor.at) + " reads " +
                               std::to_string(end) + " values (offset " + std::to_string(offset) +
                               ", count " + std::to_string(count) + ", stride " +
                               std::to_string(stride) + ", " + std::to_string(params) +
                               " params) from '" + array->first + "', which holds " +
                               std::to_string(array->second));
    };
    for (const Tag& tag : tags) {
        if (tag.closing) {
            if (tag.name == "accessor" && !open.empty()) {
                check(*open.back().first, open.back().second);
                open.pop_back();
            }
            continue;
        }
        if (tag.name == "param")
            for (auto& accessor : open)
                ++accessor.second;
        if (tag.name == "accessor") {
            if (tag.selfClosing)
                check(tag, 0);
            else
                open.emplace_back(&tag, 0);
        }
    }
    for (const auto& [accessor, params] : open) // never closed: Assimp's parser refuses it
        check(*accessor, params);

    // Index lists (<p>, <v>, <vcount>) hold whole numbers and nothing else up to their end tag.
    // Assimp reads a list's first run of text only, and, given a token that is not a number,
    // walks off its counts (2.4 GB asked for, found by fuzz_obstacle); a comment before the token
    // hid it from a plain scan of the text (3 GB asked for, found with finding 26).
    for (const Tag& tag : tags) {
        if (tag.closing || tag.selfClosing ||
            (tag.name != "p" && tag.name != "v" && tag.name != "vcount"))
            continue;
        std::size_t i = tag.end;
        for (; i < text.size() && text[i] != '<'; ++i) {
            const char c = text[i];
            if ((c >= '0' && c <= '9') || space(c)) continue;
            throw InvalidInput(where + "the index list <" + tag.name + "> at line " + lineOf(i) +
                               " holds something that is not a whole number");
        }
        const std::string endTag = "</" + tag.name;
        const std::size_t after = i + endTag.size();
        if (text.compare(i, endTag.size(), endTag) != 0 ||
            (after < text.size() && text[after] != '>' && !space(text[after])))
            throw InvalidInput(where + "the index list <" + tag.name + "> at line " +
                               lineOf(tag.at) +
                               " holds markup (a comment, CDATA or an element) where only whole "
                               "numbers belong");
    }

    // Assimp reads a primitive's children in document order and assembles each index list <p>
    // with what it has read before it. Without a VERTEX input before it, its per-vertex offset is
    // SIZE_MAX and it reads the list at base − 1 (valgrind: 8 bytes before the list, finding 25
    // and again with the input after the list). A polylist's <p> before its <vcount> (or without
    // one) reads the polygon sizes from an empty array (SEGV at address 0, fuzz finding 26).
    auto primitive = [](const std::string& name) {
        return name == "triangles" || name == "polylist" || name == "polygons" || name == "lines" ||
               name == "linestrips" || name == "tristrips" || name == "trifans";
    };
    struct Open {
        const Tag* tag;
        bool vertex = false, vcount = false;
        std::uint64_t offsets = 1; // values per vertex in the index list, as far as read
        std::uint64_t corners = 0; // the polygon sizes of its <vcount>s, summed
        std::uint64_t count = 0;   // its count attribute (0: absent)
    };
    std::vector<Open> primitives; // the open ones, innermost last
    auto noVertex = [&](const Tag& tag, const std::string& before) {
        return InvalidInput(where + "<" + tag.name + "> at line " + lineOf(tag.at) +
                            " has no input of semantic VERTEX" + before);
    };
    // The whole numbers of an index list, as Assimp reads them (strtoul10: 32 bits, wrapping).
    auto numbersOf = [&](const Tag& list, std::uint64_t most, auto&& each) {
        if (list.selfClosing) return std::uint64_t{0};
        std::uint64_t n = 0;
        for (std::size_t i = list.end; i < text.size() && text[i] != '<' && n < most;) {
            if (space(text[i])) {
                ++i;
                continue;
            }
            std::uint32_t value = 0;
            for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i)
                value = value * 10 + static_cast<std::uint32_t>(text[i] - '0');
            each(value);
            ++n;
        }
        return n;
    };
    constexpr std::uint64_t kSaturated = std::uint64_t{1} << 40; // above any file's numbers
    for (const Tag& tag : tags) {
        if (tag.closing && primitive(tag.name) && !primitives.empty()) {
            if (!primitives.back().vertex) throw noVertex(*primitives.back().tag, "");
            primitives.pop_back();
        } else if (!tag.closing && primitive(tag.name)) {
            if (tag.selfClosing) throw noVertex(tag, "");
            primitives.push_back({&tag});
            primitives.back().count = whole(tag, "count", 0, maxCount, 0);
        } else if (!tag.closing && !primitives.empty()) {
            Open& open = primitives.back();
            const std::string* semantic = tag.attribute("semantic");
            if (tag.name == "input") {
                if (semantic && *semantic == "VERTEX") open.vertex = true;
                if (tag.attribute("offset"))
                    open.offsets = std::max(
                        open.offsets, whole(tag, "offset", 0, kMaxColladaInputOffsets - 1, 0) + 1);
            }
            if (tag.name == "vcount") {
                open.vcount = true;
                if (open.count > 0) // Assimp reads `count` sizes, and none without a count
                    numbersOf(tag, open.count, [&](std::uint32_t corners) {
                        open.corners = std::min(kSaturated, open.corners + corners);
                    });
            }
            if (tag.name != "p") continue;
            const std::string list = " before its index list <p> at line " + lineOf(tag.at);
            if (!open.vertex) throw noVertex(*open.tag, list);
            if (open.tag->name == "polylist" && !open.vcount)
                throw InvalidInput(where + "<polylist> at line " + lineOf(open.tag->at) +
                                   " has no <vcount> (the number of corners of each polygon)" +
                                   list);
            // Assimp reserves the index list it expects before reading it: 3 × count for
            // triangles, 2 × count for lines, the corners for a polylist, times the values per
            // vertex; count="89999999" asked for 2.2 GB, a <vcount> of 4294967295 for 34 GB.
            // A list shorter than that is an error to Assimp too (but lines, whose count it
            // corrects: SketchUp writes it wrong), so it is refused before the reservation.
            const std::string& kind = open.tag->name;
            const std::uint64_t corners = kind == "triangles"                    ? 3 * open.count
                                          : kind == "lines"                      ? 2 * open.count
                                          : kind == "polylist" && open.count > 0 ? open.corners
                                                                                 : 0;
            const std::uint64_t expected = corners * open.offsets;
            const std::uint64_t numbers = numbersOf(tag, kSaturated, [](std::uint32_t) {});
            const std::uint64_t tolerated =
                kind == "lines" ? std::max<std::uint64_t>(numbers, 1u << 20) : numbers;
            if (expected > tolerated)
                throw InvalidInput(where + "<" + kind + "> at line " + lineOf(open.tag->at) +
                                   " declares " + std::to_string(corners) + " corners of " +
                                   std::to_string(open.offsets) + " value(s) each (" +
                                   std::to_string(expected) +
                                   " numbers), but its index list <p> at line " + lineOf(tag.at) +
                                   " holds " + std::to_string(numbers));
        }
    }
    for (const Open& open : primitives)
        if (!open.vertex) throw noVertex(*open.tag, "");

    // The scene graph as Assimp builds it (finding 28, by reading): each <node> with its
    // child nodes and the nodes its <instance_node>s name, copied in recursively. A node that
    // instances itself or an ancestor recursed until the stack overflowed; a chain of nodes
    // instancing the next one twice copies 2^depth nodes; 20,000 nested nodes overflowed the
    // stack too. Refused: cycles, more than kMaxSceneNodes nodes once copied, and
    // hierarchies deeper than kMaxSceneDepth (scenegraphwalk.h).
    struct Node {
        const Tag* tag;
        std::vector<std::size_t> children;  // nested nodes
        std::vector<std::string> instances; // ids its <instance_node>s name
    };
    std::vector<Node> nodes;
    std::multimap<std::string, std::size_t> byId;
    std::vector<std::size_t> openNodes;
    for (const Tag& tag : tags) {
        // A <visual_scene> is a node to Assimp too, and can be instanced.
        const bool isNode = tag.name == "node" || tag.name == "visual_scene";
        if (isNode && tag.closing) {
            if (!openNodes.empty()) openNodes.pop_back();
        } else if (isNode) {
            const std::size_t index = nodes.size();
            nodes.push_back({&tag, {}, {}});
            if (!openNodes.empty()) nodes[openNodes.back()].children.push_back(index);
            // Assimp finds an instanced node by its id, else by its name or id in the scene
            // (absent: "", a visual scene's name "Scene"): each may be the one.
            const std::string* id = tag.attribute("id");
            const std::string* name = tag.attribute("name");
            byId.emplace(id ? *id : std::string(), index);
            byId.emplace(name ? *name : tag.name == "node" ? std::string() : "Scene", index);
            if (!tag.selfClosing) openNodes.push_back(index);
        } else if (tag.name == "instance_node" && !tag.closing && !openNodes.empty()) {
            const std::string* url = tag.attribute("url");
            if (url && !url->empty() && (*url)[0] == '#')
                nodes[openNodes.back()].instances.push_back(url->substr(1));
        }
    }
    std::vector<std::vector<std::size_t>> next(nodes.size());
    std::vector<std::size_t> roots(nodes.size());
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        roots[n] = n; // a library's nodes too: each may be instanced
        next[n] = nodes[n].children;
        for (const std::string& id : nodes[n].instances) {
            const auto [from, to] = byId.equal_range(id);
            for (auto it = from; it != to; ++it)
                next[n].push_back(it->second);
        }
    }
    throwSceneGraphProblem(
        walkSceneGraph(next, roots), where,
        [&](std::size_t n) { return "<node> at line " + lineOf(nodes[n].tag->at); },
        "its <instance_node>s are copied in");
}

/// Collada: Assimp 5.2.5 reserves what a `count` attribute declares (a polylist of 2·10^9
/// polygons asked for 16 GB) and, given an index list with a token that is not a number, walks
/// off its counts and asked for 2.4 GB (both found by fuzz_obstacle). Every `count="N"` must be
/// at most 9·maxItems (a float array of three corners of three coordinates per triangle) and
/// the index lists (`<p>`, `<v>`, `<vcount>`) hold whole numbers only (checkColladaElements). A
/// count that is not a whole number from 1 crashed Assimp (SEGV, found by fuzz_obstacle too), and
/// so did a data array without a count (SEGV, fuzz finding 14).
void checkCollada(const std::filesystem::path& file, std::ifstream& in, std::size_t maxItems) {
    std::string text = readAll(in);
    const std::string where = "obstacle mesh '" + file.string() + "': cannot read it: Collada ";
    const auto lineOf = [&](std::size_t at) {
        return std::to_string(
            1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    };
    const std::uint64_t maxCount =
        maxItems > UINT64_MAX / 9 ? UINT64_MAX : 9 * static_cast<std::uint64_t>(maxItems);
    for (std::size_t at = text.find("count=\""); at != std::string::npos;
         at = text.find("count=\"", at + 7)) {
        if (at > 0 && text[at - 1] != ' ' && text[at - 1] != '\t' && text[at - 1] != '\n' &&
            text[at - 1] != '\r')
            continue; // another attribute ending in "count" (vcount, …) is not one
        const char* begin = text.data() + at + 7;
        const char* end = text.data() + text.size();
        std::uint64_t n = 0;
        const auto [ptr, ec] = std::from_chars(begin, end, n);
        // Assimp reads what is not a number (or 0) as an empty array and then follows it: a
        // float_array of count "z192", "", "-192" or "0" holding 192 values crashed it (SEGV).
        if (ptr == begin || ptr == end || *ptr != '"' || (ec == std::errc() && n == 0)) {
            const std::size_t close = text.find('"', at + 7);
            throw InvalidInput(where + "count=\"" +
                               text.substr(at + 7, std::min<std::size_t>(close - at - 7, 32)) +
                               "\" at line " + lineOf(at) + " is not a whole number from 1");
        }
        if (ec == std::errc::result_out_of_range || n > maxCount)
            throw LimitExceeded(where + "count=\"" + std::string(begin, ptr) + "\" at line " +
                                lineOf(at) + " is more than the limit of " +
                                std::to_string(maxCount) + " items (9 per triangle of " +
                                std::to_string(maxItems) + "); decimate the mesh");
    }
    // A data array without a `count` attribute (one mutated to `cmunt`) made Assimp read
    // through a null pointer (SEGV, found by fuzz_obstacle): every array must declare its count.
    for (const char* tag : {"<float_array", "<int_array", "<Name_array", "<IDREF_array",
                            "<bool_array", "<SIDREF_array", "<token_array"}) {
        const std::size_t length = std::strlen(tag);
        for (std::size_t at = text.find(tag); at != std::string::npos;
             at = text.find(tag, at + length)) {
            const char after = at + length < text.size() ? text[at + length] : '>';
            if (after != ' ' && after != '\t' && after != '\n' && after != '\r' && after != '>' &&
                after != '/')
                continue; // a longer element name
            const std::size_t close = text.find('>', at);
            const std::string open =
                text.substr(at, close == std::string::npos ? std::string::npos : close - at);
            bool counted = false;
            for (std::size_t c = open.find("count=\""); c != std::string::npos && !counted;
                 c = open.find("count=\"", c + 7))
                counted = c > 0 && (open[c - 1] == ' ' || open[c - 1] == '\t' ||
                                    open[c - 1] == '\n' || open[c - 1] == '\r');
            if (!counted)
                throw InvalidInput(where + tag + "> at line " + lineOf(at) +
                                   " has no count attribute");
        }
    }
    checkColladaElements(text, where, lineOf, maxCount);
}

/// Binary glTF (GLB): Debian's Assimp 5.2.5 allocates the JSON chunk's declared length (plus
/// one byte) before comparing it with the file: a 2 KB file declaring a 4 GB chunk ran out of
/// memory (fuzz finding 19). The header's lengths must fit in the file.
/// What checkGlb() read of a binary glTF: its JSON chunk (version 2; the content of version
/// 1) and the length of its binary chunk (0 when it has none).
struct GlbChunks {
    std::string json;
    std::uint64_t binaryBytes = 0;
};

GlbChunks checkGlb(const std::filesystem::path& file, std::ifstream& in, std::uintmax_t size) {
    const std::string where = "obstacle mesh '" + file.string() + "': cannot read it: binary glTF ";
    auto le32 = [](const unsigned char* b) {
        return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
               std::uint32_t(b[3]) << 24;
    };
    if (size < 20) throw InvalidInput(where + "is shorter than its 20-byte header");
    unsigned char header[20];
    in.read(reinterpret_cast<char*>(header), sizeof header);
    if (!in) throw IoError("obstacle mesh '" + file.string() + "': cannot read the file");
    const std::uint32_t version = le32(header + 4);
    const std::uint32_t length = le32(header + 8);
    const std::uint32_t json = le32(header + 12); // version 2: the JSON chunk; 1: the content
    if (version != 1 && version != 2)
        throw InvalidInput(where + "version " + std::to_string(version) + " is not 1 or 2");
    if (length > size)
        throw InvalidInput(where + "declares " + std::to_string(length) + " bytes, the file has " +
                           std::to_string(size));
    if (json > size - 20)
        throw InvalidInput(where + "JSON chunk declares " + std::to_string(json) +
                           " bytes, more than the " + std::to_string(size - 20) +
                           " the file holds after its header");
    GlbChunks out;
    out.json.resize(json);
    in.read(out.json.data(), static_cast<std::streamsize>(out.json.size()));
    if (!in) throw IoError("obstacle mesh '" + file.string() + "': cannot read the file");
    out.json.erase(out.json.find_last_not_of(std::string(" \0", 2)) + 1); // the padding
    if (version != 2) return out;
    // The binary chunk, if any, follows the JSON chunk at a multiple of 4 bytes.
    const std::uint64_t next = 20 + ((std::uint64_t(json) + 3) & ~std::uint64_t(3));
    if (next + 8 > size) return out;
    unsigned char chunk[8];
    in.seekg(static_cast<std::streamoff>(next));
    in.read(reinterpret_cast<char*>(chunk), sizeof chunk);
    if (!in) throw IoError("obstacle mesh '" + file.string() + "': cannot read the file");
    if (le32(chunk) > size - next - 8)
        throw InvalidInput(where + "binary chunk declares " + std::to_string(le32(chunk)) +
                           " bytes, more than the " + std::to_string(size - next - 8) +
                           " the file holds after it");
    out.binaryBytes = le32(chunk);
    return out;
}

/// glTF: Debian's Assimp 5.2.5 reads an accessor's elements without checking that they lie in
/// its buffer view, nor the view in its buffer: an accessor whose byteOffset was mutated from 0
/// to 1 read past a 720-byte buffer (fuzz finding 21). Every accessor (sparse ones are
/// refused), buffer view and buffer must fit in what holds it, as the specification requires;
/// a buffer must fit in its data (the binary chunk of a GLB, a data URI, a file beside it).
void checkGltfBounds(const std::filesystem::path& file, const sylva::Value& doc,
                     std::uint64_t glbBinary) {
    const std::string where = "obstacle mesh '" + file.string() + "': cannot read it: glTF ";
    if (!doc.isObject()) throw InvalidInput(where + "JSON is not an object");
    auto list = [&doc](const char* name) -> const sylva::Value::Array& {
        static const sylva::Value::Array none;
        const sylva::Value* v = doc.find(name);
        return v && v->isArray() ? v->toArray() : none;
    };
    // A whole number in [0, limit]; \p fallback when absent.
    auto whole = [&where](const sylva::Value& object, const char* key, const std::string& what,
                          std::uint64_t fallback, std::uint64_t limit) -> std::uint64_t {
        const sylva::Value* v = object.isObject() ? object.find(key) : nullptr;
        if (!v) return fallback;
        const double d = v->isNumber() ? v->toNumber() : -1.0;
        if (!(d >= 0.0 && d <= double(limit) && d == std::floor(d)))
            throw InvalidInput(where + what + "." + key + " must be a whole number from 0 to " +
                               std::to_string(limit));
        return std::uint64_t(d);
    };
    constexpr std::uint64_t kMax = 0xffffffffu;
    const sylva::Value::Array& buffers = list("buffers");
    std::vector<std::uint64_t> bufferBytes;
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        const std::string what = "buffers[" + std::to_string(i) + "]";
        const std::uint64_t bytes = whole(buffers[i], "byteLength", what, kMax + 1, kMax);
        if (bytes > kMax) throw InvalidInput(where + what + " has no byteLength");
        std::uint64_t available = 0;
        const sylva::Value* uri = buffers[i].isObject() ? buffers[i].find("uri") : nullptr;
        if (!uri) {
            available = i == 0 ? glbBinary : 0; // a GLB's binary chunk
        } else if (!uri->isString()) {
            throw InvalidInput(where + what + ".uri is not a string");
        } else if (uri->toString().rfind("data:", 0) == 0) {
            const std::string& u = uri->toString();
            const std::size_t comma = u.find(',');
            std::size_t chars = comma == std::string::npos ? 0 : u.size() - comma - 1;
            while (chars > 0 && u[comma + chars] == '=')
                --chars;
            available = chars * 3 / 4;
        } else {
            std::error_code ec;
            available = std::filesystem::file_size(file.parent_path() / uri->toString(), ec);
            if (ec) available = kMax + 1; // missing: Assimp refuses it (IoError)
        }
        if (bytes > available)
            throw InvalidInput(where + what + " declares " + std::to_string(bytes) +
                               " bytes, more than its data holds (" + std::to_string(available) +
                               ")");
        bufferBytes.push_back(bytes);
    }
    const sylva::Value::Array& views = list("bufferViews");
    std::vector<std::pair<std::uint64_t, std::uint64_t>> viewBytes; // length, stride (0: none)
    for (std::size_t i = 0; i < views.size(); ++i) {
        const std::string what = "bufferViews[" + std::to_string(i) + "]";
        const std::uint64_t buffer = whole(views[i], "buffer", what, kMax + 1, kMax);
        if (buffer >= bufferBytes.size())
            throw InvalidInput(where + what + " names no buffer of the file");
        const std::uint64_t offset = whole(views[i], "byteOffset", what, 0, kMax);
        const std::uint64_t length = whole(views[i], "byteLength", what, kMax + 1, kMax);
        if (length > kMax || offset + length > bufferBytes[buffer])
            throw InvalidInput(where + what + " does not fit in buffers[" + std::to_string(buffer) +
                               "]");
        const std::uint64_t stride = whole(views[i], "byteStride", what, 0, 252);
        if (stride != 0 && stride < 4) throw InvalidInput(where + what + ".byteStride is below 4");
        viewBytes.emplace_back(length, stride);
    }
    const sylva::Value::Array& accessors = list("accessors");
    for (std::size_t i = 0; i < accessors.size(); ++i) {
        const sylva::Value& a = accessors[i];
        const std::string what = "accessors[" + std::to_string(i) + "]";
        if (a.isObject() && a.find("sparse"))
            throw InvalidInput(where + what +
                               " is sparse, which obstacles do not support; "
                               "export the mesh without sparse accessors");
        const std::uint64_t type = whole(a, "componentType", what, 0, kMax);
        const std::uint64_t component = type == 5120 || type == 5121   ? 1
                                        : type == 5122 || type == 5123 ? 2
                                        : type == 5125 || type == 5126 ? 4
                                                                       : 0;
        if (component == 0)
            throw InvalidInput(where + what + ".componentType " + std::to_string(type) +
                               " is not one of glTF's");
        const sylva::Value* t = a.isObject() ? a.find("type") : nullptr;
        const std::string name = t && t->isString() ? t->toString() : std::string();
        const std::uint64_t components = name == "SCALAR" ? 1
                                         : name == "VEC2" ? 2
                                         : name == "VEC3" ? 3
                                         : name == "VEC4" ? 4
                                         : name == "MAT2" ? 4
                                         : name == "MAT3" ? 9
                                         : name == "MAT4" ? 16
                                                          : 0;
        if (components == 0)
            throw InvalidInput(where + what + ".type '" + name + "' is not one of glTF's");
        const std::uint64_t count = whole(a, "count", what, 0, kMax);
        if (count == 0) throw InvalidInput(where + what + ".count must be at least 1");
        // Assimp allocates an accessor's elements before reading them (zeros when it names
        // no buffer view): at most three a triangle of the triangle limit.
        if (count > 3 * kMaxObstacleTriangles)
            throw LimitExceeded(
                where + what + ".count " + std::to_string(count) + " is more than the limit of " +
                std::to_string(3 * kMaxObstacleTriangles) + " (three per triangle of " +
                std::to_string(kMaxObstacleTriangles) + "); decimate the mesh");
        if (!a.find("bufferView")) continue; // all zeros
        const std::uint64_t view = whole(a, "bufferView", what, 0, kMax);
        if (view >= viewBytes.size())
            throw InvalidInput(where + what + " names no buffer view of the file");
        const std::uint64_t element = component * components;
        const std::uint64_t stride = viewBytes[view].second ? viewBytes[view].second : element;
        const std::uint64_t offset = whole(a, "byteOffset", what, 0, kMax);
        if (offset + (count - 1) * stride + element > viewBytes[view].first)
            throw InvalidInput(
                where + what + " (" + std::to_string(count) + " × " + std::to_string(element) +
                " bytes from byte " + std::to_string(offset) + ") does not fit in bufferViews[" +
                std::to_string(view) + "] (" + std::to_string(viewBytes[view].first) + " bytes)");
    }
}

/// glTF: Debian's Assimp 5.2.5 builds a line loop's closing segment and a triangle fan's
/// triangles from the faces it made before, which are empty where an index was out of range:
/// it read through a null pointer (fuzz finding 20: a binary glTF whose triangles were
/// relabelled as a line loop). Obstacles need triangles; primitives drawn as line loops (mode
/// 2) or triangle fans (6) are refused with the mesh that has them. The JSON must parse.
void checkGltfBounds(const std::filesystem::path& file, const sylva::Value& doc,
                     std::uint64_t glbBinary);

void checkGltfJson(const std::filesystem::path& file, const std::string& json,
                   std::uint64_t glbBinary = 0) {
    const std::string where = "obstacle mesh '" + file.string() + "': cannot read it: glTF ";
    sylva::Value doc;
    try {
        doc = sylva::Value::parseJson(json, file.string());
    } catch (const InvalidInput& e) {
        throw InvalidInput(where + "JSON is not valid: " + e.what());
    }
    checkGltfBounds(file, doc, glbBinary);
    // A skin without inverse bind matrices (identity, by the specification) made Assimp 5.2.5
    // read through a null pointer (fuzz finding 22): required, and an accessor of the file.
    if (const sylva::Value* skins = doc.find("skins"); skins && skins->isArray()) {
        const sylva::Value* accessors = doc.find("accessors");
        const std::size_t count =
            accessors && accessors->isArray() ? accessors->toArray().size() : 0;
        for (std::size_t k = 0; k < skins->toArray().size(); ++k) {
            const sylva::Value& skin = skins->toArray()[k];
            const sylva::Value* ibm = skin.isObject() ? skin.find("inverseBindMatrices") : nullptr;
            if (!ibm || !ibm->isNumber() || ibm->toNumber() < 0 ||
                ibm->toNumber() >= double(count) || ibm->toNumber() != std::floor(ibm->toNumber()))
                throw InvalidInput(where + "skins[" + std::to_string(k) +
                                   "] names no accessor of inverse bind matrices, which the "
                                   "importer needs; export the obstacle without its skin");
        }
    }
    // The node hierarchy (finding 30): Assimp copies a node under every node that lists it as a
    // child, recursively, so 30 nodes each listing the next twice asked for 2^30 nodes (out of
    // memory). Assimp refuses loops itself; refused here with the other limits.
    if (const sylva::Value* nodes = doc.isObject() ? doc.find("nodes") : nullptr;
        nodes && nodes->isArray()) {
        const auto& list = nodes->toArray();
        std::vector<std::vector<std::size_t>> next(list.size());
        std::vector<std::size_t> roots(list.size());
        for (std::size_t k = 0; k < list.size(); ++k) {
            roots[k] = k;
            const sylva::Value* children = list[k].isObject() ? list[k].find("children") : nullptr;
            if (!children || !children->isArray()) continue;
            for (const sylva::Value& c : children->toArray())
                if (c.isNumber() && c.toNumber() >= 0 && c.toNumber() < double(list.size()) &&
                    c.toNumber() == std::floor(c.toNumber()))
                    next[k].push_back(static_cast<std::size_t>(c.toNumber()));
        }
        throwSceneGraphProblem(
            walkSceneGraph(next, roots), where,
            [](std::size_t n) { return "nodes[" + std::to_string(n) + "]"; },
            "the nodes listed as children more than once are copied under each");
    }
    const sylva::Value* meshes = doc.isObject() ? doc.find("meshes") : nullptr;
    if (!meshes || !meshes->isArray()) return;
    for (std::size_t m = 0; m < meshes->toArray().size(); ++m) {
        const sylva::Value& mesh = meshes->toArray()[m];
        const sylva::Value* primitives = mesh.isObject() ? mesh.find("primitives") : nullptr;
        if (!primitives || !primitives->isArray()) continue;
        for (std::size_t p = 0; p < primitives->toArray().size(); ++p) {
            const sylva::Value& primitive = primitives->toArray()[p];
            const std::string what =
                "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
            const sylva::Value* mode = primitive.isObject() ? primitive.find("mode") : nullptr;
            const double v = mode && mode->isNumber() ? mode->toNumber() : 4.0;
            if (v == 2 || v == 3 || v == 6)
                throw InvalidInput(where + what + " is drawn as " +
                                   (v == 2   ? "a line loop (mode 2)"
                                    : v == 3 ? "a line strip (mode 3)"
                                             : "a triangle fan (mode 6)") +
                                   ", which the importer cannot read safely; export the "
                                   "obstacle as triangles");
            // A strip of fewer vertices than a triangle: Assimp counts its faces as count - 2
            // in unsigned arithmetic and asked for 64 GB (finding 23, a line strip of none).
            if (v == 5) {
                const sylva::Value* indices = primitive.find("indices");
                const sylva::Value* attributes = primitive.find("attributes");
                const sylva::Value* position =
                    attributes && attributes->isObject() ? attributes->find("POSITION") : nullptr;
                const sylva::Value* source = indices ? indices : position;
                const sylva::Value* accessors = doc.find("accessors");
                const sylva::Value* count = nullptr;
                if (source && source->isNumber() && accessors && accessors->isArray() &&
                    source->toNumber() >= 0 &&
                    source->toNumber() < double(accessors->toArray().size()))
                    count = accessors->toArray()[std::size_t(source->toNumber())].find("count");
                if (!count || !count->isNumber() || count->toNumber() < 3)
                    throw InvalidInput(where + what +
                                       " is a triangle strip of fewer than 3 vertices");
            }
        }
    }
}

} // namespace

void checkMeshFile(const std::filesystem::path& file, std::size_t maxItems) {
    std::ifstream in(file, std::ios::binary);
    if (!in)
        throw IoError("obstacle mesh '" + file.string() + "': cannot open the file for reading");
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (ec) throw IoError("obstacle mesh '" + file.string() + "': " + ec.message());
    char magic[4] = {0, 0, 0, 0};
    in.read(magic, 4);
    in.clear();
    in.seekg(0);
    if (std::string_view(magic, 4) == "glTF") {
        // By content: Assimp sniffs the magic whatever the extension.
        const GlbChunks glb = checkGlb(file, in, size);
        checkGltfJson(file, glb.json, glb.binaryBytes);
        return;
    }
    const std::string ext = lowerAscii(file.extension().string());
    if (ext == ".ply" || std::string_view(magic, 3) == "ply") {
        checkPly(file, in, size, maxItems);
        return;
    }
    // Collada by extension or by its root element near the start (Assimp also sniffs content).
    std::string head(4096, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    in.clear();
    in.seekg(0);
    // FBX by extension, magic, or (an extension Assimp does not know) "fbx" near the start, as
    // Assimp sniffs it.
    const std::string lowered = lowerAscii(head.substr(0, 200));
    const bool knownExtension = ext == ".obj" || ext == ".stl" || ext == ".dae" || ext == ".gltf" ||
                                ext == ".glb" || ext == ".fbx";
    if (ext == ".fbx" || head.compare(0, 18, "Kaydara FBX Binary") == 0 ||
        (!knownExtension && lowered.find("fbx") != std::string::npos)) {
        const std::string bytes = readAll(in);
        checkFbx(bytes, "obstacle mesh '" + file.string() + "': cannot read it: ");
        return;
    }
    if (ext == ".dae" || head.find("<COLLADA") != std::string::npos)
        checkCollada(file, in, maxItems);
    else if (ext == ".gltf" ||
             head.substr(std::min(head.size(), head.find_first_not_of(" \t\r\n\xEF\xBB\xBF")), 1) ==
                 "{")
        // A glTF by extension, or anything that looks like JSON (Assimp sniffs the content of
        // a file whose extension it does not know).
        checkGltfJson(file, readAll(in));
}

std::string objGeometryOnly(std::string text) {
    // Where Assimp 5.2.5 starts a line (IOStreamBuffer::getNextDataLine): after any of \r, \n,
    // \0 and \f, and at the start of the file (after a UTF-8 byte order mark). A line that starts
    // with 'l' or 'p' is read as a line or point element whatever follows (ObjFileParser::
    // parseFile), one that starts with 'm' as a material library (`mtllib`) or merging group;
    // marking it '#' makes it a comment. Lines continued with a backslash are also marked after
    // their line end: that only turns more of a line into a comment, never less.
    auto lineEnd = [](char c) { return c == '\r' || c == '\n' || c == '\0' || c == '\f'; };
    std::size_t start = 0;
    if (text.size() >= 3 && static_cast<unsigned char>(text[0]) == 0xEF &&
        static_cast<unsigned char>(text[1]) == 0xBB && static_cast<unsigned char>(text[2]) == 0xBF)
        start = 3;
    for (std::size_t i = start; i < text.size(); ++i)
        if ((i == start || lineEnd(text[i - 1])) &&
            (text[i] == 'l' || text[i] == 'p' || text[i] == 'm'))
            text[i] = '#';
    return text;
}

} // namespace sylva::env
