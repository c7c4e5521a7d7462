#version 460
#extension GL_GOOGLE_include_directive : require
// Temporal anti-aliasing's resolve (agaa/temporal/temporal_aa.h), written from Karis 2014 ("High
// quality temporal supersampling") and Yang, Liu and Salvi 2020 ("A survey of temporal
// antialiasing techniques"). The inner method's frame (no-AA, or AGAA's resolve) was rendered
// with this frame's sub-pixel jitter; per pixel:
//  1. reprojection: the pixel centre's view-space position, from this frame's depth, into the
//     previous frame's clip space (TemporalParams::reprojection). The scenes are static, so the
//     camera's motion is all the motion there is and no motion vectors are drawn; the sky (depth
//     0) reprojects as a direction.
//  2. the history at that position, bilinear from four texel fetches (clamped to the edge);
//  3. clipped towards the 3x3 neighbourhood's mean, into the box mean +- gamma sigma in YCoCg
//     (Salvi's variance clipping; Karis's clip along the segment to the box's centre);
//  4. blended with the current sample with weight alpha, each side weighted by 1 / (1 + luma)
//     (Karis: a firefly does not own the history).
// A pixel whose position falls outside the previous frame, or the first frame, takes the current
// sample alone. The display history goes through the same steps on the inner method's display
// (plain blend: its values are bounded). Outputs: the two new histories, the frame's HDR and display.
#include "shared/frame.h"
#include "shared/temporal.h"
#include "common/depth.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
layout(set = 0, binding = 1) uniform sampler2D currentHdr; // texelFetch only
// TEMPORAL_DEPTH_MS (resolve_ms.comp): the inner method's 4x layered per-sample depth (AGAA + TAA,
// n >= 4), of which the nearest sample (Karis: the foreground's motion wins at an edge); else one
// sample per pixel.
#ifndef TEMPORAL_DEPTH_MS
#define TEMPORAL_DEPTH_MS 0
#endif
#if TEMPORAL_DEPTH_MS
layout(set = 0, binding = 2) uniform sampler2DMSArray currentDepth;
#else
layout(set = 0, binding = 2) uniform sampler2D currentDepth;
#endif
layout(set = 0, binding = 3) uniform sampler2D history;
layout(set = 0, binding = 4, rgba32f) uniform writeonly image2D outHistory;
layout(set = 0, binding = 5, rgba32f) uniform writeonly image2D outDisplay;
// The display side: the inner method's display (its shading events tone-mapped and averaged, as
// the truth's display is) and its own history, resolved alongside the HDR with the same
// reprojection, so the temporal average of tone-mapped frames is the display, not the tone map of
// the averaged radiance.
layout(set = 0, binding = 6) uniform sampler2D currentDisplay;
layout(set = 0, binding = 7) uniform sampler2D historyDisplay;
layout(push_constant) uniform Push { TemporalParams params; };

vec3 toYCoCg(vec3 c) {
    return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}
vec3 fromYCoCg(vec3 y) {
    return vec3(y.x + y.y - y.z, y.x + y.z, y.x - y.y - y.z);
}
float luma(vec3 c) {
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

// A history at a pixel-space position (texel centres at +0.5), bilinear, clamped to the edge.
vec3 historyAt(sampler2D image, vec2 position, ivec2 size) {
    vec2 p = position - 0.5;
    ivec2 i = ivec2(floor(p));
    vec2 f = p - vec2(i);
    ivec2 hi = size - 1;
    vec3 a = texelFetch(image, clamp(i, ivec2(0), hi), 0).rgb;
    vec3 b = texelFetch(image, clamp(i + ivec2(1, 0), ivec2(0), hi), 0).rgb;
    vec3 c = texelFetch(image, clamp(i + ivec2(0, 1), ivec2(0), hi), 0).rgb;
    vec3 d = texelFetch(image, clamp(i + ivec2(1, 1), ivec2(0), hi), 0).rgb;
    return mix(mix(a, b, f.x), mix(c, d, f.x), f.y);
}

// The 3x3 neighbourhood's mean and standard deviation in YCoCg, clamped to the edge.
void neighbourhood(sampler2D image, ivec2 pixel, ivec2 size, out vec3 mean, out vec3 sigma) {
    vec3 m1 = vec3(0.0), m2 = vec3(0.0);
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            vec3 c = toYCoCg(texelFetch(image, clamp(pixel + ivec2(dx, dy), ivec2(0), size - 1), 0).rgb);
            m1 += c;
            m2 += c * c;
        }
    mean = m1 / 9.0;
    sigma = sqrt(max(m2 / 9.0 - mean * mean, vec3(0.0)));
}

// The pixel's depth, reversed Z (1 at znear, 0 = sky): its nearest sample.
float pixelDepth(ivec2 pixel) {
#if TEMPORAL_DEPTH_MS
    float nearest = 0.0;
    for (int l = 0; l < textureSize(currentDepth).z; ++l)
        for (int s = 0; s < textureSamples(currentDepth); ++s)
            nearest = max(nearest, texelFetch(currentDepth, ivec3(pixel, l), s).r);
    return nearest;
#else
    return texelFetch(currentDepth, pixel, 0).r;
#endif
}

// Karis's clip: the point where the segment from the box's centre to h leaves the box, or h inside.
vec3 clipToBox(vec3 h, vec3 centre, vec3 halfExtent) {
    vec3 d = h - centre;
    vec3 reach = abs(d) / max(halfExtent, vec3(kTemporalMinExtent));
    float m = max(reach.x, max(reach.y, reach.z));
    return m > 1.0 ? centre + d / m : h;
}

void main() {
    ivec2 size = ivec2(frame.extent.xy);
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, size))) return;
    vec3 current = texelFetch(currentHdr, pixel, 0).rgb;
    vec3 currentTone = texelFetch(currentDisplay, pixel, 0).rgb;
    vec3 result = current, resultTone = currentTone;
    vec2 previous = vec2(-1.0);
    bool found = false;
    // The motion view's depths: the point's distance along this camera's axis and along the
    // previous camera's (its clip w: the projection is perspective); 0 for the sky.
    float distance = 0.0, previousDistance = 0.0;
    float d = pixelDepth(pixel);
    vec2 centre = vec2(pixel) + 0.5;
    vec4 p = d > 0.0 ? vec4(viewPositionFromDepth(centre, d, frame.extent, frame.depthParams, frame.projParams), 1.0)
                     : vec4(viewPositionAtDistance(centre, 1.0, frame.extent, frame.projParams), 0.0);
    if (d > 0.0) distance = -p.z;
    if (params.blend.y > 0.0) {
        vec4 clip = params.reprojection * p;
        if (clip.w > kTemporalMinClipW) {
            previous = (clip.xy / clip.w * 0.5 + 0.5) * frame.extent.xy;
            found = all(greaterThanEqual(previous, vec2(0.0))) && all(lessThanEqual(previous, frame.extent.xy));
            if (d > 0.0) previousDistance = clip.w;
        }
    }
    if (found) {
        vec3 mean, sigma;
        neighbourhood(currentHdr, pixel, size, mean, sigma);
        vec3 h = fromYCoCg(clipToBox(toYCoCg(historyAt(history, previous, size)), mean, params.blend.z * sigma));
        float wc = params.blend.x / (1.0 + luma(max(current, vec3(0.0))));
        float wh = (1.0 - params.blend.x) / (1.0 + luma(max(h, vec3(0.0))));
        result = (current * wc + h * wh) / (wc + wh); // wc + wh > 0: alpha in (0, 1], luma >= 0
        // Display values are bounded already: a plain blend, no firefly weights.
        neighbourhood(currentDisplay, pixel, size, mean, sigma);
        vec3 t = fromYCoCg(clipToBox(toYCoCg(historyAt(historyDisplay, previous, size)), mean, params.blend.z * sigma));
        resultTone = mix(t, currentTone, params.blend.x);
    }
    if (params.blend.w != 0.0) {
        imageStore(outHistory, pixel, vec4(previous, found ? 1.0 : 0.0, found ? previousDistance : 0.0));
        imageStore(outDisplay, pixel, vec4(distance, 0.0, 0.0, 1.0));
        return;
    }
    imageStore(outHistory, pixel, vec4(result, 1.0));
    imageStore(outDisplay, pixel, vec4(resultTone, 1.0));
}
