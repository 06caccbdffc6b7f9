#include "engine/export/obj/objwriter.h"

#include "engine/export/materials.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <future>
#include <memory>
#include <type_traits>

#if defined(__linux__)
#include <fcntl.h>
#include <unistd.h>
#endif

#include "engine/mesh/leaftint.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

namespace sylva::exporter {

namespace {

constexpr std::uint64_t kPow10[] = {1ull,         10ull,         100ull,        1000ull,
                                    10000ull,     100000ull,     1000000ull,    10000000ull,
                                    100000000ull, 1000000000ull, 10000000000ull};

constexpr char kDigitPairs[201] = "00010203040506070809101112131415161718192021222324"
                                  "25262728293031323334353637383940414243444546474849"
                                  "50515253545556575859606162636465666768697071727374"
                                  "75767778798081828384858687888990919293949596979899";

inline int digitCount(std::uint64_t v) {
    int n = 1;
    for (;;) {
        if (v < 10) return n;
        if (v < 100) return n + 1;
        if (v < 1000) return n + 2;
        if (v < 10000) return n + 3;
        v /= 10000;
        n += 4;
    }
}

// Writes the digits straight into place (counted first), two at a time from the last.
inline char* writeUint(char* p, std::uint64_t v) {
    char* const end = p + digitCount(v);
    char* c = end;
    while (v >= 100) {
        const auto r = static_cast<std::size_t>(v % 100) * 2;
        v /= 100;
        *--c = kDigitPairs[r + 1];
        *--c = kDigitPairs[r];
    }
    if (v >= 10) {
        const auto r = static_cast<std::size_t>(v) * 2;
        *--c = kDigitPairs[r + 1];
        *--c = kDigitPairs[r];
    } else {
        *--c = static_cast<char>('0' + v);
    }
    return end;
}

// A growable text buffer that the hot loops write into directly: no staging copy, and unlike
// std::string::resize no zero-fill of the room it reserves.
class TextBuffer {
public:
    std::string_view view() const { return {mData.get(), mSize}; }
    void reserve(std::size_t bytes) {
        if (bytes <= mCapacity) return;
        auto grown = std::make_unique_for_overwrite<char[]>(bytes);
        if (mSize > 0) std::memcpy(grown.get(), mData.get(), mSize);
        mData = std::move(grown);
        mCapacity = bytes;
    }
    // Returns a pointer with at least 512 bytes of room; commit the end with done().
    char* room() {
        if (mSize + 512 > mCapacity) reserve(std::max<std::size_t>(2 * mCapacity, mSize + 4096));
        return mData.get() + mSize;
    }
    void done(char* end) { mSize = static_cast<std::size_t>(end - mData.get()); }
    void text(std::string_view s) {
        reserve(mSize + s.size() + 512);
        std::memcpy(mData.get() + mSize, s.data(), s.size());
        mSize += s.size();
    }

private:
    std::unique_ptr<char[]> mData;
    std::size_t mSize = 0, mCapacity = 0;
};

enum class Section { Header, V, VT, VN, F };

// Mesh::colors channels (linear) as the sRGB values OBJ readers expect, once for all bytes.
float srgbOfByte(std::uint8_t v) {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i)
            t[static_cast<std::size_t>(i)] = mesh::srgbFromByte(static_cast<std::uint8_t>(i));
        return t;
    }();
    return table[v];
}

struct Task {
    const ObjObject* object = nullptr;
    Section section = Section::Header;
    std::size_t begin = 0, end = 0; // vertices, or triangles for F
    ObjOffsets base;                // offsets of this object's first v/vt/vn
    std::uint64_t vertices = 0;     // the object's vertex count (relative indices count back)
    bool hasUv = false, hasNormal = false;
    bool hasColor = false; // `v x y z r g b`
    bool identity = true;
    glm::mat3 normalMatrix{1.0f};
    /// The normal matrix is a rotation (the transform rotates, translates and scales uniformly,
    /// as placed trees do): unit normals stay unit, so no normalisation per vertex.
    bool rotationOnly = false;
};

std::string objectName(const std::string& name) {
    std::string s = name.empty() ? std::string("tree") : name;
    for (char& c : s)
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') c = '_';
    return s;
}

// Compile-time decimals turn the divisions by 10^D into multiplications.
template <int D> char* formatFixedT(char* p, double value) {
    constexpr std::uint64_t scale = kPow10[D];
    const double scaled = value * static_cast<double>(scale);
    const double magnitude = std::abs(scaled);
    if (!(magnitude < 9.0e18)) return std::to_chars(p, p + 40, value).ptr;
    // Rounded half away from zero (a library nearbyint() is a call per number); the
    // difference is exact in double, so 0.49999999999999994 does not round up.
    // Both tests below are as random as the data: written without branches.
    // Through int64 (magnitude < 9e18 < 2^63): one instruction each way, where the unsigned
    // conversions compile to a branchy sequence on x86-64.
    const auto truncated = static_cast<std::int64_t>(magnitude);
    auto q = static_cast<std::uint64_t>(truncated);
    q += static_cast<std::uint64_t>(magnitude - static_cast<double>(truncated) >= 0.5);
    if (q == 0) {
        *p++ = '0';
        return p;
    }
    *p = '-';
    p += scaled < 0.0 ? 1 : 0;
    const std::uint64_t whole = q / scale;
    // Below 10^9, so 32-bit arithmetic (cheaper divisions by 100) does.
    auto fp = static_cast<std::uint32_t>(q - whole * scale);
    p = writeUint(p, whole);
    if (fp != 0) {
        // All D decimals from the last, two at a time, then the trailing zeros dropped.
        *p++ = '.';
        char* end = p + D;
        char* c = end;
        for (int d = D; d >= 2; d -= 2) {
            const auto r = static_cast<std::size_t>(fp % 100) * 2;
            fp /= 100;
            *--c = kDigitPairs[r + 1];
            *--c = kDigitPairs[r];
        }
        if constexpr (D % 2 == 1) *--c = static_cast<char>('0' + fp);
        while (end[-1] == '0')
            --end;
        p = end;
    }
    return p;
}

// Calls f(std::integral_constant<int, D>) for D = decimals (1..9), so that the loops below
// are compiled once per precision with formatFixedT<D> inlined.
template <class F> void withDecimals(int decimals, F&& f) {
    switch (decimals) {
    case 1:
        return f(std::integral_constant<int, 1>{});
    case 2:
        return f(std::integral_constant<int, 2>{});
    case 3:
        return f(std::integral_constant<int, 3>{});
    case 4:
        return f(std::integral_constant<int, 4>{});
    case 5:
        return f(std::integral_constant<int, 5>{});
    case 6:
        return f(std::integral_constant<int, 6>{});
    case 7:
        return f(std::integral_constant<int, 7>{});
    case 8:
        return f(std::integral_constant<int, 8>{});
    default:
        return f(std::integral_constant<int, 9>{});
    }
}

void formatTask(TextBuffer& w, const Task& t, const ObjOptions& o) {
    const mesh::Mesh& m = *t.object->mesh;
    // Typical line lengths, so the part grows without reallocation copies in most cases.
    const std::size_t lines = t.end - t.begin;
    const std::size_t perLine = t.section == Section::F    ? 24 + 30 * (t.hasUv + t.hasNormal)
                                : t.section == Section::VT ? 4 + 2 * (o.uvDecimals + 3)
                                : t.section == Section::VN ? 4 + 3 * (o.normalDecimals + 4)
                                                           : 3 + 3 * (o.positionDecimals + 6);
    w.reserve(lines * perLine + 1024);
    switch (t.section) {
    case Section::Header:
        w.text("o " + objectName(t.object->name) + "\n");
        break;
    case Section::V:
        withDecimals(o.positionDecimals, [&](auto decimals) {
            constexpr int D = decltype(decimals)::value;
            for (std::size_t i = t.begin; i < t.end; ++i) {
                glm::vec3 p = m.positions[i];
                if (!t.identity) p = glm::vec3(t.object->transform * glm::vec4(p, 1.0f));
                char* c = w.room();
                *c++ = 'v';
                *c++ = ' ';
                c = formatFixedT<D>(c, p.x);
                *c++ = ' ';
                c = formatFixedT<D>(c, p.y);
                *c++ = ' ';
                c = formatFixedT<D>(c, p.z);
                if (t.hasColor) {
                    const glm::u8vec4 col = m.colors[i];
                    for (int k = 0; k < 3; ++k) {
                        *c++ = ' ';
                        c = formatFixedT<3>(c, srgbOfByte(col[k]));
                    }
                }
                *c++ = '\n';
                w.done(c);
            }
        });
        break;
    case Section::VT:
        withDecimals(o.uvDecimals, [&](auto decimals) {
            constexpr int D = decltype(decimals)::value;
            for (std::size_t i = t.begin; i < t.end; ++i) {
                const glm::vec2 uv = m.uvs[i];
                char* c = w.room();
                *c++ = 'v';
                *c++ = 't';
                *c++ = ' ';
                c = formatFixedT<D>(c, uv.x);
                *c++ = ' ';
                c = formatFixedT<D>(c, uv.y);
                *c++ = '\n';
                w.done(c);
            }
        });
        break;
    case Section::VN:
        withDecimals(o.normalDecimals, [&](auto decimals) {
            constexpr int D = decltype(decimals)::value;
            for (std::size_t i = t.begin; i < t.end; ++i) {
                glm::vec3 n = m.normals[i];
                if (t.rotationOnly)
                    n = t.normalMatrix * n;
                else if (!t.identity)
                    n = glm::normalize(t.normalMatrix * n);
                char* c = w.room();
                *c++ = 'v';
                *c++ = 'n';
                *c++ = ' ';
                c = formatFixedT<D>(c, n.x);
                *c++ = ' ';
                c = formatFixedT<D>(c, n.y);
                *c++ = ' ';
                c = formatFixedT<D>(c, n.z);
                *c++ = '\n';
                w.done(c);
            }
        });
        break;
    case Section::F: {
        // usemtl lines go before the first triangle of each submesh run.
        std::vector<std::pair<std::size_t, std::string>> switches;
        if (o.materials) {
            if (m.submeshes.empty())
                switches.emplace_back(0, "bark");
            else
                for (const mesh::Submesh& s : m.submeshes)
                    switches.emplace_back(s.firstIndex / 3, materialName(s));
        }
        // The text of a corner ("v/vt/vn") depends only on its vertex, and a tube mesh's
        // triangles reuse nearby vertices: corners are formatted once into a small
        // direct-mapped cache and copied from there (one fixed-size copy per corner).
        struct Corner {
            std::uint64_t key = 0; // vertex + 1; 0 = empty
            std::uint32_t len = 0;
            char text[52]{};
        };
        constexpr std::size_t kCacheSize = 2048;
        std::vector<Corner> cache(kCacheSize);
        auto formatCorner = [&](std::uint64_t idx, char* out) {
            char* c = out;
            auto number = [&](std::uint64_t base) {
                if (o.relativeIndices) {
                    // v, vt and vn of an object come in equal numbers: one text serves all.
                    *c++ = '-';
                    c = writeUint(c, t.vertices - idx);
                } else {
                    c = writeUint(c, base + idx);
                }
            };
            number(t.base.v);
            if (t.hasUv || t.hasNormal) {
                *c++ = '/';
                if (t.hasUv) number(t.base.vt);
                if (t.hasNormal) {
                    *c++ = '/';
                    number(t.base.vn);
                }
            }
            return static_cast<std::size_t>(c - out);
        };
        std::size_t next = 0;
        while (next < switches.size() && switches[next].first < t.begin)
            ++next;
        for (std::size_t tri = t.begin; tri < t.end; ++tri) {
            while (next < switches.size() && switches[next].first == tri) {
                w.text("usemtl " + switches[next].second + "\n");
                ++next;
            }
            char* c = w.room();
            *c++ = 'f';
            for (int k = 0; k < 3; ++k) {
                const std::uint64_t idx = m.indices[tri * 3 + static_cast<std::size_t>(k)];
                *c++ = ' ';
                Corner& e = cache[idx % kCacheSize];
                if (e.key != idx + 1) {
                    char text[80]; // three 20-digit numbers, signs and slashes at most
                    const std::size_t len = formatCorner(idx, text);
                    if (len > sizeof e.text) { // absurdly large indices: not cached
                        std::memcpy(c, text, len);
                        c += len;
                        continue;
                    }
                    e.key = idx + 1;
                    e.len = static_cast<std::uint32_t>(len);
                    std::memcpy(e.text, text, len);
                }
                std::memcpy(c, e.text, sizeof e.text);
                c += e.len;
            }
            *c++ = '\n';
            w.done(c);
        }
        break;
    }
    }
}

void checkOptions(const ObjOptions& o) {
    requireRange("position decimals", o.positionDecimals, 1, 9);
    requireRange("normal decimals", o.normalDecimals, 1, 9);
    requireRange("uv decimals", o.uvDecimals, 1, 9);
}

// Splits objects into ordered tasks; \p chunk bounds the vertices/triangles per task.
std::vector<Task> makeTasks(const std::vector<ObjObject>& objects, ObjOffsets& offsets,
                            const ObjOptions& o, std::size_t chunk) {
    std::vector<Task> tasks;
    for (const ObjObject& object : objects) {
        if (!object.mesh) throw InvalidInput("OBJ object '" + object.name + "' has no mesh");
        const mesh::Mesh& m = *object.mesh;
        const std::size_t nv = m.positions.size();
        Task t;
        t.object = &object;
        t.base = offsets;
        t.hasUv = o.uvs && m.uvs.size() == nv && nv > 0;
        t.hasNormal = o.normals && m.normals.size() == nv && nv > 0;
        t.hasColor = o.colors && m.colors.size() == nv && nv > 0;
        t.vertices = nv;
        t.identity = object.transform == glm::mat4(1.0f);
        if (!t.identity) {
            t.normalMatrix = glm::transpose(glm::inverse(glm::mat3(object.transform)));
            // Orthogonal columns of equal length: a rotation times a uniform scale, which
            // divided out leaves a rotation.
            const glm::mat3& nm = t.normalMatrix;
            const float len = glm::length(nm[0]);
            constexpr float kTolerance = 1e-6f;
            auto near = [&](float a, float b) { return std::abs(a - b) <= kTolerance * len * len; };
            if (len > 0.0f && near(glm::dot(nm[1], nm[1]), len * len) &&
                near(glm::dot(nm[2], nm[2]), len * len) && near(glm::dot(nm[0], nm[1]), 0.0f) &&
                near(glm::dot(nm[0], nm[2]), 0.0f) && near(glm::dot(nm[1], nm[2]), 0.0f)) {
                t.normalMatrix = nm / len;
                t.rotationOnly = true;
            }
        }
        tasks.push_back(t);
        auto split = [&](Section s, std::size_t n) {
            for (std::size_t b = 0; b < n; b += chunk) {
                Task c = t;
                c.section = s;
                c.begin = b;
                c.end = std::min(n, b + chunk);
                tasks.push_back(c);
            }
        };
        split(Section::V, nv);
        if (t.hasUv) split(Section::VT, nv);
        if (t.hasNormal) split(Section::VN, nv);
        split(Section::F, m.indices.size() / 3);
        offsets.v += nv;
        if (t.hasUv) offsets.vt += nv;
        if (t.hasNormal) offsets.vn += nv;
    }
    return tasks;
}

std::vector<TextBuffer> formatParts(const std::vector<Task>& tasks, const ObjOptions& o) {
    std::vector<TextBuffer> parts(tasks.size());
#pragma omp parallel for schedule(dynamic, 1)
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(tasks.size()); ++i)
        formatTask(parts[static_cast<std::size_t>(i)], tasks[static_cast<std::size_t>(i)], o);
    return parts;
}

std::string formatTasks(const std::vector<Task>& tasks, const ObjOptions& o) {
    const std::vector<TextBuffer> parts = formatParts(tasks, o);
    std::size_t total = 0;
    for (const TextBuffer& part : parts)
        total += part.view().size();
    std::string out;
    out.reserve(total);
    for (const TextBuffer& part : parts)
        out += part.view();
    return out;
}

constexpr std::size_t kChunk = 32768;

} // namespace

char* formatFixed(char* p, double value, int decimals) {
    withDecimals(decimals, [&](auto d) { p = formatFixedT<decltype(d)::value>(p, value); });
    return p;
}

void appendObj(std::string& out, const ObjObject& object, ObjOffsets& offsets,
               const ObjOptions& options) {
    checkOptions(options);
    const std::vector<ObjObject> one{object};
    const std::vector<Task> tasks = makeTasks(one, offsets, options, static_cast<std::size_t>(-1));
    for (Task t : tasks) {
        t.object = &object;
        TextBuffer text;
        formatTask(text, t, options);
        out += text.view();
    }
}

std::string formatObj(const std::vector<ObjObject>& objects, const ObjOptions& options) {
    checkOptions(options);
    ObjOffsets offsets;
    std::string head;
    if (!options.mtllib.empty()) head = "mtllib " + options.mtllib + "\n";
    const std::vector<Task> tasks = makeTasks(objects, offsets, options, kChunk);
    return head + formatTasks(tasks, options);
}

// The writing half of ObjStreamWriter: one batch in flight on a background thread.
struct ObjStreamWriter::Background {
    std::future<void> pending;
    std::uint64_t kicked = 0; // bytes handed to the kernel's writeback so far
#if defined(__linux__)
    int fd = -1; // a second descriptor of the temporary, only for sync_file_range
    ~Background() {
        if (fd >= 0) ::close(fd);
    }
#endif
};

ObjStreamWriter::ObjStreamWriter(const std::filesystem::path& path, ObjOptions options)
    : mFile(std::make_unique<AtomicFile>(path,
                                         options.fsync ? Durability::Durable : Durability::Atomic)),
      mOptions(std::move(options)), mWriter(std::make_unique<Background>()) {
    checkOptions(mOptions);
#if defined(__linux__)
    if (mOptions.fsync) mWriter->fd = ::open(mFile->temporaryPath().c_str(), O_WRONLY | O_CLOEXEC);
#endif
    if (!mOptions.mtllib.empty()) {
        const std::string head = "mtllib " + mOptions.mtllib + "\n";
        mFile->write(head);
        mBytes += head.size();
    }
}

ObjStreamWriter::~ObjStreamWriter() {
    // The background write must end before the file goes; its error no longer matters.
    if (mWriter && mWriter->pending.valid()) mWriter->pending.wait();
}

void ObjStreamWriter::waitForWriter() {
    if (mWriter->pending.valid()) mWriter->pending.get(); // rethrows IoError
}

void ObjStreamWriter::add(const std::vector<ObjObject>& objects) {
    const std::vector<Task> tasks = makeTasks(objects, mOffsets, mOptions, kChunk);
    std::vector<TextBuffer> parts = formatParts(tasks, mOptions);
    std::uint64_t bytes = 0;
    for (const TextBuffer& part : parts)
        bytes += part.view().size();
    waitForWriter();
    mBytes += bytes;
    const std::uint64_t end = mBytes;
    mWriter->pending = std::async(std::launch::async, [this, end, parts = std::move(parts)] {
        for (const TextBuffer& part : parts)
            mFile->write(part.view());
#if defined(__linux__)
        // Start writing back what is certainly out of stdio's buffer (its size is far below
        // 1 MiB), so the disk works while the next batches are formatted.
        constexpr std::uint64_t kSlack = 1 << 20;
        if (mWriter->fd >= 0 && end > mWriter->kicked + 2 * kSlack) {
            const std::uint64_t upTo = end - kSlack;
            ::sync_file_range(mWriter->fd, static_cast<off_t>(mWriter->kicked),
                              static_cast<off_t>(upTo - mWriter->kicked), SYNC_FILE_RANGE_WRITE);
            mWriter->kicked = upTo;
        }
#else
        (void)end;
#endif
    });
}

void ObjStreamWriter::commit() {
    waitForWriter();
    mFile->commit();
}

void writeObjFile(const std::filesystem::path& path, const std::vector<ObjObject>& objects,
                  const ObjOptions& options, Progress& progress) {
    ObjStreamWriter writer(path, options);
    constexpr std::size_t kBatchVertices = 1 << 18;
    std::vector<ObjObject> batch;
    std::size_t batchVertices = 0;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        batch.push_back(objects[i]);
        batchVertices += objects[i].mesh ? objects[i].mesh->positions.size() : 0;
        if (batchVertices >= kBatchVertices || i + 1 == objects.size()) {
            progress.checkCancelled();
            writer.add(batch);
            progress.report(static_cast<double>(i + 1) / static_cast<double>(objects.size()),
                            "write");
            batch.clear();
            batchVertices = 0;
        }
    }
    writer.commit();
}

} // namespace sylva::exporter
