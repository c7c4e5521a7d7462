#ifndef AGAA_DEPTH_GLSL
#define AGAA_DEPTH_GLSL
#include "common/epsilon.glsl"
// Reversed Z with a finite far plane: d(t) = n (f - t) / (t (f - n)) maps view
// distance t in [n, f] to depth d in [1, 0]. Cleared depth 0 is the far plane:
// such a sample is sky. Inverse: t = n f / (d (f - n) + n); the denominator is
// >= n > 0 for d >= 0, so it needs no guard.
float viewDistanceFromDepth(float d, float znear, float zfar) {
    return znear * zfar / (d * (zfar - znear) + znear);
}

bool isSky(float d) { return d <= 0.0; }

// Height in metres of one pixel's footprint at view distance t: 2 t / (|p11| height). |p11|:
// the Vulkan projection flips y, so proj[1][1] (projParams.y) is negative (issue 14: without the
// abs() the shadow footprint's pixel offsets pointed the other way, 1/8 px off centre).
float pixelFootprint(float t, vec4 extent, vec4 projParams) {
    return t * 2.0 * extent.w / abs(projParams.y);
}

// An aggregate's extent along the view-space direction d, in pixels (the shadow footprint's,
// common/shadow.glsl): its samples' sub-pixel positions have covariance S = (sxx, sxy, syy) in
// pixel^2, and a uniform spread of variance v spans sqrt(12 v): 1 for a whole pixel, 1/2 across
// a pixel its clustering split in two. d's screen direction is its xy (the footprint's
// directions lie in the tangent plane, off the view ray); guard kMinScreenDirection2: d along the
// ray has none, and the whole pixel is used. Cancellation in S (v < 0) gives 0.
float aggregateWidth(vec3 d, vec3 S) {
    float l2 = dot(d.xy, d.xy);
    if (l2 <= kMinScreenDirection2) return 1.0;
    float v = (d.x * d.x * S.x + 2.0 * d.x * d.y * S.y + d.y * d.y * S.z) / l2;
    return sqrt(12.0 * max(v, 0.0));
}

// Near mirrors (issue 14): how far one view direction fails to stand for an aggregate's samples',
// 0 (it does) to 1 (each sample's own view direction). At a fixed light the half vector moves half
// as far as V: over a footprint of sub-pixel covariance S (pixel^2), theta radians a pixel, its
// slope variance per axis is theta^2 (sxx + syy) / 8, against a GGX lobe's alpha^2 / 2. The weight
// ramps from their ratio rho = kViewFootprintLobeRatio to twice it: a smooth switch, so images do
// not pop and a double-precision twin agrees across it. alpha floored at kMinGgxAlpha.
float viewFootprintWeight(float theta, vec3 S, float alpha) {
    float a = max(alpha, kMinGgxAlpha);
    float rho = theta * theta * max(S.x + S.z, 0.0) / (4.0 * a * a);
    return clamp(rho / kViewFootprintLobeRatio - 1.0, 0.0, 1.0);
}

// The view ray's slope numerator at pixel-space position pixelPos: its NDC, plus the projection's
// off-axis terms (projParams.zw, 0 except in a tile of a larger view), so that x_view = r.x t / P00.
vec2 viewRayNdc(vec2 pixelPos, vec4 extent, vec4 projParams) {
    return pixelPos * extent.zw * 2.0 - 1.0 + projParams.zw;
}

// View-space point at view distance t on the ray through pixel-space position pixelPos.
vec3 viewPositionAtDistance(vec2 pixelPos, float t, vec4 extent, vec4 projParams) {
    vec2 ndc = viewRayNdc(pixelPos, extent, projParams);
    return vec3(ndc.x * t / projParams.x, ndc.y * t / projParams.y, -t);
}

// View-space position of a point at pixel-space position (pixel + subpixel) with depth d.
vec3 viewPositionFromDepth(vec2 pixelPos, float d, vec4 extent, vec4 depthParams, vec4 projParams) {
    return viewPositionAtDistance(pixelPos, viewDistanceFromDepth(d, depthParams.x, depthParams.y), extent,
                                  projParams);
}
#endif
