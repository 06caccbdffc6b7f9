#version 330 core
// The reference sampler of docs/lods.md (mesh::renderImpostor on the CPU): the three atlas
// views around the view direction, barycentric weights over the grid's triangle so that the
// picture changes continuously while the view turns, each reprojected along the viewer's ray
// onto its view's plane and walked to the depth it stored. Lit like the meshes (mesh.frag: key
// light and hemisphere ambient, gamma 2) with the atlas' normals; the crown's occlusion, which
// the meshes carry per vertex, is a constant here.
// Everything that depends on the view direction alone is the card's (impostor.vert); here each
// view costs two fetches (depth, then colour), and a fragment the heaviest view shows empty
// even blurred (the colour's coarsest kept mipmap) is cut out after one.
in vec2 vT0[3];
flat in vec2 vStep[3];
flat in vec2 vCell[3];
flat in vec3 vWeight;
flat in mat3 vNormalMatrix;
flat in float vHighlight;
uniform sampler2D uColor;
uniform sampler2D uNormal;
uniform sampler2D uDepth;
uniform int uGrid;
uniform int uCell;
uniform vec3 uLightDir;
out vec4 fragColor;

void main() {
    float grid = float(uGrid);
    float halfTexel = 0.5 / float(uCell);
    // Most of a card is empty: one fetch of the heaviest view, blurred over about a quarter of
    // its cell (more than the depth step moves a point), decides, so the rasteriser skips the
    // rest for empty blocks.
    vec2 t = clamp(vT0[0], halfTexel, 1.0 - halfTexel);
    if (textureLod(uColor, vCell[0] + t / grid, 3.0).a < 0.01) discard;
    // Coverage averages down the mipmaps: one level finer than the screen asks for and a
    // threshold under a half keep sparse crowns about as dense as the meshes look at that size
    // (as the crossed cards before did). Under a software renderer every texture fetch counts:
    // one step toward the stored depth (docs/lods.md walks four; at the few dozen pixels the
    // viewport draws impostors, one is within a pixel), the alpha test before the normals, and
    // the normal of the heaviest view.
    vec4 sum = vec4(0.0);
    vec2 heaviest = vec2(0.0);
    float most = -1.0;
    for (int k = 0; k < 3; ++k) {
        if (vWeight[k] <= 0.0) continue;
        t = clamp(vT0[k], halfTexel, 1.0 - halfTexel);
        float h = texture(uDepth, vCell[k] + t / grid).r * 2.0 - 1.0;
        t = clamp(vT0[k] + h * vStep[k], halfTexel, 1.0 - halfTexel);
        vec2 uv = vCell[k] + t / grid;
        vec4 s = texture(uColor, uv, -1.0);
        sum += vWeight[k] * vec4(s.rgb * s.a, s.a);
        if (vWeight[k] * s.a > most) {
            most = vWeight[k] * s.a;
            heaviest = uv;
        }
    }
    if (sum.a < 0.3) discard;
    vec3 nsum = texture(uNormal, heaviest).rgb * 2.0 - 1.0;
    vec3 srgb = sum.rgb / sum.a;
    vec3 albedo = srgb * srgb;
    vec3 n = vNormalMatrix * nsum;
    float len = length(n);
    n = len > 1e-6 ? n / len : vec3(0.0, 1.0, 0.0);
    float diffuse = max(dot(n, uLightDir), 0.0);
    vec3 sky = vec3(0.62, 0.70, 0.85);
    vec3 ground = vec3(0.30, 0.25, 0.20);
    vec3 ambient = mix(ground, sky, 0.5 * n.y + 0.5);
    // The crown's occlusion the meshes carry per vertex, as one constant: 0.42 makes a forest of
    // impostors as bright as the same trees' meshes at that size (mean leaf colour of the
    // 1,000-tree benchmark from four times its camera's distance, both ways: 0.75 was 1.6
    // times brighter, a visible step where the meshes hand over).
    const float ao = 0.42;
    vec3 color = albedo * (0.55 * ambient * ao + 1.35 * vec3(1.0, 0.96, 0.90) * diffuse *
                                                     (0.4 + 0.6 * ao));
    color = mix(color, vec3(1.0, 0.45, 0.05), vHighlight);
    fragColor = vec4(sqrt(color), 1.0);
}
