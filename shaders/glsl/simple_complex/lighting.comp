#version 460
// Simple/Complex tiled deferred lighting (Lauritzen 2010; DESIGN section 5): sample 0
// of every pixel is lit; the other samples only of complex pixels. Resolve as in
// DESIGN section 6: each shading event tone-mapped, weighted by the sample fraction
// it stands for, summed; sky samples get the sky. A simple pixel's one shade stands
// for all its samples (they are all covered or all sky, see classify.glsl), so its
// weight is 1. Built as lighting_ms.comp (4x layered G-buffer) and lighting_ss.comp
// (shaders/CMakeLists.txt).
//
// Schedules (specialisation constant kSchedule):
//  - kScheduleDeferPerSample (Lauritzen's "defer per-sample"): the extra samples of the
//    tile's complex pixels form an implicit per-tile list (complex pixels ranked by a
//    prefix popcount in shared memory, n - 1 entries each), shaded 256 at a time by the
//    whole workgroup, so a tile with few complex pixels keeps every invocation busy.
//  - kScheduleNaive: each invocation loops over its own pixel's extra samples.
// Both sum a pixel's events in sample order, the reference's order (reference/
// lighting.comp), with no float atomics: results are bit-reproducible, identical
// between the two schedules, and a complex pixel equals the reference's value.
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/simple_complex.h"
#include "shared/specialization.h"

layout(local_size_x = 16, local_size_y = 16) in;
layout(constant_id = kSpecSimpleComplexSchedule) const uint kSchedule = kScheduleDeferPerSample;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D outHdr;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D outDisplay;
layout(set = 0, binding = 8, r32ui) uniform writeonly uimage2D outShadingEvents;
layout(push_constant) uniform Push { SimpleComplexParams params; };

#include "common/gbuffer_lighting.glsl"
#include "simple_complex/classify.glsl"

const uint kTilePixels = kTileSize * kTileSize;

shared uint sComplexMask[kTilePixels / 32u]; // bit i: tile pixel i is complex
shared uint sComplexPixel[kTilePixels]; // tile pixel index of the r-th complex pixel
// One round of the per-tile list: entry j's unweighted tone-mapped value and radiance
// (w: 1 when covered, i.e. a shading event).
shared vec3 sEntryDisplay[kTilePixels];
shared vec4 sEntryRadiance[kTilePixels];

// Debug view: complex pixels red, simple ones grey, both at the pixel's luma so the scene stays readable.
vec3 complexHighlight(vec3 display, bool complexPixel) {
    float luma = dot(display, vec3(0.2126, 0.7152, 0.0722));
    return complexPixel ? vec3(1.0, 0.1, 0.05) * (0.4 + 0.6 * luma) : vec3(0.6 * luma);
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.extent.xy);
    bool inside = all(lessThan(pixel, size));
    uint n = frame.counts.x;
    uint self = gl_LocalInvocationIndex;

    float tmin = 1e30, tmax = -1e30;
    if (inside) gbufferDistanceRange(pixel, tmin, tmax);
    bool complexPixel = inside && n > 1u && isComplexPixel(pixel, params.thresholds.x, params.thresholds.y);
    if (self < kTilePixels / 32u) sComplexMask[self] = 0u;
    tileBoundsBegin(); // its barrier also orders the mask clear before the atomics
    if (complexPixel) atomicOr(sComplexMask[self / 32u], 1u << (self % 32u));
    tileBoundsAdd(tmin, tmax); // barrier: the mask is complete after it
    tileCullLights();
    barrier();

    // Rank among the tile's complex pixels: complex pixels before this one, in tile order.
    uint rank = 0u, complexCount = 0u;
    for (uint w = 0u; w < kTilePixels / 32u; ++w) {
        uint bits = sComplexMask[w];
        if (w < self / 32u) rank += bitCount(bits);
        if (w == self / 32u) rank += bitCount(bits & ((1u << (self % 32u)) - 1u));
        complexCount += bitCount(bits);
    }
    if (kSchedule == kScheduleDeferPerSample && complexPixel) sComplexPixel[rank] = self;

    float weight = 1.0 / float(n);
    vec3 display = vec3(0.0), hdr = vec3(0.0);
    uint events = 0u;
    if (inside) {
        vec3 radiance, toneMapped;
        bool covered = shadeGBufferSample(pixel, 0u, radiance, toneMapped);
        if (covered && !complexPixel) {
#if GBUFFER_SHADOWS
            // Shadow taps per sample, one BRDF evaluation (common/gbuffer_lighting.glsl).
            if (n > 1u)
                shadeGBufferSurfaceShadowedPerSample(pixel, 0u, simplePixelShadingPoint(pixel, params.thresholds.y),
                                                     radiance, toneMapped);
            else
#endif
                shadeGBufferSurface(pixel, 0u, simplePixelShadingPoint(pixel, params.thresholds.y), radiance,
                                    toneMapped);
        }
        float w0 = complexPixel ? weight : 1.0;
        display += w0 * toneMapped;
        hdr += w0 * radiance;
        events += covered ? 1u : 0u;
    }

    if (kSchedule == kScheduleNaive) {
        for (uint s = 1u; complexPixel && s < n; ++s) {
            vec3 radiance, toneMapped;
            bool covered = shadeGBufferSample(pixel, s, radiance, toneMapped);
            display += weight * toneMapped;
            hdr += weight * radiance;
            events += covered ? 1u : 0u;
        }
    } else {
        barrier(); // sComplexPixel is complete
        uint extra = n - 1u; // list entries per complex pixel: samples 1..n-1
        uint total = complexCount * extra; // uniform across the workgroup
        ivec2 tileOrigin = ivec2(gl_WorkGroupID.xy * kTileSize);
        for (uint base = 0u; base < total; base += kTilePixels) {
            uint entry = base + self;
            if (entry < total) {
                uint owner = sComplexPixel[entry / extra];
                ivec2 p = tileOrigin + ivec2(owner % kTileSize, owner / kTileSize);
                vec3 radiance, toneMapped;
                bool covered = shadeGBufferSample(p, 1u + entry % extra, radiance, toneMapped);
                sEntryDisplay[self] = toneMapped;
                sEntryRadiance[self] = vec4(radiance, covered ? 1.0 : 0.0);
            }
            barrier();
            if (complexPixel) {
                // This pixel's entries in this round, in sample order.
                uint first = max(rank * extra, base), last = min((rank + 1u) * extra, base + kTilePixels);
                for (uint e = first; e < last; ++e) {
                    display += weight * sEntryDisplay[e - base];
                    hdr += weight * sEntryRadiance[e - base].rgb;
                    events += sEntryRadiance[e - base].w > 0.0 ? 1u : 0u;
                }
            }
            barrier(); // the next round overwrites the entries
        }
    }

    if (!inside) return;
    if (params.options.x == kDebugViewComplex) display = complexHighlight(display, complexPixel);
    imageStore(outHdr, pixel, vec4(hdr, 1.0));
    imageStore(outDisplay, pixel, vec4(display, 1.0));
    imageStore(outShadingEvents, pixel, uvec4(events));
}
