#version 460
// AGAA's error-driven shading rate, the flagged pixels' shading (docs/decisions/
// shading-rate-estimate.md): in every pixel the lighting pass flagged (one of its aggregates'
// estimates reached --agaa-tolerance; agaa/lighting/prefilter_estimate.glsl) each sample it named
// is lit and tone-mapped on its own, by the code the reference shades its samples with
// (common/gbuffer_lighting.glsl), and resolved into the lighting pass's images: over the whole
// pixel where it named every sample, else added to the trusted aggregates' resolve there.
// A pass of its own rather than a branch in the lighting pass: on lavapipe the per-sample
// shading's mere presence in that shader cost furball's lighting pass 10 % with no pixel flagged.
// One workgroup per tile the lighting pass listed (agaa/lighting/shading_rate.glsl), dispatched
// indirectly: a frame with no flagged pixel dispatches none. Its input is the per-sample G-buffer
// on the samples path, and on the accumulate path (GBUFFER_SAMPLE_MATERIAL) the visibility depth
// and the per-sample material the accumulation kernel kept (shared/sample_material.h).
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/specialization.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
// Read too: a partly flagged pixel's trusted aggregates are the lighting pass's, resolved there.
layout(set = 0, binding = 6, rgba32f) uniform image2D outHdr;
layout(set = 0, binding = 7, rgba32f) uniform image2D outDisplay;
layout(set = 0, binding = 8, r32ui) uniform uimage2D outShadingEvents;
// The lighting pass's flags (FrameTargets::perSampleShaded): the samples this pass shades, all n
// of them (the sky's too) where it writes the whole pixel (agaa/lighting/shading_rate.glsl
// perSampleSamples).
layout(set = 0, binding = 11, r32ui) uniform readonly uimage2D perSampleShaded;
// The tiles it listed: workgroup i shades tile flaggedTiles[i] (x | y << 16).
layout(set = 0, binding = 12, std430) readonly buffer FlaggedTiles {
    uint flaggedDispatch[3];
    uint flaggedTiles[];
};

uvec2 flaggedTile() {
    uint tile = flaggedTiles[gl_WorkGroupID.x];
    return uvec2(tile & 0xFFFFu, tile >> 16u);
}
#define TILE_COORD flaggedTile() // the light culling's tile (common/tile_culling.glsl)

#define GBUFFER_MS 1 // the 4x layered samples (G-buffer, or visibility depth and sample material)
#include "common/gbuffer_lighting.glsl"
#include "agaa/lighting/shading_rate_view.glsl"

// --debug shading-rate (AggregateDebugView::ShadingRate): this pass's pixels drawn in red.
layout(constant_id = kSpecPerSampleShadingRateView) const uint kShadingRateView = 0u;

// The tile's flagged samples, compacted: they are shaded one per invocation, kTilePixels a round,
// so every SIMD lane shades a flagged sample however few of the tile's pixels, or of their
// samples, were flagged (issue 49: with one invocation per pixel, a SIMD group of 8 paid n
// samples' shading for each flagged pixel it held). Each flagged pixel's samples are listed
// contiguously and in sample order, so its resolve sums them in the reference's order.
const uint kTilePixels = kTileSize * kTileSize;
// The flagged pixels << 16 | their listed samples: one atomic gives a pixel both its slot and its
// first entry, so the slots' first entries ascend.
shared uint sFlaggedCounts;
shared uint sFlaggedPixel[kTilePixels]; // per slot: the tile-local index of the pixel
shared uint sFlaggedFirst[kTilePixels]; // per slot: its first entry
shared uint sFlaggedMask[kTilePixels];  // per slot: its samples
// One round's shading, by the invocation that shaded it: tone-mapped display, linear HDR and
// whether the sample was covered (w).
shared vec4 sSampleDisplay[kTilePixels];
shared vec4 sSampleHdr[kTilePixels];

// The pixel of the tile's slot i.
ivec2 listedPixel(uint i) {
    uint local = sFlaggedPixel[i];
    return ivec2(flaggedTile() * kTileSize + uvec2(local % kTileSize, local / kTileSize));
}

// The slot that lists entry e: the last one whose first entry is at most e.
uint listedSlot(uint e, uint slots) {
    uint lo = 0u, hi = slots; // sFlaggedFirst[lo] <= e, and e is before slot hi's entries
    while (hi - lo > 1u) {
        uint mid = (lo + hi) / 2u;
        if (sFlaggedFirst[mid] <= e) lo = mid;
        else hi = mid;
    }
    return lo;
}

// The sample of mask's k-th set bit (k < bitCount(mask)).
uint listedSample(uint mask, uint k) {
    for (uint i = 0u; i < k; ++i)
        mask &= mask - 1u; // clears the lowest set bit
    return uint(findLSB(mask));
}

void main() {
    ivec2 pixel = ivec2(flaggedTile() * kTileSize + gl_LocalInvocationID.xy);
    bool inside = all(lessThan(pixel, ivec2(frame.extent.xy)));
    uint mask = inside ? imageLoad(perSampleShaded, pixel).x : 0u;

    // The tile's lights, culled against the flagged samples' depth bounds only.
    float tmin = 1e30, tmax = -1e30;
    if (mask != 0u) gbufferSamplesDistanceRange(pixel, mask, tmin, tmax);
    if (gl_LocalInvocationIndex == 0u) sFlaggedCounts = 0u;
    tileBoundsBegin(); // its barrier orders the counts' reset before the appends
    tileBoundsAdd(tmin, tmax);
    if (mask != 0u) {
        uint counts = atomicAdd(sFlaggedCounts, (1u << 16u) | uint(bitCount(mask)));
        uint slot = counts >> 16u;
        sFlaggedPixel[slot] = gl_LocalInvocationIndex;
        sFlaggedFirst[slot] = counts & 0xFFFFu;
        sFlaggedMask[slot] = mask;
    }
    tileCullLights();
    barrier();

    // Rounds of kTilePixels entries: the counts are the workgroup's, so every invocation runs the
    // same rounds and reaches the same barriers. Invocation i resolves slot i.
    uint slots = sFlaggedCounts >> 16u, entries = sFlaggedCounts & 0xFFFFu;
    uint self = gl_LocalInvocationIndex;
    uint ownFirst = self < slots ? sFlaggedFirst[self] : 0u;
    uint ownEnd = self < slots ? ownFirst + uint(bitCount(sFlaggedMask[self])) : 0u;
    // The reference's resolve (reference/lighting.comp): every sample weighted 1/n, the sky's
    // too, summed in sample order.
    float weight = 1.0 / float(kSampleCount);
    vec3 display = vec3(0.0);
    vec3 hdr = vec3(0.0);
    uint events = 0u;
    for (uint first = 0u; first < entries; first += kTilePixels) {
        uint entry = first + self;
        if (entry < entries) {
            uint slot = listedSlot(entry, slots);
            uint s = listedSample(sFlaggedMask[slot], entry - sFlaggedFirst[slot]);
            vec3 radiance, toneMapped;
            bool covered = shadeGBufferSample(listedPixel(slot), s, radiance, toneMapped);
            sSampleDisplay[self] = vec4(toneMapped, covered ? 1.0 : 0.0);
            sSampleHdr[self] = vec4(radiance, 0.0);
        }
        barrier();
        for (uint e = max(ownFirst, first); e < min(ownEnd, first + kTilePixels); ++e) {
            vec4 d = sSampleDisplay[e - first];
            display += weight * d.rgb;
            hdr += weight * sSampleHdr[e - first].rgb;
            events += d.w != 0.0 ? 1u : 0u;
        }
        barrier(); // the next round overwrites the samples' shading
    }
    if (self < slots) {
        ivec2 target = listedPixel(self);
        if (sFlaggedMask[self] != kAllGBufferSamples) { // the trusted aggregates', resolved by the lighting pass
            display += imageLoad(outDisplay, target).rgb;
            hdr += imageLoad(outHdr, target).rgb;
            events += imageLoad(outShadingEvents, target).x;
        }
        if (kShadingRateView != 0u) display = shadingRateView(display, true);
        imageStore(outHdr, target, vec4(hdr, 1.0));
        imageStore(outDisplay, target, vec4(display, 1.0));
        imageStore(outShadingEvents, target, uvec4(events));
    }
}
