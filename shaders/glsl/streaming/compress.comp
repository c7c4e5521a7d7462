#version 460
#extension GL_GOOGLE_include_directive : require
// Streaming G-buffer compression (Kerzner and Salvi 2014, section 3), one pixel per invocation.
// lavapipe has no fragment-shader interlock, so the primitive order the paper's single pass gets
// from the critical section is rebuilt here: the pixel's recorded fragments (its samples grouped
// by primitive id, the prepass's per-sample id) are replayed in primitive order (ascending
// scene-wide triangle number = draw order) through the streaming algorithm:
//   1. merge (3.1): into the first surface, front to back, whose coverage is disjoint from the
//      fragment's, whose depth range zView +- (|dz/dx| + |dz/dy|) overlaps its range, and whose
//      normal is within the threshold (n0 . n1 > cos alpha); coverage and depth-tested coverage
//      ORed, normals, derivatives, albedo, metallic, roughness, emissive averaged, zView the minimum;
//   2. else insert, keeping the surfaces front to back;
//   3. occluder fusion (3.2.1): a surface whose depth range lies entirely behind nearer ones loses
//      their coverage from its depth-tested coverage;
//   4. a 4th (S+1-th) surface: drop the farthest one that nearer surfaces fully cover and that lies
//      entirely behind them, else the one with the fewest depth-tested samples (ties: the farther).
// The CPU reference is agaa/streaming/streaming_compression.cpp.
#include "shared/frame.h"
#include "shared/streaming.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 12, std430) writeonly buffer Surfaces { uint surfaces[]; };
layout(set = 0, binding = 13, r32ui) uniform writeonly uimage2D outLostSamples;
layout(push_constant) uniform Push { StreamingParams params; } pc;

#include "common/depth.glsl"
#include "common/epsilon.glsl"
#include "common/octahedral.glsl"
#include "streaming/gbuffer_fetch.glsl"

struct Surface {
    uint coverage, depthTested;
    float zView, dzdx, dzdy;
    vec3 normal, albedo, emissive;
    float metallic, roughness;
};

// Half the depth interval of a surface within the pixel (section 3.1), plus the relative floor
// under fp32 reconstruction of a face-on plane (whose slope is 0).
float halfRange(Surface s) { return abs(s.dzdx) + abs(s.dzdy) + kDepthCompareRelative * s.zView; }
float zMin(Surface s) { return s.zView - halfRange(s); }
float zMax(Surface s) { return s.zView + halfRange(s); }

// The fragment of primitive group g: its first sample's normal and material; dz/dx, dz/dy of the
// plane through that sample with that normal, and that plane's depth at the pixel centre.
// t(q) = c / (N.D(q)) on the ray t D(q), so dt/dq = -t (N.dD/dq) / (N.D); N.D is kept at least
// kStreamingMinFacing |D| from 0 with its sign (shared/streaming.h: shading normals of thin
// geometry), the slope clamped to a finite half.
Surface fragmentOf(ivec2 pixel, uint rep, uint mask) {
    Surface f;
    f.coverage = mask;
    f.depthTested = mask; // the prepass depth-tested the samples: each is visible
    f.zView = viewDistanceFromDepth(STREAMING_FETCH(gDepth, pixel, rep).r, frame.depthParams.x,
                                    frame.depthParams.y);
    f.normal = decodeOctahedral(STREAMING_FETCH(gNormal, pixel, rep).xy);
    vec2 q = vec2(pixel) + frame.samplePositions[rep].xy;
    vec2 ndc = q * frame.extent.zw * 2.0 - 1.0;
    vec3 D = vec3(ndc.x / frame.projParams.x, ndc.y / frame.projParams.y, -1.0);
    float NoD = dot(f.normal, D);
    float floorNoD = kStreamingMinFacing * length(D);
    if (abs(NoD) < floorNoD) NoD = NoD >= 0.0 ? floorNoD : -floorNoD;
    f.dzdx = clamp(-f.zView * f.normal.x * (2.0 * frame.extent.z / frame.projParams.x) / NoD,
                   -kStreamingMaxDerivative, kStreamingMaxDerivative);
    f.dzdy = clamp(-f.zView * f.normal.y * (2.0 * frame.extent.w / frame.projParams.y) / NoD,
                   -kStreamingMaxDerivative, kStreamingMaxDerivative);
    // The plane at the pixel centre (the lighting shades there): on the surface, not off it.
    vec2 toCentre = vec2(0.5) - frame.samplePositions[rep].xy;
    f.zView = clamp(f.zView + f.dzdx * toCentre.x + f.dzdy * toCentre.y, f.zView / kStreamingCentreDepthRange,
                    f.zView * kStreamingCentreDepthRange);
    vec4 am = STREAMING_FETCH(gAlbedoMetal, pixel, rep);
    vec4 er = STREAMING_FETCH(gEmissiveRoughness, pixel, rep);
    f.albedo = am.rgb;
    f.metallic = am.a;
    f.emissive = er.rgb;
    f.roughness = er.a;
    return f;
}

// Section 3.1: all three conditions.
bool canMerge(Surface s, Surface f) {
#ifdef AGAA_TEST_PERTURB_METHODS
    return false; // tools/perturb-test.sh: no fragment merges into a surface
#endif
    return (s.coverage & f.coverage) == 0u && zMin(s) <= zMax(f) && zMin(f) <= zMax(s) &&
           dot(s.normal, f.normal) > pc.params.merge.x;
}

Surface merged(Surface s, Surface f) {
    Surface m;
    m.coverage = s.coverage | f.coverage;
    m.depthTested = s.depthTested | f.depthTested;
    m.zView = min(s.zView, f.zView);
    m.dzdx = 0.5 * (s.dzdx + f.dzdx);
    m.dzdy = 0.5 * (s.dzdy + f.dzdy);
    vec3 sum = s.normal + f.normal;
    float len = length(sum);
    // Opposing normals cancel only past 90 degrees of threshold; keep the surface's normal then.
    m.normal = len > kMinNormalLength ? sum / len : s.normal;
    m.albedo = 0.5 * (s.albedo + f.albedo);
    m.metallic = 0.5 * (s.metallic + f.metallic);
    m.roughness = 0.5 * (s.roughness + f.roughness);
    m.emissive = 0.5 * (s.emissive + f.emissive);
    return m;
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.extent.xy)))) return;
    const uint n = frame.counts.x;
    const uint S = pc.params.counts.x;

    // The recorded fragments: samples grouped by primitive, then in primitive order.
    uint groupId[kMaxSamples], groupMask[kMaxSamples], groupRep[kMaxSamples];
    uint groups = 0u, covered = 0u;
    for (uint s = 0u; s < n; ++s) {
        if (isSky(STREAMING_FETCH(gDepth, pixel, s).r)) continue;
        covered |= 1u << s;
        uint id = uint(STREAMING_FETCH(gPrimitive, pixel, s).r);
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
    for (uint i = 1u; i < groups; ++i) // insertion sort by primitive id (ids are distinct)
        for (uint j = i; j > 0u && groupId[j - 1u] > groupId[j]; --j) {
            uint t = groupId[j]; groupId[j] = groupId[j - 1u]; groupId[j - 1u] = t;
            t = groupMask[j]; groupMask[j] = groupMask[j - 1u]; groupMask[j - 1u] = t;
            t = groupRep[j]; groupRep[j] = groupRep[j - 1u]; groupRep[j - 1u] = t;
        }

    Surface list[kStreamingMaxSurfaces + 1u]; // front to back; one spare slot for the arrival
    uint count = 0u;
    for (uint g = 0u; g < groups; ++g) {
        Surface f = fragmentOf(pixel, groupRep[g], groupMask[g]);
        // 1. Merge into the first matching surface, front to back; its zView may drop: re-sort.
        uint target = count;
        for (uint j = 0u; j < count && target == count; ++j)
            if (canMerge(list[j], f)) target = j;
        if (target < count) {
            list[target] = merged(list[target], f);
            for (uint j = target; j > 0u && list[j - 1u].zView > list[j].zView; --j) {
                Surface t = list[j]; list[j] = list[j - 1u]; list[j - 1u] = t;
            }
        } else {
            // 2. Insert behind every surface at the same or a smaller zView.
            uint at = count;
            while (at > 0u && list[at - 1u].zView > f.zView) {
                list[at] = list[at - 1u];
                --at;
            }
            list[at] = f;
            ++count;
        }
        // 3. Occluder fusion, front to back.
        for (uint j = 1u; j < count; ++j) {
            uint occluders = 0u;
            for (uint i = 0u; i < j; ++i)
                if (zMax(list[i]) < zMin(list[j])) occluders |= list[i].coverage;
            list[j].depthTested &= ~occluders;
        }
        // 4. Over capacity: choose the surface to drop.
        if (count > S) {
            uint drop = count;
            for (uint k = count - 1u; k > 0u && drop == count; --k) {
                uint nearer = 0u;
                float nearMax = -1e30;
                for (uint i = 0u; i < k; ++i) {
                    nearer |= list[i].coverage;
                    nearMax = max(nearMax, zMax(list[i]));
                }
                if ((list[k].coverage & ~nearer) == 0u && zMin(list[k]) > nearMax) drop = k;
            }
            if (drop == count) {
                drop = 0u;
                for (uint k = 1u; k < count; ++k)
                    if (bitCount(list[k].depthTested) <= bitCount(list[drop].depthTested)) drop = k;
            }
            for (uint k = drop; k + 1u < count; ++k)
                list[k] = list[k + 1u];
            --count;
        }
    }

    uint kept = 0u;
    uint first = (uint(pixel.y) * uint(frame.extent.x) + uint(pixel.x)) * S * kStreamingSurfaceWords;
    for (uint k = 0u; k < S; ++k) {
        uint w = first + k * kStreamingSurfaceWords;
        if (k >= count) {
            for (uint i = 0u; i < kStreamingSurfaceWords; ++i)
                surfaces[w + i] = 0u;
            continue;
        }
        Surface s = list[k];
        kept |= s.depthTested;
        surfaces[w + kStreamingWordCoverage] = s.coverage;
        surfaces[w + kStreamingWordDepthTested] = s.depthTested;
        surfaces[w + kStreamingWordZView] = floatBitsToUint(s.zView);
        surfaces[w + kStreamingWordDepthDerivatives] = packHalf2x16(vec2(s.dzdx, s.dzdy));
        surfaces[w + kStreamingWordNormal] = packSnorm2x16(encodeOctahedral(s.normal));
        surfaces[w + kStreamingWordAlbedoRg] = packHalf2x16(s.albedo.rg);
        surfaces[w + kStreamingWordAlbedoBMetal] = packHalf2x16(vec2(s.albedo.b, s.metallic));
        surfaces[w + kStreamingWordEmissiveRg] = packHalf2x16(s.emissive.rg);
        surfaces[w + kStreamingWordEmissiveBRoughness] = packHalf2x16(vec2(s.emissive.b, s.roughness));
    }
    // Lost coverage: covered samples no kept surface owns (the sky takes them in the resolve).
    imageStore(outLostSamples, pixel, uvec4(bitCount(covered & ~kept)));
}
