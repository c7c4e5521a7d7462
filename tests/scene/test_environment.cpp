// Issue 16 on the CPU: the equirectangular mapping, the procedural sky's scale, the SH9
// irradiance against brute-force quadrature of the map, the pre-filtered levels, the default and
// fill lighting, and physical exposure.

#include "engine/frame/environment_maps.h"
#include "engine/frame/exposure.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/environment.h"
#include "engine/scene/scene_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace eng::scene;

namespace {

double luminance(const glm::dvec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

Scene sceneWithCamera() {
    Scene s;
    s.bounds = {{-1, 0, -1}, {1, 2, 1}};
    Camera c;
    c.view = glm::mat4(1.0f);
    c.view[3] = glm::vec4(0, -1, -5, 1); // at (0, 1, 5) looking down -Z
    s.cameras.push_back(c);
    return s;
}

} // namespace

TEST(Environment, EquirectMappingRoundTripsAndTexelsTileTheSphere) {
    for (float u : {0.05f, 0.3f, 0.5f, 0.77f, 0.95f})
        for (float v : {0.02f, 0.25f, 0.5f, 0.9f}) {
            const glm::vec2 back = equirectCoordinates(equirectDirection(u, v));
            EXPECT_NEAR(back.x, u, 1e-5f) << "u " << u << " v " << v;
            EXPECT_NEAR(back.y, v, 1e-5f) << "u " << u << " v " << v;
        }
    EXPECT_NEAR(equirectDirection(0.5f, 0.0f).y, 1.0f, 1e-6f) << "row 0 is the zenith";
    EXPECT_NEAR(equirectDirection(0.5f, 0.5f).z, -1.0f, 1e-6f) << "the map's centre looks down -Z";
    double sphere = 0.0;
    for (uint32_t y = 0; y < 64; ++y)
        sphere += 128.0 * equirectTexelSolidAngle(y, 128, 64);
    EXPECT_NEAR(sphere, 4.0 * std::numbers::pi, 1e-9);
}

// The sky gives its stated illuminance on a horizontal plane; the ground below reflects the sun
// and sky as a Lambertian plane of albedo 0.2 (its radiance times pi is the illuminance it sends up).
TEST(Environment, ProceduralSkyIsScaledToItsIlluminance) {
    SkySettings s;
    s.sunDirection = glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f));
    const Environment sky = proceduralSky(s);
    EXPECT_NEAR(luminance(environmentIrradiance(sky, {0, 1, 0})), double(s.skyIlluminance),
                1e-3 * s.skyIlluminance);
    const double ground = double(s.groundAlbedo) * (s.sunIlluminance * s.sunDirection.y + s.skyIlluminance);
    EXPECT_NEAR(luminance(environmentIrradiance(sky, {0, -1, 0})), ground * luminance({0.9, 0.85, 0.8}),
                1e-3 * ground);
    // The circumsolar glow: the sky is brightest towards the sun.
    const glm::vec2 towardsSun = equirectCoordinates(s.sunDirection);
    const uint32_t x = uint32_t(towardsSun.x * 128), y = uint32_t(towardsSun.y * 64);
    const glm::vec3 atSun = sky.radiance[y * 128 + x], opposite = sky.radiance[y * 128 + (x + 64) % 128];
    EXPECT_GT(luminance(atSun), 2.0 * luminance(opposite));
}

// SH9 irradiance (what every lighting pass evaluates) against brute-force quadrature of the map,
// for 200 normals over the sphere, on the default sky and on a high-contrast map. Bands 0..2 hold
// ~99 % of the clamped cosine's energy; the rest shows up where the map changes sharply.
TEST(Environment, ShIrradianceMatchesBruteForceQuadrature) {
    SkySettings settings;
    settings.sunDirection = glm::normalize(glm::vec3(-0.4f, 0.7f, 0.5f));
    Environment contrast = proceduralSky(settings);
    for (uint32_t y = 0; y < contrast.height; ++y) // a bright window in one octant
        for (uint32_t x = 0; x < 16; ++x)
            contrast.radiance[y * contrast.width + x] *= (y < 20 ? 10.0f : 1.0f);
    const Environment sky = proceduralSky(settings);
    for (const Environment* e : {&sky, static_cast<const Environment*>(&contrast)}) {
        const eng::frame::EnvironmentMaps m = eng::frame::prefilterEnvironment(*e);
        auto normal = [](int i) { // a Fibonacci sphere: even coverage without randomness
            const double z = 1.0 - 2.0 * (i + 0.5) / 200.0, r = std::sqrt(1.0 - z * z);
            const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
            return glm::dvec3(r * std::cos(phi), z, r * std::sin(phi));
        };
        double peak = 0.0, worst = 0.0, sum = 0.0;
        for (int i = 0; i < 200; ++i)
            peak = std::max(peak, luminance(environmentIrradiance(*e, normal(i))));
        for (int i = 0; i < 200; ++i) {
            const double truth = luminance(environmentIrradiance(*e, normal(i)));
            const double sh =
                luminance(glm::dvec3(eng::frame::evaluateIrradianceSh(m.irradianceSh, glm::vec3(normal(i)))));
            // Relative to the map's brightest irradiance: the SH error is absolute, so a dim side
            // of a bright map is judged against the light it could have had.
            const double err = std::abs(sh - truth) / peak;
            worst = std::max(worst, err);
            sum += err;
        }
        std::printf("[ measured ] SH9 irradiance vs quadrature (%s): max %.4f, mean %.4f of the peak\n",
                    e == &sky ? "sky" : "sky + bright window", worst, sum / 200.0);
        EXPECT_LT(worst, 0.06) << "SH9 irradiance departs from the quadrature";
        EXPECT_LT(sum / 200.0, 0.02);
    }
}

// A constant environment is its own pre-filtered map at every roughness (the filter's weights are
// normalised), and the rough levels of a map hold its mean radiance (energy is not lost or made).
TEST(Environment, PrefilteredLevelsPreserveRadiance) {
    Environment flat;
    flat.width = 128;
    flat.height = 64;
    flat.radiance.assign(128 * 64, glm::vec3(3.0f, 2.0f, 1.0f));
    const eng::frame::EnvironmentMaps maps = eng::frame::prefilterEnvironment(flat);
    ASSERT_EQ(maps.levels, shared::kEnvironmentLevels);
    for (const glm::vec3& t : maps.specular) {
        ASSERT_NEAR(t.x, 3.0f, 1e-4f);
        ASSERT_NEAR(t.z, 1.0f, 1e-4f);
    }
    const Environment sky = proceduralSky({});
    const eng::frame::EnvironmentMaps m = eng::frame::prefilterEnvironment(sky);
    for (uint32_t level = 0; level < m.levels; ++level) {
        double mean = 0.0;
        for (uint32_t y = 0; y < m.height; ++y)
            for (uint32_t x = 0; x < m.width; ++x)
                mean += luminance(glm::dvec3(m.specular[(size_t(level) * m.height + y) * m.width + x])) *
                        equirectTexelSolidAngle(y, m.width, m.height);
        double source = 0.0;
        for (uint32_t y = 0; y < sky.height; ++y)
            for (uint32_t x = 0; x < sky.width; ++x)
                source += luminance(glm::dvec3(sky.radiance[y * sky.width + x])) *
                          equirectTexelSolidAngle(y, sky.width, sky.height);
        EXPECT_NEAR(mean / source, 1.0, 0.05) << "level " << level;
    }
}

TEST(Environment, UserMapsAreBoxFilteredAndBadOnesRefusedByName) {
    std::vector<float> rgba(256 * 128 * 4, 1.0f);
    for (size_t i = 0; i < 256 * 128; ++i)
        rgba[i * 4] = (i % 2) ? 4.0f : 0.0f; // alternate columns: the box filter averages them
    const Environment e = environmentFromEquirect("sky.exr", 256, 128, rgba);
    EXPECT_EQ(e.width, 128u);
    EXPECT_EQ(e.height, 64u);
    EXPECT_FLOAT_EQ(e.radiance[0].x, 2.0f);
    EXPECT_THROW(environmentFromEquirect("square.exr", 128, 128, std::vector<float>(128 * 128 * 4)),
                 SceneError);
    rgba[5 * 4 + 1] = -1.0f;
    try {
        environmentFromEquirect("negative.exr", 256, 128, rgba);
        ADD_FAILURE() << "a negative radiance must be refused";
    } catch (const SceneError& err) {
        EXPECT_NE(std::string(err.what()).find("negative.exr: pixel (5, 0) channel G"), std::string::npos)
            << err.what();
    }
}

TEST(DefaultLighting, ASceneWithoutLightsGetsTheSunAndSky) {
    Scene s = sceneWithCamera();
    applyLighting(s, LightingMode::Automatic);
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_EQ(s.lights[0].type, LightType::Directional);
    EXPECT_FLOAT_EQ(s.lights[0].intensity, 100000.0f);
    EXPECT_TRUE(s.lights[0].castsShadows);
    EXPECT_EQ(s.lightingMode, "default");
    EXPECT_NE(s.lightingCause.find("no lights"), std::string::npos);
    EXPECT_FALSE(s.environment.empty());
    // The sun is above the horizon, behind the camera (at +Z looking down -Z): light travels -Z.
    EXPECT_LT(s.lights[0].direction.y, -0.7f);
    EXPECT_LT(s.lights[0].direction.z, 0.0f);
}

TEST(DefaultLighting, ASceneWithLightsGetsAFillSkyAtAQuarterOfTheirIlluminance) {
    Scene s = sceneWithCamera();
    Light lamp;
    lamp.type = LightType::Point;
    lamp.intensity = 100.0f; // candela, 2 m above the bounds' centre: 25 lux there
    lamp.position = {0, 3, 0};
    s.lights.push_back(lamp);
    EXPECT_NEAR(lightIlluminanceAt(s, {0, 1, 0}), 25.0, 1e-4);
    Scene fill = s;
    applyLighting(fill, LightingMode::Automatic);
    EXPECT_EQ(fill.lightingMode, "fill");
    ASSERT_EQ(fill.lights.size(), 1u) << "no sun is added";
    EXPECT_NEAR(luminance(environmentIrradiance(fill.environment, {0, 1, 0})), 25.0 * kFillRatio, 0.01);
    Scene only = s;
    applyLighting(only, LightingMode::Scene);
    EXPECT_TRUE(only.environment.empty());
    EXPECT_EQ(only.lights.size(), 1u);
    Scene both = s;
    applyLighting(both, LightingMode::Both);
    ASSERT_EQ(both.lights.size(), 2u);
    EXPECT_EQ(both.lights[0].name, "default sun") << "first, so it gets a shadow map";
    EXPECT_THROW(parseLightingMode("ambient"), std::invalid_argument);
}

// Lagarde and de Rousiers 2014: L_avg -> EV100 = log2(L_avg 100 / 12.5), exposure = 1 / (1.2 2^EV100),
// so a frame of log-average luminance L_avg is exposed to 1 / 9.6 = 0.104 (middle grey's
// neighbourhood) whatever its absolute level: a 100 klux sun and a 1 lux lamp alike.
TEST(Exposure, MeteringMapsTheLogAverageToTheSameDisplayLevel) {
    for (double L : {1e-3, 0.3, 100.0, 3e4}) {
        const double exposed = L * eng::frame::exposureFromEv100(eng::frame::ev100FromLuminance(L));
        EXPECT_NEAR(exposed, 1.0 / 9.6, 1e-6) << "L_avg " << L;
    }
    EXPECT_NEAR(eng::frame::ev100FromLuminance(4096.0), 15.0, 1e-9)
        << "4096 cd/m^2 (sunny 16) is EV 15: 4096 * 8 = 2^15";
    // Geometric mean over covered pixels only, brought back from the exposure it was rendered at.
    const std::vector<float> rgba = {2, 2, 2, 1, 8, 8, 8, 1, 1000, 1000, 1000, 1};
    const std::vector<uint32_t> covered = {1, 1, 0};
    EXPECT_NEAR(eng::frame::logAverageLuminance(rgba, covered, 2.0f), 2.0, 1e-5) << "sqrt(1 * 4)";
    EXPECT_NEAR(eng::frame::logAverageLuminance(rgba, std::vector<uint32_t>{0, 0, 0}, 1.0f),
                std::cbrt(2.0 * 8.0 * 1000.0), 1e-3)
        << "nothing covered: every pixel";
    EXPECT_GT(eng::frame::logAverageLuminance(std::vector<float>{0, 0, 0, 1}, std::vector<uint32_t>{1}, 1.0f),
              0.0)
        << "a black frame: the floor, not log(0)";
    Scene dark = sceneWithCamera();
    EXPECT_FLOAT_EQ(eng::frame::meteringExposure(dark), 1.0f) << "no light at all";
}
