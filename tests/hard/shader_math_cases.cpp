#include "shader_math_cases.h"

#include "shader_math_checks.h"

#include "../agaa/filtered_diffuse_reference.h"

#include "engine/frame/frame_constants.h"
#include "engine/frame/sample_pattern.h"
#include "shared/sggx.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <tuple>

namespace agaa::hard {

namespace {

using namespace checks;

// The guard values of epsilon.glsl, restated: the twins below implement the documented
// behaviour (guards included) in double precision.
constexpr double kMinGgxAlpha = 1.0e-3, kMaxGgxAlpha = 0.9, kMinCosine = 1.0e-4, kMinLightDistance2 = 1.0e-4,
                 kMinNormalLength = 1.0e-6, kMaxRadiance = 6.0e4, kDepthCompareRelative = 1.0e-4,
                 kFlakeSpreadRange = 0.1;
constexpr double kPi = 3.14159265358979323846;
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kDenormal = 1.0e-40f;

// ---- double twins --------------------------------------------------------------------
double ggxD(double NoH, double alpha) {
    double a2 = alpha * alpha, f = NoH * NoH * (a2 - 1.0) + 1.0;
    return a2 / (kPi * f * f);
}
double smith(double NoV, double NoL, double alpha) {
    double a2 = alpha * alpha;
    double gv = NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2),
           gl = NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2);
    return 0.5 / std::max(gv + gl, kMinCosine * kMinCosine);
}
D3 fresnel(D3 f0, double VoH) {
    return f0 + (1.0 - f0) * std::pow(1.0 - std::clamp(VoH, 0.0, 1.0), 5.0);
}
// The half vector and cosines brdf.glsl's brdfAngles computes; false below the surface.
struct Angles {
    D3 H;
    double NoL, NoV, NoH, VoH;
};
bool angles(D3 N, D3 V, D3 L, Angles& g) {
    g.NoL = glm::dot(N, L);
    g.NoV = std::max(glm::dot(N, V), kMinCosine);
    D3 Hraw = V + L;
    double hlen = glm::length(Hraw);
    g.H = hlen > kMinNormalLength ? Hraw / hlen : N;
    g.NoH = std::clamp(glm::dot(N, g.H), 0.0, 1.0);
    g.VoH = std::clamp(glm::dot(V, g.H), 0.0, 1.0);
    return g.NoL > 0.0;
}
D3 diffuse(D3 albedo, double metallic, D3 F) {
    return (1.0 - F) * (1.0 - metallic) * albedo / kPi;
}
D3 brdf(D3 albedo, double metallic, D3 N, double roughness, D3 V, D3 L, D3 E) {
    Angles g;
    if (!angles(N, V, L, g)) return D3(0.0);
    double alpha = std::clamp(roughness * roughness, kMinGgxAlpha, kMaxGgxAlpha);
    D3 F = fresnel(glm::mix(D3(0.04), albedo, metallic), g.VoH);
    D3 spec = F * (ggxD(g.NoH, alpha) * smith(g.NoV, std::max(g.NoL, kMinCosine), alpha));
    return (diffuse(albedo, metallic, F) + spec) * E * g.NoL;
}
// Anisotropic GGX (Burley 2012) with the height-correlated Smith visibility (Heitz 2014), the
// tangent components rescaled to the clamped cosines as brdf.glsl does.
D3 brdfAnisotropic(D3 albedo, double metallic, D3 N, D3 T, double ax, double ay, D3 V, D3 L, D3& specular) {
    specular = D3(0.0);
    const D3 B = glm::cross(N, T);
    Angles g;
    if (!angles(N, V, L, g)) return D3(0.0);
    ax = std::clamp(ax, kMinGgxAlpha, kMaxGgxAlpha);
    ay = std::clamp(ay, kMinGgxAlpha, kMaxGgxAlpha);
    auto tangential = [&](D3 X, double NoX) {
        glm::dvec2 p(glm::dot(T, X), glm::dot(B, X));
        double l = glm::length(p);
        return l > kMinNormalLength ? p * (std::sqrt(std::max(1.0 - NoX * NoX, 0.0)) / l) : glm::dvec2(0.0);
    };
    double NoLc = std::max(g.NoL, kMinCosine);
    glm::dvec2 h = tangential(g.H, g.NoH), v = tangential(V, g.NoV), l = tangential(L, NoLc);
    double d = h.x * h.x / (ax * ax) + h.y * h.y / (ay * ay) + g.NoH * g.NoH;
    double D = 1.0 / (kPi * ax * ay * d * d);
    double gv = NoLc * std::sqrt(ax * ax * v.x * v.x + ay * ay * v.y * v.y + g.NoV * g.NoV);
    double gl = g.NoV * std::sqrt(ax * ax * l.x * l.x + ay * ay * l.y * l.y + NoLc * NoLc);
    double Vis = 0.5 / std::max(gv + gl, kMinCosine * kMinCosine);
    D3 F = fresnel(glm::mix(D3(0.04), albedo, metallic), g.VoH);
    specular = F * (D * Vis) * g.NoL;
    return diffuse(albedo, metallic, F) * g.NoL + specular;
}
// An SGGX aggregate's BRDF with normals of mean length `spread` (common/brdf.glsl
// evaluateBrdfAnisotropicFiltered): the diffuse through the spread's filtered cosine; the specular the
// microfacet form (brdfAnisotropic) times 1 - w plus, times w = clamp((1 - spread) / kFlakeSpreadRange, 0,
// 1), the microflake form F D(H) / (4 sigma(V)), D the lobe's GGX at the unclamped N.H and sigma(V) =
// |(ax T.V, ay B.V, N.V)|, which lights it past N's horizon too.
D3 brdfFiltered(D3 albedo, double metallic, D3 N, D3 T, double ax, double ay, double spread, D3 V, D3 L,
                D3& specular) {
    const D3 B = glm::cross(N, T);
    Angles g;
    const bool above = angles(N, V, L, g);
    const D3 F = fresnel(glm::mix(D3(0.04), albedo, metallic), g.VoH);
    const D3 lambert =
        diffuse(albedo, metallic, F) * agaa::test::filteredCosine(g.NoL, std::clamp(spread, 0.0, 1.0));
    ax = std::clamp(ax, kMinGgxAlpha, kMaxGgxAlpha);
    ay = std::clamp(ay, kMinGgxAlpha, kMaxGgxAlpha);
    const double w = std::clamp((1.0 - spread) / kFlakeSpreadRange, 0.0, 1.0);
    const double th = glm::dot(T, g.H) / ax, bh = glm::dot(B, g.H) / ay, nh = glm::dot(N, g.H);
    const double q = th * th + bh * bh + nh * nh;
    const double sigma = glm::length(D3(ax * glm::dot(T, V), ay * glm::dot(B, V), glm::dot(N, V)));
    const D3 flake = F / (kPi * ax * ay * q * q * 4.0 * sigma);
    D3 microfacet(0.0);
    if (above) brdfAnisotropic(albedo, metallic, N, T, ax, ay, V, L, microfacet);
    specular = (1.0 - w) * microfacet + w * flake;
    return lambert + specular;
}
double window(double d2, double range) {
    if (range <= 0.0) return 1.0;
    double r = d2 / (range * range), w = std::clamp(1.0 - r * r, 0.0, 1.0);
    return w * w;
}
double aces(double x) {
    x = std::clamp(x, 0.0, kMaxRadiance);
    return std::clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
// E[T] over the two-point distribution of toneMapAggregate (common/tonemap.glsl), per channel.
double toneMapAggregate(double L, double S, double variance) {
    constexpr double kMinSpike = 1.0e-8;
    if (!(S > kMinSpike) || !(variance > 0.0)) return aces(L);
    double energy = S * S + variance, p = S * S / energy, base = std::max(L - S, 0.0);
    return p * aces(base + energy / S) + (1.0 - p) * aces(base);
}
double toksvig(double alpha, double smax, double amin, double amax) {
    double a = std::clamp(alpha, amin, amax), s = std::clamp(2.0 / (a * a) - 2.0, 0.0, smax);
    return s * smax / (smax - s + s * smax);
}
double filtered(double len, double smax) {
    len = std::clamp(len, 0.0, 1.0);
    double f = len / (len + smax * (1.0 - len));
    return std::sqrt(2.0 / (f * smax + 2.0));
}

uint32_t quantize(double v, uint32_t scale) {
    double c = v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0; // NaN -> 0
    return uint32_t(std::floor(c * scale + 0.5));
}

const double kSmax = 2.0 / (kMinGgxAlpha * kMinGgxAlpha) - 2.0;

glm::vec4 v4(D3 v, double w = 0.0) {
    return glm::vec4(glm::vec3(v), float(w));
}

} // namespace

std::vector<EdgeCase> shaderMathCases() {
    std::vector<EdgeCase> cases;
    auto add = [&](std::string name, std::vector<std::string> guards, MathCase in,
                   std::function<std::string(const MathResult&)> check) {
        cases.push_back({std::move(name), std::move(guards), in, std::move(check)});
    };

    // ---- octahedral normals (common/octahedral.glsl) ----
    for (glm::vec3 n : {glm::vec3(0, 0, 1), glm::vec3(0, 0, -1), glm::vec3(1, 0, 0),
                        glm::vec3(0.577350f, -0.577350f, -0.577350f), glm::vec3(0.6f, 0.0f, -0.8f)}) {
        add("octahedral round trip (" + fmt(n.x) + "," + fmt(n.y) + "," + fmt(n.z) + ")", {},
            op(kOpOctahedral, glm::vec4(n, 0)), [n](const MathResult& r) {
                return near3("decode(encode(n))", glm::vec3(r.r1), D3(glm::normalize(n)), 0.0, 2e-6);
            });
    }
    add("octahedral encode of a zero vector", {"kMinNormalLength"}, op(kOpOctahedral, glm::vec4(0)),
        [](const MathResult& r) { return unitLength("decode(encode(0))", glm::vec3(r.r1)); });
    add("octahedral encode of a denormal vector", {"kMinNormalLength"},
        op(kOpOctahedral, glm::vec4(kDenormal, 0, 0, 0)),
        [](const MathResult& r) { return unitLength("decode(encode(1e-40 x))", glm::vec3(r.r1)); });
    add("octahedral encode of a huge vector", {}, op(kOpOctahedral, glm::vec4(3e38f, -3e38f, 3e38f, 0)),
        [](const MathResult& r) { return unitLength("decode(encode(3e38))", glm::vec3(r.r1)); });
    for (glm::vec2 e :
         {glm::vec2(1, 1), glm::vec2(-1, 1), glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(-1, -1)})
        add("octahedral decode corner (" + fmt(e.x) + "," + fmt(e.y) + ")", {"kMinNormalLength"},
            op(kOpOctDecode, glm::vec4(e, 0, 0)),
            [](const MathResult& r) { return unitLength("decode", glm::vec3(r.r0)); });

    // ---- hemisphere face normals (common/hemisphere_normal.glsl) ----
    struct Hemi {
        glm::vec3 n, v;
        const char* what;
    };
    for (Hemi h :
         {Hemi{{0, 0, 1}, {0, 0, 1}, "N == V (atan(0,0))"}, Hemi{{1, 0, 0}, {0, 0, 1}, "N on the rim"},
          Hemi{{0, 0, -1}, {0, 0, 1}, "N behind the rim (clamped)"},
          Hemi{glm::normalize(glm::vec3(0.3f, -0.4f, 0.5f)), glm::normalize(glm::vec3(-0.2f, 0.1f, 1.0f)),
               "oblique"}}) {
        add(std::string("hemisphere encode ") + h.what, {},
            op(kOpHemisphere, glm::vec4(h.n, 0), glm::vec4(h.v, 0)), [h](const MathResult& r) -> std::string {
                double theta = std::acos(std::clamp(double(glm::dot(h.n, h.v)), 0.0, 1.0));
                double want = std::clamp(std::round(theta * 255.0 / 1.5707963), 0.0, 255.0);
                if (std::string e = near("theta level", r.r0.x, want, 0.0, 1.0); !e.empty()) return e;
                if (!(r.r0.y >= 0.0f && r.r0.y <= 255.0f))
                    return "phi level " + fmt(r.r0.y) + " outside 0..255";
                return {};
            });
    }

    // ---- GGX (common/brdf.glsl) ----
    // At NoH = 1, f = 1 + NoH^2 (a^2 - 1) cancels to a^2 = 1e-6 in fp32 (ulp(1) = 6e-8): the peak is
    // within 15 % of the exact one, and finite: that is what kMinGgxAlpha buys.
    add("ggxD peak at alpha_min", {"kMinGgxAlpha"}, op(kOpGgxD, glm::vec4(1.0f, float(kMinGgxAlpha), 0, 0)),
        [](const MathResult& r) { return near("D", r.r0.x, ggxD(1.0, kMinGgxAlpha), 0.15); });
    for (float noh : {0.0f, 0.5f, 0.999f, kDenormal})
        add("ggxD NoH=" + fmt(noh) + " alpha=0.3", {}, op(kOpGgxD, glm::vec4(noh, 0.3f, 0, 0)),
            [noh](const MathResult& r) { return near("D", r.r0.x, ggxD(noh, 0.3)); });
    add("ggxD at alpha_max", {"kMaxGgxAlpha"}, op(kOpGgxD, glm::vec4(0.7f, float(kMaxGgxAlpha), 0, 0)),
        [](const MathResult& r) { return near("D", r.r0.x, ggxD(0.7, kMaxGgxAlpha)); });
    struct SmithIn {
        float nov, nol, alpha;
    };
    for (SmithIn s : {SmithIn{0, 0, 0}, SmithIn{0, 0, float(kMinGgxAlpha)},
                      SmithIn{kDenormal, kDenormal, 0.5f}, SmithIn{1, 1, float(kMinGgxAlpha)},
                      SmithIn{float(kMinCosine), float(kMinCosine), float(kMinGgxAlpha)},
                      SmithIn{0.5f, 0.25f, float(kMaxGgxAlpha)}})
        add("smithVisibility NoV=" + fmt(s.nov) + " NoL=" + fmt(s.nol) + " alpha=" + fmt(s.alpha),
            {"kMinCosine"}, op(kOpSmith, glm::vec4(s.nov, s.nol, s.alpha, 0)),
            [s](const MathResult& r) { return near("Vis", r.r0.x, smith(s.nov, s.nol, s.alpha), 1e-4); });
    for (float voh : {-1.0f, 0.0f, kDenormal, 1.0f, 2.0f})
        add("fresnelSchlick VoH=" + fmt(voh), {}, op(kOpFresnel, glm::vec4(0.04f, 0.5f, 1.0f, voh)),
            [voh](const MathResult& r) {
                return near3("F", glm::vec3(r.r0), fresnel(D3(0.04, 0.5, 1.0), voh));
            });

    // ---- the whole BRDF ----
    struct BrdfIn {
        const char* what;
        std::vector<std::string> guards;
        D3 albedo;
        double metallic, roughness;
        D3 N, V, L;
        double rel;
    };
    const D3 z(0, 0, 1);
    const D3 grazingV = glm::normalize(D3(1, 0, 1e-5)), oblique = glm::normalize(D3(0.3, 0.2, 1.0));
    for (const BrdfIn& b : std::vector<BrdfIn>{
             {"mirror peak, roughness 0 metal", {"kMinGgxAlpha"}, {0.9, 0.9, 0.9}, 1, 0, z, z, z, 0.15},
             {"roughness 1 dielectric",
              {"kMaxGgxAlpha"},
              {0.5, 0.5, 0.5},
              0,
              1,
              z,
              oblique,
              glm::normalize(D3(-0.4, 0.1, 1)),
              1e-4},
             {"grazing view N.V = 1e-5", {"kMinCosine"}, {0.8, 0.8, 0.8}, 0, 0.2, z, grazingV, oblique, 1e-3},
             {"view exactly in the plane N.V = 0",
              {"kMinCosine"},
              {0.8, 0.8, 0.8},
              1,
              0.05,
              z,
              D3(1, 0, 0),
              oblique,
              1e-3},
             {"light exactly in the plane N.L = 0",
              {},
              {0.8, 0.8, 0.8},
              0,
              0.5,
              z,
              oblique,
              D3(0, 1, 0),
              1e-4},
             {"light grazing N.L = 1e-6",
              {"kMinCosine"},
              {0.8, 0.8, 0.8},
              1,
              0.0,
              z,
              oblique,
              glm::normalize(D3(1, 0, 1e-6)),
              1e-3},
             {"viewer below the horizon, V = -L (H = 0)",
              {"kMinNormalLength", "kMinCosine"},
              {0.8, 0.8, 0.8},
              0,
              0.5,
              z,
              -oblique,
              oblique,
              1e-3},
         }) {
        MathCase in =
            op(kOpBrdf, v4(b.albedo, b.metallic), v4(b.N, b.roughness), v4(b.V), v4(b.L), v4(D3(1.0)));
        add("evaluateBrdf " + std::string(b.what), b.guards, in, [b, in](const MathResult& r) {
            D3 want = brdf(b.albedo, b.metallic, glm::dvec3(glm::vec3(in.b)), b.roughness,
                           glm::dvec3(glm::vec3(in.c)), glm::dvec3(glm::vec3(in.d)), D3(1.0));
            return near3("radiance", glm::vec3(r.r0), want, b.rel, 1e-6);
        });
    }
    // The capped shading event: a roughness-0 highlight of 1e4 lux exceeds fp16 and the tone
    // curve's useful range; kMaxRadiance caps it, the tone map keeps it <= 1.
    add("shading event over the radiance cap", {"kMaxRadiance", "kMinGgxAlpha"},
        op(kOpShadeEvent, glm::vec4(0.9f, 0.9f, 0.9f, 1.0f), glm::vec4(0, 0, 1, 0), glm::vec4(0, 0, 1, 1.0f),
           glm::vec4(0, 0, 1, 0), glm::vec4(1e4f, 1e4f, 1e4f, 0.0f)),
        [](const MathResult& r) -> std::string {
            if (std::string e = near3("capped radiance", glm::vec3(r.r0), D3(kMaxRadiance), 0.0, 0.0);
                !e.empty())
                return e;
            return near3("tone-mapped", glm::vec3(r.r1), D3(aces(kMaxRadiance)), 1e-6, 1e-6);
        });
    add("shading event emissive 1e4 at exposure 1e3", {"kMaxRadiance"},
        op(kOpShadeEvent, glm::vec4(0.0f), glm::vec4(0, 0, 1, 1), glm::vec4(0, 0, 1, 1e3f),
           glm::vec4(0, 0, -1, 0), glm::vec4(0, 0, 0, 1e4f)),
        [](const MathResult& r) {
            return near3("capped radiance", glm::vec3(r.r0), D3(kMaxRadiance), 0.0, 0.0);
        });

    // ---- lights (common/lights.glsl) ----
    struct LightIn {
        const char* what;
        std::vector<std::string> guards;
        glm::vec4 posRange, dirType, radiance;
        glm::vec3 P;
        glm::vec4 spot;
    };
    const float point = 1.0f;
    std::vector<LightIn> lights = {
        {"point light at the shaded point (d = 0)",
         {"kMinLightDistance2"},
         {0, 0, 0, 0},
         {0, 0, -1, point},
         {5, 5, 5, 0},
         {0, 0, 0},
         {}},
        {"point light at denormal distance",
         {"kMinLightDistance2"},
         {kDenormal, 0, 0, 0},
         {0, 0, -1, point},
         {5, 5, 5, 0},
         {0, 0, 0},
         {}},
        {"point light at 0.99e-4 m (d^2 = 1e-8)",
         {"kMinLightDistance2"},
         {0.99e-4f, 0, 0, 0},
         {0, 0, -1, point},
         {5, 5, 5, 0},
         {0, 0, 0},
         {}},
        {"point light at 1.01e-4 m",
         {"kMinLightDistance2"},
         {1.01e-4f, 0, 0, 0},
         {0, 0, -1, point},
         {5, 5, 5, 0},
         {0, 0, 0},
         {}},
        // Issue 14: between these two the direction guard once disagreed with the falloff's floor.
        {"point light just inside the shared guard (d = 0.0099, d^2 < 1e-4)",
         {"kMinLightDistance2"},
         {0.0099f, 0, 0, 0},
         {0, 0, -1, point},
         {5, 5, 5, 0},
         {0, 0, 0},
         {}},
        {"point light just outside the shared guard (d = 0.0101)",
         {"kMinLightDistance2"},
         {0.0101f, 0, 0, 0},
         {0, 0, -1, point},
         {5, 5, 5, 0},
         {0, 0, 0},
         {}},
        {"point light at the attenuation floor (d^2 = 1e-4)",
         {"kMinLightDistance2"},
         {0, 0.01f, 0, 0},
         {0, 0, -1, point},
         {5, 5, 5, 0},
         {0, 0, 0},
         {}},
        {"point light at 1e5 m",
         {},
         {1e5f, 0, 0, 0},
         {0, 0, -1, point},
         {1e4f, 1e4f, 1e4f, 0},
         {0, 0, 0},
         {}},
        {"point light exactly at its range",
         {},
         {2, 0, 0, 2},
         {0, 0, -1, point},
         {1, 1, 1, 0},
         {0, 0, 0},
         {}},
        {"directional light", {}, {0, 0, 0, 0}, {0, -1, 0, 0}, {3, 3, 3, 0}, {1e5f, 0, 0}, {}},
    };
    // Spot with inner == outer cone: the CPU packs 1 / max(cos inner - cos outer, kMinSpotCosRange).
    {
        eng::scene::Scene s;
        eng::scene::Light l;
        l.type = eng::scene::LightType::Spot;
        l.position = {0, 0, 1};
        l.direction = {0, 0, -1};
        l.innerConeAngle = l.outerConeAngle = 0.5f;
        l.intensity = 2.0f;
        s.lights.push_back(l);
        shared::GpuLight g = eng::frame::makeGpuLights(s, glm::mat4(1.0f))[0];
        for (glm::vec3 P : {glm::vec3(0, 0, 0), glm::vec3(0.5463f, 0, 0), glm::vec3(0.6f, 0, 0)})
            lights.push_back({"spot with inner == outer cone",
                              {"kMinSpotCosRange"},
                              g.positionRange,
                              g.directionType,
                              g.radiance,
                              P,
                              g.spot});
    }
    for (const LightIn& l : lights) {
        MathCase in = op(kOpLight, l.posRange, l.dirType, l.radiance, l.spot, glm::vec4(l.P, 0));
        add("lightIncidence " + std::string(l.what) + " P=(" + fmt(l.P.x) + ")", l.guards, in,
            [l](const MathResult& r) -> std::string {
                const D3 P(l.P), pos(glm::vec3(l.posRange));
                D3 L(0.0), E(0.0);
                if (uint32_t(l.dirType.w) == 0u) {
                    L = -D3(glm::vec3(l.dirType));
                    E = D3(glm::vec3(l.radiance));
                } else {
                    D3 to = pos - P;
                    double d2 = glm::dot(to, to);
                    // The shader compares in fp32; the direction and the falloff share one guard.
                    L = float(d2) > float(kMinLightDistance2) ? to / std::sqrt(d2) : D3(0, 0, 1);
                    double att = window(d2, l.posRange.w) / std::max(d2, kMinLightDistance2);
                    double spotAbs = 0.0;
                    if (uint32_t(l.dirType.w) == 2u) {
                        double cd = glm::dot(D3(glm::vec3(l.dirType)), -L);
                        double s = std::clamp((cd - l.spot.x) * l.spot.y, 0.0, 1.0);
                        // The cone's edge has slope spot.y = 1 / kMinSpotCosRange = 1e4 per unit cosine:
                        // fp32 rounding of the cosine (4 ulp of 1 = 2.4e-7) moves s by up to 2.4e-3,
                        // so E may differ by E0 ((s + ds)^2 - s^2). Stated, not hidden in a relative bound.
                        double ds = l.spot.y * 2.4e-7;
                        spotAbs = att * (2.0 * s * ds + ds * ds) * l.radiance.x;
                        att *= s * s;
                    }
                    E = D3(glm::vec3(l.radiance)) * att;
                    if (std::string e = near3("L", glm::vec3(r.r0), L, 1e-5, 1e-5); !e.empty()) return e;
                    return near3("irradiance", glm::vec3(r.r1), E, 1e-4, 1e-5 + spotAbs);
                }
                if (std::string e = near3("L", glm::vec3(r.r0), L, 1e-5, 1e-5); !e.empty()) return e;
                return near3("irradiance", glm::vec3(r.r1), E, 1e-4, 1e-5);
            });
    }
    for (float d2 : {0.0f, 1.0f, 4.0f, 5.0f, kInf})
        add("rangeWindow d2=" + fmt(d2), {}, op(kOpRangeWindow, glm::vec4(d2, 2.0f, 0, 0)),
            [d2](const MathResult& r) { return near("window", r.r0.x, window(d2, 2.0)); });

    // ---- tone map (common/tonemap.glsl) ----
    for (float x : {0.0f, kDenormal, 0.18f, 1.0f, 6.0e4f, 6.1e4f, 1e30f, kInf, -1.0f, -kInf})
        add("toneMapAces x=" + fmt(x), {"kMaxRadiance"}, op(kOpToneMap, glm::vec4(x, x, x, 0)),
            [x](const MathResult& r) { return near3("T(x)", glm::vec3(r.r0), D3(aces(x)), 1e-5, 1e-6); });
    addSrgbCases(cases); // shader_math_srgb_cases.cpp
    add("toneMapAces NaN", {"kMaxRadiance"}, op(kOpToneMap, glm::vec4(kNaN, 0.5f, kNaN, 0)),
        [](const MathResult& r) -> std::string {
            for (int i = 0; i < 3; ++i)
                if (!(r.r0[i] >= 0.0f && r.r0[i] <= 1.0f))
                    return "T(NaN)[" + std::to_string(i) + "] = " + fmt(r.r0[i]) + " not in [0, 1]";
            return near("T(0.5)", r.r0.y, aces(0.5), 1e-5, 1e-6);
        });

    // ---- Toksvig (shared/ag_buffer.h) ----
    for (float alpha : {0.0f, kDenormal, float(kMinGgxAlpha), 0.1f, float(kMaxGgxAlpha), 1.0f, 1e30f, kNaN}) {
        std::vector<std::string> g;
        if (alpha <= float(kMinGgxAlpha) || std::isnan(alpha)) g.push_back("kMinGgxAlpha");
        if (alpha >= float(kMaxGgxAlpha)) g.push_back("kMaxGgxAlpha");
        add("toksvigLength alpha=" + fmt(alpha), g,
            op(kOpToksvig, glm::vec4(alpha, float(kSmax), float(kMinGgxAlpha), float(kMaxGgxAlpha))),
            [alpha](const MathResult& r) -> std::string {
                // NaN fails both comparisons of the clamp and takes alpha_min (length 1).
                double a = std::isnan(alpha) ? kMinGgxAlpha : alpha;
                if (std::string e =
                        near("length", r.r0.x, toksvig(a, kSmax, kMinGgxAlpha, kMaxGgxAlpha), 1e-5);
                    !e.empty())
                    return e;
                if (r.r0.x < 0.3f)
                    return "length " + fmt(r.r0.x) + " < 0.3: the sample's direction is lost in the mean";
                return {};
            });
    }
    for (float len : {0.0f, kDenormal, 1e-7f, 0.5f, 0.9999999f, 1.0f, 1.5f, kNaN})
        add("filteredAlpha |N|=" + fmt(len), {}, op(kOpFiltered, glm::vec4(len, float(kSmax), 0, 0)),
            [len](const MathResult& r) {
                return near("alpha'", r.r0.x, filtered(std::isnan(len) ? 0.0 : len, kSmax), 1e-5);
            });

    // ---- fixed point (shared/ag_buffer.h) ----
    for (float v : {0.0f, -0.0f, kDenormal, 0.5f, 1.0f, 1.0000001f, -1.0f, 1e30f, kInf, kNaN}) {
        MathCase in = op(kOpQuantize, glm::vec4(v, 0, 0, 0));
        in.op.y = 2097151u; // kNormalScale
        add("quantizeUnit/Signed v=" + fmt(v), {}, in, [v](const MathResult& r) -> std::string {
            if (std::string e = near("quantizeUnit", r.r0.x, quantize(v, 2097151u), 0.0, 0.0); !e.empty())
                return e;
            return near("quantizeSigned", r.r0.y, quantize(double(v) * 0.5 + 0.5, 2097151u), 0.0, 0.0);
        });
    }
    struct MeanIn {
        uint32_t sum, k, scale;
    };
    for (MeanIn m :
         {MeanIn{0, 1, 2097151u}, MeanIn{2097151u, 1, 2097151u}, MeanIn{32u * 2097151u, 32, 2097151u},
          MeanIn{32u * 1048576u, 32, 2097151u}, MeanIn{65504u, 32, 2047u}}) {
        MathCase in = op(kOpMean);
        in.op = {kOpMean, m.sum, m.k, m.scale};
        add("meanUnit/Signed sum=" + std::to_string(m.sum) + " k=" + std::to_string(m.k), {}, in,
            [m](const MathResult& r) -> std::string {
                double u = double(m.sum) / (double(m.k) * m.scale);
                if (std::string e = near("meanUnit", r.r0.x, u, 1e-6, 0.0); !e.empty()) return e;
                return near("meanSigned", r.r0.y, u * 2.0 - 1.0, 0.0, 2e-7);
            });
    }

    // ---- material normals (common/material.glsl) ----
    struct MatIn {
        const char* what;
        glm::vec3 n;
        glm::vec4 tangent;
        bool front, normalMap;
        D3 want;
    };
    for (const MatIn& m : std::vector<MatIn>{
             {"zero interpolated normal, front face", {0, 0, 0}, {1, 0, 0, 1}, true, false, {0, 0, 1}},
             {"zero interpolated normal, back face", {0, 0, 0}, {1, 0, 0, 1}, false, false, {0, 0, -1}},
             {"opposing normals cancelled to 1e-7", {1e-7f, 0, 0}, {1, 0, 0, 1}, true, false, {0, 0, 1}},
             {"denormal normal", {kDenormal, kDenormal, 0}, {1, 0, 0, 1}, true, false, {0, 0, 1}},
             {"normal map with a tangent parallel to N", {0, 0, 1}, {0, 0, 1, 1}, true, true, {0, 0, 1}},
             {"normal map with a zero tangent", {0, 0, 0.5f}, {0, 0, 0, -1}, true, true, {0, 0, 1}},
             {"short normal renormalised", {0, 0.3f, 0.4f}, {1, 0, 0, 1}, true, true, {0, 0.6, 0.8}},
         }) {
        MathCase in = op(kOpMaterial, glm::vec4(0.5f, 0.5f, 0.5f, 1), glm::vec4(0),
                         glm::vec4(0.5f, 0.7f, 1.0f, 0), glm::vec4(m.n, 0), m.tangent);
        in.op.y = m.normalMap ? 0u : uint32_t(-1);
        in.op.z = m.front ? 1u : 0u;
        add(std::string("evaluateMaterial ") + m.what, {"kMinNormalLength"}, in,
            [m](const MathResult& r) { return near3("N", glm::vec3(r.r0), m.want, 1e-5, 1e-6); });
    }

    // ---- depth (common/depth.glsl) and the Simple/Complex plane tolerance ----
    struct DepthIn {
        float d, n, f;
    };
    for (DepthIn d : {DepthIn{0, 0.1f, 10}, DepthIn{1, 0.1f, 10}, DepthIn{kDenormal, 1e-4f, 1e7f},
                      DepthIn{1, 1e-4f, 1e7f}, DepthIn{0.5f, 1e-4f, 1e7f}})
        add("viewDistanceFromDepth d=" + fmt(d.d) + " near=" + fmt(d.n) + " far=" + fmt(d.f), {},
            op(kOpDepth, glm::vec4(d.d, d.n, d.f, 0)), [d](const MathResult& r) {
                double t = double(d.n) * d.f / (double(d.d) * (double(d.f) - d.n) + d.n);
                return near("t", r.r0.x, t, 1e-5);
            });
    {
        const glm::vec4 extent(32, 32, 1.0f / 32, 1.0f / 32),
            proj(1.0f / std::tan(0.35f), 1.0f / std::tan(0.35f), 0, 0);
        struct Tol {
            const char* what;
            glm::vec3 n0;
            std::vector<std::string> guards;
        };
        for (const Tol& t : std::vector<Tol>{
                 {"face-on plane (zero slope)", {0, 0, 1}, {"kDepthCompareRelative"}},
                 {"edge-on plane (N.D = 0)", {1, 0, 0}, {"kMinCosine", "kDepthCompareRelative"}},
                 {"oblique plane", glm::normalize(glm::vec3(0.3f, 0.5f, 0.8f)), {"kDepthCompareRelative"}}}) {
            const glm::vec4 pos(16.0f, 16.0f, 2.0f,
                                1.0f); // pixel position (the centre of the image: ndc 0), t0, slope scale
            add(std::string("planeDepthTolerance ") + t.what, t.guards,
                op(kOpPlaneTolerance, extent, proj, pos, glm::vec4(t.n0, 0)),
                [t, extent, proj, pos](const MathResult& r) -> std::string {
                    D3 ndc = D3(pos.x * extent.z * 2.0 - 1.0, pos.y * extent.w * 2.0 - 1.0, 0.0);
                    D3 D(ndc.x / proj.x, ndc.y / proj.y, -1.0);
                    double dx = 2.0 * extent.z / std::abs(proj.x), dy = 2.0 * extent.w / std::abs(proj.y);
                    D3 n0(t.n0);
                    double NoD = std::max(std::abs(glm::dot(n0, D)), kMinCosine * glm::length(D));
                    double slope = pos.z * (std::abs(n0.x) * dx + std::abs(n0.y) * dy) / NoD;
                    double want = pos.w * slope + kDepthCompareRelative * pos.z;
                    if (r.r0.x < float(kDepthCompareRelative) * pos.z * 0.999f)
                        return "tolerance " + fmt(r.r0.x) + " below the relative floor " +
                               fmt(kDepthCompareRelative * pos.z);
                    return near("tolerance", r.r0.x, want, 1e-4);
                });
        }
    }
    // ---- anisotropic BRDF and SGGX (common/brdf.glsl, shared/sggx.h, common/tonemap.glsl) ----
    {
        const D3 N(0, 0, 1), T(1, 0, 0);
        const D3 V = glm::normalize(D3(0.3, -0.2, 1.0)), L = glm::normalize(D3(-0.4, 0.5, 0.8));
        struct AnisoIn {
            const char* what;
            std::vector<std::string> guards;
            double ax, ay;
            D3 V, L;
        };
        for (const AnisoIn& a : std::vector<AnisoIn>{
                 {"isotropic 0.3", {}, 0.3, 0.3, V, L},
                 {"tube-like 0.8 x 0.04", {}, 0.8, 0.04, V, L},
                 {"alphas below the floor",
                  {"kMinGgxAlpha"},
                  0.0,
                  1e-6,
                  V,
                  glm::normalize(D3(-0.3, 0.2, 1.0))},
                 {"alphas above the cap", {"kMaxGgxAlpha"}, 5.0, 2.0, V, L},
                 {"V = -L (H = 0)", {"kMinNormalLength", "kMinCosine"}, 0.5, 0.1, -L, L},
                 {"viewer below the surface",
                  {"kMinCosine"},
                  0.5,
                  0.2,
                  glm::normalize(D3(0.2, 0.1, -0.5)),
                  L},
             }) {
            MathCase in =
                op(kOpBrdfAniso, v4(D3(0.8, 0.6, 0.4), 0.5), v4(N), v4(a.V, a.ax), v4(a.L, a.ay), v4(T));
            add("evaluateBrdfAnisotropic " + std::string(a.what), a.guards, in,
                [a, N, T](const MathResult& r) {
                    D3 spec;
                    D3 want = brdfAnisotropic(D3(0.8, 0.6, 0.4), 0.5, N, T, a.ax, a.ay,
                                              glm::dvec3(glm::vec3(glm::normalize(a.V))),
                                              glm::dvec3(glm::vec3(glm::normalize(a.L))), spec);
                    if (std::string e = near3("radiance", glm::vec3(r.r0), want, 1e-4, 1e-6); !e.empty())
                        return e;
                    return near3("specular", glm::vec3(r.r1), spec, 1e-4, 1e-6);
                });
        }
        // The aggregate's BRDF with a spread of normals: the microfacet form at one normal, the
        // microflake form from 1 - kFlakeSpreadRange down (lit past the mean normal's horizon).
        struct FilteredIn {
            const char* what;
            std::vector<std::string> guards;
            double ax, ay, spread;
            D3 V, L;
        };
        const D3 below = glm::normalize(D3(0.1, 0.9, -0.2)); // past N's horizon
        for (const FilteredIn& f : std::vector<FilteredIn>{
                 {"spread 1: the microfacet form", {"kFlakeSpreadRange"}, 0.8, 0.04, 1.0, V, L},
                 {"spread 1, light past the horizon: dark", {"kFlakeSpreadRange"}, 0.8, 0.04, 1.0, V, below},
                 {"spread halfway down the ramp: the blend", {"kFlakeSpreadRange"}, 0.8, 0.04, 0.95, V, L},
                 {"spread 1 - range: the microflake form", {"kFlakeSpreadRange"}, 0.8, 0.04, 0.9, V, L},
                 {"tube lit past the mean normal's horizon",
                  {"kFlakeSpreadRange"},
                  0.7,
                  0.06,
                  0.79,
                  V,
                  below},
                 {"viewer in the tangent plane, alphas below the floor",
                  {"kFlakeSpreadRange", "kMinGgxAlpha"},
                  0.0,
                  1e-6,
                  0.5,
                  D3(1, 0, 0),
                  L},
             }) {
            MathCase in = op(kOpBrdfFiltered, v4(D3(0.8, 0.6, 0.4), 0.5), v4(N), v4(f.V, f.ax), v4(f.L, f.ay),
                             v4(T, f.spread));
            add("evaluateBrdf*Filtered " + std::string(f.what), f.guards, in, [f, N, T](const MathResult& r) {
                D3 spec;
                const D3 want = brdfFiltered(D3(0.8, 0.6, 0.4), 0.5, N, T, f.ax, f.ay, f.spread,
                                             glm::dvec3(glm::vec3(glm::normalize(f.V))),
                                             glm::dvec3(glm::vec3(glm::normalize(f.L))), spec);
                if (std::string e = near3("radiance", glm::vec3(r.r0), want, 1e-4, 1e-6); !e.empty())
                    return e;
                if (std::string e = near3("specular", glm::vec3(r.r1), spec, 1e-4, 1e-6); !e.empty())
                    return e;
                // Past the horizon only the microflake share lights the specular.
                const bool pastHorizon = glm::dot(N, f.L) <= 0.0;
                if (pastHorizon && f.spread < 1.0 && !(r.r1.x > 0.0f))
                    return std::string("no specular past the horizon");
                if (pastHorizon && f.spread >= 1.0 && r.r1 != glm::vec4(0.0f))
                    return std::string("a flat lobe lit past its horizon");
                return std::string();
            });
        }
        // With equal alphas the anisotropic BRDF is the reference's isotropic one (same lobe).
        for (double roughness : {0.2, 0.6, 1.0}) {
            const double alpha = std::clamp(roughness * roughness, kMinGgxAlpha, kMaxGgxAlpha);
            MathCase in =
                op(kOpBrdfAniso, v4(D3(0.8, 0.6, 0.4), 0.5), v4(N), v4(V, alpha), v4(L, alpha), v4(T));
            add("evaluateBrdfAnisotropic == evaluateBrdf at roughness " + fmt(roughness), {}, in,
                [roughness, N, V, L](const MathResult& r) {
                    return near3("radiance", glm::vec3(r.r0),
                                 brdf(D3(0.8, 0.6, 0.4), 0.5, N, roughness, glm::dvec3(glm::vec3(V)),
                                      glm::dvec3(glm::vec3(L)), D3(1.0)),
                                 1e-4, 1e-6);
                });
        }
    }
    {
        struct LobeIn {
            const char* what;
            std::vector<std::string> guards;
            glm::vec3 diag, off, V;
        };
        const float a2 = 0.04f * 0.04f;
        for (const LobeIn& l : std::vector<LobeIn>{
                 {"diagonal", {}, {0.25f, 0.01f, 1.0f}, {0, 0, 0}, {0, 0, 1}},
                 {"tangent eigenvalues equal to rounding (any tangent)",
                  {"kSggxDegenerate"},
                  {1e-6f, 1e-6f + 1e-9f, 1.0f},
                  {1e-10f, 0, 0},
                  {0, 0, 1}},
                 {"near side-on tube (two eigenvalues nearly tie)",
                  {},
                  {0.52f, 0.0016f, 0.48f},
                  {0.0f, 0.01f, 0.0f},
                  glm::normalize(glm::vec3(0.2f, 0.1f, 1.0f))},
                 {"tilted flat pixel",
                  {},
                  glm::vec3(0.36f * (1 - a2) + a2, a2, 0.64f * (1 - a2) + a2),
                  glm::vec3(0.0f, 0.48f * (1 - a2), 0.0f),
                  {0, 0, 1}},
                 {"two orthogonal planes",
                  {},
                  {0.5f, 0.0f, 0.5f},
                  {0, 0, 0},
                  glm::normalize(glm::vec3(1, 0, 1))},
                 {"corrupt: all zero",
                  {"kMinSggxEigenvalue", "kSggxDegenerate"},
                  {0, 0, 0},
                  {0, 0, 0},
                  {0, 0, 1}},
                 {"corrupt: tiny",
                  {"kMinSggxEigenvalue"},
                  {1e-6f, 2e-6f, 3e-6f},
                  {1e-6f, 0, 1e-6f},
                  {0, 0, 1}},
                 {"negative eigenvalue from quantisation", {}, {-1e-4f, 0.5f, 1.0f}, {0, 0, 0}, {0, 0, -1}},
             }) {
            MathCase in = op(kOpSggxLobe, glm::vec4(l.diag, 0), glm::vec4(l.off, 0), glm::vec4(l.V, 0));
            add("sggxLobe " + std::string(l.what), l.guards, in, [l](const MathResult& r) -> std::string {
                // The CPU build of the same shared function (fp32) is the twin; plus invariants:
                // orthonormal frame, normal on the viewer's side, S N = lambda N.
                const shared::SggxLobe cpu = shared::sggxLobe(l.diag.x, l.diag.y, l.diag.z, l.off.x, l.off.y,
                                                              l.off.z, l.V, 1e-12f, 0.25f);
                if (std::string e = unitLength("normal", glm::vec3(r.r0)); !e.empty()) return e;
                if (std::string e = unitLength("tangent", glm::vec3(r.r1)); !e.empty()) return e;
                if (std::abs(glm::dot(glm::vec3(r.r0), glm::vec3(r.r1))) > 1e-4f)
                    return "normal and tangent not orthogonal";
                if (glm::dot(glm::vec3(r.r0), l.V) < 0.0f) return "normal faces away from the viewer";
                if (std::string e = near("alphaT", r.r0.w, cpu.alphaT, 1e-4, 1e-5); !e.empty()) return e;
                if (std::string e = near("alphaB", r.r1.w, cpu.alphaB, 1e-4, 1e-5); !e.empty()) return e;
                if (r.r1.w > r.r0.w) return "alphaB > alphaT";
                const glm::mat3 S(l.diag.x, l.off.x, l.off.y, l.off.x, l.diag.y, l.off.z, l.off.y, l.off.z,
                                  l.diag.z);
                const glm::vec3 n(r.r0), Sn = S * n;
                if (glm::length(Sn - glm::dot(Sn, n) * n) > 1e-4f)
                    return "the normal is not an eigenvector of S";
                return {};
            });
        }
    }
    for (const auto& [L, S, var, guards] :
         std::vector<std::tuple<glm::vec3, glm::vec3, glm::vec3, std::vector<std::string>>>{
             {{0.3f, 2.0f, 50.0f}, {0.2f, 1.9f, 49.0f}, {0.0f, 0.0f, 0.0f}, {}},  // no spread: T(L)
             {{5.0f, 5.0f, 5.0f}, {4.5f, 4.5f, 4.5f}, {200.0f, 20.0f, 0.5f}, {}}, // spread highlights
             {{0.1f, 0.1f, 0.1f}, {0.0f, 1e-8f, 2e-8f}, {1.0f, 1.0f, 1.0f}, {"kMinSpikeRadiance"}},
             {{6e4f, 1.0f, 0.0f}, {6e4f, 0.5f, 0.0f}, {1e9f, 1e3f, 0.0f}, {"kMaxRadiance"}},
         }) {
        MathCase in = op(kOpToneMapAggregate, glm::vec4(L, 0), glm::vec4(S, 0), glm::vec4(var, 0),
                         glm::vec4(0.8f, 0.04f, 0.04f, 0));
        add("toneMapAggregate L=" + fmt(L.x) + " S=" + fmt(S.x) + " var=" + fmt(var.x), guards, in,
            [L, S, var](const MathResult& r) -> std::string {
                D3 want(toneMapAggregate(L.x, S.x, var.x), toneMapAggregate(L.y, S.y, var.y),
                        toneMapAggregate(L.z, S.z, var.z));
                if (std::string e = near3("E[T(L)]", glm::vec3(r.r0), want, 1e-4, 1e-6); !e.empty()) return e;
                for (int i = 0; i < 3; ++i)
                    if (r.r0[i] < 0.0f || r.r0[i] > 1.0f) return "E[T(L)] outside [0, 1]";
                const double t2 = 0.8 * 0.8;
                return near("spike ratio", r.r1.x, t2 / (0.04 * std::sqrt(2.0 * t2 - 0.04 * 0.04)), 1e-5);
            });
    }
    // The spike ratio with a material lobe narrower than both axes (issue 14): each axis
    // contributes A^2 / (a sqrt(2 A^2 - a^2)); a = alphaB leaves the narrow axis at 1.
    for (const auto& [aT, aB, a] : std::vector<std::tuple<float, float, float>>{
             {0.8f, 0.04f, 0.04f}, {0.6f, 0.5f, 0.001f}, {0.3f, 0.3f, 0.3f}, {0.9f, 0.9f, 0.001f}}) {
        MathCase in = op(kOpToneMapAggregate, glm::vec4(0.1f, 0, 0, 0), glm::vec4(0.0f), glm::vec4(0.0f),
                         glm::vec4(aT, aB, a, 0));
        add("sggxSpikeRatio alphaT=" + fmt(aT) + " alphaB=" + fmt(aB) + " material=" + fmt(a), {}, in,
            [aT, aB, a](const MathResult& r) -> std::string {
                auto axis = [](double A, double m) { return A * A / (m * std::sqrt(2.0 * A * A - m * m)); };
                return near("spike ratio", r.r1.x, axis(aT, a) * axis(aB, a), 1e-5);
            });
    }

    addFootprintCases(cases); // shader_math_footprint_cases.cpp

    // Filtered Lambert (common/brdf.glsl filteredClampedCosine, issue 14): the shader against the
    // expansion in double, and the expansion against the vMF integral it stands for; r = 1 is the
    // clamped cosine exactly (a single normal shades as before), r = 0 about the sphere's mean 1/4.
    for (double r : {0.0, 0.25, 0.5, 0.75, 0.9, 0.97, 0.99, 1.0})
        for (double x : {-1.0, -0.6, -0.2, -0.05, 0.0, 0.05, 0.2, 0.6, 1.0})
            add("filteredClampedCosine x=" + fmt(float(x)) + " r=" + fmt(float(r)), {},
                op(kOpFilteredCosine, glm::vec4(float(x), float(r), 0, 0)), [x, r](const MathResult& got) {
                    if (std::string e =
                            near("expansion", got.r0.x, agaa::test::filteredCosine(x, r), 1e-5, 2e-6);
                        !e.empty())
                        return e;
                    if (r == 1.0) return near("clamped cosine", got.r0.x, std::max(x, 0.0), 0.0, 1e-6);
                    return near("vMF integral", got.r0.x, agaa::test::vmfClampedCosine(x, r), 0.0,
                                agaa::test::kFilteredCosineModelError);
                });

    // The lobe of a mean of unit normals (common/brdf.glsl meanNormalLobe; c = 1's off-layer
    // samples, issue 14): direction and length in double; normals that cancel to within
    // kMinNormalLength take the view axis, and a fixed-point mean rounded above 1 is clamped.
    for (const auto& [mean, guards] : std::vector<std::pair<glm::vec3, std::vector<std::string>>>{
             {{0.0f, 0.0f, 0.0f}, {"kMinNormalLength"}},    // a card's two faces, cancelled
             {{5e-7f, -5e-7f, 0.0f}, {"kMinNormalLength"}}, // just inside the guard
             {{2e-6f, 0.0f, 0.0f}, {"kMinNormalLength"}},   // just outside: its own direction
             {{0.3f, -0.2f, 0.1f}, {}},                     // a spread
             {{0.0f, 0.6f, 0.8f}, {}},                      // one normal
             {{0.0f, 0.0f, 1.00003f}, {}},                  // rounded above 1
         }) {
        add("meanNormalLobe " + fmt(mean.x) + "," + fmt(mean.y) + "," + fmt(mean.z), guards,
            op(kOpMeanNormalLobe, glm::vec4(mean, 0)), [mean](const MathResult& r) -> std::string {
                const glm::dvec3 m(mean);
                const double len = glm::length(m);
                const glm::dvec3 dir = len > 1e-6 ? m / len : glm::dvec3(0.0, 0.0, 1.0);
                if (std::string e = near3("direction", glm::vec3(r.r0), dir, 1e-6, 1e-7); !e.empty())
                    return e;
                return near("length", r.r0.w, std::min(len, 1.0), 1e-6, 1e-9);
            });
    }

    // The near-mirror view footprint's weight (common/depth.glsl viewFootprintWeight, issue 14): rho
    // = theta^2 (sxx + syy) / (4 alpha^2) in double, 0 up to kViewFootprintLobeRatio, 1 from twice
    // it; a rough lobe stays at 0, a mirror at the floor alpha (and below it: kMinGgxAlpha) at 1, and
    // a covariance cancelled below 0 counts as none.
    const float theta = 0.0114f;                           // a 64-pixel image's pixel at 40 degrees
    const glm::vec3 box(1.0f / 12.0f, 0.0f, 1.0f / 12.0f); // a whole pixel's samples
    for (const auto& [alpha, S, guards] : std::vector<std::tuple<float, glm::vec3, std::vector<std::string>>>{
             {0.05f, box, {"kViewFootprintLobeRatio"}},                // rough: 0
             {1e-3f, box, {"kViewFootprintLobeRatio"}},                // the floor: 1
             {0.0f, box, {"kViewFootprintLobeRatio", "kMinGgxAlpha"}}, // below the floor
             {0.0047f, box, {"kViewFootprintLobeRatio"}},              // rho 0.245: just below the ramp, 0
             {0.0040f, box, {"kViewFootprintLobeRatio"}},              // rho 0.34: in the ramp
             {0.0032f, box, {"kViewFootprintLobeRatio"}},              // rho 0.53: above its top, 1
             {1e-3f, glm::vec3(-1e-7f, 0.0f, -1e-7f), {"kViewFootprintLobeRatio"}}, // cancelled
         }) {
        add("viewFootprintWeight alpha=" + fmt(alpha) + " sxx=" + fmt(S.x), guards,
            op(kOpViewFootprint, glm::vec4(theta, alpha, 0, 0), glm::vec4(S, 0)),
            [theta, alpha, S](const MathResult& r) -> std::string {
                const double a = std::max(double(alpha), 1e-3);
                const double rho = double(theta) * theta * std::max(double(S.x) + S.z, 0.0) / (4.0 * a * a);
                return near("weight", r.r0.x, std::clamp(rho / 0.25 - 1.0, 0.0, 1.0), 1e-5, 1e-6);
            });
    }

    addCurvatureRoughnessCases(cases); // shader_math_roughness_cases.cpp

    return cases;
}

std::vector<std::string> epsilonConstants(const std::string& path) {
    std::ifstream f(path);
    std::vector<std::string> names;
    if (!f) return names;
    const std::regex decl(R"(^\s*const\s+float\s+(k\w+)\s*=)");
    std::string line;
    while (std::getline(f, line)) {
        std::smatch m;
        if (std::regex_search(line, m, decl)) names.push_back(m[1]);
    }
    return names;
}

} // namespace agaa::hard
