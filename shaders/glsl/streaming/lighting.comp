#version 460
// Streaming G-buffer compression, shading and resolve (Kerzner and Salvi 2014, section 3.3):
// tiled deferred, one pixel per invocation; each of the pixel's surfaces (streaming/compress.comp)
// is lit once per light of the tile at its zView on the pixel centre's ray, tone-mapped, and
// weighted by the popcount of its depth-tested coverage over n; the sky takes the rest (its own
// samples and the samples of dropped surfaces: the issue's resolve, the paper's uncovered samples
// "treated as the background"). Built as streaming/lighting.comp and lighting_shadow.comp
// (shaders/CMakeLists.txt).
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/streaming.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D outHdr;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D outDisplay;
layout(set = 0, binding = 8, r32ui) uniform writeonly uimage2D outShadingEvents;
layout(set = 0, binding = 12, std430) readonly buffer Surfaces { uint surfaces[]; };
layout(push_constant) uniform Push { StreamingParams params; } pc;

#define GBUFFER_MS 1
#include "common/gbuffer_lighting.glsl"
#include "common/half.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.extent.xy);
    bool inside = all(lessThan(pixel, size));
    const uint n = kSampleCount;
    const uint S = pc.params.counts.x;

    // The tile's depth bounds over every covered sample (dropped ones too: conservative).
    float tmin = 1e30, tmax = -1e30;
    if (inside) gbufferDistanceRange(pixel, tmin, tmax);
    tileBoundsBegin();
    tileBoundsAdd(tmin, tmax);
    tileCullLights();
    barrier();
    if (!inside) return;

    uint first = (uint(pixel.y) * uint(frame.extent.x) + uint(pixel.x)) * S * kStreamingSurfaceWords;
    uint owned = 0u;
    for (uint k = 0u; k < S; ++k)
        owned += bitCount(surfaces[first + k * kStreamingSurfaceWords + kStreamingWordDepthTested]);
    // Depth-tested masks of inter-penetrating surfaces may overlap: then their counts, not n, are
    // the denominator, and the sky gets nothing.
    float norm = 1.0 / float(max(owned, n));
    uint skySamples = n - min(owned, n);

    vec3 hdr = vec3(0.0), display = vec3(0.0);
    uint events = 0u;
    if (skySamples > 0u) {
        vec3 sky = skyRadiance(pixel) * frame.depthParams.z;
        hdr += float(skySamples) * norm * sky;
        display += float(skySamples) * norm * toneMapAces(sky);
    }
    for (uint k = 0u; k < S; ++k) {
        uint w = first + k * kStreamingSurfaceWords;
        uint weightSamples = bitCount(surfaces[w + kStreamingWordDepthTested]);
        if (weightSamples == 0u) continue; // an empty slot, or a surface fully occluded
        vec2 albedoRg = unpackHalf2x16Exact(surfaces[w + kStreamingWordAlbedoRg]);
        vec2 albedoBMetal = unpackHalf2x16Exact(surfaces[w + kStreamingWordAlbedoBMetal]);
        vec2 emissiveRg = unpackHalf2x16Exact(surfaces[w + kStreamingWordEmissiveRg]);
        vec2 emissiveBRoughness = unpackHalf2x16Exact(surfaces[w + kStreamingWordEmissiveBRoughness]);
        SurfaceInputs surface;
        surface.normal = decodeOctahedral(unpackSnorm2x16(surfaces[w + kStreamingWordNormal]));
        surface.albedo = vec3(albedoRg, albedoBMetal.x);
        surface.metallic = albedoBMetal.y;
        surface.roughness = emissiveBRoughness.y;
        vec3 P = viewPositionAtDistance(vec2(pixel) + 0.5, uintBitsToFloat(surfaces[w + kStreamingWordZView]),
                                        frame.extent, frame.projParams);
        vec3 radiance, toneMapped;
        shadeSurfaceInputs(surface, vec3(emissiveRg, emissiveBRoughness.x), P, radiance, toneMapped);
        float weight = float(weightSamples) * norm;
        hdr += weight * radiance;
        display += weight * toneMapped;
        ++events;
    }
    imageStore(outHdr, pixel, vec4(hdr, 1.0));
    imageStore(outDisplay, pixel, vec4(display, 1.0));
    imageStore(outShadingEvents, pixel, uvec4(events));
}
