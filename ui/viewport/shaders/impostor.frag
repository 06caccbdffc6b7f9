#version 330 core
// docs/lods.md's sampler of the baked atlas, as a software renderer (Mesa llvmpipe) can afford
// it for hundreds of trees a frame: the three atlas views around the view direction with
// barycentric weights over the grid's triangle (the picture changes continuously while the
// view turns), the viewer's ray marched against the chosen view's depth map, lit like the
// meshes (mesh.frag: key light and hemisphere ambient, gamma 2) with the atlas' normals; the
// crown's occlusion, which the meshes carry per vertex, is one value per card here.
// Everything that depends on the view direction alone is the card's (impostor.vert). Per
// pixel: one blurred fetch that cuts out the empty part of the card, then ONE of the three
// views, chosen by an ordered dither against the weights (on average the blend, a third of
// the fetches; measured in docs/perf/lods.md), uSteps depth fetches of the march, the
// colour and the normal. Every fetch reads the card's one mipmap level (uLevel, a uniform):
// neighbouring pixels may take other views and hits, so the level cannot come from their
// texture coordinates, and under llvmpipe a level that varies per pixel costs about as much as
// three more fetches.
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
uniform float uLevel; // Impostors::levelFor(): about a texel a pixel
uniform int uSteps;   // samples of the march, 2 or more (Impostors::kNearSteps, kFarSteps)
uniform vec3 uLightDir;
// The crown's occlusion the meshes carry per vertex, as its mean over the source mesh's leaves
// (Impostors::crownOcclusion). A constant 0.42 made a tree's impostor 0.50-0.68 times as bright
// as its own mesh from the same view (tests/ui/test_viewportimpostor.cpp, docs/lods.md).
uniform float uOcclusion;
out vec4 fragColor;

void main() {
    float grid = float(uGrid);
    float halfTexel = 0.5 / float(uCell);
    // Most of a card is empty: one fetch of the heaviest view, blurred over about a quarter of
    // its cell (more than the ray's march moves a point), decides, so the rasteriser skips the
    // rest for empty blocks.
    vec2 t = clamp(vT0[0], halfTexel, 1.0 - halfTexel);
    if (textureLod(uColor, vCell[0] + t / grid, 3.0).a < 0.01) discard;

    // The view: a 4 x 4 Bayer threshold against the weights' running sum.
    ivec2 q = ivec2(gl_FragCoord.xy);
    int fine = 2 * ((q.x ^ q.y) & 1) + (q.y & 1);
    int coarse = 2 * (((q.x >> 1) ^ (q.y >> 1)) & 1) + ((q.y >> 1) & 1);
    float r = (float(4 * fine + coarse) + 0.5) / 16.0;
    bool first = r < vWeight.x, second = !first && r < vWeight.x + vWeight.y;
    vec2 t0 = first ? vT0[0] : second ? vT0[1] : vT0[2];
    vec2 step = first ? vStep[0] : second ? vStep[1] : vStep[2];
    vec2 cell = first ? vCell[0] : second ? vCell[1] : vCell[2];

    // The march (docs/lods.md): the viewer's ray, in height over the view's plane (its point
    // at height h is t0 + h · step), from the top of the stored depths (1) to the back (-1) in
    // uSteps samples; the first sample behind the stored surface that the ray met from
    // in front (the surface no more than kShell above the ray's sample before) is refined by
    // the secant between the two. A ray that meets nothing of the view shows nothing of it.
    // Coverage is the colour's alpha test at the hit (the depth of empty texels is bled from
    // their neighbours, so a ray that "hits" beside a twig finds no colour there).
    const float kShell = 0.2;
    float hPrev = 1.0, fPrev = -1.0, hit = 2.0;
    for (int i = 0; i < uSteps; ++i) {
        float h = 1.0 - 2.0 * float(i) / float(uSteps - 1);
        vec2 at = cell + clamp(t0 + h * step, halfTexel, 1.0 - halfTexel) / grid;
        float d = textureLod(uDepth, at, uLevel).r * 2.0 - 1.0;
        float f = d - h; // >= 0: the ray is behind the surface
        bool crossed = hit > 1.5 && f >= 0.0 && d <= hPrev + kShell;
        float a = i > 0 ? clamp(fPrev / min(fPrev - f, -1e-6), 0.0, 1.0) : 0.0;
        hit = crossed ? mix(hPrev, h, a) : hit;
        hPrev = h;
        fPrev = f;
    }
    if (hit > 1.5) discard;
    vec2 uv = cell + clamp(t0 + hit * step, halfTexel, 1.0 - halfTexel) / grid;
    // Coverage averages down the mipmaps: one level finer than the screen asks for and a
    // threshold under a half keep sparse crowns about as dense as the meshes look at that size
    // (as the crossed cards before did).
    vec4 s = textureLod(uColor, uv, max(uLevel - 1.0, 0.0));
    if (s.a < 0.3) discard;
    vec3 albedo = s.rgb * s.rgb;
    vec3 n = vNormalMatrix * (textureLod(uNormal, uv, uLevel).rgb * 2.0 - 1.0);
    float len = length(n);
    n = len > 1e-6 ? n / len : vec3(0.0, 1.0, 0.0);
    float diffuse = max(dot(n, uLightDir), 0.0);
    vec3 sky = vec3(0.62, 0.70, 0.85);
    vec3 ground = vec3(0.30, 0.25, 0.20);
    vec3 ambient = mix(ground, sky, 0.5 * n.y + 0.5);
    float ao = uOcclusion;
    vec3 color = albedo * (0.55 * ambient * ao + 1.35 * vec3(1.0, 0.96, 0.90) * diffuse *
                                                     (0.4 + 0.6 * ao));
    color = mix(color, vec3(1.0, 0.45, 0.05), vHighlight);
    fragColor = vec4(sqrt(color), 1.0);
}
