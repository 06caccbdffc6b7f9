#version 330 core
// docs/lods.md's sampler of the baked atlas, as a software renderer (Mesa llvmpipe) can afford
// it for hundreds of trees a frame: the three atlas views around the view direction with
// barycentric weights over the grid's triangle (the picture changes continuously while the
// view turns), the viewer's ray marched against the chosen view's depth map. The atlas comes
// lit (ui/viewport/impostorlighting.h: the camera's key light, the hemisphere ambient and the
// crown's occlusion as mesh.frag has them, baked per view), so the colour is one fetch.
// Everything that depends on the view direction alone is the card's (impostor.vert). Per
// pixel: one blurred fetch that cuts out the empty part of the card, then ONE of the three
// views, chosen by an ordered dither against the weights (on average the blend, a third of
// the fetches; measured in docs/perf/lods.md), uSteps depth fetches of the march and the lit
// colour. With FLAT defined (cards a few dozen pixels high, Impostors::kFlatFromLevel, and every
// card while the view moves), no march: the chosen view's plane through the centre, one fetch
// a pixel (the march would move the picture by about a pixel there). Every fetch reads the
// card's one mipmap level (uLevel, a uniform): neighbouring pixels may take other views and
// hits, so the level cannot come from their texture coordinates, and under llvmpipe a level
// that varies per pixel costs about as much as three more fetches.
in vec2 vT0[3];
flat in vec2 vStep[3];
flat in vec2 vCell[3];
flat in vec3 vWeight;
flat in float vHighlight;
uniform sampler2D uLit;
uniform sampler2D uDepth;
uniform int uGrid;
uniform int uCell;
uniform float uLevel; // Impostors::levelFor(): about a texel a pixel
uniform int uSteps;   // samples of the march, 2 or more (Impostors::kNearSteps, kFarSteps)
// The heaviest view alone, no dither (a frame drawn while the view moves, FLAT): without the
// march the three views' pictures of a trunk lie a pixel or two apart, and dithered between
// them it would read as a dotted line; one view keeps it whole and may step by about that
// much when another view becomes the heaviest.
uniform bool uOneView;
out vec4 fragColor;

void main() {
    float grid = float(uGrid);
    float halfTexel = 0.5 / float(uCell);
#ifndef FLAT
    // Most of a card is empty: one fetch of the heaviest view, blurred over about a quarter of
    // its cell (more than the ray's march moves a point), decides, so the rasteriser skips the
    // rest for empty blocks.
    vec2 t = clamp(vT0[0], halfTexel, 1.0 - halfTexel);
    if (textureLod(uLit, vCell[0] + t / grid, 3.0).a < 0.01) discard;
#endif

    // The view: a 4 x 4 Bayer threshold against the weights' running sum.
    ivec2 q = ivec2(gl_FragCoord.xy);
    int fine = 2 * ((q.x ^ q.y) & 1) + (q.y & 1);
    int coarse = 2 * (((q.x >> 1) ^ (q.y >> 1)) & 1) + ((q.y >> 1) & 1);
    float r = (float(4 * fine + coarse) + 0.5) / 16.0;
    bool first = uOneView || r < vWeight.x, second = !first && r < vWeight.x + vWeight.y;
    vec2 t0 = first ? vT0[0] : second ? vT0[1] : vT0[2];
    vec2 cell = first ? vCell[0] : second ? vCell[1] : vCell[2];

#ifdef FLAT
    float hit = 0.0;
    vec2 step = vec2(0.0);
#else
    vec2 step = first ? vStep[0] : second ? vStep[1] : vStep[2];
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
#endif
    vec2 uv = cell + clamp(t0 + hit * step, halfTexel, 1.0 - halfTexel) / grid;
    // Coverage averages down the mipmaps: one level finer than the screen asks for and a
    // threshold under a half keep sparse crowns about as dense as the meshes look at that size
    // (as the crossed cards before did). A small card reads its own level with a threshold
    // of 0.4: as much green on screen (the 1,000-tree benchmark from 2.5 times its camera's
    // distance: 9.0 % of the view either way) for a fetch that stays in the cache (the
    // finer level cost it twice as much, docs/perf/lods.md).
#ifdef FLAT
    vec4 s = textureLod(uLit, uv, uLevel);
    if (s.a < 0.4) discard;
#else
    vec4 s = textureLod(uLit, uv, max(uLevel - 1.0, 0.0));
    if (s.a < 0.3) discard;
#endif
    vec3 color = mix(s.rgb * s.rgb, vec3(1.0, 0.45, 0.05), vHighlight);
    fragColor = vec4(sqrt(color), 1.0);
}
