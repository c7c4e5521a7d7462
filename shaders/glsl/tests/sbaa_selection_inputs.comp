#version 460
#extension GL_GOOGLE_include_directive : require
// Copies what SBAA's surface selection reads (every sample's depth, stored geometric normal and
// primitive id) from the prepass into a buffer, so its CPU twin (agaa/sbaa/surface_selection.cpp)
// runs on the same inputs. A test kernel (agaa_test_shaders; tests/support/sample_inputs_export.h).
#include "shared/frame.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
// Sample s of pixel (x, y) at (y * width + x) * n + s: (depth, geometric normal as stored .xy,
// primitive id).
layout(set = 0, binding = 14, std430) writeonly buffer Samples { vec4 samples[]; };

#include "common/octahedral.glsl"
#include "sbaa/gbuffer_fetch.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.extent.xy)))) return;
    uint n = frame.counts.x;
    uint first = (uint(pixel.y) * uint(frame.extent.x) + uint(pixel.x)) * n;
    for (uint s = 0u; s < n; ++s) {
        samples[first + s] = vec4(SBAA_FETCH(gDepth, pixel, s).r, SBAA_FETCH(gGeometricNormal, pixel, s).xy,
                                  SBAA_FETCH(gPrimitive, pixel, s).r);
    }
}
