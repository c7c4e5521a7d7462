#ifndef AGAA_RASTER_SURFACE_FILL_OUTPUT_GLSL
#define AGAA_RASTER_SURFACE_FILL_OUTPUT_GLSL
// For a drawer's fragment shaders (agaa/common/raster_pass.h): RasterOutput::SurfaceFill, SBAA's
// second geometry pass (agaa/sbaa/surface_fill.h). No colour targets: the fragment's material goes
// into the per-surface G-buffer record (shared/sbaa.h words 2..6) of each kept surface it
// represents: its representative primitive is this one and its representative sample lies in this
// layer. A primitive is rasterised once per pixel and layer, and the prepass found it visible at
// that sample, so this fragment covers the sample and is the only one that can: exactly one
// invocation writes each record (at sample rate, the one at that sample), no race, no ordering.
// The prepass depth is attached read-only with an EQUAL test, early, so hidden fragments never
// run the material. Set 0: binding 0 the frame, binding 2 the records.
// SURFACE_FILL_SAMPLE_RATE 1: the build for RasterPass::sampleRateShading.
#include "raster/frame.glsl"
#include "shared/sbaa.h"
#include "shared/specialization.h"
#include "common/octahedral.glsl"

#ifndef SURFACE_FILL_SAMPLE_RATE
#define SURFACE_FILL_SAMPLE_RATE 0
#endif

layout(early_fragment_tests) in;
layout(constant_id = kSpecFillSbaaSurfaces) const uint kSbaaSurfaces = 4u; // S
layout(set = 0, binding = 2, std430) buffer Surfaces { uint surfaces[]; };

// primitive: the scene-wide triangle number (the drawer's first triangle + gl_PrimitiveID), as the
// prepass wrote it (RasterOutput::SurfaceVisibility). viewNormal: unit, view space.
void writeSurfaceFill(uint primitive, vec3 viewNormal, vec3 albedo, float metallic, vec3 emissive,
                      float roughness) {
    const uint key = primitive + 1u;
    const uint perLayer = frame.counts.y; // hardware samples per layer
    const uvec2 pixel = uvec2(gl_FragCoord.xy);
    const uint first = (pixel.y * uint(frame.extent.x) + pixel.x) * kSbaaSurfaces * kSbaaSurfaceWords;
    const vec3 clamped = min(emissive, vec3(kMaxRadiance));
    for (uint k = 0u; k < kSbaaSurfaces; ++k) {
        const uint w = first + k * kSbaaSurfaceWords;
        const uint record = surfaces[w + kSbaaWordSampleAndPrimitive];
        if (surfaces[w + kSbaaWordMask] == 0u || (record >> 8u) != key) continue;
        const uint rep = record & 0xFFu;
        if (rep / perLayer != uint(gl_Layer)) continue;
#if SURFACE_FILL_SAMPLE_RATE
        if (uint(gl_SampleID) != rep % perLayer) continue; // the invocation at that sample
#endif
        surfaces[w + kSbaaWordNormal] = packSnorm2x16(encodeOctahedral(viewNormal));
        surfaces[w + kSbaaWordAlbedoRg] = packHalf2x16(albedo.rg);
        surfaces[w + kSbaaWordAlbedoBMetal] = packHalf2x16(vec2(albedo.b, metallic));
        surfaces[w + kSbaaWordEmissiveRg] = packHalf2x16(clamped.rg);
        surfaces[w + kSbaaWordEmissiveBRoughness] = packHalf2x16(vec2(clamped.b, roughness));
    }
}
#endif
