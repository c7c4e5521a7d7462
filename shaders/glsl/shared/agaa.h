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
// Per aggregate 5 words (20 bytes):
//   w0: bits 26..31 sample count; bits 0..25 sum of Toksvig normal x
//   w1, w2: sums of Toksvig normal y, z
//   w3: albedo R (bits 0..15) | albedo G (bits 16..31)
//   w4: albedo B (bits 0..15) | metallic (bits 16..31)
// Each sample contributes round(v * scale) with v in [0, 1] (normals offset-binary: (x+1)/2).
// No overflow at n = 32, c = 1 (every sample in one aggregate, every value at its maximum):
//   normal:  32 * (2^21 - 1) = 67108832 < 2^26        (fits below the count bits)
//   16-bit:  32 * (2^11 - 1) = 65504    < 2^16        (no carry into the upper field)
//   count:   32                         < 2^6
// tests/agaa/test_fixed_point.cpp checks these bounds and the round trip.
SHARED_CONST kAggregateWords = 5u;
SHARED_CONST kNormalBits = 21u;
SHARED_CONST kNormalScale = 2097151u; // 2^21 - 1
SHARED_CONST kNormalFieldMask = 67108863u; // 2^26 - 1
SHARED_CONST kCountShift = 26u;
SHARED_CONST kUnormBits = 11u;
SHARED_CONST kUnormScale = 2047u; // 2^11 - 1
SHARED_CONST kMaxAggregates = 4u;

struct AgaaConstants {
    vec4 cosSinTheta[kNormalAngleLevels]; // x cos(theta_q), y sin(theta_q); zw unused
    vec4 cosSinPhi[kNormalAngleLevels]; // x cos(phi_q), y sin(phi_q)
    // x 1/k (k: characteristic length, metres), y t (seed threshold, Equation 1 units),
    // z n*f, w f-n (clip planes, so positions need no division by constants the CPU rounds differently)
    vec4 clustering;
    // x 2/width, y 2/height, z proj[0][0], w proj[1][1]
    vec4 ndcParams;
    // x aggregates c, y metadata bits per sample b, z metadata words per pixel, w samples n
    uvec4 shape;
    // x Toksvig reference exponent s_max (Blinn-Phong), y alpha_min, z alpha_max; w unused
    vec4 toksvig;
    // x debug view (0 none, 1 aggregates), y position mode (0 mean of sample positions, 1 UE4 pixel centre), z has emissive
    uvec4 options;
};

SHARED_END
#endif
