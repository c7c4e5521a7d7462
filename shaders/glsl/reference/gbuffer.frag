#version 460
#extension GL_GOOGLE_include_directive : require
// Per-sample G-buffer: 16 bytes per sample plus depth (DESIGN section 5):
//   RT0 RG16_SNORM   shading normal, octahedral, view space
//   RT1 RGBA8_SRGB   albedo (sRGB-encoded for precision in the darks), A metallic
//   RT2 RGBA16F      emissive radiance (HDR), A roughness
#include "shared/frame.h"

// Masked materials (agaa/common/effects.h AlphaPath): 0 opaque (samples nothing), 1 discard below
// the cutoff (1 sample per pixel), 2 alpha-to-coverage (MSAA; common/alpha_coverage.glsl).
layout(constant_id = 0) const uint kAlphaPath = 0u;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 1, binding = 0) uniform sampler2D textures[kMaxSceneTextures];
layout(push_constant) uniform Push { uint material; } pc;

#include "common/material.glsl"
#include "common/octahedral.glsl"
#include "common/alpha_coverage.glsl"

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec4 inTangent;
layout(location = 2) in vec2 inUv;

layout(location = 0) out vec4 outNormal; // xy octahedral; w coverage alpha (alpha-to-coverage reads it)
layout(location = 1) out vec4 outAlbedoMetal;
layout(location = 2) out vec4 outEmissiveRoughness;

void main() {
    GpuMaterial m = materials[pc.material];
    float coverage = 1.0;
    if (kAlphaPath != 0u) coverage = maskedCoverage(kAlphaPath, materialAlpha(m, inUv), m.emissive.w);
    MaterialSample s = evaluateMaterial(m, inUv, inNormal, inTangent, gl_FrontFacing);
    outNormal = vec4(encodeOctahedral(s.normal), 0.0, coverage);
    outAlbedoMetal = vec4(s.albedo, s.metallic);
    outEmissiveRoughness = vec4(min(s.emissive, vec3(kMaxRadiance)), s.roughness);
}
