// AGAA step 4: tiled-deferred lighting that aggregates at the top of each tile (paper
// section 3.5, the UE4 variant of seed 004). One workgroup per 16x16 tile:
//   1. each invocation turns its pixel's accumulations into normalised aggregates (divide by
//      the sample count; filtered roughness from the Toksvig length, or the anisotropic lobe of
//      the SGGX matrix, shared/sggx.h) and rebuilds each
//      aggregate's depth mean and variance from the per-sample depths its metadata assigns it;
//      they stay in registers: an invocation only ever shades its own pixel's aggregates, and
//      c = 4 aggregates x 256 pixels would not fit lavapipe's 32 KB of shared memory;
//   2. tile depth bounds and light culling in shared memory (common/tile_culling.glsl);
//   3. each aggregate lit once per light with the reference's BRDF (common/brdf.glsl);
//   4. resolve (DESIGN section 6): per sample, its aggregate's radiance plus the sample's own
//      emissive, tone-mapped and weighted 1/n; uncovered samples get the sky. With SGGX the
//      tone map takes the expected value over the aggregate's samples (toneMapAggregate).
#extension GL_GOOGLE_include_directive : require
#include "shared/ag_buffer.h"
#include "shared/agaa.h"
#include "shared/clustering.h"
#include "shared/frame.h"
#include "shared/sggx.h"

layout(local_size_x = 16, local_size_y = 16) in;
// n and c as specialisation constants: constant trip counts for the per-sample loops.
layout(constant_id = 0) const uint kSamples = 8u;
layout(constant_id = 1) const uint kAggregates = 2u;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 2) uniform Agaa { AgaaConstants agaa; };
layout(set = 0, binding = 3) uniform sampler2DMSArray visibilityDepth;
layout(set = 0, binding = 4, std430) readonly buffer Metadata { uint metadata[]; };
layout(set = 0, binding = 5, r8ui) uniform readonly uimage2D aggregateCount;
layout(set = 0, binding = 6, std430) readonly buffer AgBuffer { uint agBuffer[]; };
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D outHdr;
layout(set = 0, binding = 8, rgba32f) uniform writeonly image2D outDisplay;
layout(set = 0, binding = 9, r32ui) uniform writeonly uimage2D outShadingEvents;
#if AGAA_EMISSIVE
layout(set = 0, binding = 10) uniform sampler2DMSArray emissiveSamples;
#endif

#ifndef AGAA_SHADOWS
#define AGAA_SHADOWS 0
#endif
#if AGAA_SHADOWS
// Shadow maps of the scene's shadowed lights (agaa/common/shadow_map.h), filtered inside each
// aggregate's footprint (paper section 3.5.3, common/shadow.glsl).
#define SHADOW_MAP_BINDING 11
#define SHADOW_CONSTANTS_BINDING 12
#include "common/shadow.glsl"
#endif

#include "common/brdf.glsl"
#include "common/depth.glsl"
#include "common/lights.glsl"
#include "common/tile_culling.glsl"
#include "common/tonemap.glsl"

uint sampleAggregate(uint s, uint pixelIndex) {
    const uint words = (kSamples * metadataBits(kAggregates) + 31u) / 32u;
    if (words == 0u) return 0u;
    const uint c = kAggregates;
    return unpackMetadata(metadata[pixelIndex * words + (s * metadataBits(c)) / 32u], s, c);
}

#if AGAA_SHADOWS
// Specialisation id 6 (agaa/common/effects.h ShadowFootprint): 0 the statistical footprint
// (common/shadow.glsl shadowVisibilityAggregate), 1 taps at the aggregate's own sample positions.
layout(constant_id = 6) const uint kShadowFootprint = 0u;

// The paper's "more precise" footprint (section 3.5.3): min(taps, k) of the aggregate's k samples,
// evenly spread in sample order (ranks (2j + 1) k / (2 taps)), each tapped at its own position.
float shadowVisibilityAggregateSamples(uint light, ivec2 pixel, uint pixelIndex, uint a, uint k, vec3 N) {
    int layer = shadowLayer(light);
    if (layer < 0 || k == 0u) return 1.0;
    uint taps = min(kShadowTaps, k);
    uint rank = 0u, j = 0u;
    float sum = 0.0;
    for (uint s = 0u; s < kSamples && j < taps; ++s) {
        float d = texelFetch(visibilityDepth, ivec3(pixel, s / 4u), int(s % 4u)).r;
        if (isSky(d) || sampleAggregate(s, pixelIndex) != a) continue;
        if (rank == ((2u * j + 1u) * k) / (2u * taps)) {
            vec3 Ps = viewPositionFromDepth(vec2(pixel) + frame.samplePositions[s].xy, d, frame.extent,
                                            frame.depthParams, frame.projParams);
            sum += shadowTap(layer, shadowReceiver(layer, Ps, N));
            ++j;
        }
        ++rank;
    }
    return sum / float(max(j, 1u));
}
#endif

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.extent.xy);
    bool inside = all(lessThan(pixel, size));
    const uint n = kSamples;
    const uint c = kAggregates;
    uint pixelIndex = inside ? uint(pixel.y * size.x + pixel.x) : 0u;

    // ---- 1. aggregate at the top of the tile -------------------------------------------
    uint count = inside ? imageLoad(aggregateCount, pixel).r : 0u;
    float depthSum[kMaxAggregates] = float[](0.0, 0.0, 0.0, 0.0);
    float depthSquares[kMaxAggregates] = float[](0.0, 0.0, 0.0, 0.0);
    vec3 positionSum[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    uint samplesIn[kMaxAggregates] = uint[](0u, 0u, 0u, 0u);
    float tmin = 1e30, tmax = -1e30;
    if (inside) {
        for (uint s = 0u; s < n; ++s) {
            float d = texelFetch(visibilityDepth, ivec3(pixel, s / 4u), int(s % 4u)).r;
            if (isSky(d)) continue;
            uint a = sampleAggregate(s, pixelIndex);
            vec3 P = viewPositionFromDepth(vec2(pixel) + frame.samplePositions[s].xy, d, frame.extent,
                                           frame.depthParams, frame.projParams);
            float t = -P.z;
            depthSum[a] += t;
            depthSquares[a] += t * t;
            positionSum[a] += P;
            samplesIn[a] += 1u;
            tmin = min(tmin, t);
            tmax = max(tmax, t);
        }
    }
    SurfaceInputs surfaces[kMaxAggregates];
    vec3 positions[kMaxAggregates];
    float depthVariance[kMaxAggregates] = float[](0.0, 0.0, 0.0, 0.0);
    bool present[kMaxAggregates] = bool[](false, false, false, false);
    const bool sggx = agaa.options.w == kNdfSggx;
    vec3 tangents[kMaxAggregates], bitangents[kMaxAggregates];
    vec2 alphas[kMaxAggregates]; // SGGX: (alphaT, alphaB), clamped to the BRDF's range
    for (uint a = 0u; a < c; ++a) {
        uint base = (pixelIndex * c + a) * kAggregateWords;
        uint w[kAggregateWords];
        for (uint j = 0u; j < kAggregateWords; ++j) w[j] = inside ? agBuffer[base + j] : 0u;
        uint k = aggregateSampleCount(agaa.options.w, w[0], w[4]); // samples the generation pass accumulated
        // An aggregate with no accumulated sample (no fragment passed EQUAL for it) has nothing to
        // normalise: it is not lit, and its samples resolve to black rather than to a division by 0.
        present[a] = a < count && k > 0u && samplesIn[a] > 0u;
        if (!present[a]) continue;
        float fs = float(samplesIn[a]);
        float meanDepth = depthSum[a] / fs;
        // Position: the mean of the samples' view positions, or the UE4 shortcut (seed 004): the
        // mean depth on the pixel centre's ray (measured against each other in the README).
        vec3 P = agaa.options.y == 0u ? positionSum[a] / fs
                                      : viewPositionAtDistance(vec2(pixel) + 0.5, meanDepth, frame.extent,
                                                               frame.projParams);
        positions[a] = P;
        vec3 V = normalize(-P); // |P| >= znear > 0
        if (sggx) {
            uint scale = unitScale(kSggxFieldBits, n);
            SggxLobe lobe = sggxLobe(meanUnit(w[0] & 0xFFFFu, k, scale), meanUnit(w[0] >> 16u, k, scale),
                                     meanUnit(w[1] & 0xFFFFu, k, scale), meanUnit(w[1] >> 16u, k, scale) - 0.5,
                                     meanUnit(w[2] & 0xFFFFu, k, scale) - 0.5, meanUnit(w[2] >> 16u, k, scale) - 0.5,
                                     V, kSggxOffDiagonal, kMinSggxEigenvalue);
            surfaces[a].normal = lobe.normal;
            tangents[a] = lobe.tangent;
            bitangents[a] = lobe.bitangent;
            alphas[a] = clamp(vec2(lobe.alphaT, lobe.alphaB), kMinGgxAlpha, kMaxGgxAlpha);
            surfaces[a].roughness = sqrt(alphas[a].x); // unused by the anisotropic BRDF
            surfaces[a].albedo = vec3(meanUnit(w[3] & 0xFFFFu, k, scale), meanUnit(w[3] >> 16u, k, scale),
                                      meanUnit(w[4] & 0xFFFFu, k, scale));
            surfaces[a].metallic =
                meanUnit((w[4] >> 16u) & ((1u << kSggxMetallicBits) - 1u), k, unitScale(kSggxMetallicBits, n));
        } else {
            vec3 toksvig = vec3(meanSigned(w[0] & kNormalFieldMask, k, kNormalScale),
                                meanSigned(w[1], k, kNormalScale), meanSigned(w[2], k, kNormalScale));
            float len = length(toksvig);
            // |N| -> 0 when opposing normals cancel: no mean direction; shade facing the viewer
            // (the filtered roughness is then 1, so the direction barely matters).
            surfaces[a].normal = len > kMinNormalLength ? toksvig / len : V;
            surfaces[a].roughness = sqrt(filteredAlpha(len, agaa.toksvig.x)); // the BRDF squares it back
            surfaces[a].albedo = vec3(meanUnit(w[3] & 0xFFFFu, k, kUnormScale), meanUnit(w[3] >> 16u, k, kUnormScale),
                                      meanUnit(w[4] & 0xFFFFu, k, kUnormScale));
            surfaces[a].metallic = meanUnit(w[4] >> 16u, k, kUnormScale);
        }
        // Depth variance (E[t^2] - E[t]^2, clamped: cancellation can make it slightly negative):
        // the aggregate's extent along the view ray, the footprint shadow filtering samples in.
        depthVariance[a] = max(depthSquares[a] / fs - meanDepth * meanDepth, 0.0);
    }

    // ---- 2. tile depth bounds and light culling --------------------------------------
    tileBoundsBegin();
    tileBoundsAdd(tmin, tmax);
    tileCullLights();
    barrier();
    if (!inside) return;

    // ---- 3. light each aggregate once per light ----------------------------------------
    float exposure = frame.depthParams.z;
    vec3 radiance[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    // SGGX: the specular part of the radiance and its variance over the aggregate's samples.
    vec3 specular[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    vec3 specularVariance[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    uint events = 0u;
    for (uint a = 0u; a < c; ++a) {
        if (!present[a]) continue;
        events += 1u;
        vec3 P = positions[a];
        vec3 V = normalize(-P);
#if AGAA_SHADOWS
        // The aggregate's footprint: depth standard deviation along the ray, one pixel across.
        float sigma = sqrt(depthVariance[a]);
        float pixelSize = -P.z * 2.0 * frame.extent.w / frame.projParams.y;
#endif
        for (uint i = nextTileLight(0u); i < kMaxLights; i = nextTileLight(i + 1u)) {
            vec3 L, irradiance;
            if (!lightIncidence(lights[i], P, L, irradiance)) continue;
#if AGAA_SHADOWS
            irradiance *= kShadowFootprint == 1u
                              ? shadowVisibilityAggregateSamples(i, pixel, pixelIndex, a, samplesIn[a], surfaces[a].normal)
                              : shadowVisibilityAggregate(i, P, surfaces[a].normal, sigma, pixelSize);
#endif
            if (sggx) {
                vec3 spec;
                radiance[a] += evaluateBrdfAnisotropic(surfaces[a], tangents[a], bitangents[a], alphas[a].x,
                                                       alphas[a].y, V, L, irradiance, spec);
                // Var = (E[L^2] / E[L]^2 - 1) E[L]^2 per light; highlights of different lights
                // fall on different samples, so their variances add.
                specular[a] += spec;
                specularVariance[a] += (sggxSpikeRatio(alphas[a].x, alphas[a].y) - 1.0) * spec * spec;
            } else {
                radiance[a] += evaluateBrdf(surfaces[a], V, L, irradiance);
            }
        }
    }

    // ---- 4. resolve: tone-map per sample, weight by the sample fraction -------------------
    float weight = 1.0 / float(n);
    vec3 sky = frame.skyRadiance.rgb * exposure;
    vec3 display = vec3(0.0), hdr = vec3(0.0);
    for (uint s = 0u; s < n; ++s) {
        float d = texelFetch(visibilityDepth, ivec3(pixel, s / 4u), int(s % 4u)).r;
        if (isSky(d)) {
            display += weight * toneMapAces(sky);
            hdr += weight * sky;
            continue;
        }
        uint a = sampleAggregate(s, pixelIndex);
        vec3 L = present[a] ? radiance[a] : vec3(0.0);
#if AGAA_EMISSIVE
        L += texelFetch(emissiveSamples, ivec3(pixel, s / 4u), int(s % 4u)).rgb;
#endif
        L = min(L * exposure, vec3(kMaxRadiance));
        display += weight * (sggx && present[a] ? toneMapAggregate(L, specular[a] * exposure,
                                                                  specularVariance[a] * (exposure * exposure))
                                                : toneMapAces(L));
        hdr += weight * L;
    }
    imageStore(outHdr, pixel, vec4(hdr, 1.0));
    imageStore(outDisplay, pixel, vec4(display, 1.0));
    imageStore(outShadingEvents, pixel, uvec4(events));
}
