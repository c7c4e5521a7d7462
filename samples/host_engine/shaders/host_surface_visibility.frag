#version 460
#extension GL_GOOGLE_include_directive : require
// A host's own shader for RasterOutput::SurfaceVisibility, SBAA's prepass
// (raster/surface_visibility_output.glsl): its geometric normal and triangle number, no material;
// opaque materials, so full coverage. HOST_SAMPLE_RATE: the build for
// RasterPass::sampleRateShading, interpolated as the fill pass (host_gbuffer.frag) interpolates.
#include "raster/surface_visibility_output.glsl"
#include "host_material.glsl"

#if HOST_SAMPLE_RATE
layout(location = 0) sample in vec3 inNormal;
#else
layout(location = 0) centroid in vec3 inNormal;
#endif

void main() {
    vec3 face = surfaceVisibilityFaceNormal(); // first: screen derivatives
    float len = length(inNormal);
    vec3 n = len > kHostShortestNormal ? (gl_FrontFacing ? inNormal : -inNormal) / len : face;
    writeSurfaceVisibility(n, 1.0, hostTriangle());
}
