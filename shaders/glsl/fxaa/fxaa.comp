#version 460
#extension GL_GOOGLE_include_directive : require
// FXAA 3.11, quality version (Lottes, "FXAA", NVIDIA white paper 2009, and the FXAA
// 3.11 release notes), as a compute post-process on the tone-mapped no-AA image.
// Written from the algorithm's description; the steps are numbered as in it:
//  1. luma of the 3x3 neighbourhood; local contrast test (early exit, pixel unchanged)
//  2. sub-pixel aliasing amount from the 3x3 lowpass
//  3. edge orientation (horizontal or vertical) from second differences
//  4. the edge's side: the neighbour across the edge with the larger gradient
//  5. end-of-edge search in both directions along the edge, with the preset's steps
//  6. blend towards the neighbour across the edge by the position along the edge
//     span (or the sub-pixel amount, whichever is larger)
// Work is in pixel units; every filtered luma read is a bilinear interpolation of
// per-texel lumas done here (clamp to edge), as FXAA's "luma in alpha" bilinear fetch
// would give, but exact and reproducible; the CPU twin (agaa/fxaa/fxaa_reference.cpp)
// does the same arithmetic in the same order.
#include "shared/fxaa.h"
#include "shared/specialization.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(constant_id = kSpecFxaaSearchSteps) const uint kSearchSteps = 12u;
layout(constant_id = kSpecFxaaStepTable + 0u) const float kStep0 = 1.0;
layout(constant_id = kSpecFxaaStepTable + 1u) const float kStep1 = 1.5;
layout(constant_id = kSpecFxaaStepTable + 2u) const float kStep2 = 2.0;
layout(constant_id = kSpecFxaaStepTable + 3u) const float kStep3 = 2.0;
layout(constant_id = kSpecFxaaStepTable + 4u) const float kStep4 = 2.0;
layout(constant_id = kSpecFxaaStepTable + 5u) const float kStep5 = 2.0;
layout(constant_id = kSpecFxaaStepTable + 6u) const float kStep6 = 2.0;
layout(constant_id = kSpecFxaaStepTable + 7u) const float kStep7 = 2.0;
layout(constant_id = kSpecFxaaStepTable + 8u) const float kStep8 = 2.0;
layout(constant_id = kSpecFxaaStepTable + 9u) const float kStep9 = 2.0;
layout(constant_id = kSpecFxaaStepTable + 10u) const float kStep10 = 4.0;
layout(constant_id = kSpecFxaaStepTable + 11u) const float kStep11 = 8.0;

layout(set = 0, binding = 0) uniform sampler2D inDisplay; // tone-mapped, linear [0,1]
layout(set = 0, binding = 1, rgba32f) uniform writeonly image2D outDisplay;
layout(push_constant) uniform Push { FxaaParams params; };

ivec2 gSize;

vec3 colorAt(ivec2 p) { return texelFetch(inDisplay, clamp(p, ivec2(0), gSize - 1), 0).rgb; }

// Perceptual luma: Rec. 601 weights on the linear tone-mapped colour, then sqrt as the
// gamma-2 approximation FXAA's documentation recommends. Inputs are >= 0 (tone-mapped).
float lumaAt(ivec2 p) { return sqrt(max(dot(colorAt(p), vec3(0.299, 0.587, 0.114)), 0.0)); }

float lerp1(float a, float b, float t) { return a + (b - a) * t; }

// Bilinear luma at a pixel-space position (texel centres at integer + 0.5).
float lumaBilinear(vec2 pos) {
    vec2 f = pos - 0.5;
    vec2 i = floor(f);
    vec2 w = f - i;
    ivec2 p = ivec2(i);
    float top = lerp1(lumaAt(p), lumaAt(p + ivec2(1, 0)), w.x);
    float bottom = lerp1(lumaAt(p + ivec2(0, 1)), lumaAt(p + ivec2(1, 1)), w.x);
    return lerp1(top, bottom, w.y);
}

float searchStep(uint i) {
    const float steps[12] = float[](kStep0, kStep1, kStep2, kStep3, kStep4, kStep5, kStep6, kStep7, kStep8, kStep9,
                                    kStep10, kStep11);
    return steps[i];
}

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    gSize = textureSize(inDisplay, 0);
    if (any(greaterThanEqual(pixel, gSize))) return;
    float subpixAmount = params.thresholds.x, edgeThreshold = params.thresholds.y;
    float edgeThresholdMin = params.thresholds.z;
    vec3 colorM = colorAt(pixel);

    // 1. Local contrast over the 4-neighbourhood; below the threshold: unchanged, bit for bit.
    float lumaM = lumaAt(pixel);
    float lumaN = lumaAt(pixel + ivec2(0, -1)), lumaS = lumaAt(pixel + ivec2(0, 1));
    float lumaW = lumaAt(pixel + ivec2(-1, 0)), lumaE = lumaAt(pixel + ivec2(1, 0));
    float rangeMax = max(max(lumaN, lumaW), max(lumaE, max(lumaS, lumaM)));
    float rangeMin = min(min(lumaN, lumaW), min(lumaE, min(lumaS, lumaM)));
    float range = rangeMax - rangeMin;
    if (range < max(edgeThresholdMin, rangeMax * edgeThreshold)) {
        imageStore(outDisplay, pixel, vec4(colorM, 1.0));
        return;
    }
    float lumaNW = lumaAt(pixel + ivec2(-1, -1)), lumaNE = lumaAt(pixel + ivec2(1, -1));
    float lumaSW = lumaAt(pixel + ivec2(-1, 1)), lumaSE = lumaAt(pixel + ivec2(1, 1));

    // 2. Sub-pixel aliasing: |lowpass - centre| / range. range >= edgeThresholdMin > 0
    //    here (the early exit above), so the division is safe.
    float lowpass = (2.0 * (lumaN + lumaS + lumaW + lumaE) + (lumaNW + lumaNE + lumaSW + lumaSE)) / 12.0;
    float subpixC = clamp(abs(lowpass - lumaM) / range, 0.0, 1.0);
    float subpixF = (-2.0 * subpixC + 3.0) * subpixC * subpixC; // smoothstep
    float subpixBlend = subpixF * subpixF * subpixAmount;

    // 3. Orientation: second differences across rows vs across columns, centre row weighted 2.
    float edgeHorz = abs(-2.0 * lumaW + lumaNW + lumaSW) + 2.0 * abs(-2.0 * lumaM + lumaN + lumaS) +
                     abs(-2.0 * lumaE + lumaNE + lumaSE);
    float edgeVert = abs(-2.0 * lumaN + lumaNW + lumaNE) + 2.0 * abs(-2.0 * lumaM + lumaW + lumaE) +
                     abs(-2.0 * lumaS + lumaSW + lumaSE);
    bool horzSpan = edgeHorz >= edgeVert; // a horizontal edge: step across in y, search along x
    ivec2 across = horzSpan ? ivec2(0, 1) : ivec2(1, 0);
    vec2 along = horzSpan ? vec2(1.0, 0.0) : vec2(0.0, 1.0);

    // 4. Which side: the neighbour across the edge (negative or positive) with the larger gradient.
    float luma1 = horzSpan ? lumaN : lumaW; // negative side
    float luma2 = horzSpan ? lumaS : lumaE; // positive side
    float gradient1 = luma1 - lumaM, gradient2 = luma2 - lumaM;
    bool negativeSide = abs(gradient1) >= abs(gradient2);
    float gradientScaled = 0.25 * max(abs(gradient1), abs(gradient2));
    float lengthSign = negativeSide ? -1.0 : 1.0;
    float lumaLocalAverage = 0.5 * ((negativeSide ? luma1 : luma2) + lumaM);

    // 5. End-of-edge search from the point half a pixel towards that side, along the edge.
    vec2 posB = vec2(pixel) + 0.5 + 0.5 * lengthSign * vec2(across);
    vec2 posN = posB - along * searchStep(0u);
    vec2 posP = posB + along * searchStep(0u);
    float lumaEndN = lumaBilinear(posN) - lumaLocalAverage;
    float lumaEndP = lumaBilinear(posP) - lumaLocalAverage;
    bool doneN = abs(lumaEndN) >= gradientScaled;
    bool doneP = abs(lumaEndP) >= gradientScaled;
    for (uint i = 1u; i < kSearchSteps; ++i) {
        if (!doneN) posN -= along * searchStep(i);
        if (!doneP) posP += along * searchStep(i);
        // The last step only extrapolates: an edge not ended by then is taken to end there.
        if ((doneN && doneP) || i + 1u == kSearchSteps) break;
        if (!doneN) lumaEndN = lumaBilinear(posN) - lumaLocalAverage;
        if (!doneP) lumaEndP = lumaBilinear(posP) - lumaLocalAverage;
        doneN = abs(lumaEndN) >= gradientScaled;
        doneP = abs(lumaEndP) >= gradientScaled;
    }

    // 6. Blend: pixels nearer an end of the span move further across the edge, if that end
    //    turns the same way as this pixel (lumaEnd's sign vs the centre's); span >= 2 steps0 > 0.
    vec2 centre = vec2(pixel) + 0.5;
    float dstN = horzSpan ? centre.x - posN.x : centre.y - posN.y;
    float dstP = horzSpan ? posP.x - centre.x : posP.y - centre.y;
    bool centreBelow = lumaM - lumaLocalAverage < 0.0;
    bool nearerN = dstN < dstP;
    bool goodSpan = ((nearerN ? lumaEndN : lumaEndP) < 0.0) != centreBelow;
    float pixelOffset = -min(dstN, dstP) / (dstN + dstP) + 0.5;
#ifdef AGAA_TEST_PERTURB_METHODS
    goodSpan = false; // tools/perturb-test.sh: the end-of-edge search's blend lost
#endif
    float offset = max(goodSpan ? pixelOffset : 0.0, subpixBlend);
    ivec2 neighbour = pixel + (negativeSide ? -across : across);
    vec3 color = colorM + (colorAt(neighbour) - colorM) * offset;
    imageStore(outDisplay, pixel, vec4(color, 1.0));
}
