#version 460
// AGAA step 4: tiled-deferred lighting that aggregates at the top of each tile (paper section
// 3.5, the UE4 variant of seed 004). One workgroup per 16x16 tile; main reads as the paper's step:
//   1. aggregate: one walk over each pixel's n samples (agaa/lighting/pixel_samples.glsl) sums
//      every aggregate's coverage, depth and position, and the generation path's loader its
//      material: agaa/lighting/load_accumulated.glsl reads the AG-buffer the accumulation kernel
//      summed (AGAA_GBUFFER 0), agaa/lighting/load_samples.glsl sums the per-sample G-buffer in
//      registers (AGAA_GBUFFER 1). agaa/lighting/aggregate.glsl normalises each into a surface
//      with a filtered normal distribution; c = 1's off-layer samples become one surface of their
//      own (agaa/lighting/off_layer.glsl);
//   2. tile depth bounds and light culling in shared memory (common/tile_culling.glsl);
//   3. each aggregate lit once per light (agaa/lighting/shade.glsl) on one of two schedules
//      (agaa/lighting/schedule.glsl);
//   4. resolve: each shading event tone-mapped and weighted by its samples
//      (agaa/lighting/resolve.glsl).
// With a tolerance (--agaa-tolerance, either path), an aggregate whose normal spread the estimate
// distrusts (agaa/lighting/prefilter_estimate.glsl) skips steps 3 and 4 here and its pixel is
// flagged (agaa/lighting/shading_rate.glsl), and so is the whole of a pixel above the alias limit
// whose resolved radiance saturates the tone map: the next pass, agaa/lighting_per_sample.comp,
// lights and resolves each of their samples on its own, and adds them to the trusted aggregates'
// resolve.
#extension GL_GOOGLE_include_directive : require
#include "agaa/lighting/lighting_pass.glsl"
#include "agaa/lighting/shade_aggregates.glsl"
#include "agaa/lighting/shadow_footprint.glsl"

// Nothing is observed in the shipping pass.
void exportSample(uint pixelIndex, uint s, vec4 a, vec4 b, vec4 c, vec4 d) {}
void exportAggregate(uint pixelIndex, uint a, vec4 m0, vec4 m1, vec4 m2, vec4 m3) {}
