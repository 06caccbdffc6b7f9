#version 330 core
// The reference sampler of docs/lods.md (mesh::renderImpostor on the CPU): the three atlas
// views around the view direction, barycentric weights over the grid's triangle so that the
// picture changes continuously while the view turns, each reprojected along the viewer's ray
// onto its view's plane and walked to the depth it stored. Lit like the meshes (mesh.frag: key
// light and hemisphere ambient, gamma 2) with the atlas' normals; the crown's occlusion, which
// the meshes carry per vertex, is a constant here.
in vec2 vBillboard;
flat in vec3 vView;
flat in vec3 vRight;
flat in vec3 vUp;
flat in mat3 vNormalMatrix;
flat in float vHighlight;
uniform sampler2D uColor;
uniform sampler2D uNormal;
uniform sampler2D uDepth;
uniform int uGrid;
uniform int uCell;
uniform vec3 uLightDir;
out vec4 fragColor;

vec3 decodeDir(vec2 uv) {
    vec2 p = uv * 2.0 - 1.0;
    float x = 0.5 * (p.x + p.y), z = 0.5 * (p.x - p.y);
    return normalize(vec3(x, 1.0 - abs(x) - abs(z), z));
}
vec2 encodeDir(vec3 d) {
    d.y = max(d.y, 0.0);
    d /= abs(d.x) + abs(d.y) + abs(d.z);
    return clamp(vec2(d.x + d.z, d.x - d.z) * 0.5 + 0.5, 0.0, 1.0);
}

void main() {
    vec3 p = vBillboard.x * vRight + vBillboard.y * vUp;
    float n1 = float(uGrid - 1);
    vec2 g = encodeDir(vView) * n1;
    vec2 base = clamp(floor(g), vec2(0.0), vec2(n1 - 1.0));
    vec2 f = g - base;
    vec2 c0, c1, c2;
    vec3 w;
    if (f.x + f.y <= 1.0) {
        c0 = base; c1 = base + vec2(1.0, 0.0); c2 = base + vec2(0.0, 1.0);
        w = vec3(1.0 - f.x - f.y, f.x, f.y);
    } else {
        c0 = base + vec2(1.0, 1.0); c1 = base + vec2(0.0, 1.0); c2 = base + vec2(1.0, 0.0);
        w = vec3(f.x + f.y - 1.0, 1.0 - f.x, 1.0 - f.y);
    }
    // Coverage averages down the mipmaps: one level finer than the screen asks for and a
    // threshold under a half keep sparse crowns about as dense as the meshes look at that size
    // (as the crossed cards before did). Under a software renderer every texture fetch counts: one step toward the stored depth
    // (docs/lods.md walks four; at the few dozen pixels the viewport draws impostors, one is
    // within a pixel), the alpha test before the normals, and the normal of the heaviest view.
    vec4 sum = vec4(0.0);
    vec2 heaviest = vec2(0.0);
    float most = -1.0;
    float halfTexel = 0.5 / float(uCell);
    for (int k = 0; k < 3; ++k) {
        vec2 c = k == 0 ? c0 : (k == 1 ? c1 : c2);
        if (w[k] <= 0.0) continue;
        vec3 vk = decodeDir(c / n1);
        vec3 hint = abs(vk.y) > 0.9999 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, 1.0, 0.0);
        vec3 rk = normalize(cross(hint, vk));
        vec3 uk = cross(vk, rk);
        float facing = max(dot(vView, vk), 0.05);
        vec2 cellMin = c / float(uGrid);
        vec3 q = p - vView * (dot(p, vk) / facing);
        vec2 t = clamp(vec2(dot(q, rk), -dot(q, uk)) * 0.5 + 0.5, halfTexel, 1.0 - halfTexel);
        float h = texture(uDepth, cellMin + t / float(uGrid)).r * 2.0 - 1.0;
        q = p - vView * ((dot(p, vk) - h) / facing);
        t = clamp(vec2(dot(q, rk), -dot(q, uk)) * 0.5 + 0.5, halfTexel, 1.0 - halfTexel);
        vec2 uv = cellMin + t / float(uGrid);
        vec4 s = texture(uColor, uv, -1.0);
        sum += w[k] * vec4(s.rgb * s.a, s.a);
        if (w[k] * s.a > most) {
            most = w[k] * s.a;
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
    const float ao = 0.75;
    vec3 color = albedo * (0.55 * ambient * ao + 1.35 * vec3(1.0, 0.96, 0.90) * diffuse *
                                                     (0.4 + 0.6 * ao));
    color = mix(color, vec3(1.0, 0.45, 0.05), vHighlight);
    fragColor = vec4(sqrt(color), 1.0);
}
