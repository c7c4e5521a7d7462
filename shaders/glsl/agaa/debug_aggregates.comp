#version 460
#extension GL_GOOGLE_include_directive : require
// `agaa-render --method agaa --debug aggregates`: the clustering made visible. Hue is the
// pixel's aggregate count (sky grey, 1 green, 2 yellow, 3 orange, 4 red); brightness is the
// fraction of covered samples in aggregate 0, so the split inside a pixel shows as shading.
#include "shared/agaa.h"
#include "shared/clustering.h"
#include "shared/frame.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1) uniform Agaa { AgaaConstants agaa; };
layout(set = 0, binding = 2, std430) readonly buffer Metadata { uint metadata[]; };
layout(set = 0, binding = 3, r8ui) uniform readonly uimage2D aggregateCount;
layout(set = 0, binding = 4) uniform sampler2DMSArray visibilityDepth;
layout(set = 0, binding = 5, rgba32f) uniform writeonly image2D outHdr;
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D outDisplay;
layout(set = 0, binding = 7, r32ui) uniform writeonly uimage2D outShadingEvents;

const vec3 kCountColour[5] = vec3[](vec3(0.25), vec3(0.1, 0.8, 0.2), vec3(0.95, 0.85, 0.1),
                                    vec3(1.0, 0.5, 0.05), vec3(0.9, 0.1, 0.1));

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, ivec2(frame.extent.xy)))) return;
    uint n = agaa.shape.w, c = agaa.shape.x, words = agaa.shape.z;
    uint pixelIndex = uint(pixel.y) * uint(frame.extent.x) + uint(pixel.x);
    uint count = imageLoad(aggregateCount, pixel).r;
    uint covered = 0u, inFirst = 0u;
    for (uint s = 0u; s < n; ++s) {
        if (texelFetch(visibilityDepth, ivec3(pixel, s / 4u), int(s % 4u)).r <= 0.0) continue;
        covered += 1u;
        uint id = words == 0u ? 0u : unpackMetadata(metadata[pixelIndex * words + (s * metadataBits(c)) / 32u], s, c);
        if (id == 0u) inFirst += 1u;
    }
    float share = covered > 0u ? float(inFirst) / float(covered) : 1.0;
    vec3 colour = kCountColour[min(count, 4u)] * (0.45 + 0.55 * share);
    imageStore(outHdr, pixel, vec4(colour, 1.0));
    imageStore(outDisplay, pixel, vec4(colour, 1.0));
    imageStore(outShadingEvents, pixel, uvec4(count));
}
