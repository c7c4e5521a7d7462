#ifndef AGAA_SHARED_CLUSTERING_H
#define AGAA_SHARED_CLUSTERING_H
// AGAA step 2, aggregate definition (paper section 3.3, Algorithm 1, Equation 1), written
// once for both the GPU kernel (shaders/glsl/agaa/cluster.comp) and its CPU reference
// (agaa/aggregate/clustering.cpp). The two must produce identical metadata words, so:
//   - only scalar float operations whose IEEE results are exact-rounded (+ - * / sqrt, compares);
//   - every float local is PRECISE (GLSL `precise`: no contraction into fused multiply-add);
//     the C++ side compiles with -ffp-contract=off;
//   - sums are accumulated in increasing sample order, and ties are broken by the lowest index.
#include "shared/agaa.h"
#include "shared/frame.h"

#ifdef __cplusplus
#define PRECISE
#define OUT(T) T&
#define OUT_ARRAY(T) T
#define IN_ARRAY(T) const T
#else
#define PRECISE precise
#define OUT(T) out T
#define OUT_ARRAY(T) out T
#define IN_ARRAY(T) T
#endif

SHARED_BEGIN

// b = ceil(log2 c) bits per sample (figure 5), and one at c = 1: its layer flag (kOffLayer).
inline_fn uint metadataBits(uint c) {
    return c <= 2u ? 1u : 2u;
}
// At c = 1 a sample's bit is 1 when it lies off the aggregate's layer (clusterSamples): it takes
// the aggregate's radiance in the resolve but none of its statistics. At c >= 2 no id reaches c.
SHARED_CONST kOffLayer = 1u;
// ceil(n b / 32) words per pixel. 32 is a multiple of b, so no sample's bits straddle two words.
inline_fn uint metadataWords(uint n, uint c) {
    return (n * metadataBits(c) + 31u) / 32u;
}

// Unit direction from the pixel centre's view ray to the camera (the hemisphere's pole).
inline_fn void pixelCentreToCamera(uint px, uint py, float ndcScaleX, float ndcScaleY, float p00, float p11,
                                   OUT(float) vx, OUT(float) vy, OUT(float) vz) {
    PRECISE float nx = (float(px) + 0.5f) * ndcScaleX - 1.0f;
    PRECISE float ny = (float(py) + 0.5f) * ndcScaleY - 1.0f;
    PRECISE float x = nx / p00;
    PRECISE float y = ny / p11;
    PRECISE float len = sqrt((x * x + y * y) + 1.0f); // >= 1: no guard
    vx = -x / len;
    vy = -y / len;
    vz = 1.0f / len;
}

// Orthonormal basis around V (Duff et al. 2017); V.z > 0 for any pixel of a perspective view.
inline_fn void hemisphereBasis(float vx, float vy, float vz, OUT(float) tx, OUT(float) ty, OUT(float) tz,
                               OUT(float) bx, OUT(float) by, OUT(float) bz) {
    PRECISE float s = vz >= 0.0f ? 1.0f : -1.0f;
    PRECISE float a = -1.0f / (s + vz);
    PRECISE float b = (vx * vy) * a;
    PRECISE float t0 = 1.0f + ((s * vx) * vx) * a;
    PRECISE float t1 = s * b;
    PRECISE float t2 = -s * vx;
    PRECISE float b1 = s + (vy * vy) * a;
    tx = t0;
    ty = t1;
    tz = t2;
    bx = b;
    by = b1;
    bz = -vy;
}

// Decodes the two angles through the tables (cos/sin of each level), around V.
inline_fn void decodeFaceNormal(float cosTheta, float sinTheta, float cosPhi, float sinPhi, float vx,
                                float vy, float vz, OUT(float) nx, OUT(float) ny, OUT(float) nz) {
    float tx, ty, tz, bx, by, bz;
    hemisphereBasis(vx, vy, vz, tx, ty, tz, bx, by, bz);
    PRECISE float a = sinTheta * cosPhi;
    PRECISE float b = sinTheta * sinPhi;
    PRECISE float x = (a * tx + b * bx) + cosTheta * vx;
    PRECISE float y = (a * ty + b * by) + cosTheta * vy;
    PRECISE float z = (a * tz + b * bz) + cosTheta * vz;
    nx = x;
    ny = y;
    nz = z;
}

// View-space position of a sample from its depth (reversed Z, see common/depth.glsl) and its
// sub-pixel position, divided by the characteristic length k (Equation 1 works in units of k).
inline_fn void sampleScaledPosition(uint px, uint py, float sx, float sy, float d, float ndcScaleX,
                                    float ndcScaleY, float p00, float p11, float znear, float nf, float fmn,
                                    float invK, OUT(float) x, OUT(float) y, OUT(float) z) {
    PRECISE float t = nf / (d * fmn + znear); // denominator >= znear > 0
    PRECISE float ndcX = (float(px) + sx) * ndcScaleX - 1.0f;
    PRECISE float ndcY = (float(py) + sy) * ndcScaleY - 1.0f;
    PRECISE float vx = (ndcX * t) / p00;
    PRECISE float vy = (ndcY * t) / p11;
    PRECISE float rx = vx * invK;
    PRECISE float ry = vy * invK;
    PRECISE float rz = -t * invK;
    x = rx;
    y = ry;
    z = rz;
}

// Equation 1: d(a, b) = |(p_a - p_b)/k|^2 + (1 - n_a . n_b)^2, positions already divided by k.
inline_fn float aggregateDistance(float ax, float ay, float az, float anx, float any, float anz, float bx,
                                  float by, float bz, float bnx, float bny, float bnz) {
    PRECISE float dx = ax - bx;
    PRECISE float dy = ay - by;
    PRECISE float dz = az - bz;
    PRECISE float position = (dx * dx + dy * dy) + dz * dz;
    PRECISE float cosine = (anx * bnx + any * bny) + anz * bnz;
    PRECISE float o = 1.0f - cosine;
    PRECISE float r = position + o * o;
    return r;
}

// How far apart two samples' surfaces lie, whatever their normals: the position term of the
// plane variant (the mean of the squared distances of each sample to the other's tangent plane,
// in units of k). Samples of one surface are close however far apart they lie on it, so a face-on
// pixel near a light stays one layer; a sphere's edge over the wall behind it does not.
inline_fn float layerDistance(float ax, float ay, float az, float anx, float any, float anz, float bx,
                              float by, float bz, float bnx, float bny, float bnz) {
    PRECISE float dx = ax - bx;
    PRECISE float dy = ay - by;
    PRECISE float dz = az - bz;
    PRECISE float da = (dx * anx + dy * any) + dz * anz;
    PRECISE float db = (dx * bnx + dy * bny) + dz * bnz;
    PRECISE float r = (da * da + db * db) * 0.5f;
    return r;
}

// The plane variant (AggregateDistance::Plane, agaa/aggregate/agaa_constants.h): the position
// term is layerDistance (above), so samples of one plane are 0 apart however far apart they lie
// on it (a flat floor at grazing angles spreads a pixel's samples over more than k in depth); the
// normal term is Equation 1's.
inline_fn float aggregatePlaneDistance(float ax, float ay, float az, float anx, float any, float anz,
                                       float bx, float by, float bz, float bnx, float bny, float bnz) {
    PRECISE float position = layerDistance(ax, ay, az, anx, any, anz, bx, by, bz, bnx, bny, bnz);
    PRECISE float cosine = (anx * bnx + any * bny) + anz * bnz;
    PRECISE float o = 1.0f - cosine;
    PRECISE float r = position + o * o;
    return r;
}

SHARED_CONST kDistancePosition = 0u;
SHARED_CONST kDistancePlane = 1u;

inline_fn float clusterDistance(uint mode, float ax, float ay, float az, float anx, float any, float anz,
                                float bx, float by, float bz, float bnx, float bny, float bnz) {
    if (mode == kDistancePlane)
        return aggregatePlaneDistance(ax, ay, az, anx, any, anz, bx, by, bz, bnx, bny, bnz);
    return aggregateDistance(ax, ay, az, anx, any, anz, bx, by, bz, bnx, bny, bnz);
}

// Samples of different shading models (metal against dielectric; the samples path reads it from
// the G-buffer, the prepass has none) are this far apart on top of their distance, so they never
// share an aggregate while c leaves a seed for each model (seed 004: pre-filtered shading assumes
// one shading model per aggregate). Any distance between samples of one pixel is far below it:
// positions are in units of k and the normal term is at most 4.
SHARED_CONST_FLOAT kShadingModelDistance = 1.0e6f;
// The G-buffer's metallic at or above which a sample is shaded as a metal.
SHARED_CONST_FLOAT kMetalModelThreshold = 0.5f;

#define AGAA_DIST(a, b)                                                                                      \
    (clusterDistance(mode, px[a], py[a], pz[a], nx[a], ny[a], nz[a], px[b], py[b], pz[b], nx[b], ny[b],      \
                     nz[b]) +                                                                                \
     (model[a] != model[b] ? kShadingModelDistance : 0.0f))

// c = 1: one aggregate cannot hold two surfaces apart, and their mean would be shaded at a
// point between them, in empty space, with a normal neither has (a sphere's silhouette over a
// wall: lights between them light the mean as if it touched them). So the pixel's samples are
// split into two layers as Algorithm 1 would split them into two seeds, but on the distance
// between their surfaces alone (layerDistance: normals spread inside a layer are what the
// aggregate's filtered lobe is for): seed 0 the sample farthest from the mean, seed 1 the one farthest from
// seed 0 if beyond `threshold`, every sample to its nearer seed. The larger layer is the aggregate (ties:
// seed 0's); the other's samples get kOffLayer and keep only their coverage (they resolve to the aggregate's
// radiance): where no-AA shades the one surface its centre sample hits, c = 1 shades the surface
// most of the pixel's samples hit, pre-filtered.
inline_fn void splitLayers(uint n, float threshold, IN_ARRAY(float) px[kMaxSamples],
                           IN_ARRAY(float) py[kMaxSamples], IN_ARRAY(float) pz[kMaxSamples],
                           IN_ARRAY(float) nx[kMaxSamples], IN_ARRAY(float) ny[kMaxSamples],
                           IN_ARRAY(float) nz[kMaxSamples], IN_ARRAY(bool) valid[kMaxSamples], float mx,
                           float my, float mz, float mnx, float mny, float mnz,
                           OUT_ARRAY(uint) ids[kMaxSamples]) {
    uint seed0 = 0u;
    PRECISE float best = -1.0f;
    for (uint s = 0u; s < n; ++s) {
        if (!valid[s]) continue;
        PRECISE float dm = layerDistance(px[s], py[s], pz[s], nx[s], ny[s], nz[s], mx, my, mz, mnx, mny, mnz);
        if (dm > best) {
            best = dm;
            seed0 = s;
        }
    }
    int seed1 = -1;
    best = threshold;
    for (uint s = 0u; s < n; ++s) {
        if (!valid[s]) continue;
        PRECISE float d = layerDistance(px[s], py[s], pz[s], nx[s], ny[s], nz[s], px[seed0], py[seed0],
                                        pz[seed0], nx[seed0], ny[seed0], nz[seed0]);
        if (d > best) {
            best = d;
            seed1 = int(s);
        }
    }
    uint inSeed0 = 0u, inSeed1 = 0u;
    for (uint s = 0u; s < n; ++s) {
        ids[s] = 0u;
        if (!valid[s] || seed1 < 0) continue;
        uint t = uint(seed1);
        PRECISE float d0 = layerDistance(px[s], py[s], pz[s], nx[s], ny[s], nz[s], px[seed0], py[seed0],
                                         pz[seed0], nx[seed0], ny[seed0], nz[seed0]);
        PRECISE float d1 =
            layerDistance(px[s], py[s], pz[s], nx[s], ny[s], nz[s], px[t], py[t], pz[t], nx[t], ny[t], nz[t]);
        ids[s] = d1 < d0 ? 1u : 0u;
        if (ids[s] == 1u)
            inSeed1 = inSeed1 + 1u;
        else
            inSeed0 = inSeed0 + 1u;
    }
    // ids hold the seed: 0 for seed 0's layer. The larger layer becomes the aggregate (id 0).
    bool swap = inSeed1 > inSeed0;
    for (uint s = 0u; s < n; ++s)
        if (valid[s]) ids[s] = (ids[s] == 1u) != swap ? kOffLayer : 0u;
}

// Algorithm 1. Inputs: n samples (valid = not sky), positions divided by k, unit normals, shading
// models (all 0 when there is no model to separate).
// Output: ids[s] for s < n: each valid sample's aggregate id (0 for sky samples), and the
// number of aggregates. Entries from n up are not written.
//  1(b) mean position and normal of the valid samples;
//  1(c) seed 0: the sample farthest from the mean;
//  1(d) seed 1: the sample farthest from seed 0;
//  1(e) further seeds: the largest sum of distances (Equation 1 is already squared) to the seeds;
//  a seed is only created from samples farther than `threshold` from every existing seed, so a
//  flat pixel gets one aggregate and is lit once;
//  2(a) every valid sample joins its nearest seed.
// Ties go to the lowest sample index (strict comparisons while scanning upwards) and, in the
// assignment, to the lowest aggregate id.
// mode: kDistancePosition (Equation 1) or kDistancePlane.
inline_fn uint clusterSamples(uint n, uint c, uint mode, float threshold, IN_ARRAY(float) px[kMaxSamples],
                              IN_ARRAY(float) py[kMaxSamples], IN_ARRAY(float) pz[kMaxSamples],
                              IN_ARRAY(float) nx[kMaxSamples], IN_ARRAY(float) ny[kMaxSamples],
                              IN_ARRAY(float) nz[kMaxSamples], IN_ARRAY(uint) model[kMaxSamples],
                              IN_ARRAY(bool) valid[kMaxSamples], OUT_ARRAY(uint) ids[kMaxSamples]) {
    uint count = 0u;
    PRECISE float mx = 0.0f, my = 0.0f, mz = 0.0f, mnx = 0.0f, mny = 0.0f, mnz = 0.0f;
    for (uint s = 0u; s < n; ++s) {
        ids[s] = 0u;
        if (!valid[s]) continue;
        mx = mx + px[s];
        my = my + py[s];
        mz = mz + pz[s];
        mnx = mnx + nx[s];
        mny = mny + ny[s];
        mnz = mnz + nz[s];
        count = count + 1u;
    }
    if (count == 0u) return 0u; // sky-only pixel: no aggregate
    PRECISE float fc = float(count);
    mx = mx / fc;
    my = my / fc;
    mz = mz / fc;
    mnx = mnx / fc;
    mny = mny / fc;
    mnz = mnz / fc;
    if (c == 1u) {
        splitLayers(n, threshold, px, py, pz, nx, ny, nz, valid, mx, my, mz, mnx, mny, mnz, ids);
        return 1u;
    }

    uint seeds[kMaxAggregates];
    for (uint k = 0u; k < kMaxAggregates; ++k)
        seeds[k] = 0u;
    PRECISE float best = -1.0f;
    for (uint s = 0u; s < n; ++s) {
        if (!valid[s]) continue;
        PRECISE float dm =
            clusterDistance(mode, px[s], py[s], pz[s], nx[s], ny[s], nz[s], mx, my, mz, mnx, mny, mnz);
        if (dm > best) {
            best = dm;
            seeds[0] = s;
        }
    }
    uint seedCount = 1u;
    for (uint k = 1u; k < c && k < kMaxAggregates; ++k) {
        int chosen = -1;
        PRECISE float bestScore = -1.0f;
        for (uint s = 0u; s < n; ++s) {
            if (!valid[s]) continue;
            PRECISE float nearest = 3.0e38f;
            PRECISE float sum = 0.0f;
            for (uint j = 0u; j < seedCount; ++j) {
                PRECISE float dj = AGAA_DIST(s, seeds[j]);
                if (dj < nearest) nearest = dj;
                sum = sum + dj;
            }
            if (nearest > threshold) {
                PRECISE float score = k == 1u ? nearest : sum;
                if (score > bestScore) {
                    bestScore = score;
                    chosen = int(s);
                }
            }
        }
        if (chosen < 0) break; // every sample is within t of a seed: no further aggregate
        seeds[seedCount] = uint(chosen);
        seedCount = seedCount + 1u;
    }
    for (uint s = 0u; s < n; ++s) {
        if (!valid[s]) continue;
        uint id = 0u;
        PRECISE float nearest = AGAA_DIST(s, seeds[0]);
        for (uint j = 1u; j < seedCount; ++j) {
            PRECISE float dj = AGAA_DIST(s, seeds[j]);
            if (dj < nearest) {
                nearest = dj;
                id = j;
            }
        }
        ids[s] = id;
    }
    return seedCount;
}

#undef AGAA_DIST

// Figure 5: sample s's id in bits [s b, s b + b) of the pixel's words; nothing else in those bits.
inline_fn uint packMetadataWord(uint word, uint n, uint c, IN_ARRAY(uint) ids[kMaxSamples]) {
    uint b = metadataBits(c);
    uint bits = 0u;
    for (uint s = 0u; s < n; ++s) {
        uint first = s * b;
        if (first / 32u == word) bits = bits | (ids[s] << (first % 32u));
    }
    return bits;
}

inline_fn uint unpackMetadata(uint wordValue, uint s, uint c) {
    uint b = metadataBits(c);
    return (wordValue >> ((s * b) % 32u)) & ((1u << b) - 1u);
}

SHARED_END

#undef PRECISE
#undef OUT
#undef OUT_ARRAY
#undef IN_ARRAY
#endif
