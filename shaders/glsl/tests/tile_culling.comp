#version 460
// Test kernel (tests/gpu/test_tile_culling.cpp): the production tile light culling
// (common/tile_culling.glsl, included unchanged) on view distances the test chooses, one
// workgroup per 16x16 tile, one pixel per invocation. Each invocation hands in its pixel's
// [tmin, tmax] (tmin > tmax: no geometry); invocation 0 writes the tile's light mask and depth
// bounds back for the CPU's brute-force comparison.
#extension GL_GOOGLE_include_directive : require

#include "shared/frame.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 2, std430) readonly buffer PixelBounds { vec2 pixelBounds[]; };
// Per tile: kMaxLights / 32 mask words, then the tile's min and max bits.
layout(set = 0, binding = 3, std430) writeonly buffer TileMasks { uint tileMasks[]; };

#include "common/tile_culling.glsl"

void main() {
    tileBoundsBegin();
    uvec2 pixel = gl_GlobalInvocationID.xy;
    uvec2 size = uvec2(frame.extent.xy);
    vec2 bounds = vec2(1.0, 0.0); // outside the image: no geometry
    if (all(lessThan(pixel, size))) bounds = pixelBounds[pixel.y * size.x + pixel.x];
    tileBoundsAdd(bounds.x, bounds.y);
    tileCullLights();
    barrier();
    if (gl_LocalInvocationIndex != 0u) return;
    const uint stride = kMaxLights / 32u + 2u;
    uint tile = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    for (uint w = 0u; w < kMaxLights / 32u; ++w) tileMasks[tile * stride + w] = sLightMask[w];
    tileMasks[tile * stride + kMaxLights / 32u] = sTileMinBits;
    tileMasks[tile * stride + kMaxLights / 32u + 1u] = sTileMaxBits;
}
