#version 460
#extension GL_GOOGLE_include_directive : require
// Per-sample G-buffer: 16 bytes per sample plus depth (DESIGN section 5), this project's scene's
// materials written through the include a host's material shaders use
// (raster/sample_gbuffer_output.glsl, which lists the targets).
#include "shared/frame.h"
#include "shared/specialization.h"

// Masked materials (agaa/common/effects.h AlphaPath): 0 opaque (samples nothing), 1 discard below
// the cutoff (1 sample per pixel), 2 alpha-to-coverage (MSAA; common/alpha_coverage.glsl).
layout(constant_id = kSpecFillAlphaPath) const uint kAlphaPath = 0u;
// Curvature roughness (raster/sample_gbuffer_output.glsl; agaa/common/sample_gbuffer.h
// GBufferOptions): off for the reference and Simple/Complex, whose samples must be the material's own.

#include "raster/frame.glsl"
#include "common/scene_materials.glsl"
// GBUFFER_PRIMITIVE_ID (gbuffer_primitive*.frag; GBufferOptions::primitiveIds, SBAA's prepass):
// RT3 R32_SFLOAT holds the scene-wide triangle number + 1 (0 = nothing), exact below 2^24.
// Integer MSAA colour formats are 1x only on lavapipe (framebufferIntegerColorSampleCounts).
#ifndef GBUFFER_PRIMITIVE_ID
#define GBUFFER_PRIMITIVE_ID 0
#endif
// GBUFFER_SURFACE_FILL (sbaa/fill*.frag): SBAA's second geometry pass, which writes the same
// material into the per-surface records of the surfaces this fragment represents
// (raster/surface_fill_output.glsl) instead of targets.
#ifndef GBUFFER_SURFACE_FILL
#define GBUFFER_SURFACE_FILL 0
#endif
#ifndef GBUFFER_SAMPLE_RATE
#define GBUFFER_SAMPLE_RATE 0 // reference/gbuffer_inputs.glsl
#endif
#if GBUFFER_SURFACE_FILL
#define SURFACE_FILL_SAMPLE_RATE GBUFFER_SAMPLE_RATE
#include "raster/surface_fill_output.glsl"
#endif
#if GBUFFER_PRIMITIVE_ID || GBUFFER_SURFACE_FILL
layout(push_constant) uniform Push { uint material; uint firstTriangle; } pc;
#else
layout(push_constant) uniform Push { uint material; } pc;
#endif

#include "common/material.glsl"
#include "common/octahedral.glsl"
#include "common/alpha_coverage.glsl"
#if GBUFFER_SURFACE_FILL
#define SAMPLE_GBUFFER_TARGETS 0
#endif
#include "raster/sample_gbuffer_output.glsl"

// GBUFFER_SAMPLE_RATE (gbuffer_sample_rate.frag; agaa/common/sample_gbuffer.h GBufferOptions):
// the material, its textures and normal map run once per sample (the supersampled G-buffer).
#include "reference/gbuffer_inputs.glsl"

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
    s.roughness = sampleGBufferRoughness(s.roughness, dNdx, dNdy);
#if GBUFFER_SURFACE_FILL
    writeSurfaceFill(pc.firstTriangle + uint(gl_PrimitiveID), s.normal, s.albedo, s.metallic, s.emissive,
                     s.roughness);
#else
    writeSampleGBuffer(s.normal, coverage, s.albedo, s.metallic, s.emissive, s.roughness);
#endif
#if GBUFFER_PRIMITIVE_ID
    writeSampleGBufferPrimitive(pc.firstTriangle + uint(gl_PrimitiveID));
#endif
}
