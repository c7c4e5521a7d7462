// Issue 16 on lavapipe with validation: environment lighting against a brute-force integral of
// the BRDF over the map (written here from the glTF BRDF, sharing nothing with the shaders), and
// every shared real scene (../shared/scenes) readable with every method under the lighting and
// exposure users get by default.

#include "agaa/methods.h"
#include "engine/io/tone_map.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/environment.h"
#include "engine/scene/gltf_loader.h"
#include "gpu_test_support.h"
#include "tools/harness/frame_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>

namespace {

namespace fs = std::filesystem;
using eng::scene::Scene;
constexpr double kPi = std::numbers::pi;

// The glTF metallic-roughness BRDF (glTF 2.0 appendix B) times N.L, in double: GGX D,
// height-correlated Smith visibility, Schlick Fresnel, Lambert diffuse weighted by 1 - F.
glm::dvec3 brdfTimesCosine(const glm::dvec3& N, const glm::dvec3& V, const glm::dvec3& L,
                           const glm::dvec3& albedo, double metallic, double roughness) {
    const double NoL = glm::dot(N, L), NoV = glm::dot(N, V);
    if (NoL <= 0.0 || NoV <= 0.0) return glm::dvec3(0.0);
    const glm::dvec3 H = glm::normalize(V + L);
    const double NoH = glm::dot(N, H), VoH = glm::dot(V, H);
    const double a = roughness * roughness, a2 = a * a;
    const double d = NoH * NoH * (a2 - 1.0) + 1.0;
    const double D = a2 / (kPi * d * d);
    const double vis =
        0.5 / (NoL * std::sqrt(NoV * NoV * (1.0 - a2) + a2) + NoV * std::sqrt(NoL * NoL * (1.0 - a2) + a2));
    const glm::dvec3 f0 = glm::mix(glm::dvec3(0.04), albedo, metallic);
    const glm::dvec3 F = f0 + (1.0 - f0) * std::pow(1.0 - VoH, 5.0);
    const glm::dvec3 diffuse = (1.0 - F) * (1.0 - metallic) * albedo / kPi;
    return (diffuse + F * D * vis) * NoL;
}

// Outgoing radiance towards V from the whole map: the sum over its texels of L f N.L dw.
glm::dvec3 bruteForceRadiance(const eng::scene::Environment& env, const glm::dvec3& N, const glm::dvec3& V,
                              const glm::dvec3& albedo, double metallic, double roughness) {
    glm::dvec3 sum(0.0);
    for (uint32_t y = 0; y < env.height; ++y) {
        const double dw = eng::scene::equirectTexelSolidAngle(y, env.width, env.height);
        for (uint32_t x = 0; x < env.width; ++x) {
            const glm::dvec3 L(
                eng::scene::equirectDirection((x + 0.5f) / float(env.width), (y + 0.5f) / float(env.height)));
            sum += glm::dvec3(env.radiance[size_t(y) * env.width + x]) *
                   brdfTimesCosine(N, V, L, albedo, metallic, roughness) * dw;
        }
    }
    return sum;
}

// The wall's material in the environment tests' cases.
struct WallMaterial {
    const char* name;
    glm::vec3 albedo;
    float metallic, roughness;
};

// A wall facing the camera (world = view) of one material, lit by the procedural sky alone, the
// sun's glow in front of it (what the wall reflects).
Scene skyWall(const WallMaterial& m) {
    Scene s = agaa::test::emptyScene("environment wall");
    s.lights.clear();
    s.materials[0].baseColorFactor = glm::vec4(m.albedo, 1.0f);
    s.materials[0].metallicFactor = m.metallic;
    s.materials[0].roughnessFactor = m.roughness;
    agaa::test::addRectangle(s, {-10, -10}, {10, 10}, -2.0f, 0);
    eng::scene::SkySettings sky;
    sky.sunDirection = glm::normalize(glm::vec3(0.3f, 0.6f, 0.74f));
    s.environment = eng::scene::proceduralSky(sky);
    return s;
}

} // namespace

// A wall facing the camera (world = view), lit by the procedural sky alone: what every method's
// lighting returns (SH9 irradiance + split-sum pre-filtered specular with the integrated BRDF
// table) against the brute-force integral, for metals under a constant sky and a dielectric and a
// metal under the procedural sky. The tolerances are the measured errors of the approximations,
// printed.
TEST(EnvironmentGpu, EveryMethodMatchesABruteForceIntegralOfTheBrdfOverTheMap) {
    auto device = agaa::test::makeValidatedDevice();
    struct Case {
        WallMaterial m;
        bool constantSky;
        double tolerance;
    } cases[] = {// A constant sky: the split sum is exact there but for the table's and the filter's own
                 // error (measured: <= 0.9 %).
                 {{"metal, flat sky", {0.9f, 0.7f, 0.5f}, 1.0f, 0.6f}, true, 0.02},
                 {{"glossy metal, flat", {0.9f, 0.7f, 0.5f}, 1.0f, 0.3f}, true, 0.02},
                 // The procedural sky: the split sum's separation of the lobe from the light it
                 // gathers (n = v = r, and the horizon's step inside a rough lobe) is the error
                 // (measured: 2.7 % dielectric, 9.9 % rough metal; the flat cases show the rest
                 // is not the implementation).
                 {{"rough dielectric", {0.6f, 0.5f, 0.4f}, 0.0f, 0.7f}, false, 0.04},
                 {{"rough metal", {0.9f, 0.7f, 0.5f}, 1.0f, 0.6f}, false, 0.12}};
    for (const Case& wall : cases) {
        const WallMaterial& c = wall.m;
        Scene s = skyWall(c);
        if (wall.constantSky)
            std::fill(s.environment.radiance.begin(), s.environment.radiance.end(), glm::vec3(5000.0f));
        agaa::FrameRenderer renderer(*device, s);
        for (const char* method :
             {"reference", "noaa", "simple-complex", "agaa-accumulate", "agaa-samples"}) {
            agaa::RenderRequest r;
            r.method = method;
            r.view.width = r.view.height = 32;
            r.view.exposure = 1e-3f;
            const agaa::RenderResult out = renderer.render(r);
            const shared::FrameConstants k =
                eng::frame::makeFrameConstants(s, r.view, eng::frame::makeSamplePattern(out.samples));
            double worst = 0.0;
            for (uint32_t py : {4u, 16u, 27u})
                for (uint32_t px : {4u, 16u, 27u}) {
                    const double ndcX = (px + 0.5) / 32.0 * 2.0 - 1.0, ndcY = (py + 0.5) / 32.0 * 2.0 - 1.0;
                    const glm::dvec3 ray =
                        glm::normalize(glm::dvec3(ndcX / k.projParams.x, ndcY / k.projParams.y, -1.0));
                    const glm::dvec3 truth =
                        bruteForceRadiance(s.environment, {0, 0, 1}, -ray, glm::dvec3(c.albedo), c.metallic,
                                           c.roughness) *
                        double(r.view.exposure);
                    const float* got = &out.hdr.rgba[(size_t(py) * 32 + px) * 4];
                    for (int ch = 0; ch < 3; ++ch)
                        worst = std::max(worst, std::abs(got[ch] - truth[ch]) / truth[ch]);
                }
            std::printf("[ measured ] %-16s %-16s worst relative error vs the brute-force integral %.4f\n",
                        c.name, method, worst);
            EXPECT_LT(worst, wall.tolerance) << c.name << ", " << method;
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Mirrors (roughness exactly 0, chrome and a dielectric) and a near-mirror facing the camera,
// under the procedural sky whose sun glow they reflect: every aggregate has one normal, so AGAA
// must read the pre-filtered map as the per-sample reference does, level 0 for roughness 0. With
// the punctual BRDF's alpha floor in its roughness it read level sqrt(kMinGgxAlpha) = 0.03 of the
// chain and blurred the reflection (issue 14; common/environment.glsl
// environmentAggregateRoughness). Compared pixel by pixel, relative to the reference.
TEST(EnvironmentGpu, MirrorsReflectTheEnvironmentUnblurred) {
    auto device = agaa::test::makeValidatedDevice();
    const WallMaterial cases[] = {{"chrome, roughness 0", {0.95f, 0.95f, 0.95f}, 1.0f, 0.0f},
                                  {"dielectric, roughness 0", {0.1f, 0.3f, 0.8f}, 0.0f, 0.0f},
                                  {"gold, roughness 0.02", {1.0f, 0.8f, 0.4f}, 1.0f, 0.02f},
                                  {"gold, roughness 0.05", {1.0f, 0.8f, 0.4f}, 1.0f, 0.05f}};
    for (const WallMaterial& c : cases) {
        const Scene s = skyWall(c);
        agaa::FrameRenderer renderer(*device, s);
        auto render = [&](const char* method) {
            agaa::RenderRequest r;
            r.method = method;
            r.settings.samples = 8;
            r.view.width = r.view.height = 32;
            r.view.exposure = 1e-3f;
            return renderer.render(r);
        };
        const agaa::RenderResult ref = render("reference");
        for (const char* method : {"agaa-accumulate", "agaa-samples"}) {
            const agaa::RenderResult out = render(method);
            double worst = 0.0;
            for (size_t i = 0; i < ref.hdr.rgba.size(); ++i)
                if (i % 4 != 3)
                    worst = std::max(worst, std::abs(double(out.hdr.rgba[i]) - ref.hdr.rgba[i]) /
                                                std::max(double(ref.hdr.rgba[i]), 1e-6));
            std::printf("[ measured ] %-24s %-16s worst relative difference from the reference %.5f\n",
                        c.name, method, worst);
            EXPECT_LT(worst, 0.01) << c.name << ", " << method;
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Every shared real scene with every method, at the settings a user gets without flags (lighting
// auto, exposure metered): finite, validation-clean, and readable: the mean of the displayed
// (sRGB-encoded) covered pixels in [0.1, 0.9], neither black nor white.
TEST(EnvironmentGpu, EverySharedSceneIsReadableWithEveryMethod) {
    const fs::path dir = AGAA_SHARED_SCENES_DIR;
    const char* files[] = {"dutch_ship_medium/dutch_ship_medium_1k.gltf",
                           "MixedLightingExample/MixedLightingExample.gltf", "Cubes/Cubes.glb"};
    if (!fs::exists(dir / files[0])) GTEST_SKIP() << dir << " is missing (AGAA_SHARED_SCENES_DIR)";
    auto device = agaa::test::makeValidatedDevice();
    for (const char* file : files) {
        Scene s = eng::scene::loadGltf(dir / file);
        eng::scene::applyLighting(s, eng::scene::LightingMode::Automatic);
        agaa::FrameRenderer renderer(*device, s);
        for (const agaa::MethodInfo& m : agaa::knownMethods()) {
            agaa::RenderRequest r;
            r.method = m.name;
            r.view.width = r.view.height = 64;
            r.autoExposure = true;
            const agaa::RenderResult out = renderer.render(r);
            ASSERT_TRUE(eng::io::allFinite(out.hdr) && eng::io::allFinite(out.display))
                << file << " " << m.name;
            const eng::io::ImageF shown = eng::io::srgbEncoded(out.display);
            double sum = 0.0;
            size_t covered = 0;
            for (size_t i = 0; i < out.shadingEvents.size(); ++i) {
                if (out.shadingEvents[i] == 0) continue;
                const float* p = &shown.rgba[i * 4];
                sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
                ++covered;
            }
            ASSERT_GT(covered, 0u) << file << " " << m.name << ": no geometry in view";
            const double mean = sum / double(covered);
            std::printf(
                "[ measured ] %-48s %-22s EV100 %6.2f, displayed mean of %4zu covered pixels %.3f (%s)\n",
                file, m.name.c_str(), out.meteredEv100.value_or(0.0), covered, mean, s.lightingMode.c_str());
            EXPECT_GE(mean, 0.1) << file << " " << m.name << ": too dark";
            EXPECT_LE(mean, 0.9) << file << " " << m.name << ": blown out";
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}
