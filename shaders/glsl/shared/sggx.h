#ifndef AGAA_SHARED_SGGX_H
#define AGAA_SHARED_SGGX_H
// The SGGX normal distribution of an aggregate (Heitz et al. 2015; paper sections 3.3 and 5.1.3,
// seed 004), shared by the lighting pass and its CPU twin (tests/hard/shader_math_cases.cpp).
// Each sample adds its GGX lobe as the SGGX matrix S = (1 - a^2) n n^T + a^2 I (eigenvalue 1
// along its shading normal n, a^2 across it); the aggregate's matrix is the mean of its samples'
// (linear, so it accumulates with the same fixed-point atomics as the other attributes). Shading
// reads the mean back as an anisotropic GGX surface: normal = the eigenvector of the largest
// eigenvalue (turned towards the viewer), alphas sqrt(lambda_t / lambda_n) and
// sqrt(lambda_b / lambda_n) along the other two. A flat pixel gives back (n, a, a) exactly; the
// samples of a thin tube spread along one axis only, which the isotropic Toksvig lobe cannot
// represent (the paper's metal-rod case).
#include "shared/glsl_cpp.h"

SHARED_BEGIN

// The normal's eigenvector by repeated squaring (power iteration in powers of two): S^(2^k),
// renormalised by its trace at every step, is lambda1's projector plus terms of relative size
// (lambda2 / lambda1)^(2^k). Where lambda2 nearly ties lambda1 (a tube seen side on) that leaves
// a mix of the two directions, which one rotation between the normal and the tangent then takes
// out (sggxLobe). Five 3x3 products and two closed-form 2x2 problems replace the cyclic Jacobi
// sweeps, whose rotations (a division and two roots each, three sweeps on most means) were two
// thirds of SGGX's walk on lavapipe (issue 49, docs/decisions/aggregate-cost.md, seventh session).
SHARED_CONST kSggxPowerSquarings = 5u;

struct SggxLobe {
    vec3 normal;    // unit, on the viewer's side
    vec3 tangent;   // unit, the axis of the larger alpha
    vec3 bitangent; // normal x tangent
    float alphaT;   // GGX alpha along the tangent (>= alphaB), unclamped
    float alphaB;
};

// The symmetric 2x2 [[a, b], [b, d]]: its eigenvalues, and the unit eigenvector (c, s) of the
// larger one, in the form without cancellation: (larger - d, b) or (b, larger - a). Where the two
// agree to rounding (squared length at or below `degenerate`) every vector is one: (1, 0).
struct SggxEigenPair {
    float c, s;
    float larger, smaller;
};

inline_fn SggxEigenPair sggxEigenPair(float a, float b, float d, float degenerate) {
    float halfGap = 0.5f * (a - d);
    float root = sqrt(halfGap * halfGap + b * b);
    float x = halfGap >= 0.0f ? halfGap + root : b;
    float y = halfGap >= 0.0f ? b : root - halfGap;
    float length2 = x * x + y * y;
    float scale = length2 > degenerate ? 1.0f / sqrt(length2) : 0.0f;
    SggxEigenPair pair;
    pair.c = length2 > degenerate ? x * scale : 1.0f;
    pair.s = y * scale;
    pair.larger = 0.5f * (a + d) + root;
    pair.smaller = 0.5f * (a + d) - root;
    return pair;
}

// The eigen-decomposition of the symmetric S without a loop that ends on convergence, a rotation
// angle or a dynamic index: the same work for every mean.
//  1. The normal by repeated squaring (kSggxPowerSquarings).
//  2. The tangent and bitangent: the eigenvectors of S restricted to the plane across it.
//  3. One rotation between the normal and the tangent, which zeroes what the squarings left of
//     their coupling; the larger of the two is the normal.
// Guards: `degenerate` floors the traces the squarings divide by (only a zero matrix reaches it)
// and is the squared length below which a vector has no direction (sggxEigenPair; the normal of a
// zero matrix is then V); the normal's eigenvalue is floored at eigenvalueFloor (a valid mean has
// trace >= 1, so its largest eigenvalue is >= 1/3; the floor only meets corrupt input).
inline_fn SggxLobe sggxLobe(float sxx, float syy, float szz, float sxy, float sxz, float syz, vec3 V,
                            float degenerate, float eigenvalueFloor) {
    mat3 A = mat3(sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz);
    float trace = sxx + syy + szz;
    mat3 P = A * (1.0f / (trace > degenerate ? trace : degenerate));
    for (uint k = 0u; k < kSggxPowerSquarings; ++k) {
        P = P * P; // symmetric: its trace is the sum of its squared eigenvalues
        float t = P[0][0] + P[1][1] + P[2][2];
        P = P * (1.0f / (t > degenerate ? t : degenerate));
    }
    // The projector's column along the axis the normal leans on most (its largest diagonal entry,
    // >= 1/3 of the trace), by constant indices: lavapipe keeps a dynamically indexed matrix in
    // memory.
    vec3 column =
        P[0][0] >= P[1][1] ? (P[0][0] >= P[2][2] ? P[0] : P[2]) : (P[1][1] >= P[2][2] ? P[1] : P[2]);
    float columnLength2 = dot(column, column);
    vec3 N = columnLength2 > degenerate ? column * (1.0f / sqrt(columnLength2)) : V;
    // 2. An orthonormal pair across N: N x the coordinate axis N leans on least (|N x e| >= sqrt(2/3)).
    vec3 an = vec3(abs(N.x), abs(N.y), abs(N.z));
    vec3 axis = an.x <= an.y && an.x <= an.z
                    ? vec3(1.0f, 0.0f, 0.0f)
                    : (an.y <= an.z ? vec3(0.0f, 1.0f, 0.0f) : vec3(0.0f, 0.0f, 1.0f));
    vec3 u = cross(N, axis);
    u = u * (1.0f / sqrt(dot(u, u)));
    vec3 w = cross(N, u);
    vec3 Au = A * u;
    SggxEigenPair plane = sggxEigenPair(dot(u, Au), dot(w, Au), dot(w, A * w), degenerate);
    vec3 T = u * plane.c + w * plane.s;
    // 3. The (N, T) rotation.
    vec3 AN = A * N;
    SggxEigenPair top = sggxEigenPair(dot(N, AN), dot(T, AN), dot(T, A * T), degenerate);
    vec3 normal = N * top.c + T * top.s;
    T = T * top.c - N * top.s;
    // The bitangent's eigenvalue is the plane's smaller; a near tie of the two tangent eigenvalues
    // can leave the rotated tangent's below it: the tangent is the larger.
    bool swap = top.smaller < plane.smaller;
    vec3 B = u * (-plane.s) + w * plane.c;
    float lT = swap ? plane.smaller : top.smaller;
    float lB = swap ? top.smaller : plane.smaller;
    SggxLobe lobe;
    lobe.normal = dot(normal, V) >= 0.0f ? normal : -normal;
    lobe.tangent = swap ? B : T;
    lobe.bitangent = cross(lobe.normal, lobe.tangent);
    float ln = top.larger > eigenvalueFloor ? top.larger : eigenvalueFloor;
    // Rounding can leave a tangent eigenvalue slightly negative: clamp before the sqrt.
    lobe.alphaT = sqrt((lT > 0.0f ? lT : 0.0f) / ln);
    lobe.alphaB = sqrt((lB > 0.0f ? lB : 0.0f) / ln);
    return lobe;
}

// Spread of the per-sample specular radiance inside an aggregate, as E[L^2] / E[L]^2 at the
// lobe's centre. Model (slope space, Gaussian lobes), per axis of the aggregate's lobe (alpha A):
// every sample reflects with the material lobe of variance m = a^2 / 2 (a: the samples' own GGX
// alpha), its normal spread by g = (A^2 - a^2) / 2. Then
//   E[D] = N(0, m + g),  E[D^2] = N(0, m/2 + g) / (2 sqrt(pi m)),
// whose ratio at h = 0 is  A^2 / (a sqrt(2 A^2 - a^2)):  1 when the aggregate's lobe is the
// material's (a flat pixel: every sample alike), about A / (sqrt(2) a) when the normals spread
// far beyond it (a highlight lights a fraction of the samples, each far brighter than the mean).
// Inputs: A >= a >= the BRDF's alpha floor > 0, so 2 A^2 - a^2 >= A^2 > 0.
inline_fn float spikeRatioAxis(float A, float a) {
    float A2 = A * A;
    return A2 / (a * sqrt(2.0f * A2 - a * a));
}

// The anisotropic lobe's ratio, both axes. alphaMaterial: the samples' mean material alpha where
// the generation path knows it (the samples path reads each sample's roughness); the accumulate
// path stores none and passes alphaB, taking the narrow axis as pure material (then only the
// tangent spreads). Issue 14: on a ball of thin mirror-like spikes a pixel's spikes point every
// way, both axes come out wide, and with alphaB as the material the ratio was about 1 where the
// samples' 1e-3 lobes make it hundreds: the resolve tone-mapped the mean, a grey glow.
// Inputs: alphaT >= alphaB >= alphaMaterial >= the BRDF's alpha floor (callers clamp).
inline_fn float sggxSpikeRatio(float alphaT, float alphaB, float alphaMaterial) {
    return spikeRatioAxis(alphaT, alphaMaterial) * spikeRatioAxis(alphaB, alphaMaterial);
}

// The fixed-point matrix (shared/agaa.h, 16-bit fields of scale unitScale(16, n)) resolves an
// eigenvalue only to about kSggxQuantizationSteps of its steps: a near-mirror's alpha^2 = 1e-6 lies
// far below one step (1.2e-4 at n = 8), and rounding left its tangent eigenvalues a step or two
// wide, a lobe ten times the material's (issue 14: the accumulate path lit hard-mirror 4.4x worse
// than no AA, its mean radiance 3.6x the reference's). An axis's alpha^2 is therefore the
// material's plus only the spread that exceeds the quantisation: alphaMaterial^2 + max(alpha^2 -
// alphaMaterial^2 - step, 0), step = kSggxQuantizationSteps / scale. (Spreads below the step are
// what the layout cannot tell from rounding.) Inputs: alpha >= 0, alphaMaterial > 0, step >= 0.
SHARED_CONST_FLOAT kSggxQuantizationSteps = 2.0f;
// The samples path sums its matrices in fp32 (agaa/lighting/load_samples.glsl), and their rounding
// does to a near-mirror what the fixed point does on the accumulate path, on a smaller scale: the
// tangent eigenvalues of a flat chrome wall (alpha 1e-3, alpha^2 1e-6) came back wider than the
// material's. Measured on hard-mirror-vgroove (issue 35), one 45-degree wall per aggregate: 0.0209
// display RMSE against the truth without this step, 0.0037 with it, the reference (8) 0.0035. The
// same correction applies, with this step in alpha^2: about 5 times the rounding of 32 summed unit
// matrices (32 x 6e-8 per entry), and 1e-5 of alpha^2 is a spread of 0.2 degrees.
SHARED_CONST_FLOAT kSggxFloatRoundingStep = 1.0e-5f;
inline_fn float sggxDequantizedAlpha(float alpha, float alphaMaterial, float step) {
    float m2 = alphaMaterial * alphaMaterial;
    float excess = alpha * alpha - m2 - step;
    return sqrt(m2 + (excess > 0.0f ? excess : 0.0f));
}

SHARED_END
#endif
