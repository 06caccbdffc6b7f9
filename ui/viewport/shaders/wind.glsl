// The engine's wind model (core/engine/wind/windmodel.cpp, docs/wind.md) in GLSL: the same
// law, term by term, so that the viewport shows what the exports play. Included by mesh.vert
// when it is compiled with WIND. A vertex carries its innermost sway element and its bend
// fraction on it (ui/generation/windvertexdata.h); the elements come from a buffer texture,
// three RGBA32F texels each: pivot + stiffness, direction + phase, parent + fraction on the
// parent + level + the root's phase. The walk from the vertex's element to its root bends
// innermost first, each about its rest pivot, so a child follows its parent and nothing tears
// at a fork.
layout(location = 5) in uvec2 aWind;        // element + 1 (0: still), flutter phase * 2^24
layout(location = 6) in float aWindU;       // bend fraction on the element
layout(location = 7) in float aWindFlutter; // leaf flutter weight, metres
uniform samplerBuffer uWindElements;
uniform vec3 uWindDirection; // horizontal unit
uniform float uWindStrength;
uniform float uWindGustiness;
uniform float uWindTime; // seconds into the loop, this tree's
uniform float uWindOmega; // 2 pi / period
uniform float uWindBaseCycles;

const float kWindTwoPi = 6.28318530717958647692;

float windCycles(float x) {
    return max(1.0, floor(x + 0.5)); // half up, as the engine rounds
}

vec3 windRotate(vec3 r, vec3 v) {
    float angle = length(r);
    if (angle < 1e-8) return v + cross(r, v);
    vec3 k = r / angle;
    float c = cos(angle), s = sin(angle);
    return v * c + cross(k, v) * s + k * (dot(k, v) * (1.0 - c));
}

vec3 windElementRotation(vec3 dir, float stiffness, float phase, float level, float gust) {
    float t = uWindTime, w = uWindOmega, S = uWindStrength;
    float pressure = S * S * (1.0 + uWindGustiness * gust);
    float n = windCycles(uWindBaseCycles * (1.0 + 0.6 * level) * (0.85 + 0.3 * phase));
    float along = sin(w * n * t + kWindTwoPi * phase);
    float across = sin(w * (n + 1.0) * t + kWindTwoPi * (phase + 0.25));
    vec3 drag = cross(dir, uWindDirection);
    vec3 side = cross(dir, drag);
    vec3 r = ((pressure + 0.35 * S * along) * drag + 0.25 * S * across * side) / stiffness;
    float limit = level < 0.5 ? 0.3 : 0.6;
    float angle = length(r);
    if (angle > 1e-8) r *= limit * tanh(angle / limit) / angle;
    return r;
}

// Moves \p position and turns \p normal (the tree's frame) as wind::displace does.
void windDisplace(inout vec3 position, inout vec3 normal) {
    if (aWind.x == 0u || uWindStrength <= 0.0) return;
    int e = int(aWind.x) - 1;
    float flutterPhase = float(aWind.y) * (1.0 / 16777216.0);
    vec3 rest = position;
    vec4 t2 = texelFetch(uWindElements, 3 * e + 2);
    // The tree's gusts, from its root's phase.
    float treePhase = t2.w;
    float g1 = windCycles(0.5 * uWindBaseCycles);
    float gust = 0.6 * sin(uWindOmega * g1 * uWindTime + kWindTwoPi * treePhase) +
                 0.4 * sin(uWindOmega * (g1 + 1.0) * uWindTime +
                           kWindTwoPi * (1.7 * treePhase + 0.3));
    if (aWindFlutter > 0.0) {
        float len = length(normal);
        if (len > 1e-12) {
            float cycles = windCycles(uWindBaseCycles * 6.0 * (0.8 + 0.4 * flutterPhase));
            float flutter = aWindFlutter * uWindStrength * (0.2 + 0.15 * uWindGustiness) *
                            sin(uWindOmega * cycles * uWindTime + kWindTwoPi * flutterPhase);
            position += normal * (flutter / len);
        }
    }
    float u = aWindU;
    float rootY = rest.y;
    for (int k = 0; k < 3 && e >= 0; ++k) {
        vec4 t0 = texelFetch(uWindElements, 3 * e);
        vec4 t1 = texelFetch(uWindElements, 3 * e + 1);
        t2 = texelFetch(uWindElements, 3 * e + 2);
        vec3 r = windElementRotation(t1.xyz, t0.w, t1.w, t2.z, gust) * (u * (2.0 - u));
        position = t0.xyz + windRotate(r, position - t0.xyz);
        normal = windRotate(r, normal);
        rootY = t0.y;
        u = t2.y;
        e = int(t2.x);
    }
    position.y = max(position.y, min(rest.y, rootY));
}
