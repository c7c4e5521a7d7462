#ifndef AGAA_BRDF_GLSL
#define AGAA_BRDF_GLSL
#include "common/epsilon.glsl"
// GGX specular (Walter et al. 2007) with the height-correlated Smith visibility,
// Schlick Fresnel, Lambert diffuse: the glTF metallic-roughness model. Shared by
// every technique so that methods differ only in what they shade, not how.

#ifdef AGAA_TEST_PERTURB_BRDF
const float kPi = 3.14159265358979 * 1.01; // tools/perturb-test.sh: every BRDF 1 % darker
#else
const float kPi = 3.14159265358979;
#endif

struct SurfaceInputs {
    vec3 albedo; // base colour, linear
    float metallic;
    float roughness; // perceptual roughness r; alpha = r^2
    vec3 normal; // unit, view space
};

float ggxD(float NoH, float alpha) {
    float a2 = alpha * alpha;
    float f = (NoH * a2 - NoH) * NoH + 1.0; // >= a2 > 0 since NoH in [0,1]
    return a2 / (kPi * f * f);
}

// Height-correlated Smith G divided by 4 N.L N.V (Heitz 2014).
float smithVisibility(float NoV, float NoL, float alpha) {
    float a2 = alpha * alpha;
    float gv = NoL * sqrt(NoV * NoV * (1.0 - a2) + a2);
    float gl = NoV * sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / max(gv + gl, kMinCosine * kMinCosine);
}

vec3 fresnelSchlick(vec3 f0, float VoH) {
    float f = pow(1.0 - clamp(VoH, 0.0, 1.0), 5.0); // base in [0,1]: pow is defined
    return f0 + (1.0 - f0) * f;
}

// The angles both GGX evaluations share. False when L is at or below the surface (no light).
struct BrdfAngles {
    vec3 H;
    float NoL, NoV, NoH, VoH;
};
bool brdfAngles(vec3 N, vec3 V, vec3 L, out BrdfAngles g) {
    g.NoL = dot(N, L);
    g.NoV = max(dot(N, V), kMinCosine);
    vec3 Hraw = V + L;
    // V = -L (light exactly behind the viewer's direction) makes H zero.
    float hlen = length(Hraw);
    g.H = hlen > kMinNormalLength ? Hraw / hlen : N;
    g.NoH = clamp(dot(N, g.H), 0.0, 1.0);
    g.VoH = clamp(dot(V, g.H), 0.0, 1.0);
    return g.NoL > 0.0;
}

// Lambert diffuse (energy the Fresnel term leaves), per unit irradiance; F from fresnelSchlick.
vec3 diffuseLobe(SurfaceInputs s, vec3 F) { return (1.0 - F) * (1.0 - s.metallic) * s.albedo / kPi; }

vec3 surfaceFresnel(SurfaceInputs s, float VoH) { return fresnelSchlick(mix(vec3(0.04), s.albedo, s.metallic), VoH); }

// Outgoing radiance towards V for irradiance E (already times N.L) from direction L.
vec3 evaluateBrdf(SurfaceInputs s, vec3 V, vec3 L, vec3 irradiance) {
    BrdfAngles g;
    if (!brdfAngles(s.normal, V, L, g)) return vec3(0.0);
    float alpha = clamp(s.roughness * s.roughness, kMinGgxAlpha, kMaxGgxAlpha);
    vec3 F = surfaceFresnel(s, g.VoH);
    vec3 specular = F * (ggxD(g.NoH, alpha) * smithVisibility(g.NoV, max(g.NoL, kMinCosine), alpha));
    return (diffuseLobe(s, F) + specular) * irradiance * g.NoL;
}

// evaluateBrdf's value, with its specular part returned too (AGAA's two-point resolve spreads
// the specular part of a Toksvig aggregate over its samples: agaa/lighting.glsl).
vec3 evaluateBrdfSplit(SurfaceInputs s, vec3 V, vec3 L, vec3 irradiance, out vec3 specularOut) {
    specularOut = vec3(0.0);
    BrdfAngles g;
    if (!brdfAngles(s.normal, V, L, g)) return vec3(0.0);
    float alpha = clamp(s.roughness * s.roughness, kMinGgxAlpha, kMaxGgxAlpha);
    vec3 F = surfaceFresnel(s, g.VoH);
    vec3 specular = F * (ggxD(g.NoH, alpha) * smithVisibility(g.NoV, max(g.NoL, kMinCosine), alpha));
    specularOut = specular * irradiance * g.NoL;
    return diffuseLobe(s, F) * irradiance * g.NoL + specularOut;
}

// Anisotropic GGX (Burley 2012; Heitz 2014 for the height-correlated visibility), alphas ax
// along T and ay along B; for AGAA's SGGX aggregates (shared/sggx.h). With ax == ay it returns
// evaluateBrdf's value (tested): the tangent components are rescaled to the clamped cosines.
// D's denominator dot(v, v) >= (ax ay)^2 min(ax, ay)^2 > 0 for alphas >= kMinGgxAlpha.
float ggxDAnisotropic(float ToH, float BoH, float NoH, float ax, float ay) {
    float a2 = ax * ay;
    vec3 v = vec3(ay * ToH, ax * BoH, a2 * NoH);
    float w2 = a2 / dot(v, v);
    return a2 * w2 * w2 / kPi;
}

float smithVisibilityAnisotropic(vec2 v, float NoV, vec2 l, float NoL, float ax, float ay) {
    float gv = NoL * length(vec3(ax * v.x, ay * v.y, NoV));
    float gl = NoV * length(vec3(ax * l.x, ay * l.y, NoL));
    return 0.5 / max(gv + gl, kMinCosine * kMinCosine);
}

// X's components along T and B, rescaled so that with the clamped cosine NoX the three form a
// unit vector (an unclamped negative cosine would otherwise leave |(ToX, BoX)| > sqrt(1 - NoX^2)).
vec2 tangentComponents(vec3 X, vec3 T, vec3 B, float NoX) {
    vec2 p = vec2(dot(T, X), dot(B, X));
    float l = length(p);
    return l > kMinNormalLength ? p * (sqrt(max(1.0 - NoX * NoX, 0.0)) / l) : vec2(0.0);
}

// As evaluateBrdf, anisotropic; `specular` receives the specular part of the result (AGAA's
// two-point resolve spreads only that part).
vec3 evaluateBrdfAnisotropic(SurfaceInputs s, vec3 T, vec3 B, float ax, float ay, vec3 V, vec3 L, vec3 irradiance,
                             out vec3 specularOut) {
    specularOut = vec3(0.0);
    BrdfAngles g;
    if (!brdfAngles(s.normal, V, L, g)) return vec3(0.0);
    ax = clamp(ax, kMinGgxAlpha, kMaxGgxAlpha);
    ay = clamp(ay, kMinGgxAlpha, kMaxGgxAlpha);
    float NoLc = max(g.NoL, kMinCosine);
    vec2 h = tangentComponents(g.H, T, B, g.NoH);
    float D = ggxDAnisotropic(h.x, h.y, g.NoH, ax, ay);
    float Vis = smithVisibilityAnisotropic(tangentComponents(V, T, B, g.NoV), g.NoV, tangentComponents(L, T, B, NoLc),
                                           NoLc, ax, ay);
    vec3 F = surfaceFresnel(s, g.VoH);
    specularOut = F * (D * Vis) * irradiance * g.NoL;
    return diffuseLobe(s, F) * irradiance * g.NoL + specularOut;
}
#endif
