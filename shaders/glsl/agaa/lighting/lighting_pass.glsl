// AGAA's lighting pass, shared by its builds: the shipping pass (agaa/lighting.comp), the test build
// that exports what step 1 read and built (tests/agaa_lighting_export.comp) and agaa-timings
// --breakdown's build without step 3 (breakdown/lighting_no_shading.comp). Each defines step 3
// (shadeAggregates) and the two observation points (exportSample, exportAggregate) after it.
#include "shared/ag_buffer.h"
#include "shared/agaa.h"
#include "shared/clustering.h"
#include "shared/frame.h"
#include "shared/sggx.h"
#include "shared/specialization.h"
#ifndef AGAA_EMISSIVE
#define AGAA_EMISSIVE 0 // 1: the emissive term (agaa_shaders' lighting*_emissive*)
#endif

#ifndef AGAA_GBUFFER
#define AGAA_GBUFFER 0
#endif

layout(local_size_x = 16, local_size_y = 16) in;
// n and c as specialisation constants: constant trip counts for the per-sample loops.
layout(constant_id = kSpecLightingSamples) const uint kSamples = 8u;
layout(constant_id = kSpecLightingAggregates) const uint kAggregates = 2u;
// agaa/aggregate/agaa_constants.h AggregateShading: 1 the compacted
// per-tile list, 0 each invocation shades its own pixel's aggregates (agaa/lighting/schedule.glsl).
layout(constant_id = kSpecLightingCompact) const uint kCompactShading = 1u;
// The normal distribution (kNdfToksvig, kNdfSggx; agaa.options.w holds the
// same value). A constant, not a uniform: lavapipe executes both sides of every branch whose
// condition is not known at compile time, so a uniform choice would pay for both BRDFs.
layout(constant_id = kSpecLightingNdf) const uint kNdf = 0u;
const bool kSggx = kNdf == kNdfSggx;
// AggregateRouting: 1 when the generation pass routed whole fragments
// (Algorithm 2); an aggregate then stands for the samples it received, which need not be the
// samples the metadata assigned it, so the resolve weights it by its accumulated count.
layout(constant_id = kSpecLightingRouting) const uint kRouteFragment = 0u;
// eng::scene::SceneFeatures::hasNearMirrors: 1 where a material can be a
// near mirror, whose lobe the pixel's view footprint can outgrow (light.glsl addLightFootprint); 0
// compiles the branch away, which alone costs lavapipe about a fifth of this pass.
layout(constant_id = kSpecLightingViewFootprint) const uint kViewFootprint = 1u;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 2) uniform Agaa { AgaaConstants agaa; };
layout(set = 0, binding = 3) uniform sampler2DMSArray visibilityDepth;
layout(set = 0, binding = 4, std430) readonly buffer Metadata { uint metadata[]; };
layout(set = 0, binding = 5, r8ui) uniform readonly uimage2D aggregateCount;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D outHdr;
layout(set = 0, binding = 8, rgba32f) uniform writeonly image2D outDisplay;
layout(set = 0, binding = 9, r32ui) uniform writeonly uimage2D outShadingEvents;
// With a tolerance (kShadingRate, prefilter_estimate.glsl): the samples the next pass shades, 0
// where it shades none (FrameTargets::perSampleShaded, shading_rate.glsl perSampleSamples); the
// layout has it only then.
layout(set = 0, binding = 18, r32ui) uniform writeonly uimage2D outPerSampleShaded;
#ifndef AGAA_SHADOWS
#define AGAA_SHADOWS 0
#endif
#if AGAA_SHADOWS
// The shadow maps of the scene's shadowed lights (agaa/common/shadow_map.h), before the tile
// culling, which then keeps a mask of them (agaa/lighting/shadowed_lights.glsl).
#define SHADOW_MAP_BINDING 11
#define SHADOW_CONSTANTS_BINDING 12
#include "common/shadow.glsl"
#endif

#include "common/brdf.glsl"
#include "common/depth.glsl"
#include "common/environment.glsl"
#include "common/lights.glsl"
#include "common/tile_culling.glsl"
#include "common/tonemap.glsl"

#include "agaa/lighting/moments.glsl"
// Where step 1 has read a sample and built an aggregate: the shipping pass (agaa/lighting.comp)
// defines both empty; the test build (tests/agaa_lighting_export.comp) writes what they are given
// for a CPU aggregation written apart from this shader (tests/support/aggregate_instrumentation.h).
void exportSample(uint pixelIndex, uint s, vec4 a, vec4 b, vec4 c, vec4 d);
void exportAggregate(uint pixelIndex, uint a, vec4 m0, vec4 m1, vec4 m2, vec4 m3);
#include "agaa/lighting/prefilter_estimate.glsl"
#if AGAA_GBUFFER
#include "agaa/lighting/load_samples.glsl"
#else
#include "agaa/lighting/load_accumulated.glsl"
#endif
#include "agaa/lighting/pixel_samples.glsl"
#include "agaa/lighting/aggregate.glsl"
#include "agaa/lighting/off_layer.glsl"
#include "agaa/lighting/light.glsl"
#include "agaa/lighting/shadowed_lights.glsl"
#include "agaa/lighting/shade.glsl"
#include "agaa/lighting/shading_rate.glsl"
#include "agaa/lighting/shading_rate_view.glsl"
#include "agaa/lighting/schedule.glsl"
#include "agaa/lighting/resolve.glsl"

// Step 3 (agaa/lighting/shade_aggregates.glsl; agaa-timings --breakdown's build leaves it out).
void shadeAggregates(OffLayer off, bool inside, uint firstEntry, out OffLayerShading offShaded);

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.extent.xy);
    bool inside = all(lessThan(pixel, size));
    uint pixelIndex = inside ? uint(pixel.y * size.x + pixel.x) : 0u;

    // 1. Aggregate at the top of the tile: one walk over the pixel's samples, then each
    //    aggregate's means normalised into the surface it is shaded as.
    clearMaterialSums();
    clearSpreadSums();
    walkPixelSamples(pixel, pixelIndex, inside);
    uint presentCount = 0u;
    for (uint a = 0u; a < kAggregates; ++a) {
        AggregateMoments moments =
            loadAggregateMoments(a, walk.count, walk.samplesIn[a], pixelIndex, inside);
        aggregates[a] = normaliseAggregate(a, moments, pixel, pixelIndex);
        presentCount += aggregates[a].present ? 1u : 0u;
    }
    OffLayerMeans offLayerMeans = noOffLayerMeans();
    if (kOffLayerOwnColour && walk.offLayerSamples > 0u)
        offLayerMeans = loadOffLayerMeans(pixelIndex, walk.offLayerSamples);
    OffLayer offLayer = offLayerSurface(offLayerMeans);
    // The shading rate: the aggregates of a pixel whose pre-filter the estimate distrusts are not
    // shaded here; the next pass takes their samples one by one instead.
    float estimate = pixelEstimate(inside);
    bool perSample = shadePerSample(inside, estimate, pixel, pixelIndex);
    if (perSample) {
        perSampleMembers = perSampleSamples(pixel, pixelIndex);
        presentCount = 0u;
        for (uint a = 0u; a < kAggregates; ++a) {
            bool distrusted = perSampleMembers == kPerSampleWholePixel || walk.samplesIn[a] == 0u ||
                              prefilterEstimate(a, walk.samplesIn[a]) >= agaa.shadingRate.x;
            aggregates[a].present = aggregates[a].present && !distrusted;
            presentCount += aggregates[a].present ? 1u : 0u;
        }
    }

    // 2. Tile depth bounds and light culling; the pixel's slots in the tile's list.
    tileListBegin();
    tileFlagBegin();
    tileBoundsBegin(); // its barrier orders the list's and the flag's resets before the appends
    uint firstEntry = tileListAppend(presentCount);
    tileFlagAdd(perSample);
    tileBoundsAdd(walk.tmin, walk.tmax);
    tileCullLights();
    barrier();

    // 3. Light each aggregate once per light.
    OffLayerShading offLayerShaded;
    shadeAggregates(offLayer, inside, firstEntry, offLayerShaded);

    // 4. Resolve; a wholly flagged pixel is the next pass's to write, a partly flagged one's
    //    trusted aggregates are resolved here and the next pass adds the others' samples. A pixel
    //    above the alias limit is flagged here, once its radiance is known, where that radiance
    //    saturates the tone map.
    if (inside && perSampleMembers != kPerSampleWholePixel) {
        Resolved resolved = resolvePixel(pixel, offLayer, offLayerShaded);
        if (!perSample) {
            perSample = shadeSaturatedAlias(inside, estimate, resolved.hdr);
            perSampleMembers = perSample ? kPerSampleWholePixel : 0u;
            tileFlagAdd(perSample);
        }
        if (kShadingRateView != 0u && !perSample) resolved.display = shadingRateView(resolved.display, false);
        if (perSampleMembers != kPerSampleWholePixel) {
            imageStore(outHdr, pixel, vec4(resolved.hdr, 1.0));
            imageStore(outDisplay, pixel, vec4(resolved.display, 1.0));
            imageStore(outShadingEvents, pixel, uvec4(presentCount));
        }
    }
    if (kShadingRate != 0u && inside) imageStore(outPerSampleShaded, pixel, uvec4(perSampleMembers));
}
