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

// The angles of one light a BRDF evaluation needs beside N.V (which the aggregates' lobes make once
// for all their lights: FilteredLobe, AnisotropicLobe).
struct LightAngles {
    vec3 H;
    float NoL, NoH, VoH;
};
LightAngles lightAngles(vec3 N, vec3 V, vec3 L) {
    LightAngles a;
    a.NoL = dot(N, L);
    vec3 Hraw = V + L;
    // V = -L (light exactly behind the viewer's direction) makes H zero.
    float hlen = length(Hraw);
    a.H = hlen > kMinNormalLength ? Hraw / hlen : N;
    a.NoH = clamp(dot(N, a.H), 0.0, 1.0);
    a.VoH = clamp(dot(V, a.H), 0.0, 1.0);
    return a;
}

// The angles both GGX evaluations share. False when L is at or below the surface (no light).
struct BrdfAngles {
    vec3 H;
    float NoL, NoV, NoH, VoH;
};
bool brdfAngles(vec3 N, vec3 V, vec3 L, out BrdfAngles g) {
    LightAngles a = lightAngles(N, V, L);
    g.H = a.H;
    g.NoL = a.NoL;
    g.NoV = max(dot(N, V), kMinCosine);
    g.NoH = a.NoH;
    g.VoH = a.VoH;
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

// The environment's pre-filtered level (common/environment.glsl), as a perceptual roughness, for an aggregate whose filtered GGX alpha is
// `alpha` (Toksvig's, or the geometric mean of the SGGX lobe's two) and whose samples' mean
// material alpha is `materialAlpha` (not floored): sqrt(alpha), except at the punctual BRDF's floor
// kMinGgxAlpha. The floor keeps the punctual GGX peak finite and stands in for any smaller alpha;
// the pre-filtered map has no peak, so there the level is the material's own, as the per-sample
// methods read it. With the floor, a roughness-0 chrome wall read level sqrt(kMinGgxAlpha) = 0.03
// of the chain and its reflection was up to 31 % off the reference's (issue 14;
// tests/features/test_environment_gpu.cpp MirrorsReflectTheEnvironmentUnblurred).
float environmentAggregateRoughness(float alpha, float materialAlpha) {
    bool floored = alpha <= kMinGgxAlpha * (1.0 + kGgxAlphaFloorRelative);
    return sqrt(floored ? clamp(materialAlpha, 0.0, kMinGgxAlpha) : alpha);
}

// Lambert through a spread of normals: E[max(0, N.L)] over a von Mises-Fisher lobe of mean
// length r around the shading normal, x = N0.L. AGAA's filtered diffuse (paper section 3.5.2,
// after Baker and Hill 2012): without it an aggregate lights its diffuse with the clamped cosine
// of its mean normal, as if every sample faced that way (issue 14: strands and edges whose normals
// spread over a half circle). The clamped cosine's Legendre bands l = 1, 2, 4, 6 (a_l = 1/2, 5/16,
// -3/32, 13/256; odd l > 1 vanish) are attenuated by the lobe's band factors r^(l(l+1)/2) (a vMF
// lobe's bands fall as exp(-l(l+1) / 2 kappa), Han et al. 2007; A_1 = r fixes kappa), on top of
// the exact clamped cosine: r = 1 is max(0, x) exactly, r = 0 the sphere's mean 1/4 up to the
// bands above 6 (0.207 to 0.231). Clamped at 0: the truncated series dips below it near x = -1.
// The lobe's band factors filteredClampedCosineBands reads, (r - 1, r^3 - 1, r^10 - 1, r^21 - 1)
// times the bands' coefficients: what does not depend on the light, computed once per lobe.
vec4 clampedCosineBandFactors(float r) {
    float r3 = r * r * r;
    float r10 = r3 * r3 * r3 * r;
    float r21 = r10 * r10 * r;
    return vec4(0.5 * (r - 1.0), 0.3125 * (r3 - 1.0), 0.09375 * (r10 - 1.0), 0.05078125 * (r21 - 1.0));
}

// filteredClampedCosine at x = N0.L from the lobe's clampedCosineBandFactors.
float filteredClampedCosineBands(float x, vec4 k) {
    float x2 = x * x;
    float p2 = 1.5 * x2 - 0.5;
    float p4 = ((35.0 * x2 - 30.0) * x2 + 3.0) / 8.0;
    float p6 = (((231.0 * x2 - 315.0) * x2 + 105.0) * x2 - 5.0) / 16.0;
    float bands = k.x * x + k.y * p2 - k.z * p4 + k.w * p6;
    return max(max(x, 0.0) + bands, 0.0);
}

float filteredClampedCosine(float x, float r) { return filteredClampedCosineBands(x, clampedCosineBandFactors(r)); }

// The lobe filteredClampedCosine reads from the mean of a set of unit normals: its direction and
// its length r = |mean| in w (clamped to 1: fixed-point means can round above it). Normals that
// cancel (|mean| <= kMinNormalLength: a pixel's two faces of a thin card) have no direction; the
// view axis +z stands in, which r -> 0 makes all but irrelevant (the lobe is the sphere's mean).
vec4 meanNormalLobe(vec3 meanNormal) {
    float r = length(meanNormal);
    return vec4(r > kMinNormalLength ? meanNormal / r : vec3(0.0, 0.0, 1.0), min(r, 1.0));
}

// The share of an aggregate's specular taken in the microflake form (specularFlake), from the mean
// length `spread` of its normals: 0 for one normal, 1 from 1 - kFlakeSpreadRange down.
float flakeWeight(float spread) { return clamp((1.0 - spread) / kFlakeSpreadRange, 0.0, 1.0); }

// The specular of an aggregate as a cloud of microflakes (Heitz et al. 2015, the SGGX paper's
// specular phase function): F D(H) E / (4 sigma(V)), with sigma(V) = |(ax T.V, ay B.V, N.V)| the
// lobe's projected area towards the viewer (S = diag(ax^2, ay^2, 1) in the lobe's frame), D the
// anisotropic GGX of the same S at the unclamped H, and no horizon of the mean normal.
// Why: the reference averages its samples' own GGX, F D_i(H) E G / (4 N_i.V) each; the samples
// are spread over the screen, so a normal's share of them is its projected area N_i.V / sigma(V),
// which cancels the 1 / N_i.V, and the mean is F D(H) E / (4 sigma(V)) with D the normals'
// distribution. The microfacet form of the mean normal instead cuts every light past that normal's
// horizon, and with it the upper half of a tube seen side-on under a light from above: the metal
// lattice's bars lost the sun's highlights, the image -9 % (c = 4) to -14 % (c = 1) of the
// reference's mean radiance (issue 14; tests/agaa/test_agaa_quality_gpu.cpp). Guards: the alphas
// are in [kMinGgxAlpha, kMaxGgxAlpha] <= 1, so sigma(V)^2 >= min(ax, ay)^2 > 0 and the D term's
// |(T.H / ax, B.H / ay, N.H)|^2 >= |H|^2 = 1.
// SGGX aggregates only (evaluateBrdfAnisotropicFiltered). On Toksvig's isotropic lobe it also
// lifted metal (c = 1 -17.5 % to -11.8 %) but doubled foliage's display error (c = 2 0.06x to
// 0.11x no-AA) and put goal P8 at 1.12x: an isotropic lobe as wide as a tube's spread lights a
// strand's or a leaf's edge from every side.
// piAxAy = kPi ax ay and sigmaV = sigma(V) come from the lobe (anisotropicLobe): they do not
// depend on the light.
vec3 specularFlake(vec3 F, vec3 N, vec3 T, vec3 B, float ax, float ay, float piAxAy, float sigmaV, vec3 H,
                   vec3 irradiance) {
    vec3 h = vec3(dot(T, H) / ax, dot(B, H) / ay, dot(N, H));
    float q = dot(h, h);
    float D = 1.0 / (piAxAy * q * q);
    return F * (D / (4.0 * sigmaV)) * irradiance;
}

// An aggregate's isotropic filtered lobe seen from V: everything evaluateBrdfFilteredSplit needs
// that does not depend on the light, computed once per shading event (DESIGN section 4, the cost
// rule: the per-light work is the reference's evaluateBrdf with a filtered lobe). `spread` is the
// mean length of the aggregate's normals (1: one normal); the surface's roughness is the caller's
// filtered one.
struct FilteredLobe {
    vec3 f0;         // Schlick's reflectance at normal incidence
    float alpha;     // GGX alpha, clamped to the BRDF's range
    float a2;        // alpha^2
    float NoV;       // max(N.V, kMinCosine)
    float viewSmith; // sqrt(NoV^2 (1 - a2) + a2): the height-correlated visibility's view term
    vec4 bands;      // clampedCosineBandFactors(spread)
};

FilteredLobe filteredLobe(SurfaceInputs s, float spread, vec3 V) {
    FilteredLobe lobe;
    lobe.f0 = mix(vec3(0.04), s.albedo, s.metallic);
    lobe.alpha = clamp(s.roughness * s.roughness, kMinGgxAlpha, kMaxGgxAlpha);
    lobe.a2 = lobe.alpha * lobe.alpha;
    lobe.NoV = max(dot(s.normal, V), kMinCosine);
    lobe.viewSmith = sqrt(lobe.NoV * lobe.NoV * (1.0 - lobe.a2) + lobe.a2);
    lobe.bands = clampedCosineBandFactors(clamp(spread, 0.0, 1.0));
    return lobe;
}

// evaluateBrdf for a Toksvig aggregate through its FilteredLobe: the specular lobe is the
// caller's filtered roughness, the diffuse filteredClampedCosine, which stays lit for lights below
// the mean normal's horizon that some of the samples face. `specularOut` receives the specular
// part (AGAA's two-point resolve spreads only that part over the aggregate's samples). The same
// operations as evaluateBrdf's per light, on the lobe's precomputed terms.
vec3 evaluateFilteredLobe(SurfaceInputs s, FilteredLobe lobe, vec3 V, vec3 L, vec3 irradiance, out vec3 specularOut) {
    specularOut = vec3(0.0);
    LightAngles a = lightAngles(s.normal, V, L);
    float NoL = a.NoL, NoH = a.NoH;
    vec3 H = a.H;
    vec3 F = fresnelSchlick(lobe.f0, a.VoH);
    vec3 diffuse = diffuseLobe(s, F) * irradiance * filteredClampedCosineBands(NoL, lobe.bands);
    if (NoL <= 0.0) return diffuse;
    float f = (NoH * lobe.a2 - NoH) * NoH + 1.0; // ggxD: >= a2 > 0
    float D = lobe.a2 / (kPi * f * f);
    float NoLc = max(NoL, kMinCosine);
    float gl = lobe.NoV * sqrt(NoLc * NoLc * (1.0 - lobe.a2) + lobe.a2);
    float Vis = 0.5 / max(NoLc * lobe.viewSmith + gl, kMinCosine * kMinCosine); // smithVisibility
    specularOut = F * (D * Vis) * irradiance * NoL;
    return diffuse + specularOut;
}

// evaluateFilteredLobe with the lobe made on the spot (one light).
vec3 evaluateBrdfFilteredSplit(SurfaceInputs s, float spread, vec3 V, vec3 L, vec3 irradiance, out vec3 specularOut) {
    return evaluateFilteredLobe(s, filteredLobe(s, spread, V), V, L, irradiance, specularOut);
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

// X's components along T and B, rescaled so that with the clamped cosine NoX the three form a
// unit vector (an unclamped negative cosine would otherwise leave |(ToX, BoX)| > sqrt(1 - NoX^2)).
vec2 tangentComponents(vec3 X, vec3 T, vec3 B, float NoX) {
    vec2 p = vec2(dot(T, X), dot(B, X));
    float l = length(p);
    return l > kMinNormalLength ? p * (sqrt(max(1.0 - NoX * NoX, 0.0)) / l) : vec2(0.0);
}

// An SGGX aggregate's anisotropic lobe seen from V: what evaluateAnisotropicLobe needs that does
// not depend on the light, made once per shading event (DESIGN section 4, the cost rule). T and B
// are the lobe's axes, ax and ay its alphas (clamped here to the BRDF's range), `spread` as
// evaluateBrdfFilteredSplit's.
struct AnisotropicLobe {
    vec3 f0;         // Schlick's reflectance at normal incidence
    float ax, ay;    // clamped alphas
    float NoV;       // max(N.V, kMinCosine)
    float viewSmith; // |(ax T.V, ay B.V, N.V)| with V's tangent components rescaled: the visibility's view term
    float flake;     // flakeWeight(spread)
    float sigmaV;    // the microflake lobe's projected area towards V (specularFlake)
    float piAxAy;    // kPi ax ay, the microflake D's constant
    vec4 bands;      // clampedCosineBandFactors(spread)
};

AnisotropicLobe anisotropicLobe(SurfaceInputs s, vec3 T, vec3 B, float ax, float ay, float spread, vec3 V) {
    AnisotropicLobe lobe;
    lobe.f0 = mix(vec3(0.04), s.albedo, s.metallic);
    lobe.ax = clamp(ax, kMinGgxAlpha, kMaxGgxAlpha);
    lobe.ay = clamp(ay, kMinGgxAlpha, kMaxGgxAlpha);
    lobe.NoV = max(dot(s.normal, V), kMinCosine);
    vec2 v = tangentComponents(V, T, B, lobe.NoV);
    lobe.viewSmith = length(vec3(lobe.ax * v.x, lobe.ay * v.y, lobe.NoV));
    lobe.flake = flakeWeight(spread);
    lobe.sigmaV = length(vec3(lobe.ax * dot(T, V), lobe.ay * dot(B, V), dot(s.normal, V)));
    lobe.piAxAy = kPi * lobe.ax * lobe.ay;
    lobe.bands = clampedCosineBandFactors(clamp(spread, 0.0, 1.0));
    return lobe;
}

// As evaluateFilteredLobe, anisotropic (SGGX aggregates), through the lobe anisotropicLobe made:
// the specular blends the microfacet form into the microflake one (specularFlake) by the lobe's
// flake weight. The same operations as evaluateBrdfAnisotropicFiltered's per light.
vec3 evaluateAnisotropicLobe(SurfaceInputs s, AnisotropicLobe lobe, vec3 T, vec3 B, vec3 V, vec3 L, vec3 irradiance,
                             out vec3 specularOut) {
    specularOut = vec3(0.0);
    LightAngles a = lightAngles(s.normal, V, L);
    float NoL = a.NoL, NoH = a.NoH;
    vec3 H = a.H;
    vec3 F = fresnelSchlick(lobe.f0, a.VoH);
    vec3 diffuse = diffuseLobe(s, F) * irradiance * filteredClampedCosineBands(NoL, lobe.bands);
    vec3 flakeSpecular =
        lobe.flake > 0.0
            ? lobe.flake * specularFlake(F, s.normal, T, B, lobe.ax, lobe.ay, lobe.piAxAy, lobe.sigmaV, H, irradiance)
            : vec3(0.0);
    if (NoL <= 0.0) {
        specularOut = flakeSpecular;
        return diffuse + flakeSpecular;
    }
    float NoLc = max(NoL, kMinCosine);
    vec2 h = tangentComponents(H, T, B, NoH);
    float D = ggxDAnisotropic(h.x, h.y, NoH, lobe.ax, lobe.ay);
    vec2 l = tangentComponents(L, T, B, NoLc);
    float gl = lobe.NoV * length(vec3(lobe.ax * l.x, lobe.ay * l.y, NoLc));
    // Height-correlated Smith visibility, anisotropic (Heitz 2014): the view's term from the lobe.
    float Vis = 0.5 / max(NoLc * lobe.viewSmith + gl, kMinCosine * kMinCosine);
    specularOut = (1.0 - lobe.flake) * F * (D * Vis) * irradiance * NoL + flakeSpecular;
    return diffuse + specularOut;
}

// As evaluateBrdfFilteredSplit, anisotropic (SGGX aggregates); `spread` as there: the lobe made on
// the spot (one light).
vec3 evaluateBrdfAnisotropicFiltered(SurfaceInputs s, vec3 T, vec3 B, float ax, float ay, float spread, vec3 V,
                                     vec3 L, vec3 irradiance, out vec3 specularOut) {
    return evaluateAnisotropicLobe(s, anisotropicLobe(s, T, B, ax, ay, spread, V), T, B, V, L, irradiance,
                                   specularOut);
}

// As evaluateBrdf, anisotropic: one normal.
vec3 evaluateBrdfAnisotropic(SurfaceInputs s, vec3 T, vec3 B, float ax, float ay, vec3 V, vec3 L, vec3 irradiance,
                             out vec3 specularOut) {
    return evaluateBrdfAnisotropicFiltered(s, T, B, ax, ay, 1.0, V, L, irradiance, specularOut);
}
#endif
