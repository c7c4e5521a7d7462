// AGAA step 4: tiled-deferred lighting that aggregates at the top of each tile (paper
// section 3.5, the UE4 variant of seed 004). One workgroup per 16x16 tile:
//   1. each invocation walks its pixel's n samples once: each aggregate's sample count, depth
//      mean and variance and mean position from the per-sample depths its metadata assigns it,
//      the pixel's sky samples, and its view-distance range for the tile bounds; then it turns
//      the accumulations into normalised aggregates (divide by the sample count; filtered
//      roughness from the Toksvig length, or the anisotropic lobe of the SGGX matrix,
//      shared/sggx.h). Two generation paths feed it (agaa/aggregate/agaa_constants.h
//      AggregateGeneration):
//      - accumulate (AGAA_GBUFFER 0): the AG-buffer the accumulation kernel summed
//        (agaa/generation.glsl) holds each aggregate's fixed-point sums;
//      - samples (AGAA_GBUFFER 1, seed 004): the same walk also reads each sample's G-buffer
//        (reference/gbuffer.frag) and sums its Toksvig vector or SGGX matrix, albedo and metallic
//        into its aggregate here, in registers at the top of the tile, in float: no AG-buffer,
//        no second raster pass;
//   2. tile depth bounds and light culling in shared memory (common/tile_culling.glsl);
//   3. each aggregate lit once per light with the reference's BRDF (common/brdf.glsl). Two
//      schedules (specialisation id 7, agaa/aggregate/agaa_constants.h AggregateShading):
//      - compacted (the default for c >= 2): every present aggregate of the tile is appended to
//        a per-tile list in shared memory and the list is shaded kListRound entries at a time,
//        one entry per invocation, so every SIMD lane is busy whatever the clustering decided
//        (the per-pixel schedule pays for the pixel with the most aggregates in each SIMD group);
//      - registers: each invocation shades its own pixel's aggregates (cheaper when c = 1, where
//        a pixel holds at most one aggregate and the list only adds shared-memory traffic).
//      Both call shadeAggregate() on the same values: their outputs are bit-identical (tested);
//   4. resolve (DESIGN section 6): each aggregate's radiance, tone-mapped and weighted by its
//      sample fraction, plus the sky for uncovered samples. Without emissive every sample of an
//      aggregate has the same radiance, so this costs c tone maps, not n; with emissive it runs
//      per sample (emissive stays per sample, seed 004). The tone map takes the expected value
//      over the aggregate's samples (toneMapAggregate, the two-point resolve; issue 14).
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
#ifndef AGAA_GBUFFER
#define AGAA_GBUFFER 0
#endif
#ifndef AGAA_EXPORT
#define AGAA_EXPORT 0
#endif
#if AGAA_GBUFFER
// The per-sample G-buffer (agaa/common/sample_gbuffer.h): binding 3 is its depth.
layout(set = 0, binding = 6) uniform sampler2DMSArray gNormal;
layout(set = 0, binding = 13) uniform sampler2DMSArray gAlbedoMetal;
layout(set = 0, binding = 10) uniform sampler2DMSArray gEmissiveRoughness;
#define emissiveSamples gEmissiveRoughness // rgb: the per-sample emissive the resolve adds
#include "common/octahedral.glsl"
#else
layout(set = 0, binding = 6, std430) readonly buffer AgBuffer { uint agBuffer[]; };
#endif
#if AGAA_EXPORT
// Test support (tests/agaa/test_agaa_samples_gpu.cpp): what step 1 read and built, for a CPU
// aggregation written apart from this file. 16 floats per record: sample s of pixel p at
// p * n + s, aggregate a of pixel p at pixels * n + p * c + a (layouts in exportSample and
// exportAggregate below).
layout(set = 0, binding = 14, std430) writeonly buffer Export { float exportData[]; };
void exportRecord(uint record, vec4 a, vec4 b, vec4 c, vec4 d) {
    uint o = record * 16u;
    for (uint i = 0u; i < 4u; ++i) {
        exportData[o + i] = a[i];
        exportData[o + 4u + i] = b[i];
        exportData[o + 8u + i] = c[i];
        exportData[o + 12u + i] = d[i];
    }
}
#endif
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D outHdr;
layout(set = 0, binding = 8, rgba32f) uniform writeonly image2D outDisplay;
layout(set = 0, binding = 9, r32ui) uniform writeonly uimage2D outShadingEvents;
#if AGAA_EMISSIVE && !AGAA_GBUFFER
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
#include "common/environment.glsl"
#include "common/lights.glsl"
#include "common/tile_culling.glsl"
#include "common/tonemap.glsl"

uint sampleAggregate(uint s, uint pixelIndex) {
    const uint words = (kSamples * metadataBits(kAggregates) + 31u) / 32u;
    const uint c = kAggregates;
    return unpackMetadata(metadata[pixelIndex * words + (s * metadataBits(c)) / 32u], s, c);
}

#if AGAA_SHADOWS
// Specialisation id 6 (agaa/common/effects.h ShadowFootprint): 0 the statistical footprint
// (common/shadow.glsl shadowVisibilityAggregate), 1 taps at the aggregate's own sample positions,
// 2 adaptive: the statistical taps, refined at every sample where they disagree (issue 14, goal
// P8: the taps' count, not their placement, left one-surface pixels at twice per-sample shading's
// error, and a shadow edge is where the count matters; elsewhere 4 taps agree and are exact).
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

// The penumbra refinement of the adaptive footprint: every one of the aggregate's k samples,
// tapped at its own position, which is the visibility per-sample shading gives those samples.
float shadowVisibilityAggregateEverySample(uint light, ivec2 pixel, uint pixelIndex, uint a, vec3 N) {
    int layer = shadowLayer(light);
    if (layer < 0) return 1.0;
    uint count = 0u;
    float sum = 0.0;
    for (uint s = 0u; s < kSamples; ++s) {
        float d = texelFetch(visibilityDepth, ivec3(pixel, s / 4u), int(s % 4u)).r;
        if (isSky(d) || sampleAggregate(s, pixelIndex) != a) continue;
        vec3 Ps = viewPositionFromDepth(vec2(pixel) + frame.samplePositions[s].xy, d, frame.extent, frame.depthParams,
                                        frame.projParams);
        sum += shadowTap(layer, shadowReceiver(layer, Ps, N));
        ++count;
    }
    return count == 0u ? 1.0 : sum / float(count);
}
#endif

// Specialisation id 7 (agaa/aggregate/agaa_constants.h AggregateShading): 1 the compacted
// per-tile list, 0 each invocation shades its own pixel's aggregates.
layout(constant_id = 7) const uint kCompactShading = 1u;

// Specialisation id 8 (AggregateSettings::skipShading, agaa-timings --breakdown): 1 skips step 3.
layout(constant_id = 8) const uint kSkipShading = 0u;
// Specialisation id 9: the normal distribution (kNdfToksvig, kNdfSggx; agaa.options.w holds the
// same value). A constant, not a uniform: lavapipe executes both sides of every branch whose
// condition is not known at compile time, so a uniform choice would pay for both BRDFs.
layout(constant_id = 9) const uint kNdf = 0u;
// The two-point resolve (common/tonemap.glsl toneMapAggregate, shared/sggx.h spike ratio) spreads
// every aggregate's specular over its samples, from the samples' own material alpha (the samples
// path reads it per sample, the accumulate path sums it in AG-buffer word 5), so that an aggregate
// of mirror-like samples whose normals spread wide is resolved as sparse highlights, not as the
// glow of its mean (issue 14). Toksvig and SGGX alike.
// Specialisation id 10 (AggregateRouting): 1 when the generation pass routed whole fragments
// (Algorithm 2); an aggregate then stands for the samples it received, which need not be the
// samples the metadata assigned it, so the resolve weights it by its accumulated count.
layout(constant_id = 10) const uint kRouteFragment = 0u;
// Specialisation id 11 (eng::scene::SceneFeatures::hasNearMirrors): 1 where a material can be a near
// mirror, whose lobe the pixel's view footprint can outgrow (addLightFootprint); 0 compiles the
// branch away, which alone costs lavapipe about a fifth of this pass.
layout(constant_id = 11) const uint kViewFootprint = 1u;
const uint kTilePixels = kTileSize * kTileSize;
// Entries of the per-tile list shaded per round: one per invocation. c = 4 can append up to
// 4 x 256; the list is then shaded in up to 4 rounds through the same 256-entry storage, which
// keeps the tile's shared memory at 26.5 KB (lavapipe offers 32 KB).
const uint kListRound = kTilePixels;

// One round of the per-tile list, struct-of-arrays. Inputs, written by the aggregate's pixel:
//   sPosition  xyz view-space shading position, w depth standard deviation (shadow footprint)
//   sNormal    xyz shading normal, w roughness (SGGX: the square root of the material alpha)
//   sAlbedo    rgb albedo, a metallic
//   sTangent   xyz tangent (SGGX), w alphas.x;  sBitangent: xyz bitangent (SGGX), w alphas.y
//   sOwner     tile pixel index | aggregate id << 8 | the aggregate's sample count << 10
//   sSpread    x the mean length of the aggregate's normals (Toksvig's filtered diffuse; 1: none),
//              y the environment's perceptual roughness (common/environment.glsl
//              environmentAggregateRoughness)
//   sScreenSpread  the covariance (xx, xy, yy) of its samples' sub-pixel positions, pixel^2
// Outputs, written in place by the invocation that shades the entry: sPosition.xyz radiance,
// sNormal.xyz specular part, sAlbedo.xyz its variance over the aggregate's samples.
shared vec4 sPosition[kListRound];
shared vec4 sNormal[kListRound];
shared vec4 sAlbedo[kListRound];
shared vec4 sTangent[kListRound];
shared vec4 sBitangent[kListRound];
shared uint sOwner[kListRound];
shared vec2 sSpread[kListRound];
shared vec3 sScreenSpread[kListRound];
shared uint sEntryCount;

// One light's contribution to an aggregate: its radiance, its specular part, and the square of
// that (the two-point resolve's variance is (spike ratio - 1) times the sum of the squares: the
// highlights of different lights fall on different samples, so their variances add).
void addLight(SurfaceInputs surface, vec3 T, vec3 B, vec2 alphas, float spread, vec3 V, vec3 L, vec3 irradiance,
              bool sggx, inout vec3 radiance, inout vec3 specular, inout vec3 specularSquares) {
    vec3 spec;
    if (sggx)
        radiance += evaluateBrdfAnisotropicFiltered(surface, T, B, alphas.x, alphas.y, spread, V, L, irradiance, spec);
    else
        radiance += evaluateBrdfFilteredSplit(surface, spread, V, L, irradiance, spec);
    specular += spec;
    specularSquares += spec * spec;
}

// addLight for a near mirror (viewFootprintWeight > 0): the light seen from each of the aggregate's
// samples' own view direction, through the aggregate's lobe, averaged and blended with the one view
// direction by the weight t. On a flat mirror that is what per-sample shading gives those samples:
// hard-mirror's sun peak on the chrome wall falls between pixel centres, and one view direction a
// pixel finds it or misses it (-42 % of the image's energy at 128x128 against the n = 32
// reference). Widening the lobe by the footprint instead drew halos: a GGX lobe's tails reach much
// further than the pixel's box (issue 14, README). The specular's square goes in once, for the
// average: the view directions' spread is the footprint's, not the lobe's spike.
void addLightFootprint(SurfaceInputs surface, vec3 T, vec3 B, vec2 alphas, float spread, vec3 V, vec3 L,
                       vec3 irradiance, bool sggx, ivec2 pixel, uint pixelIndex, uint a, float t, inout vec3 radiance,
                       inout vec3 specular, inout vec3 specularSquares) {
    vec3 one = vec3(0.0), oneSpecular = vec3(0.0), unused = vec3(0.0);
    addLight(surface, T, B, alphas, spread, V, L, irradiance, sggx, one, oneSpecular, unused);
    vec3 each = vec3(0.0), eachSpecular = vec3(0.0);
    uint count = 0u;
    for (uint s = 0u; s < kSamples; ++s) {
        float d = texelFetch(visibilityDepth, ivec3(pixel, s / 4u), int(s % 4u)).r;
        if (isSky(d) || sampleAggregate(s, pixelIndex) != a) continue;
        vec3 Ps = viewPositionFromDepth(vec2(pixel) + frame.samplePositions[s].xy, d, frame.extent, frame.depthParams,
                                        frame.projParams);
        addLight(surface, T, B, alphas, spread, normalize(-Ps), L, irradiance, sggx, each, eachSpecular, unused);
        ++count;
    }
    if (count > 0u) {
        one = mix(one, each / float(count), t);
        oneSpecular = mix(oneSpecular, eachSpecular / float(count), t);
    }
    radiance += one;
    specular += oneSpecular;
    specularSquares += oneSpecular * oneSpecular;
}

// What light i gives c = 1's off-layer samples, unshadowed, from their mean position (a wall
// behind leaves is not where the leaves are: the range window and 1/d^2 differ): the irradiance
// through their normals' lobe (filteredClampedCosine), and the specular radiance towards the eye
// through the same mean normal, of their mean F0, with the alpha Toksvig filters from the lobe's
// length (offLayerSpecular: F0 rgb, roughness). Without the specular a metal behind the
// aggregate's layer was black: the metal lattice's bars of the other layers, -24 % of the image's
// mean radiance at c = 1 (issue 14). False where the light does not reach that position.
bool offLayerLight(uint i, vec4 offLayerPosition, vec4 offLayerLobe, vec4 offLayerSpecular, out vec3 irradiance,
                   out vec3 specular) {
    irradiance = vec3(0.0);
    specular = vec3(0.0);
    vec3 L, incidence;
    // kAggregates: a specialisation constant, so c >= 2 (no off-layer samples) compiles this away.
    if (kAggregates != 1u || offLayerPosition.w == 0.0 ||
        !lightIncidence(lights[i], offLayerPosition.xyz, L, incidence))
        return false;
    irradiance = incidence * filteredClampedCosine(dot(offLayerLobe.xyz, L), offLayerLobe.w);
    SurfaceInputs surface;
    surface.albedo = offLayerSpecular.rgb; // metallic 1: F0 is the albedo, and no diffuse lobe
    surface.metallic = 1.0;
    surface.roughness = offLayerSpecular.w;
    surface.normal = offLayerLobe.xyz;
    specular = evaluateBrdf(surface, normalize(-offLayerPosition.xyz), L, incidence); // |P| >= znear
    return true;
}

// One shading event: the aggregate `a` of `pixel` (k samples), seen at P, lit by every light of
// the tile. radiance: its linear radiance before exposure, with its specular part and the
// variance of the specular radiance over the aggregate's samples (the two-point resolve's).
// screenSpread: the covariance of the aggregate's sub-pixel sample positions (the statistical
// shadow footprint's width, common/depth.glsl aggregateWidth).
// offLayerPosition (w = 1 where the pixel has off-layer samples, else 0), offLayerLobe (their
// mean normal's direction and length), offLayerSpecular (their F0 and filtered roughness) and
// offLayerMaterialAlpha (their samples' mean material alpha): c = 1's
// off-layer samples, whose diffuse irradiance, specular radiance and its variance over their samples
// come back in offLayerIrradiance, offLayerSpecularRadiance and offLayerSpecularVariance
// (offLayerLight, offLayerRadiance; the variance as the aggregate's, for the two-point resolve).
void shadeAggregate(SurfaceInputs surface, vec3 T, vec3 B, vec2 alphas, float spread, float environmentRoughness,
                    vec3 P, float sigma,
                    vec3 screenSpread, ivec2 pixel, uint pixelIndex, uint a, uint k, bool sggx, vec4 offLayerPosition,
                    vec4 offLayerLobe, vec4 offLayerSpecular, float offLayerMaterialAlpha, out vec3 radiance, out vec3 specular, out vec3 specularVariance,
                    out vec3 offLayerIrradiance, out vec3 offLayerSpecularRadiance, out vec3 offLayerSpecularVariance) {
    radiance = vec3(0.0);
    specular = vec3(0.0);
    specularVariance = vec3(0.0);
    offLayerIrradiance = vec3(0.0);
    offLayerSpecularRadiance = vec3(0.0);
    offLayerSpecularVariance = vec3(0.0);
    vec3 offLayerSquares = vec3(0.0);
    vec3 V = normalize(-P); // |P| >= znear > 0
#if AGAA_SHADOWS
    // The aggregate's footprint: depth standard deviation along the ray, one pixel across.
    float pixelSize = pixelFootprint(-P.z, frame.extent, frame.projParams);
#endif
    vec3 specularSquares = vec3(0.0);
    // Near mirrors: the view directions' spread over the footprint against the lobe (addLightFootprint).
    float theta = pixelFootprint(-P.z, frame.extent, frame.projParams) / length(P);
    float viewWeight =
        kViewFootprint != 0u ? viewFootprintWeight(theta, screenSpread, sggx ? min(alphas.x, alphas.y) : alphas.x) : 0.0;
    // The environment through the aggregate's filtered distribution: its mean normal and its
    // filtered roughness without the punctual BRDF's floor (environmentRoughness). Smooth at the
    // scale of an aggregate: no spike, so it stays out of the two-point resolve's variance.
    if (kEnvironment != 0u) {
        radiance += environmentLightingFiltered(surface, V, environmentRoughness, spread);
        float r = offLayerLobe.w; // the lobe's band factors, as filteredClampedCosine's
        if (kAggregates == 1u && offLayerPosition.w != 0.0)
            offLayerIrradiance += environmentIrradiance(environmentDirection(offLayerLobe.xyz), vec2(r, r * r * r));
    }
    for (uint i = nextTileLight(0u); i < kMaxLights; i = nextTileLight(i + 1u)) {
        vec3 offLayerE, offLayerS;
        if (offLayerLight(i, offLayerPosition, offLayerLobe, offLayerSpecular, offLayerE, offLayerS)) {
            offLayerIrradiance += offLayerE;
            offLayerSpecularRadiance += offLayerS;
            offLayerSquares += offLayerS * offLayerS;
        }
        vec3 L, irradiance;
        if (!lightIncidence(lights[i], P, L, irradiance)) continue;
        if (viewWeight > 0.0)
            addLightFootprint(surface, T, B, alphas, spread, V, L, irradiance, sggx, pixel, pixelIndex, a, viewWeight,
                              radiance, specular, specularSquares);
        else
            addLight(surface, T, B, alphas, spread, V, L, irradiance, sggx, radiance, specular, specularSquares);
    }
#if AGAA_SHADOWS
    for (uint i = nextTileShadowedLight(0u); i < kMaxLights; i = nextTileShadowedLight(i + 1u)) {
        // c = 1: the off-layer samples' own shadow, one tap at their mean position (not the
        // aggregate's: the wall behind a leaf is not in the leaf's shadow).
        vec3 offLayerE, offLayerS;
        if (offLayerLight(i, offLayerPosition, offLayerLobe, offLayerSpecular, offLayerE, offLayerS) &&
            offLayerE + offLayerS != vec3(0.0)) {
            float offLayerVisibility = shadowVisibilityPoint(i, offLayerPosition.xyz, offLayerLobe.xyz);
            offLayerIrradiance += offLayerE * offLayerVisibility;
            offLayerSpecularRadiance += offLayerS * offLayerVisibility;
            offLayerSquares += offLayerS * offLayerS * (offLayerVisibility * offLayerVisibility);
        }
        vec3 L, irradiance;
        if (!lightIncidence(lights[i], P, L, irradiance)) continue;
        float visibility;
        if (kShadowFootprint == 1u)
            visibility = shadowVisibilityAggregateSamples(i, pixel, pixelIndex, a, k, surface.normal);
        else if (kShadowFootprint == 0u)
            visibility = shadowVisibilityAggregate(i, P, surface.normal, sigma, pixelSize, screenSpread);
        else {
            // Adaptive: where the footprint's corners disagree a shadow edge crosses the aggregate
            // and its own samples decide (up to n taps, paid by the few aggregates on a penumbra);
            // where they agree, that is the answer.
            visibility = shadowVisibilityAggregateCorners(i, P, surface.normal, sigma, pixelSize, screenSpread);
            float rooks = shadowVisibilityAggregate(i, P, surface.normal, sigma, pixelSize, screenSpread);
            if (visibility != rooks || (visibility > 0.0 && visibility < 1.0))
                visibility = shadowVisibilityAggregateEverySample(i, pixel, pixelIndex, a, surface.normal);
        }
        irradiance *= visibility;
        if (viewWeight > 0.0)
            addLightFootprint(surface, T, B, alphas, spread, V, L, irradiance, sggx, pixel, pixelIndex, a, viewWeight,
                              radiance, specular, specularSquares);
        else
            addLight(surface, T, B, alphas, spread, V, L, irradiance, sggx, radiance, specular, specularSquares);
    }
#endif
    // The spike ratio E[L^2] / E[L]^2 of the aggregate's samples (shared/sggx.h), once per event:
    // SGGX, alphas = (alphaT, alphaB) with the material alpha in surface.roughness; Toksvig,
    // alphas = (filtered alpha, material alpha), both axes alike.
    float axis = spikeRatioAxis(alphas.x, alphas.y);
    float ratio = sggx ? sggxSpikeRatio(alphas.x, alphas.y, surface.roughness * surface.roughness) : axis * axis;
    specularVariance = (ratio - 1.0) * specularSquares;
    // c = 1's off-layer samples: their Toksvig lobe (filtered, material alpha) likewise. Without it
    // the spike ball's off-layer gold, a wide lobe of the same mean, tone-mapped to a glow: 1.38x
    // no-AA's display error at c = 1.
    if (kAggregates == 1u && offLayerPosition.w != 0.0) {
        float filtered = clamp(offLayerSpecular.w * offLayerSpecular.w, kMinGgxAlpha, kMaxGgxAlpha);
        float offAxis = spikeRatioAxis(filtered, clamp(offLayerMaterialAlpha, kMinGgxAlpha, filtered));
        offLayerSpecularVariance = (offAxis * offAxis - 1.0) * offLayerSquares;
    }
}

// c = 1 (issue 14): the samples off the aggregate's layer (shared/clustering.h kOffLayer) are a
// surface the one shading event does not describe: behind or in front of the layer, with normals
// the aggregate does not carry. Both paths resolve them as one surface of their own: Lambert of
// their mean diffuse colour (albedo (1 - metallic); with emission, which resolves per sample, the
// samples path takes each sample's own) under their own irradiance, and GGX of their mean F0
// through their own mean normal and its Toksvig-filtered alpha: the tile's lights at their mean
// position, through their mean normal's lobe (filteredClampedCosine and the environment's bands),
// each shadowed light by one tap at that position (shadeAggregate, offLayerLight). A chrome wall
// behind a sphere's rim takes the wall's own flat normals there, not the rim's.
// Before, their albedo and metallic joined the aggregate's means, which the BRDF is not linear in
// (diffuse albedo (1 - m), F0 mix(0.04, albedo, m)): a grey ring round hard-mirror's plastic
// sphere, lit with its grazing normals, 1.13x no-AA's error at c = 1. Then they took the aggregate's
// irradiance, its position, normals and shadow: foliage's wall behind the leaves lost the point
// lights near it, -13.7 % of the image's mean radiance at 64x64 (-0.4 % then). Then they had no
// specular: metal's bars behind the aggregate's layer were black, -24 % (offLayerLight).
vec3 offLayerRadiance(vec3 diffuseColour, vec3 irradiance) { return diffuseColour / kPi * irradiance; }

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.extent.xy);
    bool inside = all(lessThan(pixel, size));
    const uint n = kSamples;
    const uint c = kAggregates;
    const uint self = gl_LocalInvocationIndex;
    uint pixelIndex = inside ? uint(pixel.y * size.x + pixel.x) : 0u;

    // ---- 1. aggregate at the top of the tile: one walk over the pixel's samples -----------
    uint count = inside ? imageLoad(aggregateCount, pixel).r : 0u;
    float depthSum[kMaxAggregates] = float[](0.0, 0.0, 0.0, 0.0);
    // Depths relative to the pixel's first covered sample for the variance: E[t^2] - E[t]^2 at
    // t ~ metres cancels in fp32 below about 1e-6 t^2, the whole spread of a face-on pixel.
    float depthShifted[kMaxAggregates] = float[](0.0, 0.0, 0.0, 0.0);
    float depthSquares[kMaxAggregates] = float[](0.0, 0.0, 0.0, 0.0);
    float depthOrigin = -1.0;
    vec3 positionSum[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    uint samplesIn[kMaxAggregates] = uint[](0u, 0u, 0u, 0u);
    vec2 screenSum[kMaxAggregates] = vec2[](vec2(0.0), vec2(0.0), vec2(0.0), vec2(0.0));
    vec3 screenSquares[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    uint skySamples = 0u;
    uint offLayerSamples = 0u; // c = 1: covered samples off aggregate 0's layer (offLayerRadiance)
    vec3 offLayerPositionSum = vec3(0.0); // and their view positions
    float tmin = 1e30, tmax = -1e30;
    const bool sggx = kNdf == kNdfSggx;
#if AGAA_GBUFFER
    // Per aggregate: the sums of its samples' normal distribution (Toksvig: the vector in xyz of
    // moment0; SGGX: the matrix's diagonal in moment0, its off-diagonal xy, xz, yz in moment1),
    // albedo and metallic. The same per-sample terms as the accumulation kernel's, unquantised.
    vec3 moment0[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    vec3 moment1[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    vec4 albedoMetalSum[kMaxAggregates] = vec4[](vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
    vec3 offLayerDiffuseSum = vec3(0.0); // c = 1: the off-layer samples' diffuse colours (offLayerRadiance)
    vec3 offLayerNormalSum = vec3(0.0);  // and their shading normals,
    vec4 offLayerF0AlphaSum = vec4(0.0); // F0 and material alpha (offLayerLight)
    float materialAlphaSum[kMaxAggregates] = float[](0.0, 0.0, 0.0, 0.0); // the two-point resolve's
    // The material alpha below the BRDF's floor too: the environment's level of a near-mirror.
    float materialAlphaRawSum[kMaxAggregates] = float[](0.0, 0.0, 0.0, 0.0);
#endif
    if (inside) {
        for (uint s = 0u; s < n; ++s) {
            ivec3 at = ivec3(pixel, s / 4u);
            float d = texelFetch(visibilityDepth, at, int(s % 4u)).r;
            if (isSky(d)) {
                skySamples += 1u;
#if AGAA_EXPORT
                exportRecord(pixelIndex * n + s, vec4(0.0), vec4(0.0), vec4(0.0), vec4(0.0));
#endif
                continue;
            }
            uint a = sampleAggregate(s, pixelIndex);
            vec3 P = viewPositionFromDepth(vec2(pixel) + frame.samplePositions[s].xy, d, frame.extent,
                                           frame.depthParams, frame.projParams);
            tmin = min(tmin, -P.z);
            tmax = max(tmax, -P.z);
            // c = 1, off the aggregate's layer (shared/clustering.h kOffLayer): the sample's
            // coverage joins aggregate 0, its position and normal distribution do not; its colour
            // joins aggregate 0's on the accumulate path, and on the samples path resolves it
            // (offLayerRadiance).
            bool offLayer = a >= c;
            if (offLayer) {
                offLayerSamples += 1u;
                offLayerPositionSum += P;
                a = 0u;
            }
#if AGAA_GBUFFER
            vec3 N = decodeOctahedral(texelFetch(gNormal, at, int(s % 4u)).rg);
            vec4 albedoMetal = texelFetch(gAlbedoMetal, at, int(s % 4u));
            float roughness = texelFetch(gEmissiveRoughness, at, int(s % 4u)).a;
            float alpha = roughness * roughness;
            if (offLayer) {
                offLayerDiffuseSum += albedoMetal.rgb * (1.0 - albedoMetal.a);
                offLayerNormalSum += N;
                offLayerF0AlphaSum += vec4(mix(vec3(0.04), albedoMetal.rgb, albedoMetal.a), min(alpha, 1.0));
            } else
                albedoMetalSum[a] += albedoMetal;
#if AGAA_EXPORT
            exportRecord(pixelIndex * n + s, vec4(N, roughness), albedoMetal, vec4(P, offLayer ? float(c) : float(a)),
                         vec4(1.0, 0.0, 0.0, 0.0));
#endif
#endif
            if (offLayer) continue;
#if AGAA_GBUFFER
            if (sggx) {
                // The sample's GGX lobe as an SGGX matrix, S = (1 - a^2) N N^T + a^2 I (shared/sggx.h).
                float ca = clamp(alpha, kMinGgxAlpha, kMaxGgxAlpha);
                float a2 = ca * ca;
                vec3 Nw = N * (1.0 - a2);
                moment0[a] += Nw * N + a2;
                moment1[a] += vec3(Nw.x * N.y, Nw.x * N.z, Nw.y * N.z);
            } else {
                // Roughness as normal variance: the Toksvig length of the sample's alpha.
                moment0[a] += N * toksvigLength(alpha, agaa.toksvig.x, agaa.toksvig.y, agaa.toksvig.z);
            }
            materialAlphaSum[a] += clamp(alpha, kMinGgxAlpha, kMaxGgxAlpha);
            materialAlphaRawSum[a] += min(alpha, kMaxGgxAlpha);
#endif
            float t = -P.z;
            depthSum[a] += t;
            if (depthOrigin < 0.0) depthOrigin = t;
            depthShifted[a] += t - depthOrigin;
            depthSquares[a] += (t - depthOrigin) * (t - depthOrigin);
            positionSum[a] += P;
            samplesIn[a] += 1u;
            vec2 sp = frame.samplePositions[s].xy;
            screenSum[a] += sp;
            screenSquares[a] += vec3(sp.x * sp.x, sp.x * sp.y, sp.y * sp.y);
        }
    }
    // c = 1: the off-layer samples' mean diffuse colour and normal (offLayerRadiance). Whole-
    // fragment routing fed their fragments to the aggregate: there they take its radiance instead.
    const bool offLayerOwnColour = AGAA_GBUFFER != 0 || kRouteFragment == 0u;
    vec3 offLayerDiffuse = vec3(0.0), offLayerNormal = vec3(0.0);
    vec4 offLayerF0Alpha = vec4(0.0);
    if (offLayerOwnColour && offLayerSamples > 0u) {
#if AGAA_GBUFFER
        offLayerDiffuse = offLayerDiffuseSum / float(offLayerSamples);
        offLayerNormal = offLayerNormalSum / float(offLayerSamples);
        offLayerF0Alpha = offLayerF0AlphaSum / float(offLayerSamples);
#else
        uint at = offLayerWord(uint(size.x * size.y), pixelIndex), scale = unitScale(kOffLayerFieldBits, n);
        uint w0 = agBuffer[at], w1 = agBuffer[at + 1u], w2 = agBuffer[at + 2u];
        offLayerDiffuse = vec3(meanUnit(w0 & 0xFFFFu, offLayerSamples, scale), meanUnit(w0 >> 16u, offLayerSamples, scale),
                               meanUnit(w1 & 0xFFFFu, offLayerSamples, scale));
        offLayerNormal = vec3(meanSigned(w1 >> 16u, offLayerSamples, scale), meanSigned(w2 & 0xFFFFu, offLayerSamples, scale),
                              meanSigned(w2 >> 16u, offLayerSamples, scale));
        uint w3 = agBuffer[at + 3u], w4 = agBuffer[at + 4u];
        offLayerF0Alpha = vec4(meanUnit(w3 & 0xFFFFu, offLayerSamples, scale), meanUnit(w3 >> 16u, offLayerSamples, scale),
                               meanUnit(w4 & 0xFFFFu, offLayerSamples, scale), meanUnit(w4 >> 16u, offLayerSamples, scale));
#endif
    }
    SurfaceInputs surfaces[kMaxAggregates];
    vec3 positions[kMaxAggregates];
    float depthSigma[kMaxAggregates] = float[](0.0, 0.0, 0.0, 0.0);
    vec3 screenSpreads[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    bool present[kMaxAggregates] = bool[](false, false, false, false);
    vec3 tangents[kMaxAggregates], bitangents[kMaxAggregates];
    vec2 alphas[kMaxAggregates]; // SGGX: (alphaT, alphaB), clamped to the BRDF's range
    // The mean length of the aggregate's unit normals, the material's roughness taken out of the
    // Toksvig length: the spread the filtered diffuse integrates over (1: one direction).
    float spreads[kMaxAggregates] = float[](1.0, 1.0, 1.0, 1.0);
    float environmentRoughness[kMaxAggregates] = float[](0.0, 0.0, 0.0, 0.0);
    uint presentCount = 0u;
    uint accumulated[kMaxAggregates] = uint[](0u, 0u, 0u, 0u);
    for (uint a = 0u; a < c; ++a) {
#if AGAA_GBUFFER
        uint k = samplesIn[a]; // every sample the metadata assigns was read here
#else
        uint base = (pixelIndex * c + a) * kAggregateWords;
        uint w[kAggregateWords];
        for (uint j = 0u; j < kAggregateWords; ++j) w[j] = inside ? agBuffer[base + j] : 0u;
        uint k = aggregateSampleCount(kNdf, w[0], w[4]); // samples the generation pass accumulated
#endif
        // An aggregate with no accumulated sample (no fragment passed EQUAL for it) has nothing to
        // normalise: it is not lit, and its samples resolve to black rather than to a division by 0.
        present[a] = a < count && k > 0u && samplesIn[a] > 0u;
        accumulated[a] = present[a] ? k : 0u;
        tangents[a] = vec3(0.0);
        bitangents[a] = vec3(0.0);
        alphas[a] = vec2(0.0);
        if (!present[a]) continue;
        presentCount += 1u;
        float fs = float(samplesIn[a]);
        float meanDepth = depthSum[a] / fs;
        // Position: the mean of the samples' view positions, or the UE4 shortcut (seed 004): the
        // mean depth on the pixel centre's ray (measured against each other in the README).
        vec3 P = agaa.options.y == 0u ? positionSum[a] / fs
                                      : viewPositionAtDistance(vec2(pixel) + 0.5, meanDepth, frame.extent,
                                                               frame.projParams);
        positions[a] = P;
        vec3 V = normalize(-P); // |P| >= znear > 0
        // The aggregate's means: normal-distribution moments, albedo, metallic, material alpha.
        vec3 mean0, mean1, albedo;
        float metallic, materialAlpha;
#if AGAA_GBUFFER
        materialAlpha = materialAlphaSum[a] / fs;
        mean0 = moment0[a] / fs;
        mean1 = moment1[a] / fs;
        albedo = albedoMetalSum[a].rgb / fs; // the layer's samples only (c = 1: offLayerRadiance)
        metallic = albedoMetalSum[a].a / fs;
#else
        // The colour fields hold the aggregate's own samples (c = 1: the off-layer ones add their
        // diffuse colour to the off-layer words; whole-fragment routing adds every sample in full).
        uint kColour = k;
        if (sggx) {
            uint scale = unitScale(kSggxFieldBits, n);
            mean0 = vec3(meanUnit(w[0] & 0xFFFFu, k, scale), meanUnit(w[0] >> 16u, k, scale),
                         meanUnit(w[1] & 0xFFFFu, k, scale));
            // Off-diagonal entries are stored offset by 1/2 (generation.glsl).
            mean1 = vec3(meanUnit(w[1] >> 16u, k, scale) - 0.5, meanUnit(w[2] & 0xFFFFu, k, scale) - 0.5,
                         meanUnit(w[2] >> 16u, k, scale) - 0.5);
            albedo = vec3(meanUnit(w[3] & 0xFFFFu, kColour, scale), meanUnit(w[3] >> 16u, kColour, scale),
                          meanUnit(w[4] & 0xFFFFu, kColour, scale));
            metallic = meanUnit((w[4] >> 16u) & ((1u << kSggxMetallicBits) - 1u), kColour,
                                unitScale(kSggxMetallicBits, n));
        } else {
            const uint sx = toksvigScaleX(n), syz = toksvigScaleYZ(n);
            mean0 = vec3(meanSigned(w[0] & kNormalFieldMask, k, sx), meanSigned(w[1], k, syz),
                         meanSigned(w[2], k, syz));
            mean1 = vec3(0.0);
            albedo = vec3(meanUnit(w[3] & 0xFFFFu, kColour, kUnormScale),
                          meanUnit(w[3] >> 16u, kColour, kUnormScale), meanUnit(w[4] & 0xFFFFu, kColour, kUnormScale));
            metallic = meanUnit(w[4] >> 16u, kColour, kUnormScale);
        }
        float rawMaterialMean = meanUnit(w[5], k, kMaterialAlphaScale);
        materialAlpha = max(rawMaterialMean, kMinGgxAlpha); // the BRDF's range, as the samples path's
#endif
        surfaces[a].albedo = albedo;
        surfaces[a].metallic = metallic;
        if (sggx) {
            SggxLobe lobe = sggxLobe(mean0.x, mean0.y, mean0.z, mean1.x, mean1.y, mean1.z, V, kSggxOffDiagonal,
                                     kMinSggxEigenvalue);
#if !AGAA_GBUFFER
            // Fixed-point matrix: spread below its quantisation is rounding (shared/sggx.h).
            float step = kSggxQuantizationSteps / float(unitScale(kSggxFieldBits, n));
            float material = clamp(materialAlpha, kMinGgxAlpha, kMaxGgxAlpha);
            lobe.alphaT = sggxDequantizedAlpha(lobe.alphaT, material, step);
            lobe.alphaB = sggxDequantizedAlpha(lobe.alphaB, material, step);
#endif
            surfaces[a].normal = lobe.normal;
            tangents[a] = lobe.tangent;
            bitangents[a] = lobe.bitangent;
            alphas[a] = clamp(vec2(lobe.alphaT, lobe.alphaB), kMinGgxAlpha, kMaxGgxAlpha);
            // The material alpha of the spike ratio (the anisotropic BRDF reads only the alphas).
            surfaces[a].roughness = sqrt(clamp(materialAlpha, kMinGgxAlpha, alphas[a].y));
            // The normals' spread from the matrix's second moment along the lobe normal, the
            // material's lobe taken out (S = (1 - a^2) E[N N^T] + a^2 I): m = E[(N.n)^2], and a vMF
            // lobe of mean length r has E[P2(N.n)] = (3m - 1) / 2 = r^3 (the band factors of
            // common/brdf.glsl filteredClampedCosine).
            vec3 nn = lobe.normal;
            float sn = dot(nn * nn, mean0) + 2.0 * (nn.x * nn.y * mean1.x + nn.x * nn.z * mean1.y + nn.y * nn.z * mean1.z);
            float a2 = clamp(materialAlpha, kMinGgxAlpha, kMaxGgxAlpha);
            a2 *= a2;
            float m = clamp((sn - a2) / (1.0 - a2), 1.0 / 3.0, 1.0); // 1 - a2 >= 1 - 0.81
            spreads[a] = pow(1.5 * m - 0.5, 1.0 / 3.0);
        } else {
            float len = length(mean0);
            // |N| -> 0 when opposing normals cancel: no mean direction; shade facing the viewer
            // (the filtered roughness is then 1, so the direction barely matters).
            surfaces[a].normal = len > kMinNormalLength ? mean0 / len : V;
            surfaces[a].roughness = sqrt(filteredAlpha(len, agaa.toksvig.x)); // the BRDF squares it back
            // The Toksvig length is the normals' mean length times the material's own length
            // (toksvigLength(alpha) >= 0.32 for alpha <= kMaxGgxAlpha: the division is bounded).
            spreads[a] = clamp(len / toksvigLength(materialAlpha, agaa.toksvig.x, agaa.toksvig.y, agaa.toksvig.z),
                               0.0, 1.0);
            // The two-point resolve's (filtered, material) alphas, in the BRDF's range.
            float filtered = clamp(surfaces[a].roughness * surfaces[a].roughness, kMinGgxAlpha, kMaxGgxAlpha);
            alphas[a] = vec2(filtered, clamp(materialAlpha, kMinGgxAlpha, filtered));
        }
#if AGAA_GBUFFER
        float rawMaterialAlpha = materialAlphaRawSum[a] / fs;
#else
        float rawMaterialAlpha = rawMaterialMean; // the AG-buffer's w5 is not floored (generation.glsl)
#endif
        environmentRoughness[a] =
            environmentAggregateRoughness(sggx ? sqrt(alphas[a].x * alphas[a].y) : alphas[a].x, rawMaterialAlpha);
#if AGAA_EXPORT
        exportRecord(uint(size.x * size.y) * n + pixelIndex * c + a, vec4(mean0, mean1.x), vec4(mean1.yz, albedo.rg),
                     vec4(albedo.b, metallic, float(k), surfaces[a].roughness), vec4(surfaces[a].normal, 1.0));
#endif
        // Depth variance (E[t^2] - E[t]^2, clamped: cancellation can make it slightly negative):
        // the aggregate's extent along the view ray, the footprint shadow filtering samples in.
        float meanShifted = depthShifted[a] / fs;
        depthSigma[a] = sqrt(max(depthSquares[a] / fs - meanShifted * meanShifted, 0.0));
        vec2 ms = screenSum[a] / fs;
        screenSpreads[a] = screenSquares[a] / fs - vec3(ms.x * ms.x, ms.x * ms.y, ms.y * ms.y);
    }

    // ---- 2. tile depth bounds and light culling; the pixel's place in the tile's list -------
    if (kCompactShading != 0u && self == 0u) sEntryCount = 0u;
    tileBoundsBegin(); // its barrier orders the counter's reset before the appends
    // Aggregate 0 is shaded in registers (every covered pixel has one); the others join the list.
    uint extraCount = presentCount - (present[0] ? 1u : 0u);
    uint firstEntry = kCompactShading != 0u && extraCount > 0u ? atomicAdd(sEntryCount, extraCount) : 0u;
    tileBoundsAdd(tmin, tmax);
    tileCullLights();
    barrier();

    // ---- 3. light each aggregate once per light ----------------------------------------
    vec3 radiance[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    // Two-point resolve: the specular part of the radiance and its variance over the aggregate's samples.
    vec3 specular[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    vec3 specularVariance[kMaxAggregates] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    // c = 1: the irradiance the off-layer samples resolve with (offLayerRadiance), taken with
    // aggregate 0's lights at their mean position, through their normals' lobe.
    vec3 offLayerIrradiance = vec3(0.0);
    vec4 offLayerPosition = offLayerSamples > 0u ? vec4(offLayerPositionSum / float(offLayerSamples), 1.0) : vec4(0.0);
    vec4 offLayerLobe = meanNormalLobe(offLayerNormal);
    // Their specular lobe: Toksvig's filtered alpha from the normals' mean length times the
    // material's own Toksvig length (the aggregates' Toksvig path, section 4.4), as a roughness.
    vec4 offLayerSpecular = vec4(offLayerF0Alpha.rgb,
                                 sqrt(filteredAlpha(offLayerLobe.w * toksvigLength(offLayerF0Alpha.w, agaa.toksvig.x,
                                                                                   agaa.toksvig.y, agaa.toksvig.z),
                                                    agaa.toksvig.x)));
    vec3 offLayerSpecularRadiance = vec3(0.0), offLayerSpecularVariance = vec3(0.0);
    if (kSkipShading != 0u) {
    } else if (kCompactShading != 0u) {
        // The tile's further aggregates, packed: lane j shades entry j of each round. The slots
        // are taken in whatever order the appends ran; an entry's result depends only on its own
        // values and the tile's lights, so the image does not depend on that order.
        uint entries = sEntryCount; // uniform over the workgroup: every invocation runs the same rounds
        uvec2 tileOrigin = gl_WorkGroupID.xy * kTileSize;
        for (uint listRound = 0u; listRound * kListRound < entries; ++listRound) {
            uint lo = listRound * kListRound;
            uint slot = firstEntry;
            for (uint a = 1u; a < c; ++a) {
                if (!present[a]) continue;
                if (slot >= lo && slot < lo + kListRound) {
                    uint e = slot - lo;
                    sPosition[e] = vec4(positions[a], depthSigma[a]);
                    sNormal[e] = vec4(surfaces[a].normal, surfaces[a].roughness);
                    sAlbedo[e] = vec4(surfaces[a].albedo, surfaces[a].metallic);
                    sTangent[e] = vec4(tangents[a], alphas[a].x);
                    sBitangent[e] = vec4(bitangents[a], alphas[a].y);
                    sOwner[e] = self | (a << 8u) | (samplesIn[a] << 10u);
                    sSpread[e] = vec2(spreads[a], environmentRoughness[a]);
                    sScreenSpread[e] = screenSpreads[a];
                }
                slot += 1u;
            }
            barrier();
            if (self < entries - lo) {
                uint owner = sOwner[self];
                uint ownerIndex = owner & 0xFFu;
                ivec2 ownerPixel = ivec2(tileOrigin + uvec2(ownerIndex % kTileSize, ownerIndex / kTileSize));
                SurfaceInputs surface;
                surface.normal = sNormal[self].xyz;
                surface.roughness = sNormal[self].w;
                surface.albedo = sAlbedo[self].rgb;
                surface.metallic = sAlbedo[self].a;
                vec4 T = sTangent[self];
                vec4 B = sBitangent[self];
                // No off-layer samples beyond aggregate 0.
                vec3 lit, spec, variance, unusedIrradiance, unusedSpecular, unusedVariance;
                shadeAggregate(surface, T.xyz, B.xyz, vec2(T.w, B.w), sSpread[self].x, sSpread[self].y,
                               sPosition[self].xyz,
                               sPosition[self].w, sScreenSpread[self],
                               ownerPixel, uint(ownerPixel.y * size.x + ownerPixel.x), (owner >> 8u) & 3u,
                               owner >> 10u, sggx, vec4(0.0), vec4(surface.normal, sSpread[self].x), vec4(0.0), 0.0, lit,
                               spec, variance, unusedIrradiance, unusedSpecular, unusedVariance);
                sPosition[self].xyz = lit;
                sNormal[self].xyz = spec;
                sAlbedo[self].xyz = variance;
            }
            barrier();
            slot = firstEntry;
            for (uint a = 1u; a < c; ++a) {
                if (!present[a]) continue;
                if (slot >= lo && slot < lo + kListRound) {
                    uint e = slot - lo;
                    radiance[a] = sPosition[e].xyz;
                    specular[a] = sNormal[e].xyz;
                    specularVariance[a] = sAlbedo[e].xyz;
                }
                slot += 1u;
            }
            barrier(); // the next round overwrites the list
        }
        // Aggregate 0 of every covered pixel: every lane of a SIMD group busy but for sky pixels.
        // After the list's rounds: no barrier follows it, so lavapipe (whose compute barriers
        // split the shader into coroutine segments) keeps its loop free of frame spills.
        if (inside && present[0])
            shadeAggregate(surfaces[0], tangents[0], bitangents[0], alphas[0], spreads[0], environmentRoughness[0],
                           positions[0], depthSigma[0], screenSpreads[0],
                           pixel, pixelIndex, 0u, samplesIn[0], sggx, offLayerPosition, offLayerLobe, offLayerSpecular,
                           offLayerF0Alpha.w, radiance[0], specular[0], specularVariance[0], offLayerIrradiance,
                           offLayerSpecularRadiance, offLayerSpecularVariance);
    } else if (inside) {
        for (uint a = 0u; a < c; ++a) {
            if (!present[a]) continue;
            vec3 irradiance, offSpecular, offVariance;
            shadeAggregate(surfaces[a], tangents[a], bitangents[a], alphas[a], spreads[a], environmentRoughness[a],
                           positions[a], depthSigma[a], screenSpreads[a],
                           pixel, pixelIndex, a, samplesIn[a], sggx, a == 0u ? offLayerPosition : vec4(0.0), offLayerLobe,
                           offLayerSpecular, offLayerF0Alpha.w, radiance[a], specular[a], specularVariance[a], irradiance,
                           offSpecular, offVariance);
            if (a == 0u) {
                offLayerIrradiance = irradiance;
                offLayerSpecularRadiance = offSpecular;
                offLayerSpecularVariance = offVariance;
            }
        }
    }
    if (!inside) return;

    // ---- 4. resolve: tone-map each shading event, weight by its sample fraction ------------
    float exposure = frame.depthParams.z;
    float weight = 1.0 / float(n);
    vec3 sky = skyRadiance(pixel) * exposure;
    vec3 display = vec3(0.0), hdr = vec3(0.0);
#if AGAA_EMISSIVE
    for (uint s = 0u; s < n; ++s) {
        float d = texelFetch(visibilityDepth, ivec3(pixel, s / 4u), int(s % 4u)).r;
        if (isSky(d)) {
            display += weight * toneMapAces(sky);
            hdr += weight * sky;
            continue;
        }
        uint id = sampleAggregate(s, pixelIndex);
        uint a = min(id, c - 1u); // c = 1: off-layer samples take aggregate 0's (accumulate path)
        // Fragment routing: a sample whose aggregate received no fragment takes aggregate 0's.
        if (kRouteFragment != 0u && !present[a]) a = 0u;
        vec3 L = present[a] ? radiance[a] : vec3(0.0);
        if (id >= c && offLayerOwnColour) { // c = 1, off the layer: its diffuse colour, their specular
#if AGAA_GBUFFER
            vec4 albedoMetal = texelFetch(gAlbedoMetal, ivec3(pixel, s / 4u), int(s % 4u));
            vec3 diffuse = albedoMetal.rgb * (1.0 - albedoMetal.a); // the sample's own
#else
            vec3 diffuse = offLayerDiffuse; // the pixel's off-layer mean (the AG-buffer keeps no more)
#endif
            L = offLayerRadiance(diffuse, offLayerIrradiance) + offLayerSpecularRadiance +
                texelFetch(emissiveSamples, ivec3(pixel, s / 4u), int(s % 4u)).rgb;
            L = min(L * exposure, vec3(kMaxRadiance));
            display += weight * toneMapAggregate(L, offLayerSpecularRadiance * exposure,
                                                 offLayerSpecularVariance * (exposure * exposure));
            hdr += weight * L;
            continue;
        }
        L += texelFetch(emissiveSamples, ivec3(pixel, s / 4u), int(s % 4u)).rgb;
        L = min(L * exposure, vec3(kMaxRadiance));
        display += weight * (present[a] ? toneMapAggregate(L, specular[a] * exposure,
                                                                  specularVariance[a] * (exposure * exposure))
                                                : toneMapAces(L));
        hdr += weight * L;
    }
#else
    // Every sample of an aggregate shares its radiance: one tone map per aggregate, weighted by
    // the aggregate's sample count; samples of an aggregate that received no fragment are black.
    float skyWeight = weight * float(skySamples);
    display += skyWeight * toneMapAces(sky);
    hdr += skyWeight * sky;
    for (uint a = 0u; a < c; ++a) {
        // c = 1: the aggregate stands for every covered sample, the off-layer ones too (with fragment
        // routing the fragments whose first sample is off the layer fed it nothing).
        uint stands = kRouteFragment != 0u && c > 1u ? accumulated[a]
                                                     : samplesIn[a] + (a == 0u && !offLayerOwnColour ? offLayerSamples : 0u);
        if (a == 0u && offLayerOwnColour && offLayerSamples > 0u) {
            vec3 L = min((offLayerRadiance(offLayerDiffuse, offLayerIrradiance) + offLayerSpecularRadiance) * exposure,
                         vec3(kMaxRadiance));
            display += weight * float(offLayerSamples) *
                       toneMapAggregate(L, offLayerSpecularRadiance * exposure,
                                        offLayerSpecularVariance * (exposure * exposure));
            hdr += weight * float(offLayerSamples) * L;
        }
        if (stands == 0u) continue;
        vec3 L = present[a] ? min(radiance[a] * exposure, vec3(kMaxRadiance)) : vec3(0.0);
        float w = weight * float(stands);
        display += w * (present[a] ? toneMapAggregate(L, specular[a] * exposure,
                                                             specularVariance[a] * (exposure * exposure))
                                           : toneMapAces(L));
        hdr += w * L;
    }
#endif
    imageStore(outHdr, pixel, vec4(hdr, 1.0));
    imageStore(outDisplay, pixel, vec4(display, 1.0));
    imageStore(outShadingEvents, pixel, uvec4(presentCount));
}
