#ifndef AGAA_RASTER_SAMPLE_GBUFFER_OUTPUT_GLSL
#define AGAA_RASTER_SAMPLE_GBUFFER_OUTPUT_GLSL
// For a drawer's fragment shaders (agaa/common/raster_pass.h): the per-sample G-buffer's targets,
// RasterOutput::SampleGBuffer (and, with GBUFFER_PRIMITIVE_ID 1, SampleGBufferPrimitive), and the
// one function that writes them from the drawer's own material evaluation:
//   0 RG16_SNORM  the shading normal, octahedral, view space; w the coverage alpha, which
//                 alpha-to-coverage reads (1 for an opaque material)
//   1 RGBA8_UNORM albedo, sRGB-encoded here for precision in the darks (common/srgb.glsl; read
//                 through an sRGB view), metallic in a
//   2 RGBA16F     emissive radiance (HDR, clamped to kMaxRadiance), roughness in a
//   3 R32_SFLOAT  (SampleGBufferPrimitive) the scene-wide triangle number + 1, exact below 2^24
// Interpolate the inputs at the centroid (pixel rate) or with `sample` (RasterPass::
// sampleRateShading), as reference/gbuffer_inputs.glsl does: at the pixel centre a thin triangle's
// normal is extrapolated far outside it.
// Kaplanyan's curvature roughness is the module's option (RasterPass::specialization, ids 8 to
// 10): call sampleGBufferRoughness with the geometric normal's derivatives, taken in uniform
// control flow before any discard.
#include "shared/frame.h"
#include "shared/specialization.h"
#include "common/curvature_roughness.glsl"
#include "common/octahedral.glsl"
#include "common/srgb.glsl"

#ifndef GBUFFER_PRIMITIVE_ID
#define GBUFFER_PRIMITIVE_ID 0
#endif
// 0: the constants and sampleGBufferRoughness only (SBAA's fill writes the same material into its
// per-surface records instead of targets).
#ifndef SAMPLE_GBUFFER_TARGETS
#define SAMPLE_GBUFFER_TARGETS 1
#endif

layout(constant_id = kSpecFillCurvatureRoughness) const uint kCurvatureRoughness = 0u;
layout(constant_id = kSpecFillCurvatureMaxFootprint) const float kCurvatureMaxFootprint = 0.3;
layout(constant_id = kSpecFillCurvatureBoost) const float kCurvatureBoost = 2.0;

#if SAMPLE_GBUFFER_TARGETS
layout(location = 0) out vec4 outNormal;
layout(location = 1) out vec4 outAlbedoMetal;
layout(location = 2) out vec4 outEmissiveRoughness;
#if GBUFFER_PRIMITIVE_ID
layout(location = 3) out float outPrimitive;
#endif
#endif

// The material's roughness, widened by the curvature of the geometric normal where the module
// asks for it.
float sampleGBufferRoughness(float roughness, vec3 dNdx, vec3 dNdy) {
    return kCurvatureRoughness != 0u
               ? curvatureRoughness(roughness, dNdx, dNdy, kCurvatureMaxFootprint, kCurvatureBoost)
               : roughness;
}

#if SAMPLE_GBUFFER_TARGETS
// viewNormal: unit, view space, facing the viewer's side of the surface.
void writeSampleGBuffer(vec3 viewNormal, float coverage, vec3 albedo, float metallic, vec3 emissive,
                        float roughness) {
    outNormal = vec4(encodeOctahedral(viewNormal), 0.0, coverage);
    outAlbedoMetal = vec4(srgbEncode(albedo), metallic);
    outEmissiveRoughness = vec4(min(emissive, vec3(kMaxRadiance)), roughness);
}

#endif
#if SAMPLE_GBUFFER_TARGETS && GBUFFER_PRIMITIVE_ID
// primitive: the scene-wide triangle number (the drawer's first triangle + gl_PrimitiveID).
void writeSampleGBufferPrimitive(uint primitive) {
    outPrimitive = float(primitive + 1u);
}
#endif
#endif
