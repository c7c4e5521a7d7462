#pragma once
// Shared by the hard-case frame tests: the firefly bound a scene allows, and image checks.

#include "engine/frame/frame_constants.h"
#include "engine/io/image.h"
#include "engine/scene/scene.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace agaa::hard {

// Guard values of shaders/glsl/common/epsilon.glsl the bound depends on.
inline constexpr double kMinGgxAlpha = 1.0e-3, kMaxGgxAlpha = 0.9, kMinLightDistance2 = 1.0e-4,
                        kMaxRadiance = 6.0e4;

// The brightest linear HDR value any pixel of `scene` may reach, derived from the scene:
//  - every method resolves a pixel as sum_s w_s L_s with sample weights w_s >= 0, sum w_s <= 1
//    (DESIGN section 6), so a pixel is bounded by its brightest shading event or the sky;
//  - an event is min(kMaxRadiance, exposure (emissive + sum_lights f N.L E));
//  - f N.L <= 1/pi (Lambert, albedo <= 1) + F D Vis N.L with F <= 1, D <= 1/(pi a^2) and
//    Vis N.L <= 0.5 / a (the height-correlated Smith term: gv >= N.L a), a the smallest GGX alpha
//    of the scene's materials after the BRDF's clamp (AGAA's Toksvig filtering only widens
//    lobes: the mean of unit-or-shorter vectors is no longer than the longest);
//  - E <= colour * intensity for a directional light and colour * intensity / max(d^2,
//    kMinLightDistance2) for a point or spot light, d the distance from the light to the
//    scene's bounding box (0 when inside): the range window and the spot cone are <= 1;
//  - an environment (issue 16) adds at most its brightest radiance L_env twice: diffuse
//    (albedo / pi) E with E <= pi L_env, and specular <= L_env times a directional albedo <= 1;
//    10 % headroom covers SH9's ringing (measured <= 3 % of the peak irradiance); the sky is
//    then at most L_env.
// 1 % headroom covers AGAA's fixed-point quantisation of the Toksvig length.
inline double hdrBound(const eng::scene::Scene& scene, const eng::frame::ViewSettings& view) {
    double emissive = 0.0, alpha = kMaxGgxAlpha;
    for (const auto& m : scene.materials) {
        const glm::vec3 e = m.emissiveFactor * m.emissiveStrength;
        emissive = std::max({emissive, double(e.x), double(e.y), double(e.z)});
        const double r = m.metallicRoughnessTexture >= 0 ? 0.0 : double(m.roughnessFactor);
        alpha = std::min(alpha, std::clamp(r * r, kMinGgxAlpha, kMaxGgxAlpha));
    }
    const double pi = 3.14159265358979;
    const double brdf = 1.0 / pi + 0.5 / (pi * alpha * alpha * alpha);
    double irradiance = 0.0;
    for (const auto& l : scene.lights) {
        const double c = std::max({l.color.x, l.color.y, l.color.z}) * double(l.intensity);
        if (l.type == eng::scene::LightType::Directional) {
            irradiance += c;
            continue;
        }
        const glm::vec3 q = glm::clamp(l.position, scene.bounds.min, scene.bounds.max);
        const double d2 = double(glm::dot(q - l.position, q - l.position));
        irradiance += c / std::max(d2, kMinLightDistance2);
    }
    double environment = 0.0;
    for (const glm::vec3& t : scene.environment.radiance)
        environment = std::max({environment, double(t.x), double(t.y), double(t.z)});
    const double event =
        std::min(kMaxRadiance, double(view.exposure) * (emissive + brdf * irradiance + 2.2 * environment));
    const double sky = view.exposure * std::max({double(view.skyRadiance.x), double(view.skyRadiance.y),
                                                 double(view.skyRadiance.z), environment});
    return std::max(event * 1.01, sky * (1.0 + 1e-6));
}

struct RangeReport {
    size_t nonFinite = 0, negative = 0, aboveBound = 0;
    double maxValue = 0.0;
    std::string first; // "pixel (x, y) channel c = v" of the first violation
};

// Checks the rgb channels of every pixel: finite, >= 0, <= bound.
inline RangeReport checkRange(const eng::io::ImageF& img, double bound) {
    RangeReport r;
    for (size_t i = 0; i < img.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const float v = img.rgba[i];
        const bool bad = !std::isfinite(v) || v < 0.0f || double(v) > bound;
        r.nonFinite += !std::isfinite(v);
        r.negative += v < 0.0f;
        r.aboveBound += std::isfinite(v) && double(v) > bound;
        if (std::isfinite(v)) r.maxValue = std::max(r.maxValue, double(v));
        if (bad && r.first.empty()) {
            const size_t p = i / 4;
            r.first = "pixel (" + std::to_string(p % img.width) + ", " + std::to_string(p / img.width) +
                      ") channel " + std::to_string(i % 4) + " = " + std::to_string(v);
        }
    }
    return r;
}

} // namespace agaa::hard
