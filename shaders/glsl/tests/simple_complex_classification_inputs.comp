#version 460
#extension GL_GOOGLE_include_directive : require
// Copies what the simple/complex classification reads (every sample's raw depth and
// encoded normal) from the 4x layered G-buffer into a buffer, so the CPU twin of the
// classification (agaa/simple_complex/classify.cpp) can run on the same inputs.
// A test kernel (agaa_test_shaders; tests/support/sample_inputs_export.h).
#include "shared/frame.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1) uniform sampler2DMSArray gDepth;
layout(set = 0, binding = 2) uniform sampler2DMSArray gNormal;
// Sample s of pixel (x, y) at (y * width + x) * n + s: x depth, yz octahedral normal, w 0.
layout(set = 0, binding = 3, std430) writeonly buffer Samples { vec4 samples[]; };

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.extent.xy)))) return;
    uint n = frame.counts.x, perLayer = frame.counts.y;
    uint first = (uint(pixel.y) * uint(frame.extent.x) + uint(pixel.x)) * n;
    for (uint s = 0u; s < n; ++s) {
        ivec3 p = ivec3(pixel, s / perLayer);
        float d = texelFetch(gDepth, p, int(s % perLayer)).r;
        vec2 e = texelFetch(gNormal, p, int(s % perLayer)).xy;
        samples[first + s] = vec4(d, e, 0.0);
    }
}
