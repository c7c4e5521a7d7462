#version 460
// SBAA shading and resolve (Salvi and Vidimce 2012, section 3.3): tiled deferred, one pixel per
// invocation; each of the pixel's S surfaces (sbaa/surfaces.comp) is lit once per light of the
// tile at its representative sample's position, tone-mapped, and weighted by its coverage.
// The coverage of the surfaces that were not kept is lost, as in the paper: the weights are the
// kept surfaces' and the sky's sample counts over their sum (what they cover stands for the whole
// pixel), so a lost surface's colour is missing from the pixel (the aliasing SBAA trades for its
// memory; the stats report how much coverage was lost). Built as sbaa/lighting.comp and
// lighting_shadow.comp (shaders/CMakeLists.txt).
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"
#include "shared/sbaa.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D outHdr;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D outDisplay;
layout(set = 0, binding = 8, r32ui) uniform writeonly uimage2D outShadingEvents;
layout(set = 0, binding = 12, std430) readonly buffer Surfaces { uint surfaces[]; };
layout(push_constant) uniform Push { SbaaParams params; } pc;

#define GBUFFER_MS 1
#include "common/gbuffer_lighting.glsl"
#include "common/half.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.extent.xy);
    bool inside = all(lessThan(pixel, size));
    const uint n = kSampleCount;
    const uint S = pc.params.counts.x;

    // The tile's depth bounds over every covered sample (lost ones too: conservative).
    float tmin = 1e30, tmax = -1e30;
    if (inside) gbufferDistanceRange(pixel, tmin, tmax);
    tileBoundsBegin();
    tileBoundsAdd(tmin, tmax);
    tileCullLights();
    barrier();
    if (!inside) return;

    uint skySamples = 0u;
    for (uint s = 0u; s < n; ++s)
        skySamples += isSky(gbufferDepth(pixel, s)) ? 1u : 0u;
    uint first = (uint(pixel.y) * uint(frame.extent.x) + uint(pixel.x)) * S * kSbaaSurfaceWords;
    uint keptSamples = skySamples;
    for (uint k = 0u; k < S; ++k)
        keptSamples += bitCount(surfaces[first + k * kSbaaSurfaceWords + kSbaaWordMask]);
    float norm = 1.0 / float(max(keptSamples, 1u)); // >= 1: every pixel keeps its sky or a surface

    vec3 hdr = vec3(0.0), display = vec3(0.0);
    uint events = 0u;
    if (skySamples > 0u) {
        vec3 sky = skyRadiance(pixel) * frame.depthParams.z;
        hdr += float(skySamples) * norm * sky;
        display += float(skySamples) * norm * toneMapAces(sky);
    }
    for (uint k = 0u; k < S; ++k) {
        uint w = first + k * kSbaaSurfaceWords;
        uint mask = surfaces[w + kSbaaWordMask];
        if (mask == 0u) continue;
        uint rep = surfaces[w + kSbaaWordSampleAndPrimitive] & 0xFFu;
        vec2 albedoRg = unpackHalf2x16Exact(surfaces[w + kSbaaWordAlbedoRg]);
        vec2 albedoBMetal = unpackHalf2x16Exact(surfaces[w + kSbaaWordAlbedoBMetal]);
        vec2 emissiveRg = unpackHalf2x16Exact(surfaces[w + kSbaaWordEmissiveRg]);
        vec2 emissiveBRoughness = unpackHalf2x16Exact(surfaces[w + kSbaaWordEmissiveBRoughness]);
        SurfaceInputs surface;
        surface.normal = decodeOctahedral(unpackSnorm2x16(surfaces[w + kSbaaWordNormal]));
        surface.albedo = vec3(albedoRg, albedoBMetal.x);
        surface.metallic = albedoBMetal.y;
        surface.roughness = emissiveBRoughness.y;
        vec3 P = viewPositionFromDepth(vec2(pixel) + frame.samplePositions[rep].xy,
                                       uintBitsToFloat(surfaces[w + kSbaaWordDepth]), frame.extent,
                                       frame.depthParams, frame.projParams);
        vec3 radiance, toneMapped;
        shadeSurfaceInputs(surface, vec3(emissiveRg, emissiveBRoughness.x), P, radiance, toneMapped);
        float weight = float(bitCount(mask)) * norm;
        hdr += weight * radiance;
        display += weight * toneMapped;
        ++events;
    }
    imageStore(outHdr, pixel, vec4(hdr, 1.0));
    imageStore(outDisplay, pixel, vec4(display, 1.0));
    imageStore(outShadingEvents, pixel, uvec4(events));
}
