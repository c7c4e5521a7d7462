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
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
#endif
