#pragma once

#include <glm/glm.hpp>

#include "engine/util/image.h"

namespace sylva::mesh {
struct Impostor;
}

namespace sylva::ui {

/// The viewport's key light for a camera looking along \p forward with \p up and \p right:
/// above, to the left and from the front of the viewer, so it follows the camera and keeps a
/// tree readable from every side (the meshes' shaders/mesh.frag and the impostors share it).
glm::vec3 cameraKeyLight(const glm::vec3& forward, const glm::vec3& up, const glm::vec3& right);

/// An impostor atlas with the viewport's lighting baked in (issue 32): each view's texels lit
/// as shaders/impostor.frag lit them per pixel before, by the key light as it falls when the
/// camera looks along that view (cameraKeyLight(); the turntable never rolls, so a view's
/// frame is the camera's), the hemisphere ambient and the crown's occlusion \p occlusion (one
/// value for the whole crown: Impostors::crownOcclusion, the mean of what the meshes carry per
/// vertex over the leaves; a constant 0.42 before made a tree's impostor 0.50-0.68 times as
/// bright as its own mesh, tests/ui/test_viewportimpostor.cpp). RGBA:
/// the lit colour (sRGB-like, the square root the shaders write) and the colour map's
/// coverage. The viewport reads this one texture instead of the colour and the normal maps and
/// their lighting: under Mesa llvmpipe every fetch over hundreds of cards costs milliseconds
/// a frame (docs/perf/lods.md). Where the camera looks past a tree at an angle, the light the
/// atlas keeps is the one of the view toward the tree, not of the camera's axis: a tree at the
/// edge of the picture is lit as if it stood in the middle (docs/lods.md).
Image litImpostorAtlas(const mesh::Impostor& impostor, float occlusion);

} // namespace sylva::ui
