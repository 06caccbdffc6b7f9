#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/mesh/mesh.h"
#include "engine/util/progress.h"

namespace sylva {
class AtomicFile;
}

namespace sylva::exporter {

/// One OBJ object (`o name`): a mesh placed by a transform (an instance of a tree).
struct ObjObject {
    std::string name; ///< written after `o`; spaces become '_'
    const mesh::Mesh* mesh = nullptr;
    glm::mat4 transform{1.0f}; ///< applied to positions; normals get its inverse transpose
};

/// What the writer emits and how precisely.
struct ObjOptions {
    bool normals = true; ///< `vn` (when the mesh has them)
    bool uvs = true;     ///< `vt` (when the mesh has them)
    /// Vertex colours (Mesh::colors, leaf tints) as `v x y z r g b`, sRGB to 3 decimals: the
    /// extension Blender's and Assimp's OBJ readers take (when the mesh has them).
    bool colors = true;
    bool materials = true;    ///< `usemtl <submesh material>` before each run of faces
    std::string mtllib;       ///< written as `mtllib <name>` at the top when not empty
    int positionDecimals = 6; ///< fixed decimals of `v` (6 = micrometres), 1..9
    int normalDecimals = 4;   ///< of `vn`, 1..9
    int uvDecimals = 5;       ///< of `vt`, 1..9
    /// Faces use negative (relative) indices, `f -3/-3/-3 ...`, counted back from the object's
    /// last v/vt/vn: standard OBJ, shorter in large files (a forest's absolute indices reach
    /// 8 digits) and the same for every instance of a mesh. Assimp and Blender read them.
    bool relativeIndices = false;
    /// Files: wait for the disk (fsync) before the rename (see sylva::Durability). Off by
    /// default: the export is atomic either way, and a multi-gigabyte forest would otherwise
    /// spend most of its time waiting for the disk.
    bool fsync = false;

    /// Smaller files for large forests: positions to 0.1 mm (4 decimals), normals to 3 decimals
    /// (direction error below 0.1°), uvs to 4 decimals (a texel of a 10k texture), relative
    /// face indices.
    static ObjOptions compact() {
        ObjOptions o;
        o.positionDecimals = 4;
        o.normalDecimals = 3;
        o.uvDecimals = 4;
        o.relativeIndices = true;
        return o;
    }
};

/// Running 1-based indices of the next v / vt / vn, carried from object to object.
struct ObjOffsets {
    std::uint64_t v = 1;
    std::uint64_t vt = 1;
    std::uint64_t vn = 1;
};

/// Appends one object in OBJ text to \p out and advances \p offsets. Numbers are formatted
/// without iostreams (fixed decimals, trailing zeros trimmed), faces as `f v/vt/vn`.
void appendObj(std::string& out, const ObjObject& object, ObjOffsets& offsets,
               const ObjOptions& options = {});

/// Formats several objects: the text is cut into chunks (per object and per 32k vertices or
/// faces) formatted in parallel with OpenMP and joined in order, so the bytes are the same on
/// any thread count. Includes the `mtllib` line when options.mtllib is set.
std::string formatObj(const std::vector<ObjObject>& objects, const ObjOptions& options = {});

/// Streams objects into an OBJ file through AtomicFile: a forest larger than memory can be
/// written batch by batch (each batch formatted in parallel). Writing is double-buffered: a
/// background thread writes batch k while batch k+1 is formatted. With options.fsync it also
/// asks the kernel to start writing the file back to disk as it goes (Linux), so that
/// commit()'s fsync waits only for the tail. Nothing appears at the path unless commit() runs.
class ObjStreamWriter {
public:
    ObjStreamWriter(const std::filesystem::path& path, ObjOptions options = {});
    ~ObjStreamWriter();
    ObjStreamWriter(const ObjStreamWriter&) = delete;
    ObjStreamWriter& operator=(const ObjStreamWriter&) = delete;

    /// Formats and writes a batch of objects (after all earlier batches).
    void add(const std::vector<ObjObject>& objects);
    /// Bytes written so far.
    std::uint64_t bytesWritten() const { return mBytes; }
    /// Flushes and renames the temporary into place.
    void commit();

private:
    struct Background;
    void waitForWriter();

    std::unique_ptr<AtomicFile> mFile;
    ObjOptions mOptions;
    ObjOffsets mOffsets;
    std::uint64_t mBytes = 0;
    std::unique_ptr<Background> mWriter;
};

/// Writes all objects to \p path atomically, in batches of about 256k vertices (~55 MB of
/// text): small enough that formatting one and writing the previous overlap with little idle
/// time at the start and the end.
/// \throw IoError when the file cannot be written; Cancelled through \p progress.
void writeObjFile(const std::filesystem::path& path, const std::vector<ObjObject>& objects,
                  const ObjOptions& options = {}, Progress& progress = noProgress());

/// Writes \p value with \p decimals fixed decimals (trailing zeros trimmed) at \p p and returns
/// the end; very large or non-finite values fall back to std::to_chars. Needs 40 bytes.
char* formatFixed(char* p, double value, int decimals);

} // namespace sylva::exporter
