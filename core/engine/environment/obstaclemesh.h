#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/environment/meshfilecheck.h"

namespace sylva::env {

/// Placement of an obstacle mesh in the scene: scale, then rotate about x, then y, then z
/// (degrees, extrinsic), then translate. This is the order of a project file's
/// `translate`/`rotate`/`scale` keys.
struct MeshTransform {
    glm::vec3 translate{0.0f}; ///< metres
    glm::vec3 rotateDeg{0.0f}; ///< degrees about the world x, y and z axes, applied in that order
    glm::vec3 scale{1.0f};     ///< per-axis factor; a zero factor flattens every triangle

    /// T · Rz · Ry · Rx · S.
    glm::mat4 matrix() const;
};

/// A triangle soup in world space, ready for collision queries. Only valid triangles are kept:
/// `degenerateCount` says how many were dropped (zero area, repeated or non-finite vertices).
struct ObstacleMesh {
    std::string name; ///< the file it came from (for messages), or a caller-chosen label
    std::vector<glm::vec3> vertices;
    std::vector<glm::uvec3> triangles; ///< indices into vertices
    std::size_t degenerateCount = 0;
    glm::vec3 lo{0.0f}, hi{0.0f}; ///< axis-aligned bounds of the kept triangles

    std::size_t triangleCount() const { return triangles.size(); }
    bool empty() const { return triangles.empty(); }
};

/// Builds an ObstacleMesh from raw vertices and triangles (transformed by \p transform), dropping
/// and counting degenerate triangles. Throws InvalidInput for an index out of range.
ObstacleMesh makeObstacleMesh(std::string name, const std::vector<glm::vec3>& vertices,
                              const std::vector<glm::uvec3>& triangles,
                              const glm::mat4& transform = glm::mat4(1.0f));

/// Loads every triangle of every mesh in \p file with Assimp (OBJ, PLY, STL, glTF, FBX, DAE,
/// ... whatever the installed Assimp reads), node transforms baked in, then \p transform applied.
/// \throw IoError "obstacle mesh '<file>': file not found" or not readable.
/// \throw InvalidInput "obstacle mesh '<file>': ..." when Assimp cannot parse it, or when it has
/// no valid triangle (empty, only points/lines, or all degenerate), or when checkMeshFile()
/// refuses it (a malformed PLY header).
/// \throw LimitExceeded "obstacle mesh '<file>' has N triangles, more than the limit of ..."
/// past \p maxTriangles (kMaxObstacleTriangles unless a test asks for less).
ObstacleMesh loadObstacleMesh(const std::filesystem::path& file,
                              const MeshTransform& transform = {},
                              std::size_t maxTriangles = kMaxObstacleTriangles);

/// How many obstacle mesh files loadObstacleMesh has read in this process (those it refused
/// included): what a check that a file is read once per open counts. Thread-safe.
std::size_t obstacleMeshFilesRead();

/// A closed, outward-facing axis-aligned box (12 triangles); for tests and simple walls.
ObstacleMesh makeBoxMesh(const glm::vec3& lo, const glm::vec3& hi, std::string name = "box");

/// A closed UV sphere with 2·rings·segments triangles (rings >= 2, segments >= 3).
ObstacleMesh makeSphereMesh(const glm::vec3& center, float radius, int rings, int segments,
                            std::string name = "sphere");

/// Writes \p mesh as a Wavefront OBJ (for test data and debugging). \throw IoError.
void writeObstacleObj(const ObstacleMesh& mesh, const std::filesystem::path& file);

} // namespace sylva::env
