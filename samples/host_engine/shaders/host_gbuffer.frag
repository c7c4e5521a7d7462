#version 460
#extension GL_GOOGLE_include_directive : require
// A host's own material shader for the passes that take its material per sample, written through
// the module's includes (tests/node/test_host_geometry.cpp). One source, built per output
// (programs.cmake):
//   RasterOutput::SampleGBuffer           the per-sample G-buffer (raster/sample_gbuffer_output.glsl)
//   RasterOutput::SampleGBufferPrimitive  the same and the triangle number (HOST_PRIMITIVE_ID)
//   RasterOutput::SurfaceFill             SBAA's per-surface records (HOST_SURFACE_FILL,
//                                         raster/surface_fill_output.glsl)
// HOST_SAMPLE_RATE: the build for RasterPass::sampleRateShading.
#ifndef HOST_SAMPLE_RATE
#define HOST_SAMPLE_RATE 0
#endif
#ifndef HOST_PRIMITIVE_ID
#define HOST_PRIMITIVE_ID 0
#endif
#ifndef HOST_SURFACE_FILL
#define HOST_SURFACE_FILL 0
#endif
#if HOST_SURFACE_FILL
#define SURFACE_FILL_SAMPLE_RATE HOST_SAMPLE_RATE
#include "raster/surface_fill_output.glsl"
#define SAMPLE_GBUFFER_TARGETS 0 // the fill's records, not the G-buffer's targets
#endif
#define GBUFFER_PRIMITIVE_ID HOST_PRIMITIVE_ID
#include "raster/sample_gbuffer_output.glsl"
#include "host_material.glsl"

#if HOST_SAMPLE_RATE
layout(location = 0) sample in vec3 inNormal;
#else
layout(location = 0) centroid in vec3 inNormal;
#endif

void main() {
    vec3 n = hostNormal(inNormal);
    vec3 dNdx = dFdx(n), dNdy = dFdy(n); // before anything diverges
    float roughness = sampleGBufferRoughness(clamp(material.albedoRoughness.w, 0.0, 1.0), dNdx, dNdy);
    MaterialSample m = hostMaterial(n, roughness);
#if HOST_SURFACE_FILL
    writeSurfaceFill(hostTriangle(), m.normal, m.albedo, m.metallic, m.emissive, m.roughness);
#else
    writeSampleGBuffer(m.normal, 1.0, m.albedo, m.metallic, m.emissive, m.roughness);
#endif
#if HOST_PRIMITIVE_ID
    writeSampleGBufferPrimitive(hostTriangle());
#endif
}
