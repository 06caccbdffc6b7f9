#include "engine/export/fbxfix.h"

#include <array>
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

class Repair {
public:
    Repair(std::string_view in, double unitScale) : mIn(in), mUnitScale(unitScale) {}

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
            at = node(at, mIn.size(), 0, false);
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
    std::size_t node(std::size_t at, std::size_t limit, int depth, bool inGlobalSettings) {
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
        if (name == "P" && inGlobalSettings) setUnitScale(head + kRecordHead + nameLen, count);

        std::size_t child = props + propBytes;
        bool hasChildren = false;
        const bool childGlobal = inGlobalSettings || name == "GlobalSettings";
        while (child < end) {
            // A list that already ends in its null record (as the FBX SDK writes it).
            if (end - child == kNullRecord && u64At(mIn, child) == 0) break;
            hasChildren = true;
            child = node(child, end, depth + 1, childGlobal);
        }
        if (hasChildren) mOut.append(kNullRecord, '\0');
        putU64(mOut, head, mOut.size());
        return end;
    }

    // P: "UnitScaleFactor", "double", "Number", "", <D value> — rewrites the value in mOut.
    void setUnitScale(std::size_t props, std::uint64_t count) {
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
        if (first != "UnitScaleFactor" && first != "OriginalUnitScaleFactor") return;
        if (p + 9 > mOut.size() || mOut[p] != 'D') return;
        std::memcpy(mOut.data() + p + 1, &mUnitScale, sizeof mUnitScale);
    }

    std::string_view mIn;
    double mUnitScale;
    std::string mOut;
};

} // namespace

std::string repairAssimpFbxBinary(std::string_view bytes, double unitScale) {
    return Repair(bytes, unitScale).run();
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
