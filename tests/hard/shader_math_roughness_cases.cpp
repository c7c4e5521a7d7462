// The shader-math edge cases of geometric specular anti-aliasing (issue 51): the curvature
// roughness every method's material evaluation may take, against Tokuyoshi and Kaplanyan's kernel
// in double (shader_math_cases.cpp holds the rest).

#include "shader_math_checks.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace agaa::hard {

using namespace checks;

void addCurvatureRoughnessCases(std::vector<EdgeCase>& cases) {
    auto add = [&](std::string name, std::vector<std::string> guards, MathCase in,
                   std::function<std::string(const MathResult&)> check) {
        cases.push_back({std::move(name), std::move(guards), in, std::move(check)});
    };

    // Curvature roughness (common/curvature_roughness.glsl), twin in double written from Tokuyoshi
    // and Kaplanyan (2019, listing 1): variance = sigma^2 (|dN/dx|^2 + |dN/dy|^2) with sigma^2 = 1/4,
    // kernel = min(2 variance, kappa), filtered alpha^2 = saturate(alpha^2 + kernel); the module's
    // kappa is the UE4 talk's 0.3 (max footprint) and the paper's 0.18 is a setting. Unchanged
    // below the variance floor (a flat face's interpolation rounding) and for NaN derivatives.
    for (const auto& [dx, dy, roughness, guards, maxFootprint] :
         std::vector<std::tuple<glm::vec3, glm::vec3, float, std::vector<std::string>, float>>{
             {{1e-7f, -1e-7f, 0.0f}, {0.0f, 1e-7f, 0.0f}, 0.3f, {"kMinCurvatureVariance"}, 0.3f}, // flat
             {{3e-5f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 0.3f, {"kMinCurvatureVariance"}, 0.3f}, // just above
             {{0.05f, 0.0f, 0.0f}, {0.0f, 0.02f, 0.0f}, 0.1f, {}, 0.3f},                       // a sphere
             {{2.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, 0.02f, {}, 0.3f},  // sub-pixel sphere: clamped
             {{2.0f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f}, 0.02f, {}, 0.18f}, // the paper's kappa
             {{0.3f, 0.1f, 0.0f}, {0.0f, 0.2f, 0.1f}, 0.6f, {}, 0.18f},  // rough: below the clamp
             {{3.0f, 0.0f, 0.0f}, {0.0f, 3.0f, 0.0f}, 0.95f, {}, 0.3f},  // saturated at alpha^2 = 1
             {{std::nanf(""), 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, 0.5f, {"kMinCurvatureVariance"}, 0.3f},
         }) {
        const float boost = 2.0f;
        MathCase in = op(kOpCurvature, glm::vec4(dx, 0), glm::vec4(dy, 0),
                         glm::vec4(roughness, maxFootprint, boost, 0));
        add("curvatureRoughness dx=" + fmt(dx.x) + " dy=" + fmt(dy.y) + " r=" + fmt(roughness) +
                " kappa=" + fmt(maxFootprint),
            guards, in, [dx, dy, roughness, maxFootprint](const MathResult& r) -> std::string {
                const double sigma2 = 0.25, kappa = maxFootprint;
                const double variance =
                    sigma2 * (double(dx.x) * dx.x + double(dx.y) * dx.y + double(dx.z) * dx.z +
                              double(dy.x) * dy.x + double(dy.y) * dy.y + double(dy.z) * dy.z);
                if (!(variance > 1e-10)) // exactly the material's roughness
                    return r.r0.x == roughness ? std::string()
                                               : "flat: " + fmt(r.r0.x) + " != " + fmt(roughness);
                const double a = double(roughness) * roughness;
                const double a2 = std::clamp(a * a + std::min(2.0 * variance, kappa), 0.0, 1.0);
                if (std::string e = near("filtered roughness", r.r0.x, std::pow(a2, 0.25), 1e-5); !e.empty())
                    return e;
                return r.r0.x >= roughness ? std::string() : "smoother than the material";
            });
    }
}

} // namespace agaa::hard
