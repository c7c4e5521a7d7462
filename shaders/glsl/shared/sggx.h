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

// Cyclic Jacobi sweeps over the three off-diagonal entries. The off-diagonal mass falls
// quadratically once small; 5 sweeps leave it below fp32 rounding for every matrix tested.
SHARED_CONST kSggxJacobiSweeps = 5u;

struct SggxLobe {
    vec3 normal;    // unit, on the viewer's side
    vec3 tangent;   // unit, the axis of the larger alpha
    vec3 bitangent; // normal x tangent
    float alphaT;   // GGX alpha along the tangent (>= alphaB), unclamped
    float alphaB;
};

// One Jacobi rotation of the symmetric A zeroing A_pq (p < q), accumulated into Q, whose columns
// become the eigenvectors; skipped when |A_pq| <= offDiagonalEpsilon (theta would divide by zero).
// Called with constant pairs rather than from a loop over them: with the pair a loop variable every
// index into A and Q was dynamic, which cost lavapipe about a fifth of SGGX's lighting (issue 49).
inline_fn void sggxJacobiRotation(inout_param(mat3) A, inout_param(mat3) Q, uint p, uint q,
                                  float offDiagonalEpsilon) {
    float apq = A[q][p];
    if (abs(apq) <= offDiagonalEpsilon) return;
    // tan of the rotation angle that zeroes S_pq, the smaller root (stable form).
    float theta = (A[q][q] - A[p][p]) / (2.0f * apq);
    float t = (theta >= 0.0f ? 1.0f : -1.0f) / (abs(theta) + sqrt(theta * theta + 1.0f));
    float c = 1.0f / sqrt(t * t + 1.0f);
    float s = t * c;
    for (uint k = 0u; k < 3u; ++k) { // A <- A J (columns p, q)
        float akp = A[p][k], akq = A[q][k];
        A[p][k] = c * akp - s * akq;
        A[q][k] = s * akp + c * akq;
    }
    for (uint k = 0u; k < 3u; ++k) { // A <- J^T A (rows p, q)
        float apk = A[k][p], aqk = A[k][q];
        A[k][p] = c * apk - s * aqk;
        A[k][q] = s * apk + c * aqk;
    }
    for (uint k = 0u; k < 3u; ++k) { // Q <- Q J: the columns are the eigenvectors
        float qkp = Q[p][k], qkq = Q[q][k];
        Q[p][k] = c * qkp - s * qkq;
        Q[q][k] = s * qkp + c * qkq;
    }
}

// Eigen-decomposition of the symmetric S by cyclic Jacobi rotations (Golub and Van Loan 8.5).
// Guards: a rotation is skipped when |S_pq| <= offDiagonalEpsilon (already diagonal: theta would
// divide by zero); the normal's eigenvalue is floored at eigenvalueFloor (a valid mean has
// trace >= 1, so its largest eigenvalue is >= 1/3; the floor only meets corrupt input).
inline_fn SggxLobe sggxLobe(float sxx, float syy, float szz, float sxy, float sxz, float syz, vec3 V,
                            float offDiagonalEpsilon, float eigenvalueFloor) {
    mat3 A = mat3(sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz);
    mat3 Q = mat3(1.0f);
    for (uint sweep = 0u; sweep < kSggxJacobiSweeps; ++sweep) {
        // Once all three off-diagonal entries are at or below the epsilon, every rotation of this
        // sweep and of the later ones is skipped: stopping gives the same matrices. On realistic
        // means 97 to 99.6 % stop within 3 sweeps (FixedPointSggx.StoppedSweepsMatchAConverged-
        // DoubleDecomposition); on lavapipe each sweep cost about 7 ms of metal's lighting at
        // 320x180 (issue 49, docs/decisions/aggregate-cost.md).
        if (abs(A[1][0]) <= offDiagonalEpsilon && abs(A[2][0]) <= offDiagonalEpsilon &&
            abs(A[2][1]) <= offDiagonalEpsilon)
            break;
        sggxJacobiRotation(A, Q, 0u, 1u, offDiagonalEpsilon);
        sggxJacobiRotation(A, Q, 0u, 2u, offDiagonalEpsilon);
        sggxJacobiRotation(A, Q, 1u, 2u, offDiagonalEpsilon);
    }
    float l0 = A[0][0], l1 = A[1][1], l2 = A[2][2];
    uint iN = l0 >= l1 ? (l0 >= l2 ? 0u : 2u) : (l1 >= l2 ? 1u : 2u);
    uint i1 = (iN + 1u) % 3u, i2 = (iN + 2u) % 3u;
    uint iT = A[i1][i1] >= A[i2][i2] ? i1 : i2;
    uint iB = iT == i1 ? i2 : i1;
    SggxLobe lobe;
    lobe.normal = dot(Q[iN], V) >= 0.0f ? Q[iN] : -Q[iN];
    lobe.tangent = Q[iT];
    lobe.bitangent = cross(lobe.normal, lobe.tangent);
    float ln = A[iN][iN] > eigenvalueFloor ? A[iN][iN] : eigenvalueFloor;
    // Quantisation can leave a tangent eigenvalue slightly negative: clamp before the sqrt.
    lobe.alphaT = sqrt((A[iT][iT] > 0.0f ? A[iT][iT] : 0.0f) / ln);
    lobe.alphaB = sqrt((A[iB][iB] > 0.0f ? A[iB][iB] : 0.0f) / ln);
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
