#version 330 core
// An impostor (ui/viewport/impostors.h, docs/lods.md): one card facing the eye, the part of the
// square of side 2 · radius around the atlas' bounding sphere that any view covers, made from the vertex id alone, one instance per tree (its
// model matrix and highlight per instance). The view direction is the tree's (its centre to the
// eye, in its frame), the same for the whole card: so is everything that depends on it alone
// (the three atlas views around it, their weights and frames), worked out here once per card
// rather than per pixel (a software renderer runs the fragment shader for every pixel of it).
layout(location = 0) in mat4 aModel;
layout(location = 4) in float aHighlight;
uniform mat4 uViewProj;
uniform vec3 uEye;
uniform vec3 uCentre;
uniform float uRadius;
// The part of the card any view covers (Impostors::cardExtent): [-x, x] × [y, z].
uniform vec3 uExtent;
uniform int uGrid;
flat out float vHighlight;
// The three views blended, the heaviest first: where the viewer's ray through the fragment
// meets each view's plane through the centre (cell coordinates 0..1: affine over the card, so
// interpolated exactly), how far that point moves per unit of stored depth, each view's cell
// in the atlas and its weight.
out vec2 vT0[3];
flat out vec2 vStep[3];
flat out vec2 vCell[3];
flat out vec3 vWeight;

// The atlas' views: decodeDir, basis, atlasViews (Sylva bakes hemisphere atlases).
#include "impostoratlas.glsl"

void main() {
    const vec2 corners[6] = vec2[6](vec2(-1, -1), vec2(1, -1), vec2(1, 1),
                                    vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    vec2 c01 = corners[gl_VertexID] * 0.5 + 0.5;
    vec2 st = vec2(uExtent.x * (2.0 * c01.x - 1.0), mix(uExtent.y, uExtent.z, c01.y));
    vec3 eyeLocal = (inverse(aModel) * vec4(uEye, 1.0)).xyz;
    vec3 d = eyeLocal - uCentre;
    vec3 view = length(d) > 1e-6 ? normalize(d) : vec3(0.0, 0.0, 1.0);
    vec3 right, up;
    basis(view, right, up);
    vec3 billboard = st.x * right + st.y * up; // the card's point, in bounding-sphere units

    // Barycentric weights over the grid's triangle around the view direction, so that the
    // picture changes continuously while the view turns.
    float n1 = float(uGrid - 1);
    vec2 c[3];
    vec3 w;
    atlasViews(view, uGrid, true, c, w);
    // Heaviest first: the fragment shader's early cut-out reads that view alone.
    if (w.y > w.x && w.y >= w.z) {
        c = vec2[3](c[1], c[0], c[2]);
        w = w.yxz;
    } else if (w.z > w.x && w.z > w.y) {
        c = vec2[3](c[2], c[1], c[0]);
        w = w.zyx;
    }
    for (int k = 0; k < 3; ++k) {
        vec3 vk = decodeDir(c[k] / n1, true), rk, uk;
        basis(vk, rk, uk);
        // The point moved along the viewer's ray onto the view's plane (q = p - view · s), then
        // by the stored depth h: s - h / facing (docs/lods.md's one step).
        float invFacing = 1.0 / max(dot(view, vk), 0.05);
        float s = dot(billboard, vk) * invFacing;
        vec2 a = vec2(dot(view, rk), -dot(view, uk));
        vT0[k] = (vec2(dot(billboard, rk), -dot(billboard, uk)) - a * s) * 0.5 + 0.5;
        vStep[k] = 0.5 * invFacing * a;
        vCell[k] = c[k] / float(uGrid);
    }
    vWeight = w;

    vec3 p = uCentre + (st.x * right + st.y * up) * uRadius;
    vHighlight = aHighlight;
    gl_Position = uViewProj * aModel * vec4(p, 1.0);
}
