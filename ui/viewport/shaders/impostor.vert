#version 330 core
// An impostor (ui/viewport/impostors.h, docs/lods.md): one card facing the eye, side 2 · radius
// around the atlas' bounding sphere, made from the vertex id alone, one instance per tree (its
// model matrix and highlight per instance). The view direction is the tree's (its centre to the
// eye, in its frame), the same for the whole card.
layout(location = 0) in mat4 aModel;
layout(location = 4) in float aHighlight;
uniform mat4 uViewProj;
uniform vec3 uEye;
uniform vec3 uCentre;
uniform float uRadius;
flat out mat3 vNormalMatrix; // tree frame to world, for the atlas' normals
flat out float vHighlight;
out vec2 vBillboard;     // -1..1 along right and up
flat out vec3 vView;     // tree frame, towards the eye
flat out vec3 vRight;
flat out vec3 vUp;
void main() {
    const vec2 corners[6] = vec2[6](vec2(-1, -1), vec2(1, -1), vec2(1, 1),
                                    vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    vec2 st = corners[gl_VertexID];
    vec3 eyeLocal = (inverse(aModel) * vec4(uEye, 1.0)).xyz;
    vec3 d = eyeLocal - uCentre;
    vec3 view = length(d) > 1e-6 ? normalize(d) : vec3(0.0, 0.0, 1.0);
    vec3 hint = abs(view.y) > 0.9999 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, 1.0, 0.0);
    vec3 right = normalize(cross(hint, view));
    vec3 up = cross(view, right);
    vBillboard = st;
    vView = view;
    vRight = right;
    vUp = up;
    vec3 p = uCentre + (st.x * right + st.y * up) * uRadius;
    vNormalMatrix = mat3(aModel);
    vHighlight = aHighlight;
    gl_Position = uViewProj * aModel * vec4(p, 1.0);
}
