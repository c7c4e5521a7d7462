#ifndef AGAA_SRGB_GLSL
#define AGAA_SRGB_GLSL
// The sRGB transfer function (IEC 61966-2-1), linear to encoded, evaluated by the shader rather
// than by an *_SRGB attachment. lavapipe's fixed-function encode (Mesa gallivm
// lp_bld_format_srgb.c, lp_build_linear_to_srgb) builds x^0.5 and x^0.375 from rsqrtps estimates
// where the vector width has them, and from sqrt where it does not: the estimate's bits differ
// between x86 implementations, so the same frame stored different albedo bytes on different
// CPUs. The G-buffer's albedo target is therefore UNORM, written through srgbEncode, and sampled
// through an sRGB view.
// The CPU reference is the standard's piecewise curve in double, tests/hard/shader_math_cases.cpp
// (srgbEncode), driven through shaders/glsl/tests/shader_math.comp (kOpSrgbEncode).
const float kSrgbLinearCutoff = 0.0031308; // below it the curve is the linear toe
const float kSrgbToeSlope = 12.92;
const float kSrgbScale = 1.055;
const float kSrgbOffset = 0.055;
const float kSrgbExponent = 1.0 / 2.4;

vec3 srgbEncode(vec3 linear) {
    // The clamp is the attachment's own (UNORM stores [0, 1]); it also keeps pow() off negatives.
    vec3 x = clamp(linear, 0.0, 1.0);
    vec3 toe = kSrgbToeSlope * x;
    vec3 curve = kSrgbScale * pow(x, vec3(kSrgbExponent)) - kSrgbOffset;
    return mix(curve, toe, lessThanEqual(x, vec3(kSrgbLinearCutoff)));
}

// The standard's inverse, encoded to linear, for values the shader stored encoded itself (AGAA's
// kept per-sample material, shared/sample_material.h); an sRGB view decodes the G-buffer's. Its
// CPU reference: tests/hard/shader_math_cases.cpp (srgbDecode, kOpSrgbDecode).
const float kSrgbEncodedCutoff = kSrgbLinearCutoff * kSrgbToeSlope; // 0.04045

vec3 srgbDecode(vec3 encoded) {
    vec3 x = clamp(encoded, 0.0, 1.0);
    vec3 toe = x / kSrgbToeSlope;
    vec3 curve = pow((x + kSrgbOffset) / kSrgbScale, vec3(1.0 / kSrgbExponent));
    return mix(curve, toe, lessThanEqual(x, vec3(kSrgbEncodedCutoff)));
}
#endif
