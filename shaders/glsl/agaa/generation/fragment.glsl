// The accumulation kernel's fragment, shared by every build of agaa/generation.frag: the
// shipping pass (agaa/generation.frag), the test build that records its fragments
// (tests/agaa_generation_record.frag) and agaa-timings --breakdown's part-removed builds
// (breakdown/generation_*.frag). Its declarations, bindings 0 to 4 (and 6, the AG-buffer as 64-bit
// words), and generationFragment, which evaluates and quantises the fragment's material.
#extension GL_ARB_post_depth_coverage : require
#ifndef AGAA_EMISSIVE
#define AGAA_EMISSIVE 0 // 1: the emissive output (agaa_shaders' generation_emissive*)
#endif
#ifndef AGAA_INT64
#define AGAA_INT64 0
#endif
#ifndef AGAA_SUBGROUP
#define AGAA_SUBGROUP 0
#endif
#if AGAA_INT64
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#endif
#if AGAA_SUBGROUP
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#endif
#include "shared/agaa.h"
#include "shared/ag_buffer.h"
#include "shared/clustering.h"
#include "shared/frame.h"
#include "shared/sample_material.h"
#include "shared/specialization.h"

layout(early_fragment_tests) in;
layout(post_depth_coverage) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 0, binding = 2) uniform Agaa { AgaaConstants agaa; };
layout(set = 0, binding = 3, std430) readonly buffer Metadata { uint metadata[]; };
layout(set = 0, binding = 4, std430) buffer AgBuffer { uint agBuffer[]; };
#if AGAA_INT64
// The same AG-buffer seen as 64-bit words (bound twice: binding 6 aliases binding 4).
layout(set = 0, binding = 6, std430) buffer AgBuffer64 { uint64_t agBuffer64[]; };
#endif
layout(set = 1, binding = 0) uniform sampler2D textures[kMaxSceneTextures];
layout(push_constant) uniform Push { uint material; } pc;
// Specialisation ids 0 and 1: the normal distribution (kNdfToksvig, kNdfSggx) and the routing
// (0 per sample, 1 per fragment). Constants, not uniforms: lavapipe executes both sides of a
// branch it cannot resolve at compile time.
layout(constant_id = kSpecGenerationNdf) const uint kNdf = 0u;
layout(constant_id = kSpecGenerationRouting) const uint kRouteFragment = 0u;
// With a tolerance (AggregateSettings::tolerance): 1, and each covered sample's material is kept
// for the shading rate (shared/sample_material.h); without one binding 7 is a 16-byte stand-in
// this never touches (agaa/generation/sample_material.glsl). The test build records instead (the
// test compares the shipping pass's words with the recorded fragments' materials).
layout(constant_id = kSpecGenerationSampleMaterial) const uint kSampleMaterial = 0u;

#include "common/material.glsl"
#include "common/octahedral.glsl"
#include "common/srgb.glsl"

// Centroid: a fragment that covers only some samples reads its attributes inside the triangle, as
// the reference's per-sample G-buffer does (reference/gbuffer_inputs.glsl), never extrapolated to
// an uncovered pixel centre.
layout(location = 0) centroid in vec3 inNormal;
layout(location = 1) centroid in vec4 inTangent;
layout(location = 2) centroid in vec4 inUvs; // xy TEXCOORD_0, zw TEXCOORD_1
layout(location = 3) flat in uint inLayer;
layout(location = 5) centroid in vec4 inColor;
#if AGAA_EMISSIVE
// Emissive stays per sample (seed 004: no HDR fireflies): an MSAA target, resolved per sample.
layout(location = 0) out vec4 outEmissive;
#endif

// The fragment's values as the AG-buffer's fixed-point fields (shared/agaa.h), in either
// normal-distribution layout.
AgQuantized quantizeFragment(MaterialSample m, uint n) {
    float alpha = m.roughness * m.roughness;
    AgQuantized f;
    // The sample's own lobe, for the two-point resolve and the environment's level (shared/agaa.h
    // w5): not floored at kMinGgxAlpha, so that a near-mirror's level is its own (2^26 - 1 steps
    // resolve alpha to 1.5e-8; the lighting pass floors the mean where the BRDF needs it).
    f.q[10] = quantizeUnit(min(alpha, kMaxGgxAlpha), kMaterialAlphaScale);
    if (kNdf == kNdfSggx) {
        // The sample's GGX lobe as an SGGX matrix (shared/sggx.h), alpha in the BRDF's range.
        float a = clamp(alpha, kMinGgxAlpha, kMaxGgxAlpha);
        float a2 = a * a;
        vec3 N = m.normal * (1.0 - a2); // S = (1 - a^2) n n^T + a^2 I
        uint scale = unitScale(kSggxFieldBits, n);
        f.q[0] = quantizeUnit(N.x * m.normal.x + a2, scale);
        f.q[1] = quantizeUnit(N.y * m.normal.y + a2, scale);
        f.q[2] = quantizeUnit(N.z * m.normal.z + a2, scale);
        f.q[3] = quantizeUnit(N.x * m.normal.y + 0.5, scale); // off-diagonal: [-1/2, 1/2] + 1/2
        f.q[4] = quantizeUnit(N.x * m.normal.z + 0.5, scale);
        f.q[5] = quantizeUnit(N.y * m.normal.z + 0.5, scale);
        f.q[6] = quantizeUnit(m.albedo.r, scale);
        f.q[7] = quantizeUnit(m.albedo.g, scale);
        f.q[8] = quantizeUnit(m.albedo.b, scale);
        f.q[9] = quantizeUnit(m.metallic, unitScale(kSggxMetallicBits, n));
    } else {
        vec3 t = m.normal * toksvigLength(alpha, agaa.toksvig.x, agaa.toksvig.y, agaa.toksvig.z);
        f.q[0] = quantizeSigned(t.x, toksvigScaleX(n));
        f.q[1] = quantizeSigned(t.y, toksvigScaleYZ(n));
        f.q[2] = quantizeSigned(t.z, toksvigScaleYZ(n));
        f.q[3] = 0u;
        f.q[4] = 0u;
        f.q[5] = 0u;
        f.q[6] = quantizeUnit(m.albedo.r, kUnormScale);
        f.q[7] = quantizeUnit(m.albedo.g, kUnormScale);
        f.q[8] = quantizeUnit(m.albedo.b, kUnormScale);
        f.q[9] = quantizeUnit(m.metallic, kUnormScale);
    }
    return f;
}

// What every build of the pass does first: the material evaluated at the fragment (and its emissive
// written), then, for a fragment visible at one of its layer's samples at least, its pixel, its
// covered samples (mask) and its values in the AG-buffer's fixed-point fields. False for a fragment
// the depth test left no sample of.
bool generationFragment(out uvec2 pixel, out uint pixelIndex, out uint mask, out MaterialSample m,
                        out AgQuantized f) {
    GpuMaterial gm = materials[pc.material];
    m = evaluateMaterial(gm, inUvs, inColor, inNormal, inTangent, gl_FrontFacing);
#if AGAA_EMISSIVE
    outEmissive = vec4(min(m.emissive, vec3(kMaxRadiance)), 1.0);
#endif
    mask = uint(gl_SampleMaskIn[0]) & 0xFu;
    if (mask == 0u) return false;
    pixel = uvec2(gl_FragCoord.xy);
    pixelIndex = pixel.y * uint(frame.extent.x) + pixel.x;
    f = quantizeFragment(m, agaa.shape.w);
    return true;
}
