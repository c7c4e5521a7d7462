// Issue 8, CPU side: what a scene calls for (engine/scene/scene_features.h), the variants each
// feature selects (agaa/common/effects.h), and the shadow-map fit (agaa/common/shadow_map.h).

#include "agaa/common/effects.h"
#include "agaa/common/shadow_map.h"
#include "engine/scene/scene_features.h"
#include "tools/scenes/adversarial_scenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace {

using eng::scene::AlphaMode;
using eng::scene::Light;
using eng::scene::LightType;
using eng::scene::Scene;

Scene oneDrawScene() {
    Scene s;
    s.source = "test";
    s.vertices.resize(3);
    s.indices = {0, 1, 2};
    s.materials.push_back({});
    s.draws.push_back({0, 3, 0});
    s.bounds = {{-1, -1, -1}, {1, 1, 1}};
    return s;
}

Light light(LightType type, bool shadows, const char* name = "") {
    Light l;
    l.name = name;
    l.type = type;
    l.castsShadows = shadows;
    l.direction = glm::normalize(glm::vec3(0.3f, -1.0f, -0.2f));
    l.position = {0, 5, 0};
    return l;
}

const agaa::VariantChoice& variant(const std::vector<agaa::VariantChoice>& v, const std::string& effect) {
    auto it =
        std::find_if(v.begin(), v.end(), [&](const agaa::VariantChoice& c) { return c.effect == effect; });
    EXPECT_NE(it, v.end()) << "no variant for " << effect;
    static const agaa::VariantChoice none{};
    return it == v.end() ? none : *it;
}

TEST(SceneFeatures, EmptyOfEffectsWhenTheSceneHasNone) {
    Scene s = oneDrawScene();
    s.lights.push_back(light(LightType::Directional, false));
    const auto f = eng::scene::deriveSceneFeatures(s);
    // Guards: a plain opaque scene asks for no shadow, alpha, emissive, normal-map or culling work.
    EXPECT_FALSE(f.hasShadows());
    EXPECT_FALSE(f.hasMasked());
    EXPECT_FALSE(f.hasEmissive());
    EXPECT_FALSE(f.hasNormalMaps());
    EXPECT_FALSE(f.needsLightCulling());
    EXPECT_EQ(f.directionalLights, 1u);
    const auto v = agaa::effectVariants(f, agaa::sceneTraits(s), 8, 4);
    EXPECT_EQ(variant(v, "shadows").variant, "off");
    EXPECT_EQ(variant(v, "alpha").variant, "opaque only");
    EXPECT_EQ(variant(v, "emissive").variant, "off");
    EXPECT_EQ(variant(v, "normal-maps").variant, "off");
    EXPECT_EQ(variant(v, "light-culling").variant, "off");
}

TEST(SceneFeatures, ShadowedLightsAreDirectionalOrSpotAndCapped) {
    Scene s = oneDrawScene();
    s.lights.push_back(light(LightType::Point, true, "bulb")); // cube maps unsupported: ignored, counted
    s.lights.push_back(light(LightType::Directional, true, "sun"));
    s.lights.push_back(light(LightType::Spot, true, "torch"));
    s.lights.push_back(light(LightType::Spot, false, "fill"));
    for (int i = 0; i < 4; ++i)
        s.lights.push_back(light(LightType::Directional, true));
    const auto f = eng::scene::deriveSceneFeatures(s);
    ASSERT_EQ(f.shadowedLights.size(), eng::scene::kMaxShadowedLights);
    EXPECT_EQ(f.shadowedLights[0], 1u);          // sun
    EXPECT_EQ(f.shadowedLights[1], 2u);          // torch
    EXPECT_EQ(f.shadowedLightsIgnored, 1u + 2u); // the point light and two over the cap
    EXPECT_TRUE(f.needsLightCulling());          // point and spot lights exist
    EXPECT_EQ(f.pointLights, 1u);
    EXPECT_EQ(f.spotLights, 2u);
    const auto v = agaa::effectVariants(f, agaa::sceneTraits(s), 8, 3);
    EXPECT_NE(variant(v, "shadows").cause.find("'sun'"), std::string::npos) << variant(v, "shadows").cause;
    EXPECT_NE(variant(v, "shadows").variant.find("3 taps"), std::string::npos);
}

TEST(SceneFeatures, MaterialsCountOnlyWhenADrawUsesThem) {
    Scene s = oneDrawScene();
    eng::scene::Material masked;
    masked.alphaMode = AlphaMode::Mask;
    masked.emissiveFactor = {1, 0, 0};
    masked.normalTexture = 0;
    s.materials.push_back(masked); // material 1: no draw uses it
    auto f = eng::scene::deriveSceneFeatures(s);
    EXPECT_FALSE(f.hasMasked());
    EXPECT_FALSE(f.hasEmissive());
    EXPECT_FALSE(f.hasNormalMaps());
    s.draws.push_back({0, 3, 1});
    f = eng::scene::deriveSceneFeatures(s);
    EXPECT_EQ(f.maskedMaterials, 1u);
    EXPECT_EQ(f.emissiveMaterials, 1u);
    EXPECT_EQ(f.normalMappedMaterials, 1u);
    // Emissive strength 0 switches emission off.
    s.materials[1].emissiveStrength = 0.0f;
    EXPECT_FALSE(eng::scene::deriveSceneFeatures(s).hasEmissive());
    // An empty draw does not count either.
    s.draws.back().indexCount = 0;
    EXPECT_FALSE(eng::scene::deriveSceneFeatures(s).hasMasked());
}

TEST(SceneFeatures, AlphaPathIsCoverageWithMsaaAndDiscardAtOneSample) {
    Scene s = oneDrawScene();
    s.materials[0].alphaMode = AlphaMode::Mask;
    const auto f = eng::scene::deriveSceneFeatures(s);
    EXPECT_EQ(variant(agaa::effectVariants(f, agaa::sceneTraits(s), 8, 4), "alpha").variant,
              "alpha-to-coverage");
    EXPECT_EQ(variant(agaa::effectVariants(f, agaa::sceneTraits(s), 4, 4), "alpha").variant,
              "alpha-to-coverage");
    EXPECT_EQ(variant(agaa::effectVariants(f, agaa::sceneTraits(s), 1, 4), "alpha").variant, "discard");
    EXPECT_EQ(agaa::maskedAlphaPath(1), agaa::AlphaPath::Discard);
    EXPECT_EQ(agaa::maskedAlphaPath(8), agaa::AlphaPath::Coverage);
}

TEST(SceneFeatures, ForcingTurnsEveryEffectOn) {
    Scene s = oneDrawScene();
    s.lights.push_back(light(LightType::Directional, false, "sun"));
    agaa::EffectSettings settings;
    settings.forceAll = true;
    const auto f = agaa::effectiveFeatures(agaa::sceneTraits(s), settings);
    EXPECT_TRUE(f.forced);
    EXPECT_TRUE(f.hasShadows() && f.hasMasked() && f.hasEmissive() && f.hasNormalMaps() &&
                f.needsLightCulling());
    // The forced specialisation switches every effect constant on.
    const eng::vk::Specialization spec = agaa::effectSpecialization(f, 4);
    EXPECT_TRUE(spec.values.empty()) << "every id by name";
    auto value = [&](uint32_t id) -> int64_t {
        for (const auto& [i, v] : spec.byId)
            if (i == id) return v;
        return -1;
    };
    EXPECT_EQ(value(agaa::kSpecTileLightCulling), 1);
    EXPECT_EQ(value(agaa::kSpecNormalMaps), 1);
    EXPECT_EQ(value(agaa::kSpecEmissive), 1);
    EXPECT_EQ(value(agaa::kSpecShadowTaps), 4);
    EXPECT_NE(variant(agaa::effectVariants(f, agaa::sceneTraits(s), 8, 4), "shadows").cause.find("forced"),
              std::string::npos);
}

TEST(SceneFeatures, BuiltinScenesHaveAShadowedSunAndFoliageIsMasked) {
    for (const char* name : {"plane", "foliage", "furball"}) {
        const Scene s = eng::scene::loadTestScene(name);
        const auto f = eng::scene::deriveSceneFeatures(s);
        EXPECT_EQ(f.shadowedLights.size(), 1u) << name;
        EXPECT_EQ(f.hasMasked(), std::string(name) == "foliage") << name;
    }
}

TEST(EffectSettings, OutOfRangeSettingsAreRefused) {
    agaa::EffectSettings s;
    s.shadowTaps = 0;
    EXPECT_THROW(agaa::validate(s), std::invalid_argument);
    s.shadowTaps = 9;
    EXPECT_THROW(agaa::validate(s), std::invalid_argument);
    s = {};
    s.shadowMapSize = 32;
    EXPECT_THROW(agaa::validate(s), std::invalid_argument);
    s.shadowMapSize = 1024;
    EXPECT_NO_THROW(agaa::validate(s));
    // A footprint from a host's own cast: named with the allowed values.
    s.shadowFootprint = agaa::EffectSettings::ShadowFootprint(3);
    try {
        agaa::validate(s);
        ADD_FAILURE() << "shadow footprint 3 accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("statistics (0), samples (1), adaptive (2)"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(agaa::EffectSettings{}.shadowFootprint, agaa::EffectSettings::ShadowFootprint::Adaptive);
}

// The directional fit keeps every scene-bounds corner the camera sees inside the map's volume.
TEST(ShadowFit, DirectionalLightCoversTheVisibleSceneBounds) {
    Scene s = oneDrawScene();
    s.bounds = {{-3, -1, -6}, {3, 2, -2}};
    const Light sun = light(LightType::Directional, true);
    shared::FrameConstants frame{};
    frame.view = glm::mat4(1.0f);
    // Reversed-Z perspective, as the renderer's (near -> 1, far -> 0), wide enough (150 degrees)
    // to see all of the bounds: the fit may drop only what the camera cannot see.
    frame.proj = glm::perspectiveRH_ZO(2.6f, 1.0f, 100.0f, 0.1f);
    frame.viewProj = frame.proj * frame.view;
    float texel = 0.0f;
    const glm::mat4 m(agaa::ShadowMapPass::fitLight(s.bounds, sun, &frame, &texel));
    EXPECT_GT(texel, 0.0f);
    for (int i = 0; i < 8; ++i) {
        glm::vec3 c{(i & 1) ? s.bounds.max.x : s.bounds.min.x, (i & 2) ? s.bounds.max.y : s.bounds.min.y,
                    (i & 4) ? s.bounds.max.z : s.bounds.min.z};
        glm::vec4 p = m * glm::vec4(c, 1.0f);
        EXPECT_NEAR(p.w, 1.0f, 1e-5f);
        EXPECT_GE(p.z, 0.0f) << i;
        EXPECT_LE(p.z, 1.0f) << i;
        EXPECT_LE(std::abs(p.x), 1.0f + 1e-4f) << i;
        EXPECT_LE(std::abs(p.y), 1.0f + 1e-4f) << i;
    }
    // Nearer the light means smaller depth: a point moved against the light direction.
    glm::vec4 a = m * glm::vec4(0, 0, -4, 1),
              b = m * glm::vec4(glm::vec3(0, 0, -4) - sun.direction * 0.5f, 1.0f);
    EXPECT_LT(b.z, a.z);
}

TEST(ShadowFit, SpotLightLooksAlongItsDirection) {
    Scene s = oneDrawScene();
    Light spot = light(LightType::Spot, true);
    spot.direction = {0, -1, 0};
    spot.outerConeAngle = 0.5f;
    shared::FrameConstants frame{};
    frame.viewProj = glm::perspectiveRH_ZO(1.2f, 1.0f, 100.0f, 0.1f);
    const glm::mat4 m(agaa::ShadowMapPass::fitLight(s.bounds, spot, &frame, nullptr));
    glm::vec4 p = m * glm::vec4(0, 0, 0, 1); // straight below the light
    ASSERT_GT(p.w, 0.0f);
    EXPECT_NEAR(p.x / p.w, 0.0f, 1e-4f);
    EXPECT_NEAR(p.y / p.w, 0.0f, 1e-4f);
    EXPECT_GT(p.z / p.w, 0.0f);
    EXPECT_LT(p.z / p.w, 1.0f);
}

// AGAA's --agaa-ndf auto picks SGGX from this count: glossy metals (metallic >= 0.5 and
// roughness <= 0.4) are counted at the thresholds' edges and only when a draw uses them.
TEST(SceneFeatures, GlossyMetalsCountAtTheThresholdsAndOnlyWhenDrawn) {
    Scene s = oneDrawScene();
    s.materials[0].metallicFactor = eng::scene::kGlossyMetallic;
    s.materials[0].roughnessFactor = eng::scene::kGlossyRoughness;
    EXPECT_EQ(eng::scene::deriveSceneFeatures(s).glossyMetalMaterials, 1u);
    s.materials[0].roughnessFactor = std::nextafter(eng::scene::kGlossyRoughness, 1.0f);
    EXPECT_EQ(eng::scene::deriveSceneFeatures(s).glossyMetalMaterials, 0u) << "too rough";
    s.materials[0].roughnessFactor = 0.1f;
    s.materials[0].metallicFactor = std::nextafter(eng::scene::kGlossyMetallic, 0.0f);
    EXPECT_EQ(eng::scene::deriveSceneFeatures(s).glossyMetalMaterials, 0u) << "not metallic enough";
    s.materials[0].metallicFactor = 1.0f;
    s.draws[0].indexCount = 0;
    EXPECT_EQ(eng::scene::deriveSceneFeatures(s).glossyMetalMaterials, 0u) << "an undrawn material";
    for (auto [name, glossy] : {std::pair{"metal", 2u}, std::pair{"railings", 1u}, std::pair{"furball", 0u},
                                std::pair{"foliage", 0u}, std::pair{"plane", 0u}})
        EXPECT_EQ(eng::scene::deriveSceneFeatures(eng::scene::loadTestScene(name)).glossyMetalMaterials,
                  glossy)
            << name;
}

// AGAA's near-mirror view footprint (agaa/lighting.comp addLightFootprint) is compiled in only where
// a drawn material can be a near mirror: roughness below kNearMirrorRoughness, or a metallic-
// roughness texture (it can only lower the factor); forcing every effect turns it on too.
TEST(SceneFeatures, NearMirrorsCountBelowTheRoughnessOrWithARoughnessTexture) {
    Scene s = oneDrawScene();
    s.materials[0].roughnessFactor = eng::scene::kNearMirrorRoughness;
    EXPECT_FALSE(eng::scene::deriveSceneFeatures(s).hasNearMirrors()) << "at the threshold";
    s.materials[0].roughnessFactor = std::nextafter(eng::scene::kNearMirrorRoughness, 0.0f);
    EXPECT_TRUE(eng::scene::deriveSceneFeatures(s).hasNearMirrors()) << "just below";
    s.materials[0].roughnessFactor = 0.8f;
    s.materials[0].metallicRoughnessTexture = 0;
    EXPECT_TRUE(eng::scene::deriveSceneFeatures(s).hasNearMirrors()) << "a roughness texture";
    s.materials[0].metallicRoughnessTexture = -1;
    EXPECT_FALSE(eng::scene::deriveSceneFeatures(s).hasNearMirrors()) << "rough";
    EXPECT_TRUE(eng::scene::forceAllSceneFeatures(s).hasNearMirrors()) << "forced";
    s.materials[0].roughnessFactor = 0.0f;
    s.draws[0].indexCount = 0;
    EXPECT_FALSE(eng::scene::deriveSceneFeatures(s).hasNearMirrors()) << "an undrawn material";
    for (auto [name, mirrors] : {std::pair{"furball", false}, std::pair{"foliage", false},
                                 std::pair{"spikes", true}, std::pair{"hard-mirror", true}})
        EXPECT_EQ(eng::scene::deriveSceneFeatures(eng::scene::loadTestScene(name)).hasNearMirrors(), mirrors)
            << name;
}

// --agaa-ndf auto's rule: SGGX when glossy metals that are not near mirrors are at least half of
// the drawn materials (issue 49: on near mirrors SGGX bought no accuracy, at more lighting time).
TEST(SceneFeatures, AnisotropicMetalsDominateFromHalfTheDrawnMaterials) {
    Scene s = oneDrawScene();
    s.materials[0].metallicFactor = 1.0f;
    s.materials[0].roughnessFactor = 0.1f;
    EXPECT_TRUE(eng::scene::deriveSceneFeatures(s).anisotropicMetalsDominate()) << "one of one";
    s.materials[0].roughnessFactor = 0.05f;
    EXPECT_EQ(eng::scene::deriveSceneFeatures(s).glossyMetalMaterials, 1u);
    EXPECT_FALSE(eng::scene::deriveSceneFeatures(s).anisotropicMetalsDominate()) << "a near mirror";
    s.materials[0].roughnessFactor = 0.1f;
    s.materials[0].metallicRoughnessTexture = 0;
    EXPECT_FALSE(eng::scene::deriveSceneFeatures(s).anisotropicMetalsDominate())
        << "roughness-textured: can be a near mirror";
    s.materials[0].metallicRoughnessTexture = -1;
    s.materials.push_back(s.materials[0]);
    s.materials[1].metallicFactor = 0.0f;
    s.draws.push_back(s.draws[0]);
    s.draws[1].material = 1;
    EXPECT_TRUE(eng::scene::deriveSceneFeatures(s).anisotropicMetalsDominate()) << "one of two";
    s.materials.push_back(s.materials[1]);
    s.draws.push_back(s.draws[1]);
    s.draws[2].material = 2;
    EXPECT_EQ(eng::scene::deriveSceneFeatures(s).drawnMaterials, 3u);
    EXPECT_FALSE(eng::scene::deriveSceneFeatures(s).anisotropicMetalsDominate()) << "one of three";
    s.materials[0].metallicFactor = 0.0f;
    EXPECT_FALSE(eng::scene::deriveSceneFeatures(s).anisotropicMetalsDominate()) << "none";
    for (auto [name, sggx] :
         {std::pair{"metal", true}, std::pair{"spikes", false}, std::pair{"glints", false},
          std::pair{"chainlink", false}, std::pair{"default", false}, std::pair{"furball", false}})
        EXPECT_EQ(eng::scene::deriveSceneFeatures(eng::scene::loadBuiltin(name)).anisotropicMetalsDominate(),
                  sggx)
            << name << ": "
            << eng::scene::deriveSceneFeatures(eng::scene::loadBuiltin(name)).anisotropicMetalMaterials
            << " of " << eng::scene::deriveSceneFeatures(eng::scene::loadBuiltin(name)).drawnMaterials;
}

} // namespace
