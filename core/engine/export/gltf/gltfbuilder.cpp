#include "engine/export/gltf/gltfbuilder.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <linux/falloc.h>
#include <random>
#include <unistd.h>

#include "engine/util/error.h"
#include "engine/util/text.h"

namespace sylva::exporter::gltf {

namespace fs = std::filesystem;

namespace {

// The arrays of the document in the order they are written (asset first, buffers last, as the
// glTF sample files do).
constexpr std::array<const char*, 13> kArrays = {
    "scenes", "nodes",    "meshes",  "skins",     "animations",  "materials", "textures",
    "images", "samplers", "cameras", "accessors", "bufferViews", "buffers"};

fs::path temporaryBeside(const fs::path& path, std::string_view suffix) {
    // Beside the output: the .bin of a .gltf is renamed into place (one file system), and the
    // folder was chosen by the user for a file this large (/tmp may be a memory file system).
    std::random_device rd;
    std::string name(1, '.');
    name.append(path.filename().string());
    name.append(suffix);
    name.append(std::to_string(::getpid()));
    name.push_back('-');
    name.append(std::to_string(rd()));
    return path.parent_path() / name;
}

template <int N, class V>
void bounds(std::span<const V> values, std::vector<double>& lo, std::vector<double>& hi) {
    lo.assign(N, 0.0);
    hi.assign(N, 0.0);
    if (values.empty()) return;
    for (int c = 0; c < N; ++c)
        lo[c] = hi[c] = static_cast<double>(values[0][c]);
    for (const V& v : values)
        for (int c = 0; c < N; ++c) {
            lo[c] = std::min(lo[c], static_cast<double>(v[c]));
            hi[c] = std::max(hi[c], static_cast<double>(v[c]));
        }
}

template <class T> std::span<const std::byte> bytesOf(std::span<const T> values) {
    return std::as_bytes(values);
}

// nlohmann writes NaN and infinity as null, which no reader accepts where a number belongs:
// refuse the document instead, naming where the number was (the JSON pointer is built only on
// the way back from a bad number, not for each of the document's values).
bool findNonFinite(const Json& j, std::string& where) {
    if (j.is_number_float()) return !std::isfinite(j.get<double>());
    if (j.is_object()) {
        for (auto it = j.begin(); it != j.end(); ++it)
            if (findNonFinite(it.value(), where)) {
                where.insert(0, "/" + it.key());
                return true;
            }
    } else if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i)
            if (findNonFinite(j[i], where)) {
                where.insert(0, "/" + std::to_string(i));
                return true;
            }
    }
    return false;
}

void requireFinite(const Json& j) {
    std::string where;
    if (findNonFinite(j, where)) throw InvalidInput("glTF export: a non-finite number at " + where);
}

} // namespace

double tidy(float value) {
    return decimalOf(value);
}

GltfBuilder::GltfBuilder(fs::path path, GltfFormat format, Progress& progress,
                         Durability durability)
    : mPath(std::move(path)), mFormat(format), mProgress(progress), mDurability(durability) {
    mJson["asset"] = {{"version", "2.0"}, {"generator", "Sylva"}};
    mBinTemp = temporaryBeside(mPath, ".bin.tmp");
    mBin = std::fopen(mBinTemp.c_str(), "w+b");
    if (!mBin) throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));
}

GltfBuilder::~GltfBuilder() {
    if (mBin) std::fclose(mBin);
    std::error_code ec;
    if (!mBinTemp.empty()) fs::remove(mBinTemp, ec);
}

int GltfBuilder::push(const char* array, Json value) {
    Json& a = mJson[array];
    if (a.is_null()) a = Json::array();
    a.push_back(std::move(value));
    return static_cast<int>(a.size() - 1);
}

Json& GltfBuilder::node(int index) {
    return mJson.at("nodes").at(static_cast<std::size_t>(index));
}

void GltfBuilder::writeRaw(const void* data, std::size_t bytes) {
    if (bytes == 0) return;
    if (std::fwrite(data, 1, bytes, mBin) != bytes)
        throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));
    mBinSize += bytes;
}

int GltfBuilder::addBufferView(std::span<const std::byte> bytes, Target target, int byteStride) {
    mProgress.checkCancelled();
    static constexpr char kZeros[4] = {0, 0, 0, 0};
    writeRaw(kZeros, (4 - mBinSize % 4) % 4);
    Json view = {{"buffer", 0}, {"byteOffset", mBinSize}, {"byteLength", bytes.size()}};
    if (byteStride > 0) view["byteStride"] = byteStride;
    if (target != Target::None) view["target"] = static_cast<int>(target);
    writeRaw(bytes.data(), bytes.size());
    return push("bufferViews", std::move(view));
}

int GltfBuilder::addAccessor(int bufferView, ComponentType componentType, std::size_t count,
                             std::string_view type, std::size_t byteOffset, bool normalized,
                             const std::vector<double>& min, const std::vector<double>& max) {
    Json a;
    if (bufferView >= 0) a["bufferView"] = bufferView;
    if (byteOffset) a["byteOffset"] = byteOffset;
    a["componentType"] = static_cast<int>(componentType);
    if (normalized) a["normalized"] = true;
    a["count"] = count;
    a["type"] = type;
    if (!min.empty()) a["min"] = min;
    if (!max.empty()) a["max"] = max;
    return push("accessors", std::move(a));
}

int GltfBuilder::addFloats(std::span<const float> values, Target target, bool withBounds) {
    std::vector<double> lo, hi;
    if (withBounds && !values.empty()) {
        const auto [a, b] = std::minmax_element(values.begin(), values.end());
        lo = {static_cast<double>(*a)};
        hi = {static_cast<double>(*b)};
    }
    const int view = addBufferView(bytesOf(values), target);
    return addAccessor(view, ComponentType::Float, values.size(), "SCALAR", 0, false, lo, hi);
}

int GltfBuilder::addVec2(std::span<const glm::vec2> values, Target target, bool withBounds) {
    std::vector<double> lo, hi;
    if (withBounds) bounds<2>(values, lo, hi);
    const int view = addBufferView(bytesOf(values), target);
    return addAccessor(view, ComponentType::Float, values.size(), "VEC2", 0, false, lo, hi);
}

int GltfBuilder::addVec3(std::span<const glm::vec3> values, Target target, bool withBounds) {
    std::vector<double> lo, hi;
    if (withBounds) bounds<3>(values, lo, hi);
    const int view = addBufferView(bytesOf(values), target);
    return addAccessor(view, ComponentType::Float, values.size(), "VEC3", 0, false, lo, hi);
}

int GltfBuilder::addVec4(std::span<const glm::vec4> values, Target target, bool withBounds) {
    std::vector<double> lo, hi;
    if (withBounds) bounds<4>(values, lo, hi);
    const int view = addBufferView(bytesOf(values), target);
    return addAccessor(view, ComponentType::Float, values.size(), "VEC4", 0, false, lo, hi);
}

int GltfBuilder::addQuats(std::span<const glm::quat> values, Target target) {
    // GLM_FORCE_XYZW_ONLY stores a quat as x, y, z, w: glTF's order, so the bytes go as they are.
    static_assert(sizeof(glm::quat) == 4 * sizeof(float));
    const int view = addBufferView(bytesOf(values), target);
    return addAccessor(view, ComponentType::Float, values.size(), "VEC4");
}

int GltfBuilder::addMat4(std::span<const glm::mat4> values) {
    const int view = addBufferView(bytesOf(values));
    return addAccessor(view, ComponentType::Float, values.size(), "MAT4");
}

namespace {
const char* typeFor(int components) {
    switch (components) {
    case 1:
        return "SCALAR";
    case 2:
        return "VEC2";
    case 3:
        return "VEC3";
    case 4:
        return "VEC4";
    default:
        throw InvalidInput("glTF accessor with " + std::to_string(components) +
                           " components (1 to 4 allowed)");
    }
}

template <class T>
void intBounds(std::span<const T> values, int components, std::vector<double>& lo,
               std::vector<double>& hi) {
    lo.assign(static_cast<std::size_t>(components), std::numeric_limits<double>::max());
    hi.assign(static_cast<std::size_t>(components), std::numeric_limits<double>::lowest());
    for (std::size_t i = 0; i < values.size(); ++i) {
        const std::size_t c = i % static_cast<std::size_t>(components);
        lo[c] = std::min(lo[c], static_cast<double>(values[i]));
        hi[c] = std::max(hi[c], static_cast<double>(values[i]));
    }
}
} // namespace

int GltfBuilder::addUint8(std::span<const std::uint8_t> values, int components, Target target,
                          bool normalized, bool withBounds) {
    const char* type = typeFor(components);
    std::vector<double> lo, hi;
    if (withBounds && !values.empty()) intBounds(values, components, lo, hi);
    // Vertex attributes must start and stride on 4 bytes: pad each element when needed.
    const auto n = static_cast<std::size_t>(components);
    if (target == Target::ArrayBuffer && n % 4 != 0) {
        std::vector<std::uint8_t> padded(values.size() / n * 4, 0);
        for (std::size_t i = 0; i < values.size(); ++i)
            padded[i / n * 4 + i % n] = values[i];
        const int view = addBufferView(bytesOf(std::span<const std::uint8_t>(padded)), target, 4);
        return addAccessor(view, ComponentType::UnsignedByte, values.size() / n, type, 0,
                           normalized, lo, hi);
    }
    const int view = addBufferView(bytesOf(values), target);
    return addAccessor(view, ComponentType::UnsignedByte, values.size() / n, type, 0, normalized,
                       lo, hi);
}

int GltfBuilder::addUint16(std::span<const std::uint16_t> values, int components, Target target,
                           bool normalized, bool withBounds) {
    const char* type = typeFor(components);
    std::vector<double> lo, hi;
    if (withBounds && !values.empty()) intBounds(values, components, lo, hi);
    const auto n = static_cast<std::size_t>(components);
    if (target == Target::ArrayBuffer && n % 2 != 0) {
        const std::size_t stride = n + 1; // 1 → 2, 3 → 4 shorts: a 4-byte stride
        std::vector<std::uint16_t> padded(values.size() / n * stride, 0);
        for (std::size_t i = 0; i < values.size(); ++i)
            padded[i / n * stride + i % n] = values[i];
        const int view = addBufferView(bytesOf(std::span<const std::uint16_t>(padded)), target,
                                       static_cast<int>(stride * 2));
        return addAccessor(view, ComponentType::UnsignedShort, values.size() / n, type, 0,
                           normalized, lo, hi);
    }
    const int view = addBufferView(bytesOf(values), target);
    return addAccessor(view, ComponentType::UnsignedShort, values.size() / n, type, 0, normalized,
                       lo, hi);
}

int GltfBuilder::addIndices(std::span<const std::uint32_t> indices) {
    const std::uint32_t top =
        indices.empty() ? 0 : *std::max_element(indices.begin(), indices.end());
    // 0xffff is the primitive-restart value, which glTF forbids in unsigned short indices.
    if (top < 0xffffu) {
        std::vector<std::uint16_t> shorts(indices.begin(), indices.end());
        const int view = addBufferView(bytesOf(std::span<const std::uint16_t>(shorts)),
                                       Target::ElementArrayBuffer);
        return addAccessor(view, ComponentType::UnsignedShort, indices.size(), "SCALAR");
    }
    const int view = addBufferView(bytesOf(indices), Target::ElementArrayBuffer);
    return addAccessor(view, ComponentType::UnsignedInt, indices.size(), "SCALAR");
}

int GltfBuilder::addImage(std::span<const std::byte> bytes, std::string_view mimeType,
                          std::string_view name) {
    const int view = addBufferView(bytes);
    Json image;
    if (!name.empty()) image["name"] = name;
    image["bufferView"] = view;
    image["mimeType"] = mimeType;
    return push("images", std::move(image));
}

int GltfBuilder::addImageUri(std::string_view uri, std::string_view name) {
    Json image;
    if (!name.empty()) image["name"] = name;
    image["uri"] = uri;
    return push("images", std::move(image));
}

int GltfBuilder::addSampler(const Json& sampler) {
    return push("samplers", sampler);
}

int GltfBuilder::addTexture(int image, int sampler) {
    Json t;
    if (sampler >= 0) t["sampler"] = sampler;
    t["source"] = image;
    return push("textures", std::move(t));
}

int GltfBuilder::addMaterial(const Json& material) {
    return push("materials", material);
}

int GltfBuilder::addMesh(std::string_view name, const std::vector<Primitive>& primitives,
                         const Json& extras) {
    Json m;
    if (!name.empty()) m["name"] = name;
    Json prims = Json::array();
    for (const Primitive& p : primitives) {
        Json j;
        Json attributes = Json::object();
        for (const auto& [semantic, accessor] : p.attributes)
            attributes[semantic] = accessor;
        j["attributes"] = std::move(attributes);
        if (p.indices >= 0) j["indices"] = p.indices;
        if (p.material >= 0) j["material"] = p.material;
        if (p.mode != 4) j["mode"] = p.mode;
        if (!p.extensions.is_null()) j["extensions"] = p.extensions;
        if (!p.extras.is_null()) j["extras"] = p.extras;
        prims.push_back(std::move(j));
    }
    m["primitives"] = std::move(prims);
    if (!extras.is_null()) m["extras"] = extras;
    return push("meshes", std::move(m));
}

int GltfBuilder::addNode(const Node& n) {
    Json j;
    if (!n.name.empty()) j["name"] = n.name;
    if (n.mesh >= 0) j["mesh"] = n.mesh;
    if (n.skin >= 0) j["skin"] = n.skin;
    if (!n.children.empty()) j["children"] = n.children;
    if (n.translation != glm::vec3(0.0f))
        j["translation"] = {tidy(n.translation.x), tidy(n.translation.y), tidy(n.translation.z)};
    if (n.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f))
        j["rotation"] = {tidy(n.rotation.x), tidy(n.rotation.y), tidy(n.rotation.z),
                         tidy(n.rotation.w)};
    if (n.scale != glm::vec3(1.0f))
        j["scale"] = {tidy(n.scale.x), tidy(n.scale.y), tidy(n.scale.z)};
    if (!n.extensions.is_null()) j["extensions"] = n.extensions;
    if (!n.extras.is_null()) j["extras"] = n.extras;
    return push("nodes", std::move(j));
}

void GltfBuilder::addChild(int parent, int child) {
    Json& p = node(parent);
    if (!p.contains("children")) p["children"] = Json::array();
    p["children"].push_back(child);
}

int GltfBuilder::addSkin(const Skin& skin) {
    Json j;
    if (!skin.name.empty()) j["name"] = skin.name;
    if (skin.inverseBindMatrices >= 0) j["inverseBindMatrices"] = skin.inverseBindMatrices;
    if (skin.skeleton >= 0) j["skeleton"] = skin.skeleton;
    j["joints"] = skin.joints;
    return push("skins", std::move(j));
}

int GltfBuilder::addAnimation(const Animation& animation) {
    Json j;
    if (!animation.name.empty()) j["name"] = animation.name;
    Json channels = Json::array();
    for (const AnimationChannel& c : animation.channels)
        channels.push_back(
            {{"sampler", c.sampler}, {"target", {{"node", c.node}, {"path", c.path}}}});
    Json samplers = Json::array();
    for (const AnimationSampler& s : animation.samplers)
        samplers.push_back(
            {{"input", s.input}, {"interpolation", s.interpolation}, {"output", s.output}});
    j["channels"] = std::move(channels);
    j["samplers"] = std::move(samplers);
    return push("animations", std::move(j));
}

int GltfBuilder::addScene(std::string_view name, const std::vector<int>& nodes) {
    Json s;
    if (!name.empty()) s["name"] = name;
    s["nodes"] = nodes;
    return push("scenes", std::move(s));
}

void GltfBuilder::useExtension(std::string_view name, bool required) {
    const auto add = [&](Json& list) {
        if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
    };
    add(mExtensionsUsed);
    if (required) add(mExtensionsRequired);
}

std::string GltfBuilder::jsonText() {
    Json out;
    // Moved, not copied: jsonText() runs once, from finish().
    out["asset"] = std::move(mJson["asset"]);
    if (!mExtensionsUsed.empty()) out["extensionsUsed"] = mExtensionsUsed;
    if (!mExtensionsRequired.empty()) out["extensionsRequired"] = mExtensionsRequired;
    if (mJson.contains("scenes")) out["scene"] = 0;
    for (const char* name : kArrays) {
        if (std::string_view(name) == "buffers") {
            if (mBinSize == 0) continue;
            Json buffer = {{"byteLength", (mBinSize + 3) / 4 * 4}};
            if (mFormat == GltfFormat::Gltf) buffer["uri"] = mPath.stem().string() + ".bin";
            out["buffers"] = Json::array({buffer});
            continue;
        }
        if (mJson.contains(name) && !mJson[name].empty()) out[name] = std::move(mJson[name]);
    }
    // Whatever the caller put in root() beyond the arrays (extras, extensions) goes last.
    for (auto it = mJson.begin(); it != mJson.end(); ++it)
        if (!out.contains(it.key()) &&
            std::find_if(kArrays.begin(), kArrays.end(),
                         [&](const char* a) { return it.key() == a; }) == kArrays.end())
            out[it.key()] = std::move(it.value());
    requireFinite(out);
    // Names come from file names and species: invalid UTF-8 becomes U+FFFD, not an exception.
    return out.dump(-1, ' ', false, Json::error_handler_t::replace);
}

bool GltfBuilder::prependInPlace(const std::string& prefix) {
    // FALLOC_FL_INSERT_RANGE shifts the BIN data up by whole file-system blocks without moving
    // it through memory (ext4, XFS); elsewhere (tmpfs, btrfs, blocks above 4 KiB) it fails and
    // the caller copies instead.
    const int fd = ::fileno(mBin);
    if (prefix.size() % kPrefixAlign != 0 ||
        ::fallocate(fd, FALLOC_FL_INSERT_RANGE, 0, static_cast<off_t>(prefix.size())) != 0)
        return false;
    std::size_t done = 0;
    while (done < prefix.size()) {
        const ssize_t n =
            ::pwrite(fd, prefix.data() + done, prefix.size() - done, static_cast<off_t>(done));
        if (n <= 0) throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));
        done += static_cast<std::size_t>(n);
    }
    if (mDurability == Durability::Durable && ::fsync(fd) != 0)
        throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));
    const int rc = std::fclose(mBin);
    mBin = nullptr;
    if (rc != 0) throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));
    mProgress.checkCancelled();
    std::error_code ec;
    fs::rename(mBinTemp, mPath, ec);
    if (ec) throw IoError("cannot replace " + mPath.string() + ": " + ec.message());
    mBinTemp.clear();
    return true;
}

std::vector<fs::path> GltfBuilder::finish() {
    if (mFinished) throw InvalidInput("GltfBuilder::finish called twice");
    mFinished = true;
    mProgress.checkCancelled();
    static constexpr char kZeros[4] = {0, 0, 0, 0};
    writeRaw(kZeros, (4 - mBinSize % 4) % 4);
    if (std::fflush(mBin) != 0)
        throw IoError("cannot write " + mPath.string() + ": " + std::strerror(errno));

    std::string json = jsonText();
    if (mFormat == GltfFormat::Gltf) {
        std::vector<fs::path> written{mPath};
        if (mBinSize > 0) {
            const fs::path bin = mPath.parent_path() / (mPath.stem().string() + ".bin");
            if (mDurability == Durability::Durable && ::fsync(::fileno(mBin)) != 0)
                throw IoError("cannot write " + bin.string() + ": " + std::strerror(errno));
            std::fclose(mBin);
            mBin = nullptr;
            std::error_code ec;
            fs::rename(mBinTemp, bin, ec);
            if (ec) throw IoError("cannot replace " + bin.string() + ": " + ec.message());
            mBinTemp.clear();
            written.push_back(bin);
        }
        json.push_back('\n');
        AtomicFile file(mPath, mDurability);
        file.write(json);
        file.commit();
        return written;
    }

    // GLB: JSON chunk padded with spaces, BIN chunk with zeros (already), lengths little-endian.
    // With a BIN chunk, the JSON is padded further so that everything before the BIN data ends
    // on a 4 KiB boundary: then the BIN temporary can become the .glb by inserting that many
    // bytes in front of its data (no copy). The padding is the same whichever way the file is
    // made, so the bytes do not depend on the file system.
    const std::size_t align = mBinSize > 0 ? kPrefixAlign : 4;
    const std::size_t fixed = mBinSize > 0 ? 12 + 8 + 8 : 12 + 8;
    while ((fixed + json.size()) % align != 0)
        json.push_back(' ');
    const std::uint64_t total = 12 + 8 + json.size() + (mBinSize ? 8 + mBinSize : 0);
    if (total > std::numeric_limits<std::uint32_t>::max())
        throw LimitExceeded("a .glb holds at most 4 GiB and this one would be " +
                            std::to_string(total >> 20) +
                            " MiB: export to .gltf (JSON + .bin) instead");
    const auto u32 = [](std::string& s, std::uint32_t v) {
        for (int i = 0; i < 4; ++i)
            s.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
    };
    std::string head;
    u32(head, 0x46546C67u); // "glTF"
    u32(head, 2);
    u32(head, static_cast<std::uint32_t>(total));
    u32(head, static_cast<std::uint32_t>(json.size()));
    u32(head, 0x4E4F534Au); // "JSON"
    std::string binHead;
    if (mBinSize > 0) {
        u32(binHead, static_cast<std::uint32_t>(mBinSize));
        u32(binHead, 0x004E4942u); // "BIN\0"
        mProgress.checkCancelled();
        if (prependInPlace(head + json + binHead)) return {mPath};
    }
    AtomicFile file(mPath, mDurability);
    file.write(head);
    file.write(json);
    if (mBinSize > 0) {
        file.write(binHead);
        // The kernel copies the BIN chunk (no trip through user memory; a reflink where the file
        // system shares blocks), 64 MiB at a time so a cancel is seen within a fraction of a
        // second; where it cannot (another file system type, an old kernel), read and write.
        const int out = file.flushedDescriptor();
        const int in = ::fileno(mBin);
        std::size_t left = mBinSize;
        off_t from = 0;
        while (left > 0) {
            mProgress.checkCancelled();
            const ssize_t n = ::copy_file_range(
                in, &from, out, nullptr, std::min<std::size_t>(left, std::size_t(64) << 20), 0);
            if (n <= 0) break;
            left -= static_cast<std::size_t>(n);
        }
        if (left > 0 && std::fseek(mBin, static_cast<long>(mBinSize - left), SEEK_SET) != 0)
            throw IoError("cannot read back " + mBinTemp.string() + ": " + std::strerror(errno));
        std::vector<char> chunk(left > 0 ? std::size_t(4) << 20 : 0);
        while (left > 0) {
            mProgress.checkCancelled();
            const std::size_t n = std::fread(chunk.data(), 1, std::min(left, chunk.size()), mBin);
            if (n == 0)
                throw IoError("cannot read back " + mBinTemp.string() + ": " +
                              std::strerror(errno));
            file.write(std::string_view(chunk.data(), n));
            left -= n;
        }
    }
    mProgress.checkCancelled();
    file.commit();
    return {mPath};
}

} // namespace sylva::exporter::gltf
