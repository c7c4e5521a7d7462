#ifndef AGAA_MATERIAL_GLSL
#define AGAA_MATERIAL_GLSL
#include "common/epsilon.glsl"
#include "shared/frame.h"
#include "shared/specialization.h"
// What a classic G-buffer holds, evaluated from a glTF material at one fragment.
// Requires: `textures` (sampler2D array, set 1) declared by the includer.
//
// Scene-driven variants (agaa/common/effects.h): specialisation ids 3 and 4 switch the normal-map
// fetch and the emissive fetch off for scenes without normal-mapped or emissive materials.
layout(constant_id = kSpecNormalMaps) const uint kNormalMaps = 1u;
layout(constant_id = kSpecEmissive) const uint kEmissiveMaterials = 1u;
// KHR_texture_transform or a second UV set in the scene (agaa/common/effects.h kSpecTextureTransforms).
layout(constant_id = kSpecTextureTransforms) const uint kTextureTransforms = 1u;
// Vertex colours in the scene (kSpecVertexColors): without them the interpolated 1 (which
// barycentric rounding can leave a ulp off) is not multiplied in.
layout(constant_id = kSpecVertexColors) const uint kVertexColors = 1u;

// Toksvig (2005) from a normal-map texel's pre-filtered length |Na| (engine/frame/gpu_scene.cpp
// stores it in alpha): with the GGX alpha a = r^2 and its Blinn-Phong exponent s = 2/a^2 - 2,
// f = |Na| / (|Na| + s (1 - |Na|)), s' = f s, a' = sqrt(2 / (s' + 2)), r' = sqrt(a'). |Na| = 1
// keeps r; |Na| -> 0 gives a' = 1.
float toksvigRoughness(float roughness, float normalLength) {
    float len = clamp(normalLength, 0.0, 1.0);
    float a = max(roughness * roughness, kMinGgxAlpha);
    float s = 2.0 / (a * a) - 2.0; // a <= 1: s >= 0
    float f = len / max(len + s * (1.0 - len), kMinNormalLength);
    float a2 = sqrt(2.0 / (f * s + 2.0)); // f s + 2 >= 2
    return sqrt(max(a2, a)); // never smoother than the material
}

#include "common/material_sample.glsl"

vec4 sampleTexture(int index, vec2 uv, vec4 fallback) {
    return index >= 0 ? texture(textures[index], uv) : fallback;
}

// KHR_texture_transform: slot 0 base colour, 1 metal-roughness, 2 normal, 3 emissive. Affine in uv,
// so the implicit derivatives (and the MIP level) follow the transformed coordinates.
vec2 slotUv(GpuMaterial m, uint slot, vec4 uvs) {
    // Off for scenes without a transformed texture or a second UV set (specialisation id 18): the
    // fetch then reads the interpolated coordinates themselves, whose derivatives llvmpipe takes
    // differently from a computed value's (even one multiplied by 1), which moves alpha-tested edges.
    if (kTextureTransforms == 0u) return uvs.xy;
    vec2 uv = m.texCoords[slot] == 1 ? uvs.zw : uvs.xy;
    vec4 M = m.uvMatrix[slot];
    vec4 o = m.uvOffset[slot / 2u];
    return mat2(M.xy, M.zw) * uv + ((slot & 1u) == 0u ? o.xy : o.zw);
}

// uvs: TEXCOORD_0 in xy, TEXCOORD_1 in zw; color: the vertex colour COLOR_0 (1 without), which
// multiplies the base colour and its alpha (glTF 2.0 3.9.2).
float materialAlpha(GpuMaterial m, vec4 uvs, vec4 color) {
    return m.baseColorFactor.a * (kVertexColors != 0u ? color.a : 1.0) * sampleTexture(m.textures.x, slotUv(m, 0u, uvs), vec4(1.0)).a;
}

MaterialSample evaluateMaterial(GpuMaterial m, vec4 uv, vec4 color, vec3 geometricNormal, vec4 tangent, bool frontFacing) {
    MaterialSample s;
    vec4 base = m.baseColorFactor * (kVertexColors != 0u ? color : vec4(1.0)) * sampleTexture(m.textures.x, slotUv(m, 0u, uv), vec4(1.0));
    s.albedo = base.rgb;
    s.alpha = base.a;
    vec4 mr = sampleTexture(m.textures.y, slotUv(m, 1u, uv), vec4(1.0)); // glTF: G roughness, B metallic
    s.metallic = clamp(m.params.x * mr.b, 0.0, 1.0);
    s.roughness = clamp(m.params.y * mr.g, 0.0, 1.0);
    s.emissive = kEmissiveMaterials != 0u ? m.emissive.rgb * sampleTexture(m.textures.w, slotUv(m, 3u, uv), vec4(1.0)).rgb : vec3(0.0);

    // Interpolated normals can shrink to zero between opposing vertex normals.
    float nlen = length(geometricNormal);
    vec3 N = nlen > kMinNormalLength ? geometricNormal / nlen : vec3(0.0, 0.0, 1.0);
    if (!frontFacing) N = -N; // double-sided: the back face shades with the flipped normal
    if (kNormalMaps != 0u && m.textures.z >= 0) {
        vec3 t = tangent.xyz - N * dot(N, tangent.xyz);
        float tlen = length(t);
        if (tlen > kMinNormalLength) {
            t /= tlen;
            vec3 b = cross(N, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
            vec4 texel = texture(textures[m.textures.z], slotUv(m, 2u, uv));
            vec3 tn = texel.xyz * 2.0 - 1.0;
            s.roughness = toksvigRoughness(s.roughness, texel.a);
            tn.xy *= m.params.z;
            vec3 mapped = t * tn.x + b * tn.y + N * tn.z;
            float mlen = length(mapped);
            if (mlen > kMinNormalLength) N = mapped / mlen;
        }
    }
    s.normal = N;
    return s;
}
#endif
