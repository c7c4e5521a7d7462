#ifndef AGAA_CURVATURE_ROUGHNESS_GLSL
#define AGAA_CURVATURE_ROUGHNESS_GLSL
#include "common/epsilon.glsl"
// Geometric-curvature roughness (Kaplanyan et al. 2016, "Stable specular highlights"), as the UE4
// AGAA fill pass applies it (seed 004): the geometric normal's spread over the 2x2 pixel quad,
// measured with ddx/ddy of the interpolated normal before any normal map, widens the GGX lobe so
// that a highlight narrower than a pixel on a curved surface is filtered instead of aliased.
//   variance  = kQuadVariance (|dN/dx|^2 + |dN/dy|^2): each fragment of the quad lies half a pixel
//               from the quad centre along each axis, so its normal differs from the quad's mean
//               by half a derivative per axis (kQuadVariance = 1/4);
//   kernel    = min(boost * variance, maxFootprint): the talk's constants, boost 2.0 and max
//               footprint 0.3 (AgaaKaplanyanRoughnessBoost, ...MaxFootprint); the clamp keeps the
//               bias bounded however small the sphere is on screen;
//   alpha'^2  = min(alpha^2 + kernel, 1) in GGX slope space (alpha = roughness^2), so the filtered
//               roughness is never smoother than the material.
// The derivatives are arguments (the fill pass takes them with dFdx/dFdy), so the math also runs
// in a compute test (tests/gpu/test_shader_math.cpp).
const float kQuadVariance = 0.25;

float curvatureRoughness(float roughness, vec3 dNdx, vec3 dNdy, float maxFootprint, float boost) {
    float variance = kQuadVariance * (dot(dNdx, dNdx) + dot(dNdy, dNdy));
    // A flat face: leave the material's roughness exactly as it is.
    if (!(variance > kMinCurvatureVariance)) return roughness; // also catches NaN derivatives
    float kernel = min(boost * variance, maxFootprint);
    float alpha = roughness * roughness;
    float alpha2 = min(alpha * alpha + kernel, 1.0);
    return sqrt(sqrt(alpha2));
}
#endif
