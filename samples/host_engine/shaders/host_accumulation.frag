#version 460
#extension GL_GOOGLE_include_directive : require
// A host's own material shader for RasterOutput::AggregateAccumulation
// (tests/node/test_host_geometry.cpp): its material into AGAA's accumulation kernel. One build: no
// emissive, 32-bit atomics, no subgroup reduction (RasterPass::defines empty).
#include "raster/aggregate_accumulation_output.glsl"
#define SAMPLE_GBUFFER_TARGETS 0 // the curvature roughness option alone, no G-buffer targets
#include "raster/sample_gbuffer_output.glsl"
#include "host_material.glsl"

layout(location = 0) centroid in vec3 inNormal;
layout(location = 2) flat in uint inLayer;

void main() {
    vec3 n = hostNormal(inNormal);
    vec3 dNdx = dFdx(n), dNdy = dFdy(n); // before anything diverges
    float roughness = sampleGBufferRoughness(clamp(material.albedoRoughness.w, 0.0, 1.0), dNdx, dNdy);
    MaterialSample m = hostMaterial(n, roughness);
    accumulateAggregateFragment(inLayer, m);
}
