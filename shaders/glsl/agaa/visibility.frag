#version 460
#extension GL_GOOGLE_include_directive : require
// AGAA step 1, the dense visibility prepass (paper section 3.2): depth (fixed-function) and
// the primitive's face normal as two 8-bit spherical angles (RG8) per sample. Opaque materials
// use the variant that samples nothing; masked ones sample base-colour alpha and discard.
#include "shared/agaa.h"
#include "shared/frame.h"
#include "shared/specialization.h"

// Masked materials: 0 opaque, 1 discard, 2 alpha-to-coverage (common/alpha_coverage.glsl).
layout(constant_id = kSpecVisibilityAlphaPath) const uint kAlphaPath = 0u;
// agaa-timings --breakdown's build (tools/agaa_timings/CMakeLists.txt): no face-normal encoding.
#ifndef AGAA_BREAKDOWN_NO_NORMALS
#define AGAA_BREAKDOWN_NO_NORMALS 0
#endif

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 0, binding = 2) uniform Agaa { AgaaConstants agaa; };
layout(set = 1, binding = 0) uniform sampler2D textures[kMaxSceneTextures];
layout(push_constant) uniform Push { uint material; } pc;

#include "common/face_normal.glsl"
#include "common/hemisphere_normal.glsl"
#include "common/material.glsl"
#include "common/alpha_coverage.glsl"

// Centroid for what the material reads (the alpha coverage here must be the fill passes', which read
// at the centroid: reference/gbuffer_inputs.glsl). The view position stays at the pixel centre: the
// face normal is its screen derivatives, exact only for centre-interpolated values.
layout(location = 0) centroid in vec3 inNormal;
layout(location = 1) centroid in vec4 inTangent;
layout(location = 2) centroid in vec4 inUvs; // xy TEXCOORD_0, zw TEXCOORD_1
layout(location = 3) flat in uint inLayer;
layout(location = 4) in vec3 inViewPosition;
layout(location = 5) centroid in vec4 inColor;

layout(location = 0) out vec4 outNormal; // xy encoded normal; w coverage alpha (alpha-to-coverage)

void main() {
    // Derivatives first: they must be taken in uniform control flow, before any discard.
    vec3 V = pixelToCamera(uvec2(gl_FragCoord.xy), agaa.ndcParams);
    vec3 N = viewFaceNormal(inViewPosition, V);
    float coverage = 1.0;
    if (kAlphaPath != 0u) {
        GpuMaterial m = materials[pc.material];
        coverage = maskedCoverage(kAlphaPath, materialAlpha(m, inUvs, inColor), m.emissive.w);
    }
    outNormal = vec4(AGAA_BREAKDOWN_NO_NORMALS != 0 ? vec2(0.0) : vec2(encodeHemisphereNormal(N, V)) / 255.0, 0.0, coverage);
}
