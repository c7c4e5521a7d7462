// Issue 15's light-count axis on the CPU: the generated lights' count, placement (inside the
// grown bounds, spread evenly), intensity (the key light's illuminance at the neighbourhood's
// edge), determinism and refusals.

#include "engine/scene/extra_lights.h"
#include "engine/scene/scenegen.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace eng::scene;

namespace {

Scene sceneWithSun(float lux) {
    Scene s;
    s.bounds = {{-2, 0, -1}, {2, 1, 3}};
    Light sun;
    sun.type = LightType::Directional;
    sun.intensity = lux;
    sun.color = {0.5f, 1.0f, 0.25f}; // the brightest channel counts
    s.lights.push_back(sun);
    return s;
}

} // namespace

TEST(ExtraLights, RadicalInverseIsTheHaltonSequence) {
    // Written out by hand: 1 = 0.1b, 2 = 0.01b, 3 = 0.11b, 6 = 0.011b; base 3: 1 -> 1/3, 4 = 11t -> 4/9.
    EXPECT_DOUBLE_EQ(radicalInverse(0, 2), 0.0);
    EXPECT_DOUBLE_EQ(radicalInverse(1, 2), 0.5);
    EXPECT_DOUBLE_EQ(radicalInverse(2, 2), 0.25);
    EXPECT_DOUBLE_EQ(radicalInverse(3, 2), 0.75);
    EXPECT_DOUBLE_EQ(radicalInverse(6, 2), 0.375);
    EXPECT_NEAR(radicalInverse(1, 3), 1.0 / 3.0, 1e-15);
    EXPECT_NEAR(radicalInverse(4, 3), 4.0 / 9.0, 1e-15);
    EXPECT_NEAR(radicalInverse(7, 5), 2.0 / 5.0 + 1.0 / 25.0, 1e-15); // 7 = 12 in base 5
}

TEST(ExtraLights, KeyLightIsTheBrightestSingleLightAtTheCentre) {
    Scene s = sceneWithSun(3.0f);
    EXPECT_DOUBLE_EQ(keyLightIlluminance(s), 3.0);
    Light point;
    point.intensity = 50.0f;
    point.position = 0.5f * (s.bounds.min + s.bounds.max) + glm::vec3(0, 0, 2); // 2 m away: 12.5 lux
    s.lights.push_back(point);
    EXPECT_NEAR(keyLightIlluminance(s), 12.5, 1e-5) << "the point light outshines the sun at the centre";
    EXPECT_DOUBLE_EQ(keyLightIlluminance(Scene{}), 0.0);
}

TEST(ExtraLights, CountPlacementAndIntensity) {
    for (uint32_t k : {1u, 4u, 16u, 64u}) {
        Scene s = sceneWithSun(3.0f);
        addExtraLights(s, k);
        ASSERT_EQ(s.lights.size(), size_t(k) + 1) << "K lights appended after the scene's own";
        EXPECT_EQ(s.lights[0].type, LightType::Directional) << "the scene's own light is untouched";
        // The grown box: bounds 4 x 1 x 4, diagonal sqrt(33), margin 0.1 of it on each side.
        const float margin = 0.1f * std::sqrt(33.0f);
        const glm::vec3 lo = s.bounds.min - margin, hi = s.bounds.max + margin;
        const glm::vec3 size = hi - lo;
        const float radius = 0.5f * std::cbrt(size.x * size.y * size.z / float(k));
        for (uint32_t i = 1; i <= k; ++i) {
            const Light& l = s.lights[i];
            EXPECT_EQ(l.type, LightType::Point);
            EXPECT_FALSE(l.castsShadows);
            EXPECT_EQ(l.name, "extra." + std::to_string(i - 1));
            for (int a = 0; a < 3; ++a) {
                EXPECT_GE(l.position[a], lo[a] - 1e-4f) << "light " << i << " axis " << a;
                EXPECT_LE(l.position[a], hi[a] + 1e-4f) << "light " << i << " axis " << a;
            }
            // At the neighbourhood's edge a light gives the key light's illuminance (3 lux).
            EXPECT_NEAR(l.intensity / (radius * radius), 3.0f, 3e-4f) << "K " << k;
            EXPECT_NEAR(l.range, 4.0f * radius, 1e-4f * radius);
        }
        if (k == 64) {
            // Low discrepancy: every half of the box along every axis holds about half the lights.
            for (int a = 0; a < 3; ++a) {
                uint32_t lower = 0;
                for (uint32_t i = 1; i <= k; ++i)
                    lower += s.lights[i].position[a] < lo[a] + 0.5f * size[a];
                EXPECT_GE(lower, 28u) << "axis " << a;
                EXPECT_LE(lower, 36u) << "axis " << a;
            }
        }
    }
}

TEST(ExtraLights, DeterministicAndZeroAddsNothing) {
    Scene a = loadBuiltin("foliage"), b = loadBuiltin("foliage");
    const size_t own = a.lights.size();
    addExtraLights(a, 0);
    EXPECT_EQ(a.lights.size(), own);
    addExtraLights(a, 16);
    addExtraLights(b, 16);
    ASSERT_EQ(a.lights.size(), own + 16);
    ASSERT_EQ(b.lights.size(), a.lights.size());
    for (size_t i = own; i < a.lights.size(); ++i) {
        EXPECT_EQ(a.lights[i].position, b.lights[i].position) << "light " << i;
        EXPECT_EQ(a.lights[i].intensity, b.lights[i].intensity) << "light " << i;
    }
    // The first 4 of 16 are where 4 of 4 would be (a prefix of the sequence), only dimmer.
    Scene c = loadBuiltin("foliage");
    addExtraLights(c, 4);
    for (size_t i = own; i < c.lights.size(); ++i) {
        EXPECT_EQ(c.lights[i].position, a.lights[i].position);
        EXPECT_GT(c.lights[i].intensity, a.lights[i].intensity) << "fewer lights, larger neighbourhoods";
    }
}

TEST(ExtraLights, NoLightAndPointBoundsStillGetFiniteLights) {
    Scene s; // no light: 1 lux; bounds a point: a 1 m box
    addExtraLights(s, 8);
    ASSERT_EQ(s.lights.size(), 8u);
    for (const Light& l : s.lights) {
        EXPECT_TRUE(std::isfinite(l.intensity) && l.intensity > 0.0f);
        EXPECT_NEAR(l.intensity, 0.25f * 0.25f, 1e-6f) << "r = 0.5 (1/8)^(1/3) = 0.25, E = 1 lux";
        EXPECT_LE(std::abs(l.position.x), 1.0f);
    }
}

TEST(ExtraLights, RefusesMoreThanTheMaximum) {
    Scene s = sceneWithSun(1.0f);
    try {
        addExtraLights(s, kMaxExtraLights + 1);
        FAIL() << "1001 lights were accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("--extra-lights '1001' is not an integer in 0..1000"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_EQ(s.lights.size(), 1u) << "a refusal adds nothing";
}
