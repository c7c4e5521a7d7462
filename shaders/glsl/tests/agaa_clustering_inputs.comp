#version 460
#extension GL_GOOGLE_include_directive : require
// Test support (tests/support/aggregate_instrumentation.h ClusteringInputReadback): copies what
// AGAA's clustering kernel reads for each sample on the accumulate path (the depth float as
// texelFetch returns it, and the two normal bytes) into a buffer, so the CPU reference clusters
// exactly the same inputs (MSAA images cannot be copied to buffers directly).
#include "shared/agaa.h"
#include "shared/frame.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1) uniform Agaa { AgaaConstants agaa; };
layout(set = 0, binding = 2) uniform sampler2DMSArray visibilityDepth;
layout(set = 0, binding = 3) uniform sampler2DMSArray visibilityNormal;
layout(set = 0, binding = 4, std430) writeonly buffer Samples { uvec2 samples[]; }; // per pixel, n per pixel

void main() {
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (any(greaterThanEqual(pixel, uvec2(frame.extent.xy)))) return;
    uint n = agaa.shape.w;
    uint base = (pixel.y * uint(frame.extent.x) + pixel.x) * n;
    for (uint s = 0u; s < n; ++s) {
        ivec3 at = ivec3(pixel, s / 4u);
        float d = texelFetch(visibilityDepth, at, int(s % 4u)).r;
        uvec2 q = uvec2(round(texelFetch(visibilityNormal, at, int(s % 4u)).rg * 255.0));
        samples[base + s] = uvec2(floatBitsToUint(d), q.x | (q.y << 8u));
    }
}
