// The engine's wind model (core/engine/wind/windmodel.cpp wind::displace, docs/wind.md) in
// GLSL, included by mesh.vert when it is compiled with WIND, so that the viewport shows what
// the exports play. A vertex carries its innermost sway element and its bend fraction on it
// (ui/generation/windvertexdata.h). Each element's rotation at its tip for this tree and
// frame (gusts, sway, saturation: wind::elementRotation) is made on the CPU once per tree
// and frame (appendWindRotations) and read here with the bend fraction on its parent; the
// element table gives its rest pivot and its parent. The walk from the vertex's element to
// its root bends innermost first, each about its rest pivot, so a child follows its parent and
// nothing tears at a fork. ui/generation/windvertexdata.cpp's displacePacked is this function
// on the CPU, held against the engine by ui_windvertexdata.
layout(location = 5) in uvec2 aWind;        // element + 1 (0: still), flutter phase * 2^24
layout(location = 6) in float aWindU;       // bend fraction on the element
layout(location = 7) in float aWindFlutter; // leaf flutter weight, metres
uniform samplerBuffer uWindElements;  // per element: rest pivot xyz, parent (-1: a root)
uniform samplerBuffer uWindRotations; // per element, this frame: rotation xyz, u on the parent
uniform int uWindBase;                // this tree's first element in uWindRotations
uniform float uWindStrength;
uniform float uWindGustiness;
uniform float uWindTime;  // seconds into the loop, this tree's
uniform float uWindOmega; // 2 pi / period
uniform float uWindBaseCycles;

// Rodrigues' rotation by the rotation vector r written with the series of sin(a)/a and
// (1 - cos(a))/a^2 in a^2 = r.r: no square root, division, branch or trigonometry (a software
// renderer's sin and cos reduce their argument first). The model saturates every element at
// 0.6 rad, where the terms left out are below 1e-7: as exact as float.
struct WindTurn {
    vec3 r;
    float c, s, t; // cos a, sin(a)/a, (1 - cos a)/a^2
};
WindTurn windTurn(vec3 r) {
    float a2 = dot(r, r);
    WindTurn w;
    w.r = r;
    w.s = 1.0 - a2 * (1.0 / 6.0 - a2 * (1.0 / 120.0 - a2 * (1.0 / 5040.0)));
    w.t = 0.5 - a2 * (1.0 / 24.0 - a2 * (1.0 / 720.0 - a2 * (1.0 / 40320.0)));
    w.c = 1.0 - a2 * w.t;
    return w;
}
vec3 windRotate(WindTurn w, vec3 v) {
    return v * w.c + cross(w.r, v) * w.s + w.r * (dot(w.r, v) * w.t);
}

// Moves \p position and turns \p normal (the tree's frame) as wind::displace does.
void windDisplace(inout vec3 position, inout vec3 normal) {
    if (aWind.x == 0u || uWindStrength <= 0.0) return;
    vec3 rest = position;
    if (aWindFlutter > 0.0) {
        float len = length(normal);
        if (len > 1e-12) {
            float phase = float(aWind.y) * (1.0 / 16777216.0);
            // Half up, as the engine rounds its whole numbers of cycles.
            float cycles = max(1.0, floor(uWindBaseCycles * 6.0 * (0.8 + 0.4 * phase) + 0.5));
            float flutter = aWindFlutter * uWindStrength * (0.2 + 0.15 * uWindGustiness) *
                            sin(uWindOmega * cycles * uWindTime + 6.28318530717958647692 * phase);
            position += normal * (flutter / len);
        }
    }
    int e = int(aWind.x) - 1;
    float u = aWindU;
    float rootY = rest.y;
    for (int k = 0; k < 3 && e >= 0; ++k) {
        vec4 t = texelFetch(uWindElements, e);
        vec4 r = texelFetch(uWindRotations, uWindBase + e);
        WindTurn turn = windTurn(r.xyz * (u * (2.0 - u)));
        position = t.xyz + windRotate(turn, position - t.xyz);
        normal = windRotate(turn, normal);
        rootY = t.y;
        u = r.w;
        e = int(t.w);
    }
    position.y = max(position.y, min(rest.y, rootY));
}
