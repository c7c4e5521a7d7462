#version 460
#extension GL_GOOGLE_include_directive : require
// Resolves a technique's per-sample visibility depth to one depth per pixel for a host's depth
// target (agaa/common/host_targets.h): the nearest sample, i.e. the largest value in reversed Z
// (1 at znear, 0 = sky). Nearest, not sample 0 or an average, because a host drawing after the
// node depth-tests against it: a pixel any node surface covers must hide what lies behind that
// surface, and an average of a near and a far sample is a depth no surface has.
#ifndef DEPTH_MS
#define DEPTH_MS 0 // 1: the 4x layered depth (depth_resolve_ms.comp), 0: one sample per pixel
#endif

layout(local_size_x = 8, local_size_y = 8) in;
#if DEPTH_MS
layout(set = 0, binding = 0) uniform sampler2DMSArray sampleDepth;
#else
layout(set = 0, binding = 0) uniform sampler2D sampleDepth;
#endif
layout(set = 0, binding = 1, std430) writeonly buffer Resolved { float resolved[]; }; // row-major

void main() {
#if DEPTH_MS
    const ivec2 extent = textureSize(sampleDepth).xy;
    const int layers = textureSize(sampleDepth).z;
    const int samples = textureSamples(sampleDepth);
#else
    const ivec2 extent = textureSize(sampleDepth, 0);
#endif
    const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, extent))) return;
#if DEPTH_MS
    float nearest = 0.0;
    for (int layer = 0; layer < layers; ++layer)
        for (int s = 0; s < samples; ++s)
            nearest = max(nearest, texelFetch(sampleDepth, ivec3(pixel, layer), s).r);
#else
    const float nearest = texelFetch(sampleDepth, pixel, 0).r;
#endif
    resolved[pixel.y * extent.x + pixel.x] = nearest;
}
