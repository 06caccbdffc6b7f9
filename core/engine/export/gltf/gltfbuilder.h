#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "engine/util/atomicfile.h"
#include "engine/util/progress.h"

namespace sylva::exporter::gltf {

/// The JSON of a glTF document. Insertion-ordered so the file reads in the order it was built
/// (and, being ordered, is byte-identical for the same calls).
using Json = nlohmann::ordered_json;

enum class GltfFormat {
    Glb,  ///< one binary file: header, JSON chunk, BIN chunk
    Gltf, ///< JSON text plus `<stem>.bin` beside it
};

/// accessor.componentType
enum class ComponentType : int {
    Byte = 5120,
    UnsignedByte = 5121,
    Short = 5122,
    UnsignedShort = 5123,
    UnsignedInt = 5125,
    Float = 5126,
};

/// bufferView.target; None for data no vertex fetch reads (images, animation, skins, instancing).
enum class Target : int { None = 0, ArrayBuffer = 34962, ElementArrayBuffer = 34963 };

/// One primitive of a mesh. Attribute names are glTF semantics (POSITION, NORMAL, TEXCOORD_0,
/// JOINTS_0, WEIGHTS_0) or application-specific ones, which glTF requires to start with '_'.
struct Primitive {
    std::vector<std::pair<std::string, int>> attributes; ///< semantic → accessor, in file order
    int indices = -1;                                    ///< accessor, -1: not indexed
    int material = -1;
    int mode = 4; ///< TRIANGLES
    Json extensions{};
    Json extras{};
};

/// A node. Only the non-default members are written.
struct Node {
    std::string name;
    int mesh = -1;
    int skin = -1;
    std::vector<int> children;
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f}; ///< w, x, y, z (glm); written as [x, y, z, w]
    glm::vec3 scale{1.0f};
    Json extensions{}; ///< e.g. {"EXT_mesh_gpu_instancing": {...}}, {"MSFT_lod": {...}}
    Json extras{};
};

struct AnimationSampler {
    int input = -1;  ///< accessor of key times (seconds, SCALAR float, with min/max)
    int output = -1; ///< accessor of values (VEC3 translation/scale, VEC4 rotation)
    std::string interpolation = "LINEAR";
};

struct AnimationChannel {
    int sampler = -1; ///< index into Animation::samplers
    int node = -1;
    std::string path; ///< "translation", "rotation", "scale", "weights"
};

struct Animation {
    std::string name;
    std::vector<AnimationSampler> samplers;
    std::vector<AnimationChannel> channels;
};

struct Skin {
    std::string name;
    int inverseBindMatrices = -1; ///< accessor of MAT4 float, one per joint
    std::vector<int> joints;      ///< node indices
    int skeleton = -1;            ///< common root node, -1: none given
};

/// Low-level glTF 2.0 writer. Binary data goes to a temporary file beside the output as it is
/// added (each add* call writes its bytes at once), so memory is bounded by what the caller holds
/// for one call, never the whole buffer; the JSON (small: one entry per accessor, mesh, node)
/// stays in memory. finish() writes the .glb (header, JSON chunk, BIN chunk copied from the
/// temporary, both padded to 4 bytes) or the .gltf and its .bin, atomically: nothing appears at
/// the path before finish() succeeds, and the destructor removes the temporaries otherwise.
/// Every add of binary data and the final copy call \p progress.checkCancelled(), so a cancel
/// stops the export at the next array (Cancelled is thrown, the temporaries are removed).
///
/// Indices returned by the add* functions are the glTF indices of what was added.
/// The output is a pure function of the calls made: the same calls give byte-identical files.
class GltfBuilder {
public:
    /// \throw IoError when the temporary cannot be created.
    GltfBuilder(std::filesystem::path path, GltfFormat format, Progress& progress = noProgress(),
                Durability durability = Durability::Atomic);
    ~GltfBuilder();
    GltfBuilder(const GltfBuilder&) = delete;
    GltfBuilder& operator=(const GltfBuilder&) = delete;

    // --- binary data -----------------------------------------------------------------------

    /// Appends \p bytes as a new bufferView (its start aligned to 4 bytes) and returns its index.
    int addBufferView(std::span<const std::byte> bytes, Target target = Target::None,
                      int byteStride = 0);

    /// A new accessor over \p bufferView. \p type is "SCALAR", "VEC2", "VEC3", "VEC4", "MAT4"...
    /// \p min / \p max are written when not empty (one value per component).
    int addAccessor(int bufferView, ComponentType componentType, std::size_t count,
                    std::string_view type, std::size_t byteOffset = 0, bool normalized = false,
                    const std::vector<double>& min = {}, const std::vector<double>& max = {});

    /// Float arrays as a bufferView plus an accessor. \p bounds: write min/max (required for
    /// POSITION and animation inputs; glTF allows them everywhere).
    int addFloats(std::span<const float> values, Target target = Target::None, bool bounds = false);
    int addVec2(std::span<const glm::vec2> values, Target target = Target::ArrayBuffer,
                bool bounds = false);
    int addVec3(std::span<const glm::vec3> values, Target target = Target::ArrayBuffer,
                bool bounds = false);
    int addVec4(std::span<const glm::vec4> values, Target target = Target::ArrayBuffer,
                bool bounds = false);
    /// Quaternions as VEC4 [x, y, z, w] (instancing ROTATION, animation rotation output).
    int addQuats(std::span<const glm::quat> values, Target target = Target::None);
    int addMat4(std::span<const glm::mat4> values); ///< column-major, e.g. inverseBindMatrices
    /// Unsigned integers of one component type with \p components per element (JOINTS_0 as
    /// 4 × UnsignedShort, a custom `_ORDER` as 1 × UnsignedShort); \p normalized for colours and
    /// weights stored as integers.
    int addUint8(std::span<const std::uint8_t> values, int components,
                 Target target = Target::ArrayBuffer, bool normalized = false, bool bounds = false);
    int addUint16(std::span<const std::uint16_t> values, int components,
                  Target target = Target::ArrayBuffer, bool normalized = false,
                  bool bounds = false);
    /// Triangle (or line) indices: written as unsigned short when every index fits, else as
    /// unsigned int (ELEMENT_ARRAY_BUFFER).
    int addIndices(std::span<const std::uint32_t> indices);

    /// An image embedded as a bufferView (valid in .glb and .gltf alike). \p mimeType
    /// "image/png" or "image/jpeg".
    int addImage(std::span<const std::byte> bytes, std::string_view mimeType,
                 std::string_view name = {});
    /// An image referenced by URI (relative to the .gltf).
    int addImageUri(std::string_view uri, std::string_view name = {});

    // --- JSON entities ---------------------------------------------------------------------

    /// \p sampler: e.g. {"magFilter":9729,"minFilter":9987,"wrapS":10497,"wrapT":10497}.
    int addSampler(const Json& sampler);
    int addTexture(int image, int sampler = -1);
    /// A material object as glTF spells it (name, pbrMetallicRoughness, alphaMode...).
    int addMaterial(const Json& material);
    int addMesh(std::string_view name, const std::vector<Primitive>& primitives,
                const Json& extras = {});
    int addNode(const Node& node);
    /// Adds \p child to \p parent's children (for parents made before their children).
    void addChild(int parent, int child);
    int addSkin(const Skin& skin);
    int addAnimation(const Animation& animation);
    /// A scene with \p nodes as its roots; the first scene added is the default one.
    int addScene(std::string_view name, const std::vector<int>& nodes);
    /// Lists \p name in extensionsUsed (and extensionsRequired when \p required), once.
    void useExtension(std::string_view name, bool required = false);
    /// asset.extras, root extras and anything else not covered above.
    Json& root() { return mJson; }
    /// The node's JSON, to add extensions or extras after it was made.
    Json& node(int index);

    std::size_t binaryBytes() const { return mBinSize; }

    /// Writes the file(s) and returns them (main file first). Call once.
    /// \throw IoError, Cancelled, LimitExceeded (a .glb above 4 GiB: write .gltf instead)
    std::vector<std::filesystem::path> finish();

private:
    /// What precedes the BIN data of a .glb ends on this boundary (file-system blocks).
    static constexpr std::size_t kPrefixAlign = 4096;
    /// Turns the BIN temporary into the .glb by inserting \p prefix before its data, and renames
    /// it into place; false where the file system cannot insert (then nothing was changed).
    bool prependInPlace(const std::string& prefix);
    int push(const char* array, Json value);
    void writeRaw(const void* data, std::size_t bytes);
    std::string jsonText();

    std::filesystem::path mPath;
    GltfFormat mFormat;
    Progress& mProgress;
    Durability mDurability;
    Json mJson;
    Json mExtensionsUsed = Json::array();
    Json mExtensionsRequired = Json::array();
    std::filesystem::path mBinTemp;
    std::FILE* mBin = nullptr;
    std::size_t mBinSize = 0;
    bool mFinished = false;
};

/// A float as the shortest decimal that reads back as the same float (1.2f → 1.2, not
/// 1.2000000476837158): for JSON numbers that are not accessor bounds.
double tidy(float value);

} // namespace sylva::exporter::gltf
