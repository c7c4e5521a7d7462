#ifndef AGAA_SHARED_AG_BUFFER_H
#define AGAA_SHARED_AG_BUFFER_H
// The AG-buffer's fixed-point encoding (layout in shared/agaa.h), shared by the generation
// kernel, the lighting pass and their CPU twins (agaa/aggregate/ag_buffer.cpp).
#include "shared/agaa.h"

SHARED_BEGIN

// round(v * scale) for v clamped to [0, 1]; NaN maps to 0 (the comparisons are false).
inline_fn uint quantizeUnit(float v, uint scale) {
    float c = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
    return uint(floor(c * float(scale) + 0.5f));
}

// Normal components in [-1, 1] are stored offset-binary: (x + 1) / 2.
inline_fn uint quantizeSigned(float x, uint scale) {
    return quantizeUnit(x * 0.5f + 0.5f, scale);
}

// Mean of k samples' offset-binary values back to [-1, 1]. k >= 1 (callers skip empty aggregates).
inline_fn float meanSigned(uint sum, uint k, uint scale) {
    return (float(sum) / (float(k) * float(scale))) * 2.0f - 1.0f;
}

inline_fn float meanUnit(uint sum, uint k, uint scale) {
    return float(sum) / (float(k) * float(scale));
}

// Toksvig length that encodes GGX alpha as normal variance ("roughness injected as extra
// variance", DESIGN section 4). With s = 2/alpha^2 - 2 the Blinn-Phong exponent and smax the
// exponent of alpha_min, the length L solves f(L) smax = s for the Toksvig factor
// f(L) = L / (L + smax (1 - L)):  L = s smax / (smax - s + s smax).
// alpha is clamped to [alphaMin, alphaMax] (the BRDF's range), so s is in [smin, smax] with
// smin > 0: every sample keeps a direction; the denominator is >= smax > 0.
inline_fn float toksvigLength(float alpha, float smax, float alphaMin, float alphaMax) {
    float a = alpha > alphaMin ? (alpha < alphaMax ? alpha : alphaMax) : alphaMin;
    float s = 2.0f / (a * a) - 2.0f;
    s = s > 0.0f ? (s < smax ? s : smax) : 0.0f;
    return (s * smax) / (smax - s + s * smax);
}

// Filtered GGX alpha from a Toksvig vector's length (paper section 3.5.2, steps 2-4):
// f = |N| / (|N| + s (1 - |N|)), s' = f s, alpha' = sqrt(2 / (s' + 2)), with s = smax since the
// material roughness is already inside |N|. |N| is clamped to [0, 1] (quantisation can exceed 1);
// the denominator is then >= min(1, smax) > 0, and s' + 2 >= 2.
inline_fn float filteredAlpha(float toksvigLen, float smax) {
    float len = toksvigLen > 0.0f ? (toksvigLen < 1.0f ? toksvigLen : 1.0f) : 0.0f;
    float f = len / (len + smax * (1.0f - len));
    float s = f * smax;
    return sqrt(2.0f / (s + 2.0f));
}

// Largest per-sample value of a `bits`-wide field that n samples can add without a carry out of
// the field: floor((2^bits - 1) / n). n >= 1.
inline_fn uint unitScale(uint bits, uint n) {
    return ((1u << bits) - 1u) / n;
}

// The Toksvig normal's per-sample scales at n samples (layout in shared/agaa.h): x shares its word
// with the count (26 bits), y and z have 32; both at most kToksvigMaxScale. n >= 1.
inline_fn uint toksvigScaleX(uint n) {
    uint s = kNormalFieldMask / n;
    return s < kToksvigMaxScale ? s : kToksvigMaxScale;
}
inline_fn uint toksvigScaleYZ(uint n) {
    uint s = 4294967295u / n;
    return s < kToksvigMaxScale ? s : kToksvigMaxScale;
}

struct AgQuantized {
    uint q[kQuantizedFields];
};

// What k samples of one fragment add to word w of their aggregate (layouts in shared/agaa.h).
// The generation pass adds it with atomicAdd; the CPU replay (tests/agaa) with +=.
inline_fn uint aggregateIncrement(uint ndf, uint w, uint k, AgQuantized f) {
    if (w == 5u) return k * f.q[10]; // the material alpha, both layouts
    if (ndf == kNdfSggx) {
        if (w == 4u) return k * f.q[8] + ((k * f.q[9]) << 16u) + (k << kCountShift);
        uint lo = w < 3u ? f.q[2u * w] : f.q[6];
        uint hi = w < 3u ? f.q[2u * w + 1u] : f.q[7];
        return k * lo + ((k * hi) << 16u);
    }
    if (w == 0u) return (k << kCountShift) + k * f.q[0];
    if (w < 3u) return k * f.q[w];
    if (w == 3u) return k * f.q[6] + ((k * f.q[7]) << 16u);
    return k * f.q[8] + ((k * f.q[9]) << 16u);
}

// c = 1, samples routed per sample (issue 14): after the pixels' aggregate records, kOffLayerWords
// per pixel sum the off-layer samples' diffuse colour, albedo (1 - metallic), their shading
// normals, offset to (N + 1) / 2, their specular colour F0 = mix(0.04, albedo, metallic) and their
// material alpha (roughness^2): r | g << 16, b | nx << 16, ny | nz << 16, F0r | F0g << 16,
// F0b | alpha << 16, 16-bit fields of scale unitScale(16, n) (n samples at 1 never carry). The
// lighting pass resolves those samples as a surface of their own: Lambert of that colour under the
// irradiance through their mean normal and its spread, and GGX of that F0 through the same normal
// with the alpha Toksvig filters from its spread (agaa/lighting.comp offLayerLight); none of it
// mixes into the aggregate's fields, whose albedo and metallic the BRDF is bilinear in.
SHARED_CONST kOffLayerWords = 5u;
SHARED_CONST kOffLayerFieldBits = 16u;

// Words of the AG-buffer for `pixels` pixels at c aggregates.
inline_fn uint agBufferWords(uint pixels, uint c) {
    return pixels * (c * kAggregateWords + (c == 1u ? kOffLayerWords : 0u));
}

// First off-layer word of pixel p (c = 1).
inline_fn uint offLayerWord(uint pixels, uint p) {
    return pixels * kAggregateWords + p * kOffLayerWords;
}

// Samples accumulated into an aggregate, from its first and last words.
inline_fn uint aggregateSampleCount(uint ndf, uint w0, uint w4) {
    return (ndf == kNdfSggx ? w4 : w0) >> kCountShift;
}

SHARED_END
#endif
