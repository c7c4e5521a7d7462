#ifndef AGAA_SHADOW_GLSL
#define AGAA_SHADOW_GLSL
// Shadow-map visibility for the lighting passes (issue 8; paper section 3.5.3 for AGAA).
// Requires, defined by the includer: SHADOW_MAP_BINDING, SHADOW_CONSTANTS_BINDING (set 0).
// The map is an array with one D32 layer per shadowed light (shared/shadow.h); a tap is a
// depth comparison with the nearest texel (no hardware PCF: a tap is one binary visibility).
#include "common/depth.glsl"
#include "shared/shadow.h"
#include "shared/specialization.h"

layout(set = 0, binding = SHADOW_MAP_BINDING) uniform sampler2DArray shadowMap;
layout(set = 0, binding = SHADOW_CONSTANTS_BINDING) uniform Shadow { ShadowConstants shadow; };
const float kMinTangentLength = 1.0e-3; // view ray along the normal: no depth gradient in the plane
const float kMaxFootprintStretch = 16.0; // grazing surfaces: at most 16 m along g per metre of depth
// Taps per shading event (specialisation id 5, agaa/common/effects.h): 1..8.
layout(constant_id = kSpecShadowTaps) const uint kShadowTaps = 4u;

// The shadow-map layer of light i, or -1 when it casts none.
int shadowLayer(uint light) {
    // Unused entries hold kMaxLights, which no light index equals: a constant trip count.
    uvec4 match = uvec4(equal(shadow.lightIndex, uvec4(light)));
    if (match == uvec4(0u)) return -1;
    return match.x != 0u ? 0 : (match.y != 0u ? 1 : (match.z != 0u ? 2 : 3));
}

// 1 where the view-space point P is lit by the light of `layer`, 0 where occluded. Points
// outside the map's volume are lit (nothing was rendered there to occlude them).
float shadowTap(int layer, vec3 P) {
    vec4 c = shadow.viewToShadow[layer] * vec4(P, 1.0);
    if (c.w <= 0.0) return 1.0; // behind a spot light
    vec3 p = c.xyz / c.w;
    vec2 uv = p.xy * 0.5 + 0.5;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || p.z >= 1.0) return 1.0;
    // Nearest texel by integer fetch (no sampler filtering path: cheaper on lavapipe).
    ivec2 texel = min(ivec2(uv / shadow.params.y), ivec2(1.0 / shadow.params.y) - 1);
    float occluder = texelFetch(shadowMap, ivec3(texel, layer), 0).r;
    return p.z - shadow.params.z <= occluder ? 1.0 : 0.0;
}

// Receiver moved along its normal by ~1.5 texels (normal-offset bias against acne).
vec3 shadowReceiver(int layer, vec3 P, vec3 N) { return P + N * shadow.normalOffset[layer]; }

// Per-sample methods: one tap at the shading event's own position (its footprint is a point).
float shadowVisibilityPoint(uint light, vec3 P, vec3 N) {
    int layer = shadowLayer(light);
    return layer < 0 ? 1.0 : shadowTap(layer, shadowReceiver(layer, P, N));
}

// AGAA (paper section 3.5.3): the aggregate's footprint in its mean tangent plane (normal N).
// Its mean position P and depth standard deviation sigma give the "variance vector": the
// direction g in the tangent plane along which view depth changes fastest, scaled so that the
// footprint's depths have the aggregate's variance. Staying in the tangent plane keeps the taps
// on the surface (taps along the view ray would go under a slanted plane and shadow it). Across
// g, along b = N x g (the tangent direction of constant depth), it spans the aggregate's own
// width: `pixelSize` metres at P times aggregateWidth (common/depth.glsl), a whole pixel for an
// aggregate that covers one, half for one its clustering split in two (issue 14: across a whole
// pixel for every aggregate, and a footprint on a line where depth is flat, goal P8's one-surface
// pixels had 3x per-sample shading's error).
struct AggregateFootprint {
    vec3 g, b;    // unit tangent directions (zero where the view ray runs along N)
    float sigmaG; // standard deviation along g, metres
    float width;  // full width along b, metres
};

AggregateFootprint aggregateFootprint(vec3 P, vec3 N, float sigma, float pixelSize, vec3 screenSpread) {
    vec3 ray = normalize(P); // |P| >= znear > 0
    vec3 g = ray - N * dot(N, ray); // |g|: depth change per metre along g/|g|
    float glen = length(g);
    AggregateFootprint f;
    f.g = glen > kMinTangentLength ? g / glen : vec3(0.0);
    f.b = glen > kMinTangentLength ? cross(N, f.g) : vec3(0.0);
    // Metres along g per metre of depth, bounded: a surface seen edge-on has an unbounded footprint.
    float stretch = glen > kMinTangentLength ? min(1.0 / glen, kMaxFootprintStretch) : 0.0;
    f.width = pixelSize * aggregateWidth(f.b, screenSpread);
    // Along g: the depth spread in the tangent plane (a slanted plane's), or the samples' own
    // spread across the screen (a face-on plane has no depth spread), whichever is wider.
    f.sigmaG = max(sigma * stretch, pixelSize * aggregateWidth(f.g, screenSpread) / sqrt(12.0));
    return f;
}

// The statistical footprint's filtered visibility: T taps evenly along g over [-a, a],
// a = sigmaG sqrt(3 (T - 1) / (T + 1)), so that their spread along g has the aggregate's
// variance, and in an N-rooks pattern across the footprint's width along b.
float shadowVisibilityAggregate(uint light, vec3 P, vec3 N, float sigma, float pixelSize, vec3 screenSpread) {
    int layer = shadowLayer(light);
    if (layer < 0) return 1.0;
    vec3 base = shadowReceiver(layer, P, N);
    if (kShadowTaps <= 1u) return shadowTap(layer, base);
    AggregateFootprint f = aggregateFootprint(P, N, sigma, pixelSize, screenSpread);
    // T taps evenly over [-a, a] along g have variance a^2 (T + 1) / (3 (T - 1)): a sets it to sigmaG^2.
    const float T = float(kShadowTaps);
    float spread = f.sigmaG * sqrt(3.0 * (T - 1.0) / (T + 1.0));
    // Across, an N-rooks pattern: tap j in column (j step + 1) mod T, one tap per column of the
    // width (step coprime with T, near T / golden ratio, so neighbours along g sit apart across).
    const uint kRookStep[9] = uint[](1u, 1u, 1u, 2u, 3u, 3u, 5u, 4u, 5u);
    uint step = kRookStep[min(kShadowTaps, 8u)];
    float sum = 0.0;
    for (uint j = 0u; j < kShadowTaps; ++j) {
        float u = -1.0 + 2.0 * float(j) / (T - 1.0);
        float across = (float((j * step + 1u) % kShadowTaps) + 0.5) / T - 0.5;
        vec3 q = base + f.g * (u * spread) + f.b * (across * f.width);
        sum += shadowTap(layer, q);
    }
    return sum / float(kShadowTaps);
}

// The adaptive footprint's penumbra test (issue 14): taps at the four corners of the footprint's
// rectangle (half-widths sqrt(3) sigmaG along g, the rectangle of that variance, and width / 2
// along b) and at its centre. A straight shadow edge through the aggregate separates two corners,
// and a shadow strip narrower than the footprint shows at the centre when it crosses there.
// Returns the fraction lit: 0 or 1 where all five agree (the answer), in between where a shadow
// edge crosses (the caller then taps the aggregate's samples).
float shadowVisibilityAggregateCorners(uint light, vec3 P, vec3 N, float sigma, float pixelSize, vec3 screenSpread) {
    int layer = shadowLayer(light);
    if (layer < 0) return 1.0;
    vec3 base = shadowReceiver(layer, P, N);
    AggregateFootprint f = aggregateFootprint(P, N, sigma, pixelSize, screenSpread);
    vec3 alongG = f.g * (sqrt(3.0) * f.sigmaG), alongB = f.b * (0.5 * f.width);
    float sum = shadowTap(layer, base);
    sum += shadowTap(layer, base + alongG + alongB);
    sum += shadowTap(layer, base + alongG - alongB);
    sum += shadowTap(layer, base - alongG + alongB);
    sum += shadowTap(layer, base - alongG - alongB);
    return sum / float(kAdaptiveCornerTaps); // the five taps above (shared/shadow.h)
}
#endif
