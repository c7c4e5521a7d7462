#ifndef AGAA_GBUFFER_LIGHTING_GLSL
#define AGAA_GBUFFER_LIGHTING_GLSL
// Lighting one sample of the per-sample G-buffer (reference/gbuffer.frag): the
// code every per-sample deferred method shares (the reference, Simple/Complex),
// so that they differ only in which samples they shade, never in how.
//
// Requires, declared by the includer before this file: `frame` (FrameConstants, set 0 binding 0),
// `lights` (GpuLight[], set 0 binding 1). Declares the G-buffer at set 0
// bindings 2..5 and the environment at 15 and 16 (common/environment.glsl). nextTileLight() needs tileCullLights() to have run.
// GBUFFER_MS: 1 the 4x layered G-buffer, 0 one sample per pixel.
// GBUFFER_SAMPLE_MATERIAL (with GBUFFER_MS): AGAA's accumulate path, whose G-buffer is the
// visibility depth (binding 2), the per-sample material the accumulation kernel kept (binding 3,
// shared/sample_material.h) and, with GBUFFER_EMISSIVE_SAMPLES, its per-sample emissive target
// (binding 4).
#ifndef GBUFFER_MS
#define GBUFFER_MS 0
#endif
#ifndef GBUFFER_SAMPLE_MATERIAL
#define GBUFFER_SAMPLE_MATERIAL 0
#endif
#ifndef GBUFFER_EMISSIVE_SAMPLES
#define GBUFFER_EMISSIVE_SAMPLES 0
#endif
#include "common/brdf.glsl"
#include "common/depth.glsl"
#include "common/environment.glsl"
#include "common/lights.glsl"
#include "common/octahedral.glsl"
#include "common/tonemap.glsl"

// GBUFFER_SHADOWS (1: the scene has a shadowed light, agaa/common/shadow_map.h): the shadow-map
// array and its constants at bindings 9 and 10, one tap per shading event.
#ifndef GBUFFER_SHADOWS
#define GBUFFER_SHADOWS 0
#endif
#if GBUFFER_SHADOWS
#define SHADOW_MAP_BINDING 9
#define SHADOW_CONSTANTS_BINDING 10
#include "common/shadow.glsl"
#endif
// After shadow.glsl: with shadow maps the tile keeps its shadowed lights in a mask of their own.
#include "common/tile_culling.glsl"

#if GBUFFER_SAMPLE_MATERIAL
#include "common/srgb.glsl"
#include "shared/sample_material.h"
layout(set = 0, binding = 2) uniform sampler2DMSArray gDepth;
layout(set = 0, binding = 3, std430) readonly buffer SampleMaterials { uint sampleMaterial[]; };
#if GBUFFER_EMISSIVE_SAMPLES
layout(set = 0, binding = 4) uniform sampler2DMSArray gEmissive;
#endif
#define FETCH(tex, p, layer, s) texelFetch(tex, ivec3(p, layer), int(s))
#elif GBUFFER_MS
layout(set = 0, binding = 2) uniform sampler2DMSArray gDepth;
layout(set = 0, binding = 3) uniform sampler2DMSArray gNormal;
layout(set = 0, binding = 4) uniform sampler2DMSArray gAlbedoMetal;
layout(set = 0, binding = 5) uniform sampler2DMSArray gEmissiveRoughness;
#define FETCH(tex, p, layer, s) texelFetch(tex, ivec3(p, layer), int(s))
#else
layout(set = 0, binding = 2) uniform sampler2D gDepth;
layout(set = 0, binding = 3) uniform sampler2D gNormal;
layout(set = 0, binding = 4) uniform sampler2D gAlbedoMetal;
layout(set = 0, binding = 5) uniform sampler2D gEmissiveRoughness;
#define FETCH(tex, p, layer, s) texelFetch(tex, p, 0)
#endif

// n as a specialisation constant (id 1): per-sample loops get constant trip counts and unroll.
// Sample s = layer * samplesPerLayer + hardware sample (engine/frame/sample_pattern.h); the
// hardware rate is 4 whenever n > 1.
layout(constant_id = kSpecGBufferLightingSamples) const uint kSampleCount = 1u;
const uint kSamplesPerLayer = kSampleCount > 1u ? 4u : 1u;
// A bit for each of the pixel's n samples.
const uint kAllGBufferSamples = 0xFFFFFFFFu >> (32u - kSampleCount);
#define FETCH_SAMPLE(tex, p, s) FETCH(tex, p, (s) / kSamplesPerLayer, (s) % kSamplesPerLayer)

float gbufferDepth(ivec2 pixel, uint s) { return FETCH_SAMPLE(gDepth, pixel, s).r; }

#if GBUFFER_SAMPLE_MATERIAL
uint sampleMaterialAt(ivec2 pixel, uint s) {
    return sampleMaterialWord(uint(pixel.y) * uint(frame.extent.x) + uint(pixel.x), kSampleCount, s);
}

vec3 gbufferNormal(ivec2 pixel, uint s) {
    return decodeOctahedral(unpackSnorm2x16(sampleMaterial[sampleMaterialAt(pixel, s)]));
}

// Sample s's surface and emissive radiance.
SurfaceInputs gbufferSurface(ivec2 pixel, uint s, out vec3 emissive) {
    uint at = sampleMaterialAt(pixel, s);
    vec4 albedoMetal = unpackUnorm4x8(sampleMaterial[at + 1u]);
    SurfaceInputs surface;
    surface.normal = decodeOctahedral(unpackSnorm2x16(sampleMaterial[at]));
    surface.albedo = srgbDecode(albedoMetal.rgb);
    surface.metallic = albedoMetal.a;
    surface.roughness = unpackUnorm2x16(sampleMaterial[at + 2u]).x;
#if GBUFFER_EMISSIVE_SAMPLES
    emissive = FETCH_SAMPLE(gEmissive, pixel, s).rgb;
#else
    emissive = vec3(0.0);
#endif
    return surface;
}
#else
vec3 gbufferNormal(ivec2 pixel, uint s) { return decodeOctahedral(FETCH_SAMPLE(gNormal, pixel, s).xy); }

// Sample s's surface and emissive radiance.
SurfaceInputs gbufferSurface(ivec2 pixel, uint s, out vec3 emissive) {
    vec4 am = FETCH_SAMPLE(gAlbedoMetal, pixel, s);
    vec4 er = FETCH_SAMPLE(gEmissiveRoughness, pixel, s);
    SurfaceInputs surface;
    surface.normal = gbufferNormal(pixel, s);
    surface.albedo = am.rgb;
    surface.metallic = am.a;
    surface.roughness = er.a;
    emissive = er.rgb;
    return surface;
}
#endif

// View distances of the pixel's non-sky samples among `samples` (a bit each), for the tile's
// depth bounds (tile_culling.glsl); tmin > tmax when every one is sky.
void gbufferSamplesDistanceRange(ivec2 pixel, uint samples, out float tmin, out float tmax) {
    tmin = 1e30;
    tmax = -1e30;
    for (uint s = 0u; s < kSampleCount; ++s) {
        float d = gbufferDepth(pixel, s);
        if (((samples >> s) & 1u) == 0u || isSky(d)) continue;
        float t = viewDistanceFromDepth(d, frame.depthParams.x, frame.depthParams.y);
        tmin = min(tmin, t);
        tmax = max(tmax, t);
    }
}

// The same over all n samples.
void gbufferDistanceRange(ivec2 pixel, out float tmin, out float tmax) {
    gbufferSamplesDistanceRange(pixel, kAllGBufferSamples, tmin, tmax);
}

// One shading event (DESIGN section 6): the surface stored in sample s of `pixel`, seen
// at view-space point P, lit by every light of the tile, emissive added per sample
// before the tone map (seed 004), exposure applied. radiance: the exposed linear
// radiance; display: its tone-mapped value. Both unweighted: the caller weights them
// by the sample fraction they stand for. The sample must not be sky.
// One shading event of a surface given by its inputs (SBAA's per-surface G-buffer): as
// shadeGBufferSurface, which calls it.
void shadeSurfaceInputs(SurfaceInputs surface, vec3 emissive, vec3 P, out vec3 radiance, out vec3 display) {
    vec3 V = normalize(-P); // |P| >= znear > 0
    vec3 lit = kEnvironment != 0u ? environmentLighting(surface, V, surface.roughness) : vec3(0.0);
    for (uint i = nextTileLight(0u); i < kMaxLights; i = nextTileLight(i + 1u)) {
        vec3 L, irradiance;
        if (!lightIncidence(lights[i], P, L, irradiance)) continue;
        lit += evaluateBrdf(surface, V, L, irradiance);
    }
#if GBUFFER_SHADOWS
    for (uint i = nextTileShadowedLight(0u); i < kMaxLights; i = nextTileShadowedLight(i + 1u)) {
        vec3 L, irradiance;
        if (!lightIncidence(lights[i], P, L, irradiance)) continue;
        lit += evaluateBrdf(surface, V, L, irradiance * shadowVisibilityPoint(i, P, surface.normal));
    }
#endif
    radiance = min((lit + emissive) * frame.depthParams.z, vec3(kMaxRadiance));
    display = toneMapAces(radiance);
}

void shadeGBufferSurface(ivec2 pixel, uint s, vec3 P, out vec3 radiance, out vec3 display) {
    vec3 emissive;
    SurfaceInputs surface = gbufferSurface(pixel, s, emissive);
    shadeSurfaceInputs(surface, emissive, P, radiance, display);
}

#if GBUFFER_SHADOWS
// One shading event standing for every sample of a flat pixel (Simple/Complex's simple pixels):
// the BRDF is evaluated once per light at P with sample s's surface, but the shadow is taken per
// sample (one tap at each sample's own position: the "shadowing per sample" option of paper
// section 3.5.3), and the pixel resolves per sample like the reference's, so a shadow edge
// crossing a flat pixel does not make it depart from the reference. Every sample must be covered.
void shadeGBufferSurfaceShadowedPerSample(ivec2 pixel, uint s, vec3 P, out vec3 radiance, out vec3 display) {
    vec3 V = normalize(-P); // |P| >= znear > 0
    vec3 unshadowed;
    SurfaceInputs surface = gbufferSurface(pixel, s, unshadowed);
    if (kEnvironment != 0u) unshadowed += environmentLighting(surface, V, surface.roughness);
    vec3 shadowedLight[kMaxShadowMaps] = vec3[](vec3(0.0), vec3(0.0), vec3(0.0), vec3(0.0));
    for (uint i = nextTileLight(0u); i < kMaxLights; i = nextTileLight(i + 1u)) {
        vec3 L, irradiance;
        if (!lightIncidence(lights[i], P, L, irradiance)) continue;
        unshadowed += evaluateBrdf(surface, V, L, irradiance);
    }
    for (uint i = nextTileShadowedLight(0u); i < kMaxLights; i = nextTileShadowedLight(i + 1u)) {
        vec3 L, irradiance;
        if (!lightIncidence(lights[i], P, L, irradiance)) continue;
        shadowedLight[shadowLayer(i)] += evaluateBrdf(surface, V, L, irradiance);
    }
    uint maps = uint(shadow.params.x);
    radiance = vec3(0.0);
    display = vec3(0.0);
    float weight = 1.0 / float(kSampleCount);
    for (uint k = 0u; k < kSampleCount; ++k) {
        vec2 pixelPos = vec2(pixel) + frame.samplePositions[k].xy;
        vec3 Pk = viewPositionFromDepth(pixelPos, gbufferDepth(pixel, k), frame.extent, frame.depthParams,
                                        frame.projParams);
        vec3 lk = unshadowed;
        for (uint l = 0u; l < maps; ++l)
            lk += shadowedLight[l] * shadowTap(int(l), shadowReceiver(int(l), Pk, surface.normal));
        vec3 rk = min(lk * frame.depthParams.z, vec3(kMaxRadiance));
        radiance += weight * rk;
        display += weight * toneMapAces(rk);
    }
}
#endif

// Sample s of `pixel` shaded at its own position; a sky sample gets the sky.
// Returns false for sky (not a shading event).
bool shadeGBufferSample(ivec2 pixel, uint s, out vec3 radiance, out vec3 display) {
    float d = gbufferDepth(pixel, s);
    if (isSky(d)) {
        radiance = skyRadiance(pixel) * frame.depthParams.z;
        display = toneMapAces(radiance);
        return false;
    }
    vec2 pixelPos = vec2(pixel) + frame.samplePositions[s].xy;
    shadeGBufferSurface(pixel, s, viewPositionFromDepth(pixelPos, d, frame.extent, frame.depthParams, frame.projParams),
                        radiance, display);
    return true;
}
#endif
