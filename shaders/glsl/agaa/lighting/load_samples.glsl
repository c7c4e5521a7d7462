// Step 1 on the samples path (AggregateGeneration::Samples, seed 004): the walk over the pixel's
// samples also reads each sample's G-buffer (reference/gbuffer.frag, agaa/common/sample_gbuffer.h)
// and sums its Toksvig vector or SGGX matrix, albedo, metallic and alpha into its aggregate, in
// registers at the top of the tile, in float: no AG-buffer, no second raster pass. The per-sample
// terms are the accumulation kernel's (agaa/generation.frag), unquantised.
// The G-buffer's depth is binding 3 (the visibility depth).
layout(set = 0, binding = 6) uniform sampler2DMSArray gNormal;
layout(set = 0, binding = 13) uniform sampler2DMSArray gAlbedoMetal;
layout(set = 0, binding = 10) uniform sampler2DMSArray gEmissiveRoughness;
#define emissiveSamples gEmissiveRoughness // rgb: the per-sample emissive the resolve adds
#include "common/octahedral.glsl"

const bool kQuantizedMoments = false;
const bool kOffLayerOwnColour = true; // every sample is read here, the off-layer ones too

struct MaterialSums {
    // Per aggregate: the normal distribution (Toksvig: the vector in xyz of moment0; SGGX: the
    // matrix's diagonal in moment0, its off-diagonal xy, xz, yz in moment1), albedo and metallic,
    // the material alpha in the BRDF's range (the two-point resolve's), and below its floor too
    // (the environment's level of a near mirror).
    vec3 moment0[kMaxAggregates];
    vec3 moment1[kMaxAggregates];
    vec4 albedoMetal[kMaxAggregates];
    float materialAlpha[kMaxAggregates];
    float materialAlphaRaw[kMaxAggregates];
    // c = 1: the off-layer samples' diffuse colours, shading normals, F0 and material alpha.
    vec3 offLayerDiffuse;
    vec3 offLayerNormal;
    vec4 offLayerF0Alpha;
};

// Module state, as the walk's (pixel_samples.glsl): indexed by the metadata's aggregate id.
MaterialSums material;

void clearMaterialSums() {
    material.moment0 = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    material.moment1 = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    material.albedoMetal = vec4[](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
    material.materialAlpha = float[](0.0, 0.0, 0.0, 0.0);
    material.materialAlphaRaw = float[](0.0, 0.0, 0.0, 0.0);
    material.offLayerDiffuse = vec3(0.0);
    material.offLayerNormal = vec3(0.0);
    material.offLayerF0Alpha = vec4(0.0);
}

SampleMaterial loadSampleMaterial(ivec2 pixel, uint s) {
    ivec3 at = ivec3(pixel, s / 4u);
    SampleMaterial m;
    m.normal = decodeOctahedral(texelFetch(gNormal, at, int(s % 4u)).rg);
    m.albedoMetal = texelFetch(gAlbedoMetal, at, int(s % 4u));
    m.roughness = texelFetch(gEmissiveRoughness, at, int(s % 4u)).a;
    return m;
}

// Sample s of the pixel, covered, in aggregate a (offLayer: c = 1, off aggregate 0's layer).
void sumSampleMaterial(ivec2 pixel, uint pixelIndex, uint s, uint a, bool offLayer, vec3 P) {
    SampleMaterial sm = loadSampleMaterial(pixel, s);
    vec3 N = sm.normal;
    vec4 albedoMetal = sm.albedoMetal;
    float roughness = sm.roughness;
    float alpha = roughness * roughness;
    exportSample(pixelIndex, s, vec4(N, roughness), albedoMetal,
                 vec4(P, offLayer ? float(kAggregates) : float(a)), vec4(1.0, 0.0, 0.0, 0.0));
    if (offLayer) {
        material.offLayerDiffuse += albedoMetal.rgb * (1.0 - albedoMetal.a);
        material.offLayerNormal += N;
        material.offLayerF0Alpha += vec4(mix(vec3(0.04), albedoMetal.rgb, albedoMetal.a), min(alpha, 1.0));
        return;
    }
    vec3 moment0, moment1 = vec3(0.0);
    if (kSggx) {
        // The sample's GGX lobe as an SGGX matrix, S = (1 - a^2) N N^T + a^2 I (shared/sggx.h).
        float ca = clamp(alpha, kMinGgxAlpha, kMaxGgxAlpha);
        float a2 = ca * ca;
        vec3 Nw = N * (1.0 - a2);
        moment0 = Nw * N + a2;
        moment1 = vec3(Nw.x * N.y, Nw.x * N.z, Nw.y * N.z);
    } else {
        // Roughness as normal variance: the Toksvig length of the sample's alpha.
        moment0 = N * toksvigLength(alpha, agaa.toksvig.x, agaa.toksvig.y, agaa.toksvig.z);
    }
    float materialAlpha = clamp(alpha, kMinGgxAlpha, kMaxGgxAlpha),
          materialAlphaRaw = min(alpha, kMaxGgxAlpha);
    // At constant indices, as the walk's sums (pixel_samples.glsl).
    for (uint k = 0u; k < kAggregates; ++k) {
        bool mine = k == a;
        material.albedoMetal[k] += mine ? albedoMetal : vec4(0.0);
        material.moment0[k] += mine ? moment0 : vec3(0.0);
        if (kSggx) material.moment1[k] += mine ? moment1 : vec3(0.0);
        material.materialAlpha[k] += mine ? materialAlpha : 0.0;
        material.materialAlphaRaw[k] += mine ? materialAlphaRaw : 0.0;
    }
    addSpreadSample(a, N, alpha); // the shading rate's estimate (prefilter_estimate.glsl)
}

OffLayerMeans loadOffLayerMeans(uint pixelIndex, uint samples) {
    float fs = float(samples);
    return OffLayerMeans(material.offLayerDiffuse / fs, material.offLayerNormal / fs,
                         material.offLayerF0Alpha / fs);
}

// The per-sample resolve's diffuse colour of an off-layer sample: the sample's own.
vec3 offLayerSampleDiffuse(vec3 meanDiffuse, ivec2 pixel, uint s) {
    vec4 albedoMetal = texelFetch(gAlbedoMetal, ivec3(pixel, s / 4u), int(s % 4u));
    return albedoMetal.rgb * (1.0 - albedoMetal.a);
}

AggregateMoments loadAggregateMoments(uint a, uint count, uint samplesIn, uint pixelIndex, bool inside) {
    AggregateMoments m;
    m.accumulated = samplesIn; // every sample the metadata assigns was read here
    if (!aggregatePresent(a, count, m.accumulated, samplesIn)) return m;
    float fs = float(samplesIn);
    m.materialAlpha = material.materialAlpha[a] / fs;
    m.mean0 = material.moment0[a] / fs;
    m.mean1 = material.moment1[a] / fs;
    m.albedo = material.albedoMetal[a].rgb / fs; // the layer's samples only (c = 1: off_layer.glsl)
    m.metallic = material.albedoMetal[a].a / fs;
    m.rawMaterialAlpha = material.materialAlphaRaw[a] / fs;
    return m;
}
