#version 460
#extension GL_GOOGLE_include_directive : require
// Per-sample G-buffer: 16 bytes per sample plus depth (DESIGN section 5):
//   RT0 RG16_SNORM   shading normal, octahedral, view space
//   RT1 RGBA8_UNORM  albedo, sRGB-encoded here for precision in the darks (common/srgb.glsl) and
//                    sampled through an sRGB view; A metallic
//   RT2 RGBA16F      emissive radiance (HDR), A roughness
#include "shared/frame.h"
#include "shared/specialization.h"
#include "common/srgb.glsl"

// Masked materials (agaa/common/effects.h AlphaPath): 0 opaque (samples nothing), 1 discard below
// the cutoff (1 sample per pixel), 2 alpha-to-coverage (MSAA; common/alpha_coverage.glsl).
layout(constant_id = kSpecFillAlphaPath) const uint kAlphaPath = 0u;
// Curvature roughness (common/curvature_roughness.glsl; agaa/common/sample_gbuffer.h
// GBufferOptions): id 8 on/off, ids 9 and 10 the talk's max footprint and boost. Off for the
// reference and Simple/Complex, whose samples must be the material's own.
layout(constant_id = kSpecFillCurvatureRoughness) const uint kCurvatureRoughness = 0u;
layout(constant_id = kSpecFillCurvatureMaxFootprint) const float kCurvatureMaxFootprint = 0.3;
layout(constant_id = kSpecFillCurvatureBoost) const float kCurvatureBoost = 2.0;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 1, binding = 0) uniform sampler2D textures[kMaxSceneTextures];
// GBUFFER_PRIMITIVE_ID (gbuffer_primitive*.frag; GBufferOptions::primitiveIds, SBAA's prepass):
// RT3 R32_SFLOAT holds the scene-wide triangle number + 1 (0 = nothing), exact below 2^24.
// Integer MSAA colour formats are 1x only on lavapipe (framebufferIntegerColorSampleCounts).
#ifndef GBUFFER_PRIMITIVE_ID
#define GBUFFER_PRIMITIVE_ID 0
#endif
// GBUFFER_SURFACE_FILL (sbaa/fill*.frag): SBAA's second geometry pass. No colour targets: the
// material, evaluated exactly as for the per-sample G-buffer, is stored into the per-surface
// G-buffer record (shared/sbaa.h words 2..6) of each kept surface this fragment represents: its
// representative primitive is this one and its representative sample lies in this layer. A
// primitive is rasterised once per pixel and layer, and the prepass found it visible at that
// sample, so this fragment covers the sample and is the only one that can: exactly one
// invocation writes each record (at sample rate, the one at that sample), no race, no ordering. The prepass depth is attached read-only with an EQUAL test, early, so the
// hidden fragments never run the material.
#ifndef GBUFFER_SURFACE_FILL
#define GBUFFER_SURFACE_FILL 0
#endif
#if GBUFFER_SURFACE_FILL
#include "shared/sbaa.h"
layout(early_fragment_tests) in;
layout(constant_id = kSpecFillSbaaSurfaces) const uint kSbaaSurfaces = 4u; // S
layout(set = 0, binding = 2, std430) buffer Surfaces { uint surfaces[]; };
#endif
#if GBUFFER_PRIMITIVE_ID || GBUFFER_SURFACE_FILL
layout(push_constant) uniform Push { uint material; uint firstTriangle; } pc;
#else
layout(push_constant) uniform Push { uint material; } pc;
#endif

#include "common/material.glsl"
#include "common/octahedral.glsl"
#include "common/alpha_coverage.glsl"
#include "common/curvature_roughness.glsl"

// GBUFFER_SAMPLE_RATE (gbuffer_sample_rate.frag; agaa/common/sample_gbuffer.h GBufferOptions):
// the material, its textures and normal map run once per sample (the supersampled G-buffer).
#include "reference/gbuffer_inputs.glsl"

#if !GBUFFER_SURFACE_FILL
layout(location = 0) out vec4 outNormal; // xy octahedral; w coverage alpha (alpha-to-coverage reads it)
layout(location = 1) out vec4 outAlbedoMetal;
layout(location = 2) out vec4 outEmissiveRoughness;
#endif
#if GBUFFER_PRIMITIVE_ID
layout(location = 3) out float outPrimitive;
#endif

void main() {
    // The geometric normal's derivatives first: in uniform control flow, before any discard.
    float glen = length(inNormal);
    vec3 geometric = glen > kMinNormalLength ? inNormal / glen : vec3(0.0, 0.0, 1.0);
    vec3 dNdx = kCurvatureRoughness != 0u ? dFdx(geometric) : vec3(0.0);
    vec3 dNdy = kCurvatureRoughness != 0u ? dFdy(geometric) : vec3(0.0);
    GpuMaterial m = materials[pc.material];
    float coverage = 1.0;
    if (kAlphaPath != 0u) coverage = maskedCoverage(kAlphaPath, materialAlpha(m, inUvs, inColor), m.emissive.w);
    MaterialSample s = evaluateMaterial(m, inUvs, inColor, inNormal, inTangent, gl_FrontFacing);
    if (kCurvatureRoughness != 0u)
        s.roughness = curvatureRoughness(s.roughness, dNdx, dNdy, kCurvatureMaxFootprint, kCurvatureBoost);
#if GBUFFER_SURFACE_FILL
    const uint primitive = pc.firstTriangle + uint(gl_PrimitiveID) + 1u;
    const uint perLayer = frame.counts.y; // hardware samples per layer
    const uvec2 pixel = uvec2(gl_FragCoord.xy);
    const uint first = (pixel.y * uint(frame.extent.x) + pixel.x) * kSbaaSurfaces * kSbaaSurfaceWords;
    const vec3 emissive = min(s.emissive, vec3(kMaxRadiance));
    for (uint k = 0u; k < kSbaaSurfaces; ++k) {
        const uint w = first + k * kSbaaSurfaceWords;
        const uint key = surfaces[w + kSbaaWordSampleAndPrimitive];
        if (surfaces[w + kSbaaWordMask] == 0u || (key >> 8u) != primitive) continue;
        const uint rep = key & 0xFFu;
        if (rep / perLayer != uint(gl_Layer)) continue;
#if GBUFFER_SAMPLE_RATE
        if (uint(gl_SampleID) != rep % perLayer) continue; // the invocation at that sample
#endif
        surfaces[w + kSbaaWordNormal] = packSnorm2x16(encodeOctahedral(s.normal));
        surfaces[w + kSbaaWordAlbedoRg] = packHalf2x16(s.albedo.rg);
        surfaces[w + kSbaaWordAlbedoBMetal] = packHalf2x16(vec2(s.albedo.b, s.metallic));
        surfaces[w + kSbaaWordEmissiveRg] = packHalf2x16(emissive.rg);
        surfaces[w + kSbaaWordEmissiveBRoughness] = packHalf2x16(vec2(emissive.b, s.roughness));
    }
#else
    outNormal = vec4(encodeOctahedral(s.normal), 0.0, coverage);
    outAlbedoMetal = vec4(srgbEncode(s.albedo), s.metallic);
    outEmissiveRoughness = vec4(min(s.emissive, vec3(kMaxRadiance)), s.roughness);
#endif
#if GBUFFER_PRIMITIVE_ID
    outPrimitive = float(pc.firstTriangle + uint(gl_PrimitiveID) + 1u);
#endif
}
