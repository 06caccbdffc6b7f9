#include "engine/environment/obstaclemesh.h"

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <string>
#include <system_error>
#include <vector>

#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/environment/meshfilecheck.h"
#include "engine/util/atomicfile.h"
#include "engine/util/error.h"

namespace sylva::env {

glm::mat4 MeshTransform::matrix() const {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), translate);
    m = glm::rotate(m, glm::radians(rotateDeg.z), glm::vec3(0, 0, 1));
    m = glm::rotate(m, glm::radians(rotateDeg.y), glm::vec3(0, 1, 0));
    m = glm::rotate(m, glm::radians(rotateDeg.x), glm::vec3(1, 0, 0));
    return glm::scale(m, scale);
}

namespace {

std::atomic<std::size_t> gFilesRead{0};

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string quoted(const std::filesystem::path& file) {
    return "'" + file.string() + "'";
}

/// Leaves \p importer only the importers that claim the end of \p name (lower case) as one of
/// their extensions (as Assimp matches them: `mesh.xml` too); returns how many remain. Assimp
/// picks a file's importer by its extension, but when every importer of the extension refuses
/// the file it tries all of its ~40 importers on the content: a `.glb` whose magic was moved was
/// read by the OpenGEX importer (its first bytes held "indexarray"), which read past its buffer
/// (fuzz finding 31). The formats that reach Assimp are the ones the file names. Unregistered
/// importers are deleted here (Assimp's UnregisterLoader only forgets them).
std::size_t keepImportersOf(Assimp::Importer& importer, const std::string& name) {
    std::vector<Assimp::BaseImporter*> others;
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
        Assimp::BaseImporter* candidate = importer.GetImporter(i);
        std::set<std::string> extensions;
        candidate->GetExtensionList(extensions);
        bool claims = false;
        for (const std::string& extension : extensions) {
            std::string e(1, '.');
            e += lowerAscii(extension);
            claims = claims || (name.size() > e.size() &&
                                name.compare(name.size() - e.size(), e.size(), e) == 0);
        }
        if (!claims) others.push_back(candidate);
    }
    for (Assimp::BaseImporter* other : others)
        if (importer.UnregisterLoader(other) == AI_SUCCESS) delete other;
    return importer.GetImporterCount();
}

} // namespace

ObstacleMesh makeObstacleMesh(std::string name, const std::vector<glm::vec3>& vertices,
                              const std::vector<glm::uvec3>& triangles,
                              const glm::mat4& transform) {
    ObstacleMesh mesh;
    mesh.name = std::move(name);
    mesh.vertices.reserve(vertices.size());
    for (const glm::vec3& v : vertices)
        mesh.vertices.push_back(glm::vec3(transform * glm::vec4(v, 1.0f)));

    // The area threshold is relative to the mesh's size so that millimetre and kilometre models
    // are treated alike; it only drops slivers that no ray test could hit reliably anyway.
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& v : mesh.vertices)
        if (finite(v)) {
            lo = glm::min(lo, v);
            hi = glm::max(hi, v);
        }
    const double extent = finite(hi - lo) ? glm::length(glm::dvec3(hi - lo)) : 0.0;
    const double minTwiceArea = 1e-12 * extent * extent;

    mesh.triangles.reserve(triangles.size());
    const std::size_t n = mesh.vertices.size();
    for (const glm::uvec3& t : triangles) {
        if (t.x >= n || t.y >= n || t.z >= n)
            throw InvalidInput("obstacle mesh '" + mesh.name + "': triangle index out of range");
        const glm::vec3& a = mesh.vertices[t.x];
        const glm::vec3& b = mesh.vertices[t.y];
        const glm::vec3& c = mesh.vertices[t.z];
        const bool repeated = t.x == t.y || t.y == t.z || t.x == t.z;
        if (repeated || !finite(a) || !finite(b) || !finite(c) ||
            glm::length(glm::cross(glm::dvec3(b - a), glm::dvec3(c - a))) <= minTwiceArea) {
            ++mesh.degenerateCount;
            continue;
        }
        mesh.triangles.push_back(t);
    }
    if (!mesh.triangles.empty()) {
        mesh.lo = glm::vec3(std::numeric_limits<float>::max());
        mesh.hi = glm::vec3(-std::numeric_limits<float>::max());
        for (const glm::uvec3& t : mesh.triangles)
            for (int k = 0; k < 3; ++k) {
                mesh.lo = glm::min(mesh.lo, mesh.vertices[t[k]]);
                mesh.hi = glm::max(mesh.hi, mesh.vertices[t[k]]);
            }
    }
    return mesh;
}

std::size_t obstacleMeshFilesRead() {
    return gFilesRead.load(std::memory_order_relaxed);
}

ObstacleMesh loadObstacleMesh(const std::filesystem::path& file, const MeshTransform& transform,
                              std::size_t maxTriangles) {
    gFilesRead.fetch_add(1, std::memory_order_relaxed);
    std::error_code ec;
    if (!std::filesystem::exists(file, ec))
        throw IoError("obstacle mesh " + quoted(file) + ": file not found");
    if (!std::filesystem::is_regular_file(file, ec))
        throw IoError("obstacle mesh " + quoted(file) + ": not a regular file");
    if (std::FILE* f = std::fopen(file.string().c_str(), "rb"))
        std::fclose(f);
    else
        throw IoError("obstacle mesh " + quoted(file) + ": cannot open the file for reading");
    if (std::filesystem::file_size(file, ec) == 0)
        throw InvalidInput("obstacle mesh " + quoted(file) + ": the file is empty");
    checkMeshFile(file, maxTriangles);

    Assimp::Importer importer;
    // Points and lines are removed rather than triangulated: they have no area to collide with.
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                                aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // The file is read and validated first, the other steps run after: ValidateDataStructure
    // refuses face indices past the vertex arrays, which some importers (PLY) pass through and
    // the later steps would follow out of bounds; and the primitive types an importer claims are
    // recomputed from the faces, as Triangulate asserts (aborts) when a mesh claims polygons it
    // does not have or has a face without indices. Both found by fuzz_obstacle
    // (tests/fuzz/regressions/obstacle).
    const std::string ext = lowerAscii(file.extension().string());
    const std::string name =
        ext == ".obj" ? std::string("memory.obj") : lowerAscii(file.filename().string());
    if (ext.size() < 2 || keepImportersOf(importer, name) == 0)
        throw InvalidInput(
            "obstacle mesh " + quoted(file) + ": cannot read it: no importer reads " +
            (ext.size() < 2 ? std::string("files without an extension") : "'" + ext + "' files") +
            "; use OBJ, PLY, STL, glTF (.gltf, .glb), FBX or Collada (.dae)");
    const aiScene* scene = nullptr;
    if (ext == ".obj") {
        // Without its line and point elements (no area; and Assimp's line elements are unsafe)
        // and its material libraries (obstacles use none), read from memory.
        std::ifstream in(file, std::ios::binary);
        const std::string text = objGeometryOnly(
            std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()));
        if (!in.good() && !in.eof())
            throw IoError("obstacle mesh " + quoted(file) + ": cannot read the file");
        scene = importer.ReadFileFromMemory(text.data(), text.size(),
                                            aiProcess_ValidateDataStructure, "obj");
    } else {
        scene = importer.ReadFile(file.string(), aiProcess_ValidateDataStructure);
    }
    auto refuse = [&]() {
        std::string why = importer.GetErrorString();
        if (why.empty()) why = "unknown format or incomplete scene";
        throw InvalidInput("obstacle mesh " + quoted(file) + ": cannot read it: " + why);
    };
    if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) refuse();
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        aiMesh* mesh = scene->mMeshes[m];
        unsigned types = 0;
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const unsigned n = mesh->mFaces[f].mNumIndices;
            if (n == 0) // Triangulate would count it as a triangle and assert too
                throw InvalidInput("obstacle mesh " + quoted(file) + ": cannot read it: face " +
                                   std::to_string(f) + " of mesh " + std::to_string(m) +
                                   " has no vertices");
            types |= n == 1   ? aiPrimitiveType_POINT
                     : n == 2 ? aiPrimitiveType_LINE
                     : n == 3 ? aiPrimitiveType_TRIANGLE
                              : aiPrimitiveType_POLYGON;
        }
        mesh->mPrimitiveTypes = types;
    }
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_PreTransformVertices |
                                         aiProcess_SortByPType | aiProcess_JoinIdenticalVertices);
    if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) refuse();

    std::size_t faces = 0;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        faces += scene->mMeshes[m]->mNumFaces;
    if (faces > maxTriangles)
        throw LimitExceeded("obstacle mesh " + quoted(file) + " has " + std::to_string(faces) +
                            " triangles, more than the limit of " + std::to_string(maxTriangles) +
                            "; decimate the mesh");

    std::vector<glm::vec3> vertices;
    std::vector<glm::uvec3> triangles;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* mesh = scene->mMeshes[m];
        const auto base = static_cast<unsigned>(vertices.size());
        for (unsigned v = 0; v < mesh->mNumVertices; ++v)
            vertices.emplace_back(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z);
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) continue;
            triangles.emplace_back(base + face.mIndices[0], base + face.mIndices[1],
                                   base + face.mIndices[2]);
        }
    }
    ObstacleMesh result = makeObstacleMesh(file.string(), vertices, triangles, transform.matrix());
    if (result.empty()) {
        if (result.degenerateCount > 0)
            throw InvalidInput("obstacle mesh " + quoted(file) + ": all " +
                               std::to_string(result.degenerateCount) +
                               " triangles are degenerate (check the scale)");
        throw InvalidInput("obstacle mesh " + quoted(file) + ": contains no triangles");
    }
    return result;
}

ObstacleMesh makeBoxMesh(const glm::vec3& lo, const glm::vec3& hi, std::string name) {
    std::vector<glm::vec3> v;
    for (int i = 0; i < 8; ++i)
        v.emplace_back((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    // Two triangles per face, counter-clockwise seen from outside.
    const std::vector<glm::uvec3> t = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5},
                                       {0, 1, 5}, {0, 5, 4}, {2, 6, 7}, {2, 7, 3},
                                       {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
    return makeObstacleMesh(std::move(name), v, t);
}

ObstacleMesh makeSphereMesh(const glm::vec3& center, float radius, int rings, int segments,
                            std::string name) {
    if (rings < 2 || segments < 3) throw InvalidInput("sphere needs rings >= 2 and segments >= 3");
    std::vector<glm::vec3> v;
    std::vector<glm::uvec3> t;
    v.push_back(center + glm::vec3(0, radius, 0));
    for (int r = 1; r < rings; ++r) {
        const float phi = glm::pi<float>() * static_cast<float>(r) / static_cast<float>(rings);
        for (int s = 0; s < segments; ++s) {
            const float th =
                glm::two_pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
            v.push_back(center + radius * glm::vec3(std::sin(phi) * std::cos(th), std::cos(phi),
                                                    std::sin(phi) * std::sin(th)));
        }
    }
    v.push_back(center - glm::vec3(0, radius, 0));
    const auto ring = [segments](int r, int s) {
        return static_cast<unsigned>(1 + (r - 1) * segments + (s % segments));
    };
    const auto bottom = static_cast<unsigned>(v.size() - 1);
    for (int s = 0; s < segments; ++s) {
        t.emplace_back(0u, ring(1, s + 1), ring(1, s));
        for (int r = 1; r + 1 < rings; ++r) {
            t.emplace_back(ring(r, s), ring(r, s + 1), ring(r + 1, s + 1));
            t.emplace_back(ring(r, s), ring(r + 1, s + 1), ring(r + 1, s));
        }
        t.emplace_back(ring(rings - 1, s), ring(rings - 1, s + 1), bottom);
    }
    return makeObstacleMesh(std::move(name), v, t);
}

void writeObstacleObj(const ObstacleMesh& mesh, const std::filesystem::path& file) {
    std::string text = "# " + mesh.name + "\n";
    char line[128];
    for (const glm::vec3& p : mesh.vertices) {
        std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", static_cast<double>(p.x),
                      static_cast<double>(p.y), static_cast<double>(p.z));
        text += line;
    }
    for (const glm::uvec3& t : mesh.triangles) {
        std::snprintf(line, sizeof line, "f %u %u %u\n", t.x + 1, t.y + 1, t.z + 1);
        text += line;
    }
    writeFileAtomically(file, text);
}

} // namespace sylva::env
