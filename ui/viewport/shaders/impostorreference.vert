#version 330 core
// The card of the reference impostor sampler (impostorreference.frag, docs/lods.md#reference-
// shader): a quad of side 2 · radius around the atlas' bounding sphere facing the eye, drawn
// from the vertex id alone (6 vertices). A game draws it its own way; this one gives the
// fragment shader the inputs it documents, and lets ui_viewportshaders compile and link it.
#include "impostoratlas.glsl"

uniform mat4 viewProj;
uniform mat4 model;  // the instance's transform
uniform vec3 eye;    // world space
uniform vec3 centre; // bounding sphere, in the tree's frame
uniform float radius;
out vec2 billboard;  // the quad's point, -1..1 (x along right, y along up)
out vec3 viewDir;    // unit, from the tree toward the camera (orthographic per tree)

void main() {
    const vec2 corners[6] = vec2[6](vec2(-1, -1), vec2(1, -1), vec2(1, 1),
                                    vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    vec3 d = (inverse(model) * vec4(eye, 1.0)).xyz - centre;
    viewDir = length(d) > 1e-6 ? normalize(d) : vec3(0.0, 0.0, 1.0);
    vec3 r, u;
    basis(viewDir, r, u);
    billboard = corners[gl_VertexID];
    vec3 p = centre + (billboard.x * r + billboard.y * u) * radius;
    gl_Position = viewProj * model * vec4(p, 1.0);
}
