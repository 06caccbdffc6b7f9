#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include <glm/glm.hpp>

#include "engine/mesh/mesh.h"
#include "engine/util/image.h"
#include "engine/util/progress.h"

namespace sylva::mesh {

/// How an impostor atlas is laid out and baked.
struct ImpostorSettings {
    int grid = 8;           ///< views along each side of the atlas (grid × grid views), 2..32
    int cellPixels = 256;   ///< pixels along each side of one view, 8..2048
    int supersample = 2;    ///< samples per pixel along each axis while baking, 1..4
    bool hemisphere = true; ///< hemi-octahedral (upper hemisphere only) or full octahedral
};

/// Checks the ranges above; throws InvalidInput naming the setting and its range.
void validateImpostor(const ImpostorSettings& settings);

/// What the baker needs to know of a submesh's material: its texture (sRGB RGBA, may be null)
/// and the colour used without one (sRGB 0..1); alphaTest cuts texels with alpha < 0.5 (leaves).
struct ImpostorMaterial {
    const Image* texture = nullptr;
    glm::vec3 colour{0.8f};
    bool alphaTest = false;
};
using ImpostorMaterials = std::function<ImpostorMaterial(const Submesh&)>;

/// The usual ImpostorMaterials: a submesh's own texture (Submesh::texture), else Sylva's
/// shipped bark.png / leaf.png from \p shippedDir, each file read once (thread-safe; copies
/// share the files read). A texture that cannot be read leaves the material's plain colour.
class ImpostorTextures {
public:
    explicit ImpostorTextures(std::filesystem::path shippedDir);
    ImpostorMaterial operator()(const Submesh& submesh) const;

private:
    struct State {
        std::filesystem::path shipped;
        std::mutex mutex;
        std::map<std::string, std::shared_ptr<const Image>> images;
    };
    std::shared_ptr<State> mState;
};

/// A baked octahedral impostor. The atlas is grid × grid cells of cellPixels²; the cell in column
/// i and row j (row 0 at the top of the image) shows the tree seen from the direction
/// impostorViewDirection({i / (grid - 1), j / (grid - 1)}), orthographically, the square
/// [-radius, radius]² of the view plane through \p centre (impostorViewBasis) filling the cell.
/// Everything is in the mesh's frame (Y up). docs/lods.md describes the maps for importers.
struct Impostor {
    ImpostorSettings settings;
    glm::vec3 centre{0.0f}; ///< centre of the bounding sphere, mesh frame
    float radius = 1.0f;    ///< bounding sphere radius (m)
    Image color;            ///< RGBA: albedo (sRGB) and coverage; colour bled into empty texels
    Image normal;           ///< RGB: mesh-frame normal facing the viewer, n · 0.5 + 0.5
    /// Grey: 0.5 + 0.5 · dot(p - centre, view) / radius, where view points from the tree to the
    /// viewer (1 = nearest the viewer, 0.5 = the plane through the centre).
    Image depth;
};

/// Unit direction from the tree toward the viewer for atlas coordinates \p uv in [0, 1]²
/// (u along the columns, v along the rows, downward). Hemi-octahedral: the square is the
/// upper hemisphere, its corners on the horizon; octahedral: the whole sphere.
glm::vec3 impostorViewDirection(glm::vec2 uv, bool hemisphere);
/// The inverse: atlas coordinates in [0, 1]² of a direction (below the horizon clamps onto it
/// for a hemi-octahedral atlas).
glm::vec2 impostorAtlasCoord(glm::vec3 direction, bool hemisphere);
/// The view plane's axes for a view from \p direction: right = normalize(cross(up, direction))
/// with up = +Y (−Z when looking straight down), and up = cross(direction, right).
void impostorViewBasis(const glm::vec3& direction, glm::vec3& right, glm::vec3& up);

/// The impostor's fallback card for readers that know nothing of impostors: a square of side
/// 2 · radius through the centre facing +Z, whose uvs (Sylva's convention: origin at the
/// image's bottom-left) show the atlas cell of the view from +Z (column grid - 1, row 0 of a
/// hemi-octahedral atlas; the nearest cell of an octahedral one). In that cell the normal map's
/// mesh-frame normals are the card's tangent-space normals (x along u, y along v, z out of it).
/// One submesh, "impostor". The glTF and USD LOD chains carry it (docs/lods.md).
Mesh impostorCard(const Impostor& impostor);

/// Bounding sphere of \p mesh (the centre of its bounds, the farthest vertex from it).
void boundingSphere(const Mesh& mesh, glm::vec3& centre, float& radius);
/// The height of \p mesh's bounds along y (0 for an empty mesh): a tree's height, to which its
/// size on screen refers.
float verticalExtent(const Mesh& mesh);

/// One orthographic view of \p mesh from \p direction as the baker takes it: \p pixels² RGBA
/// (albedo, coverage as alpha from \p supersample² samples a pixel), the square
/// [-radius, radius]² of the view plane through \p centre filling the image. \p normal and
/// \p depth, when given, get the view's other maps (as in Impostor).
Image renderOrthographicView(const Mesh& mesh, const ImpostorMaterials& materials,
                             const glm::vec3& direction, const glm::vec3& centre, float radius,
                             int pixels, int supersample, Image* normal = nullptr,
                             Image* depth = nullptr);

/// Bakes the atlas of \p mesh (views in parallel; the same bytes on any thread count).
/// \throw InvalidInput for settings out of range or an empty mesh; Cancelled.
Impostor bakeImpostor(const Mesh& mesh, const ImpostorMaterials& materials,
                      const ImpostorSettings& settings = {}, Progress& progress = noProgress());

/// The reference sampler (what the shader in docs/lods.md does): the impostor drawn as a
/// camera-facing square of side 2 · radius seen from \p direction (toward the viewer), \p pixels²
/// RGBA, blending the three atlas views around the direction (barycentric weights over the
/// grid's triangle); each view is met by the viewer's ray through the pixel, marched
/// against the depth that view stored (relief mapping: the first point where the ray passes behind
/// the stored surface, by at most 0.05 of the radius or one march step, where the view has
/// coverage), and sampled bilinearly there; a view the ray does not meet adds nothing, and one
/// whose ray passed behind its own stored surface abstains (the coverage is the others'); a
/// hit that a heavier view contradicts (it has no coverage within a texel of the hit's point)
/// is vetoed, by how much heavier that view is (fully at 0.25 more weight).
/// Alpha = coverage, colour unpremultiplied.
Image renderImpostor(const Impostor& impostor, const glm::vec3& direction, int pixels);

} // namespace sylva::mesh
