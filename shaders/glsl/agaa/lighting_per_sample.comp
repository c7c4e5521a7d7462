#version 460
// AGAA's error-driven shading rate, the flagged pixels' shading (docs/decisions/
// shading-rate-estimate.md): every pixel the lighting pass flagged (one of its aggregates'
// estimates reached --agaa-tolerance; agaa/lighting/prefilter_estimate.glsl) has each covered
// sample lit and tone-mapped on its own, by the code the reference shades its samples with
// (common/gbuffer_lighting.glsl), and resolved into the lighting pass's images over that pixel.
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
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D outHdr;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D outDisplay;
layout(set = 0, binding = 8, r32ui) uniform writeonly uimage2D outShadingEvents;
// The lighting pass's flags (FrameTargets::perSampleShaded): 1 where this pass shades the pixel.
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

// The tile's flagged pixels, compacted: their samples are shaded one per invocation, kListPixels
// pixels a round, so every SIMD lane shades a flagged sample however few of the tile's pixels
// were flagged (issue 49: with one invocation per pixel, a SIMD group of 8 paid n samples'
// shading for each flagged pixel it held; chainlink's 10 % of pixels flagged cost 36.5 ms against
// the lighting pass's 59). Measured after: 31.5 to 32.9 ms in two runs, within this machine's
// run-to-run noise, so the gain on lavapipe is not shown. kTileSize^2 is a multiple of every n
// (4 to 32), so a round holds whole pixels.
const uint kTilePixels = kTileSize * kTileSize;
const uint kListPixels = kTilePixels / kSampleCount;
shared uint sFlaggedCount;
shared uint sFlaggedPixel[kTilePixels]; // the tile-local index of each flagged pixel
// One round's shading, by the invocation that shaded it: tone-mapped display, linear HDR and
// whether the sample was covered (w).
shared vec4 sSampleDisplay[kTilePixels];
shared vec4 sSampleHdr[kTilePixels];

// The pixel of the tile's list entry e.
ivec2 listedPixel(uint e) {
    uint local = sFlaggedPixel[e];
    return ivec2(flaggedTile() * kTileSize + uvec2(local % kTileSize, local / kTileSize));
}

void main() {
    ivec2 pixel = ivec2(flaggedTile() * kTileSize + gl_LocalInvocationID.xy);
    bool inside = all(lessThan(pixel, ivec2(frame.extent.xy)));
    bool flagged = inside && imageLoad(perSampleShaded, pixel).x != 0u;

    // The tile's lights, culled against the flagged pixels' depth bounds only.
    float tmin = 1e30, tmax = -1e30;
    if (flagged) gbufferDistanceRange(pixel, tmin, tmax);
    if (gl_LocalInvocationIndex == 0u) sFlaggedCount = 0u;
    tileBoundsBegin(); // its barrier orders the count's reset before the appends
    tileBoundsAdd(tmin, tmax);
    if (flagged) sFlaggedPixel[atomicAdd(sFlaggedCount, 1u)] = gl_LocalInvocationIndex;
    tileCullLights();
    barrier();

    // Rounds of kListPixels flagged pixels, n samples each: the count is the workgroup's, so
    // every invocation runs the same rounds and reaches the same barriers.
    uint flaggedCount = sFlaggedCount;
    uint self = gl_LocalInvocationIndex;
    for (uint first = 0u; first < flaggedCount; first += kListPixels) {
        uint entry = first + self / kSampleCount;
        if (entry < flaggedCount) {
            vec3 radiance, toneMapped;
            bool covered = shadeGBufferSample(listedPixel(entry), self % kSampleCount, radiance, toneMapped);
            sSampleDisplay[self] = vec4(toneMapped, covered ? 1.0 : 0.0);
            sSampleHdr[self] = vec4(radiance, 0.0);
        }
        barrier();
        // The reference's resolve (reference/lighting.comp): every sample weighted 1/n, the
        // sky's too, summed in sample order.
        if (self < kListPixels && first + self < flaggedCount) {
            ivec2 target = listedPixel(first + self);
            float weight = 1.0 / float(kSampleCount);
            vec3 display = vec3(0.0);
            vec3 hdr = vec3(0.0);
            uint events = 0u;
            for (uint s = 0u; s < kSampleCount; ++s) {
                vec4 d = sSampleDisplay[self * kSampleCount + s];
                display += weight * d.rgb;
                hdr += weight * sSampleHdr[self * kSampleCount + s].rgb;
                events += d.w != 0.0 ? 1u : 0u;
            }
            if (kShadingRateView != 0u) display = shadingRateView(display, true);
            imageStore(outHdr, target, vec4(hdr, 1.0));
            imageStore(outDisplay, target, vec4(display, 1.0));
            imageStore(outShadingEvents, target, uvec4(events));
        }
        barrier(); // the next round overwrites the samples' shading
    }
}
