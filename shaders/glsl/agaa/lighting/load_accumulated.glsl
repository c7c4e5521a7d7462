// Step 1 on the accumulate path (AggregateGeneration::Accumulate): the AG-buffer the
// accumulation kernel summed (agaa/generation.frag) holds each aggregate's fixed-point sums
// (shared/agaa.h), and at c = 1 the off-layer samples' (shared/ag_buffer.h). The walk over the
// pixel's samples adds nothing to them.
layout(set = 0, binding = 6, std430) readonly buffer AgBuffer { uint agBuffer[]; };
// With a tolerance (kShadingRate), each covered sample's material, which the accumulation kernel
// kept for the shading rate (shared/sample_material.h): the estimate and the gap rule read its
// normals and roughness. A 16-byte stand-in without one, never read.
layout(set = 0, binding = 20, std430) readonly buffer SampleMaterials { uint sampleMaterial[]; };
#if AGAA_EMISSIVE
layout(set = 0, binding = 10) uniform sampler2DMSArray emissiveSamples;
#endif
#include "common/octahedral.glsl"
#include "common/srgb.glsl"
#include "shared/sample_material.h"

// The SGGX matrix is fixed point: its spread below the quantisation is rounding (aggregate.glsl).
const bool kQuantizedMoments = true;
// c = 1: the off-layer samples resolve with their own colour, except under whole-fragment
// routing, which fed their fragments to the aggregate: there they take its radiance.
const bool kOffLayerOwnColour = kRouteFragment == 0u;

void clearMaterialSums() {} // the AG-buffer already holds every sum

SampleMaterial loadSampleMaterial(ivec2 pixel, uint s) {
    uint at = sampleMaterialWord(uint(pixel.y) * uint(frame.extent.x) + uint(pixel.x), kSamples, s);
    vec4 albedoMetal = unpackUnorm4x8(sampleMaterial[at + 1u]);
    SampleMaterial m;
    m.normal = decodeOctahedral(unpackSnorm2x16(sampleMaterial[at]));
    m.albedoMetal = vec4(srgbDecode(albedoMetal.rgb), albedoMetal.a);
    m.roughness = unpackUnorm2x16(sampleMaterial[at + 2u]).x;
    return m;
}

// Only the shading rate's estimate reads a sample here (the AG-buffer holds the aggregates'
// material), and only for a sample the metadata assigns an aggregate, as on the samples path.
void sumSampleMaterial(ivec2 pixel, uint pixelIndex, uint s, uint a, bool offLayer, vec3 P) {
    if (kShadingRate == 0u || offLayer) return;
    SampleMaterial m = loadSampleMaterial(pixel, s);
    addSpreadSample(a, m.normal, m.roughness * m.roughness);
}

OffLayerMeans loadOffLayerMeans(uint pixelIndex, uint samples) {
    const uint n = kSamples;
    ivec2 size = ivec2(frame.extent.xy);
    uint at = offLayerWord(uint(size.x * size.y), pixelIndex), scale = unitScale(kOffLayerFieldBits, n);
    uint w0 = agBuffer[at], w1 = agBuffer[at + 1u], w2 = agBuffer[at + 2u];
    OffLayerMeans m;
    m.diffuse = vec3(meanUnit(w0 & 0xFFFFu, samples, scale), meanUnit(w0 >> 16u, samples, scale),
                     meanUnit(w1 & 0xFFFFu, samples, scale));
    m.normal = vec3(meanSigned(w1 >> 16u, samples, scale), meanSigned(w2 & 0xFFFFu, samples, scale),
                    meanSigned(w2 >> 16u, samples, scale));
    uint w3 = agBuffer[at + 3u], w4 = agBuffer[at + 4u];
    m.f0Alpha = vec4(meanUnit(w3 & 0xFFFFu, samples, scale), meanUnit(w3 >> 16u, samples, scale),
                     meanUnit(w4 & 0xFFFFu, samples, scale), meanUnit(w4 >> 16u, samples, scale));
    return m;
}

// The per-sample resolve's diffuse colour of an off-layer sample: the pixel's off-layer mean
// (the AG-buffer keeps no more).
vec3 offLayerSampleDiffuse(vec3 meanDiffuse, ivec2 pixel, uint s) {
    return meanDiffuse;
}

AggregateMoments loadAggregateMoments(uint a, uint count, uint samplesIn, uint pixelIndex, bool inside) {
    const uint n = kSamples;
    uint base = (pixelIndex * kAggregates + a) * kAggregateWords;
    uint w[kAggregateWords];
    for (uint j = 0u; j < kAggregateWords; ++j)
        w[j] = inside ? agBuffer[base + j] : 0u;
    AggregateMoments m;
    m.accumulated = aggregateSampleCount(kNdf, w[0], w[4]);
    if (!aggregatePresent(a, count, m.accumulated, samplesIn)) return m;
    uint k = m.accumulated;
    // The colour fields hold the aggregate's own samples (c = 1: the off-layer ones add their
    // diffuse colour to the off-layer words; whole-fragment routing adds every sample in full).
    if (kSggx) {
        uint scale = unitScale(kSggxFieldBits, n);
        m.mean0 = vec3(meanUnit(w[0] & 0xFFFFu, k, scale), meanUnit(w[0] >> 16u, k, scale),
                       meanUnit(w[1] & 0xFFFFu, k, scale));
        // Off-diagonal entries are stored offset by 1/2 (generation.frag).
        m.mean1 = vec3(meanUnit(w[1] >> 16u, k, scale) - 0.5, meanUnit(w[2] & 0xFFFFu, k, scale) - 0.5,
                       meanUnit(w[2] >> 16u, k, scale) - 0.5);
        m.albedo = vec3(meanUnit(w[3] & 0xFFFFu, k, scale), meanUnit(w[3] >> 16u, k, scale),
                        meanUnit(w[4] & 0xFFFFu, k, scale));
        m.metallic =
            meanUnit((w[4] >> 16u) & ((1u << kSggxMetallicBits) - 1u), k, unitScale(kSggxMetallicBits, n));
    } else {
        const uint sx = toksvigScaleX(n), syz = toksvigScaleYZ(n);
        m.mean0 = vec3(meanSigned(w[0] & kNormalFieldMask, k, sx), meanSigned(w[1], k, syz),
                       meanSigned(w[2], k, syz));
        m.mean1 = vec3(0.0);
        m.albedo = vec3(meanUnit(w[3] & 0xFFFFu, k, kUnormScale), meanUnit(w[3] >> 16u, k, kUnormScale),
                        meanUnit(w[4] & 0xFFFFu, k, kUnormScale));
        m.metallic = meanUnit(w[4] >> 16u, k, kUnormScale);
    }
    // w5 is not floored (generation.frag): the BRDF's range here, the raw mean for the environment.
    m.rawMaterialAlpha = meanUnit(w[5], k, kMaterialAlphaScale);
    m.materialAlpha = max(m.rawMaterialAlpha, kMinGgxAlpha);
    return m;
}
