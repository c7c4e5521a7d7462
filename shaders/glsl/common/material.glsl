#ifndef AGAA_MATERIAL_GLSL
#define AGAA_MATERIAL_GLSL
#include "common/epsilon.glsl"
#include "shared/frame.h"
// What a classic G-buffer holds, evaluated from a glTF material at one fragment.
// Requires: `textures` (sampler2D array, set 1) declared by the includer.

struct MaterialSample {
    vec3 albedo;
    float alpha;
    float metallic;
    float roughness;
    vec3 emissive; // radiance, linear
    vec3 normal; // shading normal, view space, unit
};

vec4 sampleTexture(int index, vec2 uv, vec4 fallback) {
    return index >= 0 ? texture(textures[index], uv) : fallback;
}

float materialAlpha(GpuMaterial m, vec2 uv) {
    return m.baseColorFactor.a * sampleTexture(m.textures.x, uv, vec4(1.0)).a;
}

MaterialSample evaluateMaterial(GpuMaterial m, vec2 uv, vec3 geometricNormal, vec4 tangent, bool frontFacing) {
    MaterialSample s;
    vec4 base = m.baseColorFactor * sampleTexture(m.textures.x, uv, vec4(1.0));
    s.albedo = base.rgb;
    s.alpha = base.a;
    vec4 mr = sampleTexture(m.textures.y, uv, vec4(1.0)); // glTF: G roughness, B metallic
    s.metallic = clamp(m.params.x * mr.b, 0.0, 1.0);
    s.roughness = clamp(m.params.y * mr.g, 0.0, 1.0);
    s.emissive = m.emissive.rgb * sampleTexture(m.textures.w, uv, vec4(1.0)).rgb;

    // Interpolated normals can shrink to zero between opposing vertex normals.
    float nlen = length(geometricNormal);
    vec3 N = nlen > kMinNormalLength ? geometricNormal / nlen : vec3(0.0, 0.0, 1.0);
    if (!frontFacing) N = -N; // double-sided: the back face shades with the flipped normal
    if (m.textures.z >= 0) {
        vec3 t = tangent.xyz - N * dot(N, tangent.xyz);
        float tlen = length(t);
        if (tlen > kMinNormalLength) {
            t /= tlen;
            vec3 b = cross(N, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
            vec3 tn = texture(textures[m.textures.z], uv).xyz * 2.0 - 1.0;
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
