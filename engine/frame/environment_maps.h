#pragma once
// An environment pre-filtered for shading (issue 16), on the CPU, once per scene:
//   - diffuse: the irradiance E(n) = int L(w) max(n.w, 0) dw as 9 spherical-harmonic
//     coefficients (bands 0..2; Ramamoorthi and Hanrahan 2001, "An Efficient Representation for
//     Irradiance Environment Maps": the clamped cosine keeps ~99 % of its energy in these bands);
//   - specular: the split-sum pre-filtered radiance (Karis 2013, "Real Shading in Unreal Engine
//     4"): for each direction R and perceptual roughness r_k = k / (levels - 1), the mean of L(l)
//     weighted by D_GGX(n.h; r_k^2) max(n.l, 0) with n = v = R, h = normalize(n + l) (the
//     estimator of GGX importance sampling under n = v = R). Level 0 is the map itself.
// common/environment.glsl reads both; the BRDF's half of the split sum is Karis's analytic fit.

#include "engine/scene/environment.h"
#include "shared/environment.h"

#include <array>
#include <vector>

namespace eng::frame {

struct EnvironmentMaps {
    std::array<glm::vec3, 9> irradianceSh{}; // E(n) = sum_i c_i Y_i(n), lux
    uint32_t width = 0, height = 0;          // of every level
    uint32_t levels = 0;
    std::vector<glm::vec3> specular; // levels x height x width radiance, cd/m^2
};

// The 9 real spherical harmonics Y_0..Y_8 at unit direction n (band 0, band 1 y z x,
// band 2 xy yz (3z^2-1) xz (x^2-y^2)).
std::array<float, 9> shBasis(const glm::vec3& n);
glm::vec3 evaluateIrradianceSh(const std::array<glm::vec3, 9>& sh, const glm::vec3& n);

EnvironmentMaps prefilterEnvironment(const scene::Environment& env,
                                     uint32_t levels = shared::kEnvironmentLevels);

// The BRDF's half of the split sum for GGX with height-correlated Smith visibility (the BRDF of
// common/brdf.glsl): the directional albedo is F0 * A + B, A = int D Vis N.L (1 - Fc),
// B = int D Vis N.L Fc, Fc = (1 - V.H)^5, integrated by GGX importance sampling (1024 Hammersley
// points). Texel (i, j) of the size x size table holds (A, B) at N.V = (i + 0.5) / size and
// perceptual roughness (j + 0.5) / size.
inline constexpr uint32_t kDfgTableSize = 32;
std::vector<glm::vec2> integrateDfgTable(uint32_t size = kDfgTableSize);
glm::dvec2 integrateDfg(double NoV, double roughness, uint32_t samples = 1024);

// The constants lighting reads (texel scale, levels, the SH), for maps; absent maps give the
// constants of "no environment".
shared::EnvironmentConstants makeEnvironmentConstants(const EnvironmentMaps* maps, float texelScale);

} // namespace eng::frame
