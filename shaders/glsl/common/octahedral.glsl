#ifndef AGAA_OCTAHEDRAL_GLSL
#define AGAA_OCTAHEDRAL_GLSL
#include "common/epsilon.glsl"
// Octahedral unit-vector encoding (Cigolle et al. 2014) for the per-sample
// shading normal of the G-buffer (RG16_SNORM).
vec2 octWrap(vec2 v) { return (1.0 - abs(v.yx)) * vec2(v.x >= 0.0 ? 1.0 : -1.0, v.y >= 0.0 ? 1.0 : -1.0); }

vec2 encodeOctahedral(vec3 n) {
    // |x|+|y|+|z| >= 1/sqrt(3) for a unit vector; the max() guards a zero input.
    n /= max(abs(n.x) + abs(n.y) + abs(n.z), kMinNormalLength);
    return n.z >= 0.0 ? n.xy : octWrap(n.xy);
}

vec3 decodeOctahedral(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0) n.xy = octWrap(n.xy);
    // Length >= 1/sqrt(3) after decoding any input in [-1,1]^2; guard anyway.
    return n / max(length(n), kMinNormalLength);
}
#endif
