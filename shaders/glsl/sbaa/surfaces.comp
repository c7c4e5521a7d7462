#version 460
#extension GL_GOOGLE_include_directive : require
// SBAA surface selection (Salvi and Vidimce 2012, section 3): one pixel per invocation.
//   1. The pixel's covered samples are grouped by primitive id (the prepass's per-sample id).
//   2. MERGE mode: a primitive whose representative sample (its first) lies on the plane of an
//      earlier surface's representative (geometric normals within the cosine, depth within the
//      plane's slope tolerance) joins that surface, so a tessellated surface stays one surface.
//   3. The S surfaces of largest coverage are kept (ties: the earlier representative sample):
//      their coverage, representative sample, primitive and depth are written; the fill pass
//      (sbaa/fill*.frag) then writes the material of that primitive at that sample.
//   4. The coverage of every other surface is lost (as in the paper): written per pixel.
// The CPU twin is agaa/sbaa/surface_selection.cpp; the two must agree bit for bit.
#include "shared/frame.h"
#include "shared/sbaa.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 12, std430) writeonly buffer Surfaces { uint surfaces[]; };
layout(set = 0, binding = 13, r32ui) uniform writeonly uimage2D outLostSamples;
layout(push_constant) uniform Push { SbaaParams params; } pc;

#include "common/depth.glsl"
#include "common/octahedral.glsl"
#include "sbaa/gbuffer_fetch.glsl"
#include "sbaa/plane.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.extent.xy)))) return;
    const uint n = frame.counts.x;
    const uint S = pc.params.counts.x;

    // 1. Primitives in the order of their first sample.
    uint groupId[kMaxSamples], groupMask[kMaxSamples], groupRep[kMaxSamples];
    uint groups = 0u;
    for (uint s = 0u; s < n; ++s) {
        if (isSky(SBAA_FETCH(gDepth, pixel, s).r)) continue;
        uint id = uint(SBAA_FETCH(gPrimitive, pixel, s).r);
        uint g = 0u;
        while (g < groups && groupId[g] != id) ++g;
        if (g == groups) {
            groupId[g] = id;
            groupMask[g] = 0u;
            groupRep[g] = s;
            ++groups;
        }
        groupMask[g] |= 1u << s;
    }

    // 2. Surfaces: each primitive joins the first earlier surface on its plane (MERGE), or starts one.
    uint surfMask[kMaxSamples], surfRep[kMaxSamples], surfPrim[kMaxSamples];
    uint count = 0u;
    for (uint g = 0u; g < groups; ++g) {
        uint target = count;
#ifdef AGAA_TEST_PERTURB_METHODS
        if (false) { // tools/perturb-test.sh: no primitive merges into an earlier surface
#else
        if (pc.params.counts.y != 0u) {
#endif
            float tb = viewDistanceFromDepth(SBAA_FETCH(gDepth, pixel, groupRep[g]).r, frame.depthParams.x,
                                             frame.depthParams.y);
            vec3 nb = sbaaGeometricNormal(pixel, groupRep[g]);
            for (uint j = 0u; j < count && target == count; ++j) {
                uint a = surfRep[j];
                float ta = viewDistanceFromDepth(SBAA_FETCH(gDepth, pixel, a).r, frame.depthParams.x,
                                                 frame.depthParams.y);
                vec3 na = sbaaGeometricNormal(pixel, a);
                float tolerance = sbaaPlaneDepthTolerance(vec2(pixel) + frame.samplePositions[a].xy, ta, na,
                                                          pc.params.merge.y);
                if (dot(na, nb) >= pc.params.merge.x && abs(tb - ta) <= tolerance) target = j;
            }
        }
        if (target == count) {
            surfMask[count] = 0u;
            surfRep[count] = groupRep[g];
            surfPrim[count] = groupId[g];
            ++count;
        }
        surfMask[target] |= groupMask[g];
    }

    // 3. The S most covered, by selection (count <= n <= 32).
    uint covered = 0u, kept = 0u, taken = 0u;
    for (uint j = 0u; j < count; ++j)
        covered |= surfMask[j];
    uint first = (uint(pixel.y) * uint(frame.extent.x) + uint(pixel.x)) * S * kSbaaSurfaceWords;
    for (uint k = 0u; k < S; ++k) {
        uint best = count;
        for (uint j = 0u; j < count; ++j) {
            if ((taken & (1u << j)) != 0u) continue;
            if (best == count || bitCount(surfMask[j]) > bitCount(surfMask[best]) ||
                (bitCount(surfMask[j]) == bitCount(surfMask[best]) && surfRep[j] < surfRep[best]))
                best = j;
        }
        uint w = first + k * kSbaaSurfaceWords;
        if (best == count) {
            for (uint i = 0u; i < kSbaaSurfaceWords; ++i)
                surfaces[w + i] = 0u;
            continue;
        }
        taken |= 1u << best;
        kept |= surfMask[best];
        uint r = surfRep[best];
        surfaces[w + kSbaaWordMask] = surfMask[best];
        surfaces[w + kSbaaWordDepth] = floatBitsToUint(SBAA_FETCH(gDepth, pixel, r).r);
        for (uint i = kSbaaWordNormal; i <= kSbaaWordEmissiveBRoughness; ++i)
            surfaces[w + i] = 0u; // the fill pass's
        surfaces[w + kSbaaWordSampleAndPrimitive] = r | (surfPrim[best] << 8u);
    }
    // 4. Lost coverage: covered samples of the surfaces not kept.
    imageStore(outLostSamples, pixel, uvec4(bitCount(covered & ~kept)));
}
