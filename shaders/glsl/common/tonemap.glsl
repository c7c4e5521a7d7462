#ifndef AGAA_TONEMAP_GLSL
#define AGAA_TONEMAP_GLSL
#include "common/epsilon.glsl"
// Narkowicz's fitted ACES curve, per channel, after exposure. The CPU twin is
// eng::io::toneMapAces (engine/io); the two must stay identical.
//   T(x) = clamp(x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), 0, 1)
// The denominator is >= 0.14 for x >= 0, so no guard is needed there; inputs are
// clamped to [0, kMaxRadiance] so NaN-free finite values go in.
vec3 toneMapAces(vec3 x) {
    x = clamp(x, vec3(0.0), vec3(kMaxRadiance));
#ifdef AGAA_TEST_PERTURB_SCENE
    // tools/perturb-test.sh: a black level of 1e-3 (a biased curve), which fails even a black image.
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14) + 1.0e-3, 0.0, 1.0);
#endif
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
// AGAA with SGGX (agaa/lighting.comp): E[T(L)] over an aggregate's samples instead of T(E[L]). The tone map is concave where
// highlights live, so tone-mapping the mean of a glossy tube's samples (a few very bright, most
// dark) comes out far brighter than the reference's mean of tone-mapped samples. The specular part
// S (mean) with variance `variance` is taken as a two-point distribution, the least-informative
// one matching both moments with a dark floor: a fraction p = S^2 / (S^2 + var) of the samples at
// base + (S^2 + var) / S, the rest at base = L - S. var = 0 (every isotropic aggregate, a flat
// pixel) gives p = 1 and T(L) exactly. Guard: S <= kMinSpikeRadiance has no highlight to spread.
vec3 toneMapAggregate(vec3 L, vec3 S, vec3 variance) {
    vec3 spread = vec3(greaterThan(S, vec3(kMinSpikeRadiance))) * vec3(greaterThan(variance, vec3(0.0)));
    vec3 s = max(S, vec3(kMinSpikeRadiance));
    vec3 energy = s * s + max(variance, vec3(0.0)); // >= kMinSpikeRadiance^2 > 0
    vec3 p = (s * s) / energy;
    vec3 base = max(L - S, vec3(0.0));
    vec3 twoPoint = p * toneMapAces(base + energy / s) + (1.0 - p) * toneMapAces(base);
    return mix(toneMapAces(L), twoPoint, spread);
}
#endif
