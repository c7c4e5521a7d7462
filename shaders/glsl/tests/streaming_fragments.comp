#version 460
#extension GL_GOOGLE_include_directive : require
// Copies the recorded fragments' samples (every sample's depth, encoded normal, primitive id,
// albedo/metal and emissive/roughness) into a buffer, so the CPU reference
// (agaa/streaming/streaming_compression.cpp) replays the same list. A test kernel
// (agaa_test_shaders; tests/support/sample_inputs_export.h).
#include "shared/frame.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
// Sample s of pixel (x, y) at ((y * width + x) * n + s) * 3: (depth, normal.xy, primitive id),
// albedo/metal, emissive/roughness.
layout(set = 0, binding = 14, std430) writeonly buffer Samples { vec4 samples[]; };

#include "streaming/gbuffer_fetch.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.extent.xy)))) return;
    uint n = frame.counts.x;
    uint first = (uint(pixel.y) * uint(frame.extent.x) + uint(pixel.x)) * n;
    for (uint s = 0u; s < n; ++s) {
        samples[(first + s) * 3u] = vec4(STREAMING_FETCH(gDepth, pixel, s).r,
                                         STREAMING_FETCH(gNormal, pixel, s).xy,
                                         STREAMING_FETCH(gPrimitive, pixel, s).r);
        samples[(first + s) * 3u + 1u] = STREAMING_FETCH(gAlbedoMetal, pixel, s);
        samples[(first + s) * 3u + 2u] = STREAMING_FETCH(gEmissiveRoughness, pixel, s);
    }
}
