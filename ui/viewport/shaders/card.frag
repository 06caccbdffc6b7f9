#version 330 core
// The pictures are already shaded and sRGB-encoded; the selection blends towards orange in
// linear space as the mesh shader does.
in vec2 vUv;
uniform sampler2D uPicture;
uniform float uHighlight;
out vec4 fragColor;
void main() {
    // Coverage averages down the mipmaps: one level finer than the screen asks for and a
    // threshold under a half keep sparse crowns about as dense as the meshes look at that size
    // (without multisampling any leaf over a pixel's centre fills it) and bare branches open.
    vec4 t = texture(uPicture, vUv, -1.0);
    if (t.a < 0.35) discard;
    vec3 linear = pow(t.rgb / t.a, vec3(2.2)); // the pictures are premultiplied (clear: 0)
    linear = mix(linear, vec3(1.0, 0.45, 0.05), uHighlight);
    fragColor = vec4(pow(linear, vec3(1.0 / 2.2)), 1.0);
}
