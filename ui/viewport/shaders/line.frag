#version 330 core
// The grid fades out towards its rim so that it has no hard edge (overlays set a huge extent).
in vec4 vColor;
in vec3 vWorld;
uniform vec3 uCenter;
uniform float uExtent;
out vec4 fragColor;
void main() {
    float r = length(vWorld.xz - uCenter.xz) / uExtent;
    fragColor = vec4(vColor.rgb, vColor.a * (1.0 - smoothstep(0.55, 1.0, r)));
}
