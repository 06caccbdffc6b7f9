#version 330 core
// The reference impostor sampler: what mesh::renderImpostor computes on the CPU, as GLSL, for
// a game engine to start from (docs/lods.md#reference-shader explains every step and what
// test_lodchain measures of the C++ twin). The viewport draws its cheaper cousin (impostor.*);
// both take the atlas' views from impostoratlas.glsl. Compiled and linked with
// impostorreference.vert by ui_viewportshaders.
// Inputs in the tree's frame (apply the instance's inverse transform to the camera).
uniform sampler2D colorAtlas, normalAtlas, depthAtlas;
uniform int grid;            // 8
uniform float cellPixels;    // 256
uniform bool hemisphere;     // true
in vec2 billboard;           // the quad's point, -1..1 (x along right, y along up)
in vec3 viewDir;             // unit, from the tree toward the camera (orthographic per tree)
out vec4 fragColor;

#include "impostoratlas.glsl"

// Where the point q (relative to the centre, in radii) falls in view k's cell (cell corner
// cellMin, frame rk, uk), in atlas coordinates.
vec2 cellUv(vec2 cellMin, vec3 q, vec3 rk, vec3 uk) {
    vec2 t = vec2(dot(q, rk), -dot(q, uk)) * 0.5 + 0.5;
    return cellMin + clamp(t, 0.5 / cellPixels, 1.0 - 0.5 / cellPixels) / float(grid);
}

// Whether atlas view cj has coverage within a texel of where the point q (relative to the
// centre, in radii) falls in its cell, at mip level `level`.
bool seen(vec2 cj, vec3 q, int level) {
    vec3 vj = decodeDir(cj / float(grid - 1), hemisphere), rj, uj;
    basis(vj, rj, uj);
    int size = int(cellPixels) >> level;
    ivec2 t = ivec2(floor((vec2(dot(q, rj), -dot(q, uj)) * 0.5 + 0.5) * float(size)));
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 e = clamp(t + ivec2(dx, dy), ivec2(0), ivec2(size - 1));
            if (texelFetch(colorAtlas, ivec2(cj) * size + e, level).a > 0.0) return true;
        }
    return false;
}

void main() {
    vec3 r0, u0;
    basis(viewDir, r0, u0);
    vec3 p = billboard.x * r0 + billboard.y * u0;  // in radii, relative to the centre
    float n1 = float(grid - 1);
    vec2 c[3];
    vec3 w;
    atlasViews(viewDir, grid, hemisphere, c, w);
    float pp = dot(p, p);
    if (pp >= 1.0) discard;                        // outside the bounding sphere
    float reach = sqrt(1.0 - pp);                  // the ray within it: p + viewDir * s, |s| <= reach
    // Texture reads inside loops need an explicit level: the cell's texels per screen pixel.
    float mip = max(0.0, log2(0.5 * cellPixels * length(fwidth(billboard))));
    vec4 sum = vec4(0.0);
    vec3 nsum = vec3(0.0);
    float abstained = 0.0;                         // weight of views that cannot tell
    for (int k = 0; k < 3; ++k) {
        if (w[k] <= 0.0) continue;
        vec3 vk = decodeDir(c[k] / n1, hemisphere), rk, uk;
        basis(vk, rk, uk);
        float facing = dot(viewDir, vk), h0 = dot(p, vk);
        vec2 cellMin = c[k] / float(grid);
        int steps = clamp(int(ceil(reach * sqrt(max(0.0, 1.0 - facing * facing)) * cellPixels)), 1, 256);
        // How deep behind view k's surface a ray still meets it (radii): 0.05, and at least
        // what the ray sinks in one step (near view k's own direction that is the whole sphere).
        float shell = max(0.05, 1.5 * 2.0 * reach * abs(facing) / float(steps));
        float before = reach, hitS = 0.0;
        bool hit = false, hidden = false;
        for (int i = 0; i <= steps && !hit; ++i) {
            float s = reach - 2.0 * reach * float(i) / float(steps);
            vec2 uv = cellUv(cellMin, p + viewDir * s, rk, uk);
            float height = h0 + s * facing;        // above view k's plane, in radii
            float depth = textureLod(depthAtlas, uv, mip).r * 2.0 - 1.0;
            float cover = textureLod(colorAtlas, uv, mip).a;
            if (height < depth - shell && cover >= 0.5) hidden = true; // behind what view k saw
            if (height <= depth && height >= depth - shell && cover > 0.0) {
                float lo = s, hi = before;         // behind and in front of the surface
                for (int b = 0; b < 5 && i > 0; ++b) {
                    float mid = 0.5 * (lo + hi);
                    vec2 at = cellUv(cellMin, p + viewDir * mid, rk, uk);
                    if (h0 + mid * facing <= textureLod(depthAtlas, at, mip).r * 2.0 - 1.0) lo = mid;
                    else hi = mid;
                }
                hitS = lo;
                hit = true;
            }
            before = s;
        }
        if (!hit) {                                // view k sees nothing on this ray:
            if (hidden) abstained += w[k];         // it passed behind view k's surface, where
            continue;                              // view k cannot tell what lies
        }
        // A heavier view that sees empty space where view k's hit lies vetoes it, the more
        // the heavier it is (continuous while the view turns).
        float veto = 0.0;
        vec3 q = p + viewDir * hitS;               // the surface point view k met
        for (int j = 0; j < 3; ++j)
            if (w[j] > w[k] && !seen(c[j], q, int(mip))) veto += min(1.0, (w[j] - w[k]) / 0.25);
        if (veto >= 1.0) continue;                 // as if the ray met nothing of view k
        float wk = w[k] * (1.0 - veto);
        vec2 uv = cellUv(cellMin, q, rk, uk);
        vec4 col = textureLod(colorAtlas, uv, mip);
        sum += wk * vec4(col.rgb * col.a, col.a);
        nsum += wk * col.a * (textureLod(normalAtlas, uv, mip).rgb * 2.0 - 1.0);
    }
    float coverage = sum.a / max(1.0 - abstained, 1e-4); // the views that can tell
    if (coverage < 0.5) discard;              // alpha test, as the glTF material's MASK
    vec3 albedo = sum.rgb / sum.a;            // sRGB: linearise if your pipeline needs it
    vec3 normal = normalize(nsum);            // tree frame: rotate by the instance
    fragColor = vec4(albedo, 1.0);            // light it with `normal` like the mesh levels
}
