#version 460
#extension GL_GOOGLE_include_directive : require
// A host's own material shader for RasterOutput::SampleGBuffer (tests/node/test_host_geometry.cpp),
// written through the module's include. HOST_SAMPLE_RATE: the build for RasterPass::sampleRateShading.
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
    writeSampleGBuffer(m.normal, 1.0, m.albedo, m.metallic, m.emissive, m.roughness);
}
