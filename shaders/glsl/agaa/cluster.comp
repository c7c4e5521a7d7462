#version 460
// AGAA step 2: aggregate definition, one pixel per invocation (paper section 3.3). Runs
// Algorithm 1 (shared/clustering.h, the same source as the CPU reference) on each sample's depth
// and normal and writes the bit-packed metadata and the aggregate count. Two inputs:
//  - AGAA_GBUFFER_INPUT 0 (cluster.comp, the accumulate path): the visibility prepass's depth and
//    8-bit face normal;
//  - AGAA_GBUFFER_INPUT 1 (cluster_gbuffer.comp, the samples path, seed 004): the per-sample
//    G-buffer's depth and shading normal, with no prepass. Pre-filtered shading assumes one
//    shading model per aggregate (seed 004), so metal and dielectric samples are kept apart
//    (shared/clustering.h kShadingModelDistance) before Equation 1 decides anything else.
#extension GL_GOOGLE_include_directive : require
#ifndef AGAA_GBUFFER_INPUT
#define AGAA_GBUFFER_INPUT 0
#endif
#include "shared/agaa.h"
#include "shared/frame.h"
#include "shared/clustering.h"
#include "shared/specialization.h"

layout(local_size_x = 8, local_size_y = 8) in;
// n and c as specialisation constants: the per-sample loops get constant trip counts, so the
// compiler can unroll them and keep the sample arrays in registers instead of scratch memory.
layout(constant_id = kSpecClusterSamples) const uint kSamples = 8u;
layout(constant_id = kSpecClusterAggregates) const uint kAggregates = 2u;
// The distance (kDistancePosition, kDistancePlane; agaa.modes.x holds the same value for the CPU
// reference): a constant, so only one distance is compiled in.
layout(constant_id = kSpecClusterDistance) const uint kDistance = 0u;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1) uniform Agaa { AgaaConstants agaa; };
layout(set = 0, binding = 2) uniform sampler2DMSArray visibilityDepth;
#if AGAA_GBUFFER_INPUT
// reference/gbuffer.frag's RG16_SNORM octahedral shading normal and RGBA8 albedo + metallic.
layout(set = 0, binding = 3) uniform sampler2DMSArray gNormal;
layout(set = 0, binding = 6) uniform sampler2DMSArray gAlbedoMetal;
#include "common/octahedral.glsl"
#else
layout(set = 0, binding = 3) uniform sampler2DMSArray visibilityNormal;
#endif
layout(set = 0, binding = 4, std430) writeonly buffer Metadata { uint metadata[]; };
layout(set = 0, binding = 5, r8ui) uniform writeonly uimage2D aggregateCount;

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uvec2 size = uvec2(frame.extent.xy);
    if (any(greaterThanEqual(pixel, size))) return;
    const uint n = kSamples;
    const uint c = kAggregates;
    float px[kMaxSamples], py[kMaxSamples], pz[kMaxSamples];
    float nx[kMaxSamples], ny[kMaxSamples], nz[kMaxSamples];
    bool valid[kMaxSamples];
    uint model[kMaxSamples]; // shading model: 1 metal, 0 dielectric (the prepass knows none: all 0)
    float vx, vy, vz;
    pixelCentreToCamera(pixel.x, pixel.y, agaa.ndcParams.x, agaa.ndcParams.y, agaa.ndcParams.z, agaa.ndcParams.w,
                        vx, vy, vz);
    for (uint s = 0u; s < n; ++s) {
        valid[s] = false;
        model[s] = 0u;
        ivec3 at = ivec3(pixel, s / 4u);
        float d = texelFetch(visibilityDepth, at, int(s % 4u)).r;
        valid[s] = d > 0.0; // reversed Z: cleared depth 0 is the far plane, i.e. sky
        if (!valid[s]) continue;
        sampleScaledPosition(pixel.x, pixel.y, frame.samplePositions[s].x, frame.samplePositions[s].y, d,
                             agaa.ndcParams.x, agaa.ndcParams.y, agaa.ndcParams.z, agaa.ndcParams.w,
                             frame.depthParams.x, agaa.clustering.z, agaa.clustering.w, agaa.clustering.x,
                             px[s], py[s], pz[s]);
#if AGAA_GBUFFER_INPUT
        vec3 N = decodeOctahedral(texelFetch(gNormal, at, int(s % 4u)).rg); // view space, unit
        nx[s] = N.x;
        ny[s] = N.y;
        nz[s] = N.z;
        model[s] = texelFetch(gAlbedoMetal, at, int(s % 4u)).a >= kMetalModelThreshold ? 1u : 0u;
#else
        vec2 e = texelFetch(visibilityNormal, at, int(s % 4u)).rg;
        uvec2 q = uvec2(round(e * 255.0)); // UNORM8 -> the stored byte, exactly
        decodeFaceNormal(agaa.cosSinTheta[q.x].x, agaa.cosSinTheta[q.x].y, agaa.cosSinPhi[q.y].x,
                         agaa.cosSinPhi[q.y].y, vx, vy, vz, nx[s], ny[s], nz[s]);
#endif
    }
    uint ids[kMaxSamples];
    uint count = clusterSamples(n, c, kDistance, agaa.clustering.y, px, py, pz, nx, ny, nz, model, valid, ids);
#ifdef AGAA_TEST_PERTURB_METHODS
    if (c > 1u) ids[0] ^= 1u; // tools/perturb-test.sh: metadata bit 0 (sample 0's aggregate id) flipped
#endif
    const uint words = (kSamples * metadataBits(kAggregates) + 31u) / 32u;
    uint base = (pixel.y * size.x + pixel.x) * words;
    for (uint w = 0u; w < words; ++w) metadata[base + w] = packMetadataWord(w, n, c, ids);
    imageStore(aggregateCount, ivec2(pixel), uvec4(count));
}
