#version 330 core
// Lambert key light plus a hemisphere ambient (sky above, warm ground below), both dimmed by
// the crown's per-vertex occlusion. Normals come turned towards the viewer (vertex shader); a
// leaf lit from behind lets a little light through. Textures are sRGB: decoded to linear before
// lighting, with gamma 2 (a square and a square root: under a software renderer two pow() per
// pixel cost 5 % of a frame, and the difference to 2.2 does not show). Leaf cards are
// cut out by their texture's alpha, sharpened with the mipmap level so that far leaves keep
// their area instead of fading away.
// Compiled in four variants (the loader puts TEXTURED and CUTOUT defines after the version
// line) rather than branching on uniforms: a software renderer (Mesa llvmpipe) runs both sides
// of a branch with masks, and a shader that can discard loses the early depth test for every
// triangle drawn with it, so bark paid for the leaves' texture lookup and cut-out.
in vec3 vNormal;
in vec3 vColor;
in vec2 vUv;
in float vOcclusion;
in vec3 vWorld;
uniform vec3 uAlbedo;
uniform bool uVertexColor; // colour by a node attribute instead of the material
uniform sampler2D uTexture;
uniform vec3 uLightDir;
uniform float uHighlight; // a selected tree: blended towards orange
out vec4 fragColor;
#ifdef TEXTURED
// The texture's tangent-space normal map (make_textures.py: OpenGL convention, +X along u, +Y
// along v; a flat one where a texture has none). The tangent frame comes from the screen-space
// derivatives of the world position and the uvs (Schüler's cotangent frame), not from vertex
// tangents: no attribute to compute, store and upload for millions of vertices, and it holds
// for every mesh the viewport gets (LOD levels, camera ribbons, leaf clusters, obstacles).
// Our uvs are orthogonal on tubes and cards, so it matches the MikkTSpace frame exports imply.
// With the normal turned towards the viewer the whole frame turns too: a card's back shows
// the relief mirrored, as a thin leaf does.
uniform sampler2D uNormalMap;
vec3 mappedNormal(vec3 n, vec2 uv) {
    vec3 dp1 = dFdx(vWorld);
    vec3 dp2 = dFdy(vWorld);
    vec2 duv1 = dFdx(uv);
    vec2 duv2 = dFdy(uv);
    vec3 dp2perp = cross(dp2, n);
    vec3 dp1perp = cross(n, dp1);
    vec3 t = dp2perp * duv1.x + dp1perp * duv2.x;
    vec3 b = dp2perp * duv1.y + dp1perp * duv2.y;
    float m = max(dot(t, t), dot(b, b));
    if (m < 1e-24) return n; // uvs that do not vary (a foreign mesh): no frame
    float s = inversesqrt(m);
    vec3 local = texture(uNormalMap, uv).xyz * 2.0 - 1.0;
    return normalize(mat3(t * s, b * s, n) * local);
}
#endif
void main() {
#ifdef TEXTURED
    vec4 tex = texture(uTexture, vUv);
#ifdef CUTOUT
    vec2 texel = vUv * vec2(textureSize(uTexture, 0));
    float lod = 0.5 * log2(max(dot(dFdx(texel), dFdx(texel)), dot(dFdy(texel), dFdy(texel))));
    if (tex.a * (1.0 + 0.25 * max(lod, 0.0)) < 0.5) discard;
#endif
    vec3 material = tex.rgb * tex.rgb;
#else
    vec3 material = uAlbedo;
#endif
    vec3 n = vNormal;
    float len = length(n);
    n = len > 1e-6 ? n / len : vec3(0.0, 1.0, 0.0);
#ifdef TEXTURED
    n = mappedNormal(n, vUv);
#endif
    float facing = dot(n, uLightDir);
    float diffuse = max(facing, 0.0);
#ifdef CUTOUT
    diffuse += 0.35 * max(-facing, 0.0); // a leaf card: translucent
#endif
    vec3 sky = vec3(0.62, 0.70, 0.85);
    vec3 ground = vec3(0.30, 0.25, 0.20);
    vec3 ambient = mix(ground, sky, 0.5 * n.y + 0.5);
    // Without an attribute to show, vColor is the leaf cards' tint (white elsewhere).
    vec3 albedo = uVertexColor ? vColor : material * vColor;
    float ao = clamp(vOcclusion, 0.0, 1.0);
    vec3 color = albedo * (0.55 * ambient * ao +
                           1.35 * vec3(1.0, 0.96, 0.90) * diffuse * (0.4 + 0.6 * ao));
    color = mix(color, vec3(1.0, 0.45, 0.05), uHighlight);
    fragColor = vec4(sqrt(color), 1.0);
}
