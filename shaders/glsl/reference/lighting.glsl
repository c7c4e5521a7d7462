// Tiled deferred lighting of the per-sample G-buffer: every covered sample is lit
// by every light that touches its tile, tone-mapped, and weighted 1/n (DESIGN
// section 6); uncovered samples get the sky. Included by lighting_ms.comp (4x
// layered G-buffer) and lighting_ss.comp (1 sample per pixel).
#extension GL_GOOGLE_include_directive : require
#include "shared/frame.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1, std430) readonly buffer Lights { GpuLight lights[]; };
#if GBUFFER_MS
layout(set = 0, binding = 2) uniform sampler2DMSArray gDepth;
layout(set = 0, binding = 3) uniform sampler2DMSArray gNormal;
layout(set = 0, binding = 4) uniform sampler2DMSArray gAlbedoMetal;
layout(set = 0, binding = 5) uniform sampler2DMSArray gEmissiveRoughness;
#define FETCH(tex, p, layer, s) texelFetch(tex, ivec3(p, layer), int(s))
#else
layout(set = 0, binding = 2) uniform sampler2D gDepth;
layout(set = 0, binding = 3) uniform sampler2D gNormal;
layout(set = 0, binding = 4) uniform sampler2D gAlbedoMetal;
layout(set = 0, binding = 5) uniform sampler2D gEmissiveRoughness;
#define FETCH(tex, p, layer, s) texelFetch(tex, p, 0)
#endif
layout(set = 0, binding = 6, rgba32f) uniform writeonly image2D outHdr;
layout(set = 0, binding = 7, rgba32f) uniform writeonly image2D outDisplay;
layout(set = 0, binding = 8, r32ui) uniform writeonly uimage2D outShadingEvents;

#include "common/brdf.glsl"
#include "common/depth.glsl"
#include "common/lights.glsl"
#include "common/octahedral.glsl"
#include "common/tile_culling.glsl"
#include "common/tonemap.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = ivec2(frame.extent.xy);
    bool inside = all(lessThan(pixel, size));
    uint n = frame.counts.x;
    uint perLayer = frame.counts.y;

    float tmin = 1e30, tmax = -1e30;
    if (inside) {
        for (uint s = 0u; s < n; ++s) {
            float d = FETCH(gDepth, pixel, s / perLayer, s % perLayer).r;
            if (isSky(d)) continue;
            float t = viewDistanceFromDepth(d, frame.depthParams.x, frame.depthParams.y);
            tmin = min(tmin, t);
            tmax = max(tmax, t);
        }
    }
    tileBoundsBegin();
    tileBoundsAdd(tmin, tmax);
    tileCullLights();
    barrier();
    if (!inside) return;

    float exposure = frame.depthParams.z;
    float weight = 1.0 / float(n);
    vec3 sky = frame.skyRadiance.rgb * exposure;
    vec3 display = vec3(0.0);
    vec3 hdr = vec3(0.0);
    uint events = 0u;
    for (uint s = 0u; s < n; ++s) {
        uint layer = s / perLayer, hw = s % perLayer;
        float d = FETCH(gDepth, pixel, layer, hw).r;
        if (isSky(d)) {
            display += weight * toneMapAces(sky);
            hdr += weight * sky;
            continue;
        }
        vec2 pixelPos = vec2(pixel) + frame.samplePositions[s].xy;
        vec3 P = viewPositionFromDepth(pixelPos, d, frame.extent, frame.depthParams, frame.projParams);
        vec3 V = normalize(-P); // |P| >= znear > 0
        SurfaceInputs surface;
        surface.normal = decodeOctahedral(FETCH(gNormal, pixel, layer, hw).xy);
        vec4 am = FETCH(gAlbedoMetal, pixel, layer, hw);
        vec4 er = FETCH(gEmissiveRoughness, pixel, layer, hw);
        surface.albedo = am.rgb;
        surface.metallic = am.a;
        surface.roughness = er.a;
        vec3 radiance = vec3(0.0);
        for (uint i = nextTileLight(0u); i < kMaxLights; i = nextTileLight(i + 1u)) {
            vec3 L, irradiance;
            if (lightIncidence(lights[i], P, L, irradiance)) radiance += evaluateBrdf(surface, V, L, irradiance);
        }
        // Emissive stays per sample and joins before the tone map (seed 004).
        vec3 sampleRadiance = min((radiance + er.rgb) * exposure, vec3(kMaxRadiance));
        display += weight * toneMapAces(sampleRadiance);
        hdr += weight * sampleRadiance;
        events += 1u;
    }
    imageStore(outHdr, pixel, vec4(hdr, 1.0));
    imageStore(outDisplay, pixel, vec4(display, 1.0));
    imageStore(outShadingEvents, pixel, uvec4(events));
}
