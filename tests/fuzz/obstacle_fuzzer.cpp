// Fuzzes obstacle mesh import through our Assimp wrapper (loadObstacleMesh): the first byte
// picks the format ('p' PLY, 's' STL, 'G' glTF, 'B' binary glTF, 'F' FBX, 'D' Collada DAE,
// anything else OBJ), the rest is the file. Any file loads as a mesh of valid triangles inside
// its bounds, or throws InvalidInput / LimitExceeded / IoError (a glTF naming a missing buffer).
#include "fuzztempfile.h"

#include "engine/environment/obstaclemesh.h"
#include "engine/util/error.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1 || size > 64 * 1024) return 0; // small inputs: the formats, not their size
    const char* extension = ".obj";
    switch (data[0]) {
    case 'p':
        extension = ".ply";
        break;
    case 's':
        extension = ".stl";
        break;
    case 'G':
        extension = ".gltf";
        break;
    case 'B':
        extension = ".glb";
        break;
    case 'F':
        extension = ".fbx";
        break;
    case 'D':
        extension = ".dae";
        break;
    default:
        break;
    }
    const auto file = sylva::fuzz::writeTempInput(data + 1, size - 1, extension);
    try {
        const sylva::env::ObstacleMesh mesh = sylva::env::loadObstacleMesh(file);
        if (mesh.empty()) std::abort(); // documented: no valid triangle is an error
        for (const glm::uvec3& t : mesh.triangles)
            for (int k = 0; k < 3; ++k) {
                if (t[k] >= mesh.vertices.size()) std::abort();
                const glm::vec3 p = mesh.vertices[t[k]];
                for (int a = 0; a < 3; ++a)
                    if (!std::isfinite(p[a]) || p[a] < mesh.lo[a] || p[a] > mesh.hi[a])
                        std::abort();
            }
    } catch (const sylva::InvalidInput&) {
    } catch (const sylva::LimitExceeded&) {
    } catch (const sylva::IoError&) {
    }
    return 0;
}
