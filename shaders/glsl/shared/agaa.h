#ifndef AGAA_SHARED_AGAA_H
#define AGAA_SHARED_AGAA_H
#include "shared/glsl_cpp.h"

SHARED_BEGIN

// ---- Face normals of the visibility prepass (paper section 3.2) -------------------------
// Two 8-bit spherical angles over the hemisphere around the pixel centre's direction to the
// camera: theta in [0, pi/2] in 255 steps, phi in [-pi, pi) in 256 steps. Decoding goes through
// tables computed once on the CPU, so the GPU clustering and its CPU reference read the same
// floats (no transcendental functions in the kernel).
SHARED_CONST kNormalAngleLevels = 256u;

// ---- AG-buffer accumulation (fixed point, paper figure 7 adapted to integer atomics) ----
// 6 words (24 bytes) per aggregate in either normal-distribution layout (AgaaConstants
// options.w, agaa/aggregate/agaa_constants.h AggregateNdf); at c = 1, 3 words per pixel more
// after the records (shared/ag_buffer.h kOffLayerWords). Each sample contributes
// round(v * scale) with v in [0, 1]; the k samples a fragment routes to an aggregate add k times
// that, so fields only ever sum n values of at most `scale`.
//
// Toksvig (paper section 3.5.2):
//   w0: bits 26..31 sample count; bits 0..25 sum of Toksvig normal x (offset-binary (x+1)/2)
//   w1, w2: sums of Toksvig normal y, z
//   w3: albedo R (bits 0..15) | albedo G (bits 16..31)
//   w4: albedo B (bits 0..15) | metallic (bits 16..31)
//   The normal's scales depend on n (toksvigScaleX, toksvigScaleYZ in shared/ag_buffer.h): the
//   largest that n values at the maximum never carry out of their field, and at most
//   kToksvigMaxScale = 2^23 - 1, below which fp32 quantisation (floor(v scale + 0.5)) never
//   exceeds the scale. n <= 8: 23 bits for x, y and z; n = 16: x 22; n = 32: x 21, y and z 23
//   (issue 14: near mirrors the Toksvig length is within 1e-5 of 1, and the fixed 21 bits of
//   before gave 2 to 15 % alpha error at alpha 0.002 to 0.005).
//   No overflow at n = 32, c = 1 (every sample in one aggregate, every value at its maximum):
//     normal x: 32 * (2^21 - 1) = 67108832 < 2^26     (fits below the count bits)
//     normal y, z: 32 * (2^23 - 1)         < 2^28
//     16-bit:  32 * (2^11 - 1) = 65504    < 2^16        (no carry into the upper field)
//     count:   32                         < 2^6
//
// SGGX (shared/sggx.h): the six entries of the sample's SGGX matrix, 16-bit fields whose scale
// depends on n (unitScale: floor((2^bits - 1) / n), so n values at the maximum never carry):
//   w0: S_xx (bits 0..15) | S_yy (16..31)      diagonal entries in [0, 1] as they are
//   w1: S_zz | S_xy                            off-diagonal entries in [-1/2, 1/2], stored + 1/2
//   w2: S_xz | S_yz
//   w3: albedo R | albedo G                    (16-bit)
//   w4: albedo B (bits 0..15) | metallic (bits 16..25, 10-bit) | sample count (bits 26..31)
//   Per-sample precision: 13 bits at n = 8, 11 bits at n = 32 (the Toksvig layout's albedo
//   precision); metallic 7 bits at n = 8, 5 bits at n = 32 (glTF metallic is mostly 0 or 1).
//
// Both layouts, w5: the sum of the samples' own GGX alpha (at most the BRDF's kMaxGgxAlpha, not
// floored at its kMinGgxAlpha) at the fixed scale 2^26 - 1: the two-point resolve's material lobe
// (shared/sggx.h sggxSpikeRatio; the lighting pass floors the mean), which the filtered normal
// distribution no longer holds, and a near-mirror's environment level (issue 14). No overflow at n = 32:
// 32 * 2^26 = 2^31 < 2^32.
// tests/agaa/test_fixed_point.cpp checks both layouts' bounds and round trips.
SHARED_CONST kAggregateWords = 6u;
SHARED_CONST kNormalBits = 21u;
SHARED_CONST kNormalScale = 2097151u;      // 2^21 - 1: the x scale at n = 32
SHARED_CONST kToksvigMaxScale = 8388607u;  // 2^23 - 1
SHARED_CONST kNormalFieldMask = 67108863u; // 2^26 - 1
SHARED_CONST kCountShift = 26u;
SHARED_CONST kUnormBits = 11u;
SHARED_CONST kUnormScale = 2047u; // 2^11 - 1
SHARED_CONST kSggxFieldBits = 16u;
SHARED_CONST kSggxMetallicBits = 10u;
SHARED_CONST kMaterialAlphaScale = 67108863u; // 2^26 - 1
SHARED_CONST kNdfToksvig = 0u;
SHARED_CONST kNdfSggx = 1u;
// One fragment's quantised attributes (either layout): q[0..5] the normal fields (Toksvig x, y, z
// in 0..2; SGGX xx, yy, zz, xy, xz, yz), q[6..8] albedo, q[9] metallic, q[10] material alpha.
SHARED_CONST kQuantizedFields = 11u;
SHARED_CONST kMaxAggregates = 4u;

struct AgaaConstants {
    vec4 cosSinTheta[kNormalAngleLevels]; // x cos(theta_q), y sin(theta_q); zw unused
    vec4 cosSinPhi[kNormalAngleLevels];   // x cos(phi_q), y sin(phi_q)
    // x 1/k (k: characteristic length, metres), y t (seed threshold, Equation 1 units),
    // z n*f, w f-n (clip planes, so positions need no division by constants the CPU rounds differently)
    vec4 clustering;
    // x 2/width, y 2/height, z proj[0][0], w proj[1][1]
    vec4 ndcParams;
    // x aggregates c, y metadata bits per sample b, z metadata words per pixel, w samples n
    uvec4 shape;
    // x Toksvig reference exponent s_max (Blinn-Phong), y alpha_min, z alpha_max; w unused
    vec4 toksvig;
    // x debug view (0 none, 1 aggregates), y position mode (0 mean of sample positions, 1 UE4 pixel centre),
    // z has emissive, w normal distribution (kNdfToksvig, kNdfSggx)
    uvec4 options;
    // x clustering distance (kDistancePosition, kDistancePlane), y generation routing (0 per sample,
    // 1 per fragment); z, w unused. The shaders take both as specialisation constants; the CPU
    // references read them here.
    uvec4 modes;
    // x the shading rate's tolerance (AggregateSettings::tolerance; agaa/lighting/shading_rate.glsl)
    // and y its alias limit (AggregateSettings::aliasLimit; the largest float for none): a pixel
    // whose estimate lies in [x, y) is shaded per sample, and so is one above y whose resolved,
    // exposed radiance reaches z (kAliasedSaturation), or, at c = 1, whose aggregate has its mean
    // normal in a gap of w (kMeanNormalGap) between its members' normals.
    vec4 shadingRate;
};

SHARED_END
#endif
