#version 460
// Tiled deferred lighting of the per-sample G-buffer: every covered sample is lit
// by every light that touches its tile, tone-mapped, and weighted 1/n (DESIGN
// section 6); uncovered samples get the sky. Built as lighting_ms.comp (4x
// layered G-buffer) and lighting_ss.comp (1 sample per pixel; shaders/CMakeLists.txt).
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D outHdr;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D outDisplay;
layout(set = 0, binding = 8, r32ui) uniform writeonly uimage2D outShadingEvents;

#include "common/gbuffer_lighting.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.extent.xy);
    bool inside = all(lessThan(pixel, size));
    const uint n = kSampleCount;

    float tmin = 1e30, tmax = -1e30;
    if (inside) gbufferDistanceRange(pixel, tmin, tmax);
    tileBoundsBegin();
    tileBoundsAdd(tmin, tmax);
    tileCullLights();
    barrier();
    if (!inside) return;

    float weight = 1.0 / float(n);
    vec3 display = vec3(0.0);
    vec3 hdr = vec3(0.0);
    uint events = 0u;
    for (uint s = 0u; s < n; ++s) {
        vec3 radiance, toneMapped;
        bool covered = shadeGBufferSample(pixel, s, radiance, toneMapped);
        display += weight * toneMapped;
        hdr += weight * radiance;
        events += covered ? 1u : 0u;
    }
    imageStore(outHdr, pixel, vec4(hdr, 1.0));
    imageStore(outDisplay, pixel, vec4(display, 1.0));
    imageStore(outShadingEvents, pixel, uvec4(events));
}
