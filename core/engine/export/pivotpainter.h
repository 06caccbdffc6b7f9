#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "engine/mesh/mesh.h"
#include "engine/skeleton/skeleton.h"
#include "engine/wind/windelements.h"

namespace sylva::exporter {

/// Unreal's Pivot Painter 2 data of one tree mesh (docs/wind.md, "Pivot Painter 2"): one pixel
/// per sway element (trunk, limbs, branches; wind::buildWindElements), row by row from the
/// image's top-left, the layout PivotPainter2FoliageShader reads with the default texture set:
/// - `pivotIndex` ("Pivot Position (16-bit)" + "Parent Index (Int as float)", half-float RGBA):
///   RGB the element's pivot in Unreal's frame and unit, A the parent element's index stored
///   as the half whose bit pattern is index + 1024 (a root element names itself);
/// - `axisExtent` ("X Vector (8-bit)" + "X Extent (8-bit)", RGBA8, linear): RGB the element's
///   X axis (pivot → tip, unit, Unreal's frame) as (v + 1) / 2, A its extent along that axis in
///   centimetres as clamp(cm / 8, 1, 256) / 256.
/// Unreal's frame from Sylva's (metres, Y up, right-handed): (x, z, y) × 100 cm — what Unreal's
/// FBX and glTF importers make of a Y-up file in metres.
struct PivotPainterData {
    int width = 0, height = 0;
    std::vector<glm::vec4> pivotIndex;       ///< width × height, top row first; A as a float
    std::vector<std::uint16_t> halfBits;     ///< the same as the half-float bits written, RGBA
    std::vector<glm::u8vec4> axisExtent;     ///< width × height, top row first
    std::vector<std::int32_t> vertexElement; ///< per mesh vertex: its element (pixel) index
    /// Per mesh vertex: the element's pixel centre as the UV Unreal reads (origin top-left, v
    /// down: glTF's convention; FBX stores 1 − v, which Unreal's importer flips back).
    std::vector<glm::vec2> vertexUv;
};

/// Centimetres per Sylva metre and the axis swap, in one place.
glm::vec3 toUnreal(const glm::vec3& sylva);
/// The half-float bit pattern Pivot Painter 2 stores an integer as ("Int as float"): n + 1024,
/// the smallest normal half and up; n < 30720 (Unreal's ms_PivotPainter2_UnpackIntegerAsFloat
/// subtracts 1024 from the bits).
std::uint16_t pivotPainterIntBits(std::int32_t n);
/// The float value of a half-float bit pattern (what a shader samples).
float halfToFloat(std::uint16_t bits);
std::uint16_t floatToHalf(float value);

/// Builds the data of \p mesh (with Mesh::node) grown as \p skeleton. A vertex belongs to the
/// deepest element of its node's ancestry (a leaf to its branch; a twig to the branch it hangs
/// from); vertices without a node to the first trunk. \throw LimitExceeded beyond 30,719
/// elements, InvalidInput when the mesh has no node ids.
PivotPainterData buildPivotPainter(const wind::WindElements& elements,
                                   const skel::Skeleton& skeleton, const mesh::Mesh& mesh);

/// Writes `<stem>_pivot_index.exr` (half RGBA, uncompressed OpenEXR) and
/// `<stem>_xaxis_extent.png` beside \p stem; returns both paths. Atomically, byte-identical
/// for the same data.
std::vector<std::filesystem::path> writePivotPainter(const std::filesystem::path& stem,
                                                     const PivotPainterData& data);

} // namespace sylva::exporter
