#version 330 core
// An impostor (ui/viewport/impostors.h): two crossed cards from the vertex id alone: card 0 in
// the tree's xy plane (the front picture, left half of the texture), card 1 in its zy plane
// (the side picture, right half).
uniform mat4 uViewProj;
uniform mat4 uModel;
uniform vec3 uLo;
uniform vec3 uHi;
out vec2 vUv;
void main() {
    const vec2 corners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1),
                                    vec2(0, 0), vec2(1, 1), vec2(0, 1));
    int card = gl_VertexID / 6;
    vec2 st = corners[gl_VertexID % 6];
    vec3 c = 0.5 * (uLo + uHi);
    float y = mix(uLo.y, uHi.y, st.y);
    vec3 p = card == 0 ? vec3(mix(uLo.x, uHi.x, st.x), y, c.z)
                       : vec3(c.x, y, mix(uLo.z, uHi.z, st.x));
    vUv = vec2(0.5 * float(card) + 0.5 * st.x, st.y);
    gl_Position = uViewProj * uModel * vec4(p, 1.0);
}
