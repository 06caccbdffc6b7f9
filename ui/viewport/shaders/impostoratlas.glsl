// The views of a baked impostor atlas (mesh::bakeImpostor, docs/lods.md#the-atlas): a grid of
// grid × grid views whose directions are the (hemi-)octahedral encoding of the cell's centre,
// each view's frame, and the three views around a direction with barycentric weights over the
// grid's triangle (the picture changes continuously while the view turns). The one copy of
// what every impostor shader shares: the viewport's cards (impostor.vert) and the reference
// sampler (impostorreference.frag, docs/lods.md#reference-shader); mesh::renderImpostor is its
// C++ twin. Included with `#include "impostoratlas.glsl"` (shaderprogram expands it);
// compiled in every program that includes it by ui_viewportshaders.

// The view direction (unit, in the tree's frame) of atlas point uv (0..1 across the atlas).
vec3 decodeDir(vec2 uv, bool hemisphere) {
    vec2 p = uv * 2.0 - 1.0;
    vec3 d;
    if (hemisphere) {
        float x = 0.5 * (p.x + p.y), z = 0.5 * (p.x - p.y);
        d = vec3(x, 1.0 - abs(x) - abs(z), z);
    } else {
        d = vec3(p.x, 1.0 - abs(p.x) - abs(p.y), p.y);
        if (d.y < 0.0) d.xz = (1.0 - abs(d.zx)) * sign(d.xz);
    }
    return normalize(d);
}

// The atlas point (0..1) of view direction d; below the horizon a hemisphere atlas clamps.
vec2 encodeDir(vec3 d, bool hemisphere) {
    if (hemisphere) d.y = max(d.y, 0.0);
    d /= abs(d.x) + abs(d.y) + abs(d.z);
    vec2 p = hemisphere ? vec2(d.x + d.z, d.x - d.z) : d.xz;
    if (!hemisphere && d.y < 0.0) p = (1.0 - abs(p.yx)) * sign(p);
    return clamp(p * 0.5 + 0.5, 0.0, 1.0);
}

// A view's frame: right and up across the picture, d toward the viewer.
void basis(vec3 d, out vec3 r, out vec3 u) {
    vec3 hint = abs(d.y) > 0.9999 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, 1.0, 0.0);
    r = normalize(cross(hint, d));
    u = cross(d, r);
}

// The three atlas views around view direction v (their cells' grid coordinates, 0..grid-1)
// and their barycentric weights (summing to 1).
void atlasViews(vec3 v, int grid, bool hemisphere, out vec2 c[3], out vec3 w) {
    float n1 = float(grid - 1);
    vec2 g = encodeDir(v, hemisphere) * n1;
    vec2 base = clamp(floor(g), vec2(0.0), vec2(n1 - 1.0));
    vec2 f = g - base;
    if (f.x + f.y <= 1.0) {
        c[0] = base; c[1] = base + vec2(1.0, 0.0); c[2] = base + vec2(0.0, 1.0);
        w = vec3(1.0 - f.x - f.y, f.x, f.y);
    } else {
        c[0] = base + vec2(1.0, 1.0); c[1] = base + vec2(0.0, 1.0); c[2] = base + vec2(1.0, 0.0);
        w = vec3(f.x + f.y - 1.0, 1.0 - f.x, 1.0 - f.y);
    }
}
