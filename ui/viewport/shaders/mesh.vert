#version 330 core
// The viewport's mesh shader (trees, obstacles, terrain); attributes as ViewVertex
// (ui/generation/vertexdata.h) lays them out. With WIND defined the vertex sways first
// (wind.glsl, the engine's wind model), in the tree's own frame.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec3 aColor;
layout(location = 3) in vec2 aUv;
layout(location = 4) in float aOcclusion;
uniform mat4 uViewProj;
#ifdef INSTANCED
// Instances of a variant's level drawn in one call: the transform per instance (issue 32).
layout(location = 12) in mat4 aModel;
#define uModel aModel
#else
uniform mat4 uModel; // a tree's instance transform: rotation, uniform scale, translation
#endif
uniform vec3 uEye;
out vec3 vNormal;
out vec3 vColor;
out vec2 vUv;
out float vOcclusion;
out vec3 vWorld; // for the textured fragment shader's tangent frame (derivatives)
#ifdef WIND
#include "wind.glsl"
#endif
void main() {
    vec3 position = aPosition;
    vec3 normal = aNormal;
#ifdef WIND
    windDisplace(position, normal);
#endif
    vec4 world = uModel * vec4(position, 1.0);
    // Normals turned towards the viewer here, per vertex, so that leaf cards and inconsistent
    // windings light the same from both sides: a software renderer interpolates three fewer
    // values per pixel than if the fragment shader did it from the world position.
    vec3 n = mat3(uModel) * normal;
    vNormal = dot(n, uEye - world.xyz) < 0.0 ? -n : n;
    vColor = aColor;
    vUv = aUv;
    vOcclusion = aOcclusion;
    vWorld = world.xyz;
    gl_Position = uViewProj * world;
}
