// AGAA step 3, AG-buffer generation by the accumulation kernel (paper section 3.4,
// Algorithm 2, section 4.2). The scene is rasterised again at n samples over the prepass
// depth: depth EQUAL without writes, early fragment tests and post-depth coverage, so
// gl_SampleMaskIn holds exactly the samples this fragment is visible at; the stencil keeps
// the first fragment per sample (section 4.2.2: coplanar duplicates never count twice).
// Each fragment evaluates the material as a classic G-buffer would and adds, with integer
// atomics on fixed-point values (order-independent: bit-identical frames), its Toksvig normal,
// albedo, metallic and sample count into its pixel's aggregates.
//
// Routing: Algorithm 2 routes the whole fragment to the aggregate of its first visible sample.
// Here each aggregate present in the fragment's mask receives the fragment's values weighted
// by its own number of samples, so the AG-buffer's sample counts equal the metadata's exactly
// (a fragment straddling two clusters would otherwise count all its samples in one).
#extension GL_GOOGLE_include_directive : require
#extension GL_ARB_post_depth_coverage : require
#include "shared/agaa.h"
#include "shared/ag_buffer.h"
#include "shared/clustering.h"
#include "shared/frame.h"

layout(early_fragment_tests) in;
layout(post_depth_coverage) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Materials { GpuMaterial materials[]; };
layout(set = 0, binding = 2) uniform Agaa { AgaaConstants agaa; };
layout(set = 0, binding = 3, std430) readonly buffer Metadata { uint metadata[]; };
layout(set = 0, binding = 4, std430) buffer AgBuffer { uint agBuffer[]; };
layout(set = 1, binding = 0) uniform sampler2D textures[kMaxSceneTextures];
#if AGAA_RECORD
// Test support (tests/agaa/test_agaa_gpu.cpp): every fragment of the pixels in the central
// kRecordWindow^2 block of the frame appends what it accumulates, so the CPU can re-accumulate the same
// fragments and compare with the AG-buffer.
const uint kRecordWindow = 16u;
const uint kRecordWords = 12u;
layout(set = 0, binding = 5, std430) buffer FragmentRecords { uint recordCount; uint recordCapacity; uint records[]; };
#endif
layout(push_constant) uniform Push { uint material; } pc;

#include "common/material.glsl"

layout(location = 0) in vec3 inNormal;
layout(location = 1) in vec4 inTangent;
layout(location = 2) in vec2 inUv;
layout(location = 3) flat in uint inLayer;
#if AGAA_EMISSIVE
// Emissive stays per sample (seed 004: no HDR fireflies): an MSAA target, resolved per sample.
layout(location = 0) out vec4 outEmissive;
#endif

void main() {
    GpuMaterial gm = materials[pc.material];
    MaterialSample m = evaluateMaterial(gm, inUv, inNormal, inTangent, gl_FrontFacing);
#if AGAA_EMISSIVE
    outEmissive = vec4(min(m.emissive, vec3(kMaxRadiance)), 1.0);
#endif
    uint mask = uint(gl_SampleMaskIn[0]) & 0xFu;
    if (mask == 0u) return;
    uvec2 pixel = uvec2(gl_FragCoord.xy);
    uint width = uint(frame.extent.x);
    uint pixelIndex = pixel.y * width + pixel.x;
    uint c = agaa.shape.x;
    uint words = agaa.shape.z;

    float alpha = m.roughness * m.roughness;
    vec3 t = m.normal * toksvigLength(alpha, agaa.toksvig.x, agaa.toksvig.y, agaa.toksvig.z);
    uint qx = quantizeSigned(t.x, kNormalScale);
    uint qy = quantizeSigned(t.y, kNormalScale);
    uint qz = quantizeSigned(t.z, kNormalScale);
    uint qr = quantizeUnit(m.albedo.r, kUnormScale);
    uint qg = quantizeUnit(m.albedo.g, kUnormScale);
    uint qb = quantizeUnit(m.albedo.b, kUnormScale);
    uint qm = quantizeUnit(m.metallic, kUnormScale);

#if AGAA_RECORD
    uvec2 origin = uvec2(frame.extent.xy) / 2u - kRecordWindow / 2u;
    if (all(greaterThanEqual(pixel, origin)) && all(lessThan(pixel, origin + kRecordWindow))) {
        uint slot = atomicAdd(recordCount, 1u);
        if (slot < recordCapacity) {
            uint r = slot * kRecordWords;
            records[r + 0u] = pixelIndex;
            records[r + 1u] = inLayer;
            records[r + 2u] = mask;
            records[r + 3u] = qx;
            records[r + 4u] = qy;
            records[r + 5u] = qz;
            records[r + 6u] = qr;
            records[r + 7u] = qg;
            records[r + 8u] = qb;
            records[r + 9u] = qm;
        }
    }
#endif
    uint perAggregate[kMaxAggregates] = uint[](0u, 0u, 0u, 0u);
    for (uint hw = 0u; hw < 4u; ++hw) {
        if ((mask & (1u << hw)) == 0u) continue;
        uint s = inLayer * 4u + hw;
        uint id = 0u;
        if (words > 0u) {
            uint b = metadataBits(c);
            id = unpackMetadata(metadata[pixelIndex * words + (s * b) / 32u], s, c);
        }
        perAggregate[id] += 1u;
    }
    for (uint a = 0u; a < c; ++a) {
        uint k = perAggregate[a];
        if (k == 0u) continue;
        uint base = (pixelIndex * c + a) * kAggregateWords;
        atomicAdd(agBuffer[base + 0u], (k << kCountShift) + k * qx);
        atomicAdd(agBuffer[base + 1u], k * qy);
        atomicAdd(agBuffer[base + 2u], k * qz);
        atomicAdd(agBuffer[base + 3u], k * qr + ((k * qg) << 16u));
        atomicAdd(agBuffer[base + 4u], k * qb + ((k * qm) << 16u));
    }
}
