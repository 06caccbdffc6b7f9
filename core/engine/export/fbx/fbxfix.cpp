#include "engine/export/fbx/fbxfix.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "engine/util/error.h"

namespace sylva::exporter {

namespace {

constexpr std::size_t kHeaderSize = 27; // "Kaydara FBX Binary  \0", 0x1a 0x00, u32 version
constexpr std::size_t kRecordHead = 25; // u64 end, u64 property count, u64 bytes, u8 name
constexpr std::size_t kNullRecord = 25; // FBX 7.5: a record head of zeros
constexpr int kMaxDepth = 64;           // far beyond any real FBX; guards the recursion
constexpr std::array<unsigned char, 16> kFooterId = {
    0xfa, 0xbc, 0xab, 0x09, 0xd0, 0xc8, 0xd4, 0x66, 0xb1, 0x76, 0xfb, 0x83, 0x1c, 0xf7, 0x26, 0x7e};
constexpr std::array<unsigned char, 16> kFooterMagic = {
    0xf8, 0x5a, 0x8c, 0x6a, 0xde, 0xf5, 0xd9, 0x7e, 0xec, 0xe9, 0x0c, 0xe3, 0x75, 0x8f, 0x29, 0x0b};

std::uint64_t u64At(std::string_view b, std::size_t at) {
    std::uint64_t v = 0;
    std::memcpy(&v, b.data() + at, sizeof v); // FBX is little-endian, like every target here
    return v;
}
std::uint32_t u32At(std::string_view b, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, b.data() + at, sizeof v);
    return v;
}
void putU64(std::string& out, std::size_t at, std::uint64_t v) {
    std::memcpy(out.data() + at, &v, sizeof v);
}

[[noreturn]] void malformed(const std::string& what, std::size_t at) {
    throw InvalidInput("malformed binary FBX at byte " + std::to_string(at) + ": " + what);
}

constexpr std::int64_t kKTimePerSecond = 46186158000; // FBX time unit: 1/46186158000 s

// Properties70 records rewritten in place, by the record that holds them.
enum class Scope { Other, GlobalSettings, AnimationStack };

class Repair {
public:
    Repair(std::string_view in, const FbxRepairOptions& options) : mIn(in), mOptions(options) {}

    std::string run() {
        if (mIn.size() < kHeaderSize || mIn.substr(0, 18) != "Kaydara FBX Binary")
            malformed("not a binary FBX header", 0);
        const std::uint32_t version = u32At(mIn, 23);
        if (version < 7500) malformed("version " + std::to_string(version) + " below 7500", 23);
        mOut.reserve(mIn.size() + mIn.size() / 16 + 256);
        mOut.append(mIn.substr(0, kHeaderSize));
        std::size_t at = kHeaderSize;
        for (;;) {
            if (at + kRecordHead > mIn.size()) malformed("top-level list not terminated", at);
            if (u64At(mIn, at) == 0) break; // the top-level null record
            at = node(at, mIn.size(), 0, Scope::Other);
        }
        mOut.append(kNullRecord, '\0');
        // Footer as the FBX SDK and Blender write it: id, 4 zeros, zeros up to a 16-byte
        // boundary (a full 16 when already aligned), version, 120 zeros, magic.
        mOut.append(reinterpret_cast<const char*>(kFooterId.data()), kFooterId.size());
        mOut.append(4, '\0');
        std::size_t pad = ((mOut.size() + 15) & ~std::size_t{15}) - mOut.size();
        mOut.append(pad == 0 ? 16 : pad, '\0');
        mOut.append(mIn.substr(23, 4));
        mOut.append(120, '\0');
        mOut.append(reinterpret_cast<const char*>(kFooterMagic.data()), kFooterMagic.size());
        return std::move(mOut);
    }

private:
    // Copies the node record at \p at (which must end by \p limit) and its children; returns
    // the input offset after it.
    std::size_t node(std::size_t at, std::size_t limit, int depth, Scope scope) {
        if (depth > kMaxDepth)
            malformed("nodes nested deeper than " + std::to_string(kMaxDepth), at);
        if (at + kRecordHead > limit) malformed("record head past its parent's end", at);
        const std::uint64_t end = u64At(mIn, at);
        const std::uint64_t count = u64At(mIn, at + 8);
        const std::uint64_t propBytes = u64At(mIn, at + 16);
        const auto nameLen = static_cast<unsigned char>(mIn[at + 24]);
        const std::size_t props = at + kRecordHead + nameLen;
        if (end > limit || end < props || propBytes > end - props)
            malformed("record end offset out of range", at);
        const std::string_view name = mIn.substr(at + kRecordHead, nameLen);

        const std::size_t head = mOut.size();
        mOut.append(mIn.substr(at, kRecordHead + nameLen + propBytes));
        if (name == "P" && scope != Scope::Other)
            setProperty(head + kRecordHead + nameLen, count, scope);

        std::size_t child = props + propBytes;
        bool hasChildren = false;
        const Scope childScope = name == "GlobalSettings"   ? Scope::GlobalSettings
                                 : name == "AnimationStack" ? Scope::AnimationStack
                                                            : scope;
        bool emptyList = false;
        while (child < end) {
            // A list that already ends in its null record (as the FBX SDK writes it).
            if (end - child == kNullRecord && u64At(mIn, child) == 0) {
                emptyList = !hasChildren;
                break;
            }
            hasChildren = true;
            child = node(child, end, depth + 1, childScope);
        }
        // Assimp marks AnimationLayer and References "force_has_children" but writes no null
        // record for them.
        if (hasChildren || emptyList || (depth == 1 && name == "AnimationLayer") ||
            (depth == 0 && name == "References"))
            mOut.append(kNullRecord, '\0');
        putU64(mOut, head, mOut.size());
        return end;
    }

    // P: "<name>", "<type>", "<label>", "<flags>", <value>: rewrites the value in mOut in place
    // (same type, same size) for the names the options set.
    void setProperty(std::size_t props, std::uint64_t count, Scope scope) {
        if (count != 5) return;
        std::size_t p = props;
        std::string_view first;
        for (int k = 0; k < 4; ++k) {
            if (p + 5 > mOut.size() || mOut[p] != 'S') return;
            const std::uint32_t len = u32At(mOut, p + 1);
            if (p + 5 + len > mOut.size()) return;
            if (k == 0) first = std::string_view(mOut).substr(p + 5, len);
            p += 5 + len;
        }
        const char type = p < mOut.size() ? mOut[p] : '\0';
        const std::size_t size = type == 'I' ? 4 : 8;
        if (p + 1 + size > mOut.size()) return;
        char* value = mOut.data() + p + 1;
        const double seconds = mOptions.animationSeconds;
        const auto ktime = static_cast<std::int64_t>(std::llround(seconds * kKTimePerSecond));
        if (scope == Scope::GlobalSettings) {
            if ((first == "UnitScaleFactor" || first == "OriginalUnitScaleFactor") && type == 'D')
                std::memcpy(value, &mOptions.unitScale, 8);
            else if (first == "TimeMode" && type == 'I' && mOptions.frameRate > 0.0) {
                const std::int32_t custom = 14; // FbxTime::eCustom
                std::memcpy(value, &custom, 4);
            } else if (first == "CustomFrameRate" && type == 'D' && mOptions.frameRate > 0.0)
                std::memcpy(value, &mOptions.frameRate, 8);
            else if (first == "TimeSpanStop" && type == 'L' && seconds > 0.0)
                std::memcpy(value, &ktime, 8);
        } else if (scope == Scope::AnimationStack && seconds > 0.0 && type == 'L' &&
                   (first == "LocalStop" || first == "ReferenceStop")) {
            std::memcpy(value, &ktime, 8);
        }
    }

    std::string_view mIn;
    FbxRepairOptions mOptions;
    std::string mOut;
};

} // namespace

std::string repairAssimpFbxBinary(std::string_view bytes, double unitScale) {
    FbxRepairOptions options;
    options.unitScale = unitScale;
    return Repair(bytes, options).run();
}

std::string repairAssimpFbxBinary(std::string_view bytes, const FbxRepairOptions& options) {
    return Repair(bytes, options).run();
}

std::string setFbxAsciiUnitScale(std::string text, double unitScale) {
    std::string value = std::to_string(unitScale);
    while (value.size() > 1 && value.back() == '0')
        value.pop_back();
    if (!value.empty() && value.back() == '.') value.pop_back();
    for (const char* key : {"\"UnitScaleFactor\"", "\"OriginalUnitScaleFactor\""}) {
        const std::size_t at = text.find(std::string("P: ") + key);
        if (at == std::string::npos) continue;
        const std::size_t lineEnd = text.find('\n', at);
        const std::size_t comma = text.rfind(',', lineEnd);
        if (comma == std::string::npos || comma < at) continue;
        std::size_t valueStart = comma + 1;
        while (valueStart < lineEnd && text[valueStart] == ' ')
            ++valueStart;
        std::size_t valueEnd = lineEnd == std::string::npos ? text.size() : lineEnd;
        while (valueEnd > valueStart && (text[valueEnd - 1] == '\r' || text[valueEnd - 1] == ' '))
            --valueEnd;
        text.replace(valueStart, valueEnd - valueStart, value);
    }
    return text;
}

} // namespace sylva::exporter
