#ifndef AGAA_ENVIRONMENT_GLSL
#define AGAA_ENVIRONMENT_GLSL
// Distant environment lighting (issue 16; engine/frame/environment_maps.h): diffuse irradiance
// from 9 spherical-harmonic coefficients and split-sum pre-filtered specular (Karis 2013, "Real
// Shading in Unreal Engine 4"), the same for every method. AGAA evaluates it once per aggregate
// from the aggregate's filtered normal distribution: its mean normal and its Toksvig or SGGX roughness pick the pre-filtered
// level, which is the same filtering the lights get. The environment is not shadowed.
//
// Requires, declared by the includer before this file: `frame` (FrameConstants). Declares the
// pre-filtered levels at set 0 binding 15, their constants at 16 and the BRDF table at 17. Specialisation id 16
// (agaa/common/effects.h kSpecEnvironment): 0 for a scene without an environment, whose passes
// then compile none of this (bindings 15 and 16 hold a 1x1 black stand-in).
#include "common/brdf.glsl"
#include "common/depth.glsl"
#include "common/epsilon.glsl"
#include "shared/environment.h"
#include "shared/specialization.h"

layout(constant_id = kSpecEnvironment) const uint kEnvironment = 0u;
layout(set = 0, binding = 15) uniform sampler2DArray environmentMap;
layout(set = 0, binding = 16) uniform Environment { EnvironmentConstants environment; };
layout(set = 0, binding = 17) uniform sampler2D environmentDfg;

// View space -> the map's world space. The view matrix is rigid (a rotation and a translation),
// so its rotation's inverse is its transpose.
vec3 environmentDirection(vec3 viewDirection) { return normalize(transpose(mat3(frame.view)) * viewDirection); }

// engine/scene/environment.h's mapping: u = 0.5 + atan2(x, -z) / 2 pi, v = acos(y) / pi.
vec2 equirectCoordinates(vec3 d) {
    // At the poles atan2(0, 0) is undefined: any longitude is the same texel row there.
    float u = length(d.xz) > kMinNormalLength ? 0.5 + atan(d.x, -d.z) / (2.0 * kPi) : 0.5;
    return vec2(u, acos(clamp(d.y, -1.0, 1.0)) / kPi);
}

// Irradiance (lux) on a surface with world normal N: E = sum_i c_i Y_i(N), the basis of
// engine/frame/environment_maps.cpp shBasis, with bands 1 and 2 scaled by `bands` (1, 1: a
// single normal; an aggregate's spread of normals attenuates them, environmentLightingFiltered).
// Band-2 ringing can dip below 0 opposite a bright sun: clamped.
vec3 environmentIrradiance(vec3 N, vec2 bands) {
    float x = N.x, y = N.y, z = N.z, b1 = bands.x, b2 = bands.y;
    // Each band's factor inside its term, in the sum's order: bands (1, 1) add exactly what the
    // unscaled sum adds (a point sample's irradiance is unchanged to the bit).
    vec3 e = environment.irradianceSh[0].rgb * 0.282095;
    e += environment.irradianceSh[1].rgb * (0.488603 * y * b1);
    e += environment.irradianceSh[2].rgb * (0.488603 * z * b1);
    e += environment.irradianceSh[3].rgb * (0.488603 * x * b1);
    e += environment.irradianceSh[4].rgb * (1.092548 * x * y * b2);
    e += environment.irradianceSh[5].rgb * (1.092548 * y * z * b2);
    e += environment.irradianceSh[6].rgb * (0.315392 * (3.0 * z * z - 1.0) * b2);
    e += environment.irradianceSh[7].rgb * (1.092548 * x * z * b2);
    e += environment.irradianceSh[8].rgb * (0.546274 * (x * x - y * y) * b2);
    return max(e, vec3(0.0));
}

// Pre-filtered radiance towards world direction D for perceptual roughness r: the two levels
// either side of r (level k is r = k / (levels - 1)), blended.
vec3 environmentRadiance(vec3 D, float roughness) {
    float level = clamp(roughness, 0.0, 1.0) * environment.params.z;
    float lower = floor(level);
    vec2 uv = equirectCoordinates(D);
    vec3 a = textureLod(environmentMap, vec3(uv, lower), 0.0).rgb;
    vec3 b = textureLod(environmentMap, vec3(uv, min(lower + 1.0, environment.params.z)), 0.0).rgb;
    return mix(a, b, level - lower) * environment.params.y;
}

// The BRDF's half of the split sum: the directional albedo F0 * A + B of this BRDF (GGX,
// height-correlated Smith), integrated on the CPU (environment_maps.h integrateDfgTable) into a
// 32x32 table over (N.V, roughness). Karis's analytic mobile fit was 16 % dark on a metal of
// roughness 0.3 against the brute-force integral (tests/features/test_environment_gpu.cpp).
vec2 environmentBrdf(float roughness, float NoV) {
    return textureLod(environmentDfg, vec2(NoV, clamp(roughness, 0.0, 1.0)), 0.0).rg;
}

// Outgoing radiance towards V (view space) from the whole environment, for a surface of
// perceptual roughness `roughness` (an aggregate's filtered one) whose normals spread with mean
// length `spread` around s.normal: the diffuse irradiance's bands 1 and 2 attenuated by the
// vMF lobe's factors r and r^3 (the filtered diffuse of common/brdf.glsl filteredClampedCosine).
vec3 environmentLightingFiltered(SurfaceInputs s, vec3 V, float roughness, float spread) {
    vec3 N = s.normal;
    float NoV = max(dot(N, V), kMinCosine);
    vec3 f0 = mix(vec3(0.04), s.albedo, s.metallic);
    vec2 ab = environmentBrdf(roughness, NoV);
    vec3 reflectance = f0 * ab.x + ab.y;
    vec3 specular = environmentRadiance(environmentDirection(reflect(-V, N)), roughness) * reflectance;
    // Lambert with the energy the specular lobe leaves, as the punctual lights' diffuseLobe.
    float r = clamp(spread, 0.0, 1.0);
    vec3 diffuse = (1.0 - reflectance) * (1.0 - s.metallic) * s.albedo / kPi *
                   environmentIrradiance(environmentDirection(N), vec2(r, r * r * r));
    return diffuse + specular;
}

// A point sample's (one normal): the bands unscaled.
vec3 environmentLighting(SurfaceInputs s, vec3 V, float roughness) {
    return environmentLightingFiltered(s, V, roughness, 1.0);
}

// What an uncovered sample of `pixel` sees, before exposure: the environment on the pixel
// centre's ray in every method (the map is far smoother than a pixel), else the constant sky.
vec3 skyRadiance(ivec2 pixel) {
#ifdef AGAA_TEST_PERTURB_SCENE
    if (kEnvironment == 0u) return 0.99 * frame.skyRadiance.rgb; // tools/perturb-test.sh: the sky 1 % darker
#endif
    if (kEnvironment == 0u) return frame.skyRadiance.rgb;
    vec3 ray = viewPositionAtDistance(vec2(pixel) + 0.5, 1.0, frame.extent, frame.projParams);
    return environmentRadiance(environmentDirection(normalize(ray)), 0.0);
}
#endif
