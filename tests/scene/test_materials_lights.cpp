// Materials (factors, alpha modes, emissive strength, textures and their colour
// spaces) and KHR_lights_punctual lights.

#include "engine/scene/gltf_loader.h"

#include "gltf_test_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

namespace eng::scene {
namespace {

using test::TestModel;

tinygltf::Value object(std::initializer_list<std::pair<const std::string, tinygltf::Value>> members) {
    return tinygltf::Value(tinygltf::Value::Object(members));
}

int addLight(TestModel& m, const tinygltf::Light& light, const std::vector<double>& translation,
             const std::vector<double>& rotation) {
    m.model.lights.push_back(light);
    const int node = m.addNode();
    auto& n = m.model.nodes[static_cast<size_t>(node)];
    n.translation = translation;
    n.rotation = rotation;
    n.extensions["KHR_lights_punctual"] =
        object({{"light", tinygltf::Value(static_cast<int>(m.model.lights.size() - 1))}});
    return node;
}

TEST(GltfMaterials, MaskEmissiveStrengthAndFactors) {
    TestModel m = test::makeTriangleModel();
    tinygltf::Material mat;
    mat.name = "glow";
    mat.pbrMetallicRoughness.baseColorFactor = {0.2, 0.4, 0.6, 0.8};
    mat.pbrMetallicRoughness.metallicFactor = 0.25;
    mat.pbrMetallicRoughness.roughnessFactor = 0.75;
    mat.emissiveFactor = {1.0, 0.5, 0.0};
    mat.extensions["KHR_materials_emissive_strength"] = object({{"emissiveStrength", tinygltf::Value(5.0)}});
    mat.alphaMode = "MASK";
    mat.alphaCutoff = 0.3;
    mat.doubleSided = true;
    m.model.materials.push_back(mat);
    m.model.meshes[0].primitives[0].material = 0;

    const Scene s = loadGltfModel(m.model, "material.gltf");
    ASSERT_EQ(s.materials.size(), 1u) << "no default material when every primitive has one";
    const Material& out = s.materials[0];
    EXPECT_EQ(out.baseColorFactor, glm::vec4(0.2f, 0.4f, 0.6f, 0.8f)) << "baseColorFactor";
    EXPECT_FLOAT_EQ(out.metallicFactor, 0.25f);
    EXPECT_FLOAT_EQ(out.roughnessFactor, 0.75f);
    EXPECT_EQ(out.emissiveFactor, glm::vec3(1.0f, 0.5f, 0.0f)) << "emissiveFactor";
    EXPECT_FLOAT_EQ(out.emissiveStrength, 5.0f) << "KHR_materials_emissive_strength";
    EXPECT_EQ(out.alphaMode, AlphaMode::Mask) << "alphaMode MASK";
    EXPECT_FLOAT_EQ(out.alphaCutoff, 0.3f) << "alphaCutoff";
    EXPECT_TRUE(out.doubleSided);
}

TEST(GltfMaterials, TextureUsedAsColourAndDataIsDuplicatedAndConvertedToRgba8) {
    TestModel m = test::makeTriangleModel();
    // A 2x1 single-channel 16-bit image: values 0 and 65535.
    tinygltf::Image image;
    image.width = 2;
    image.height = 1;
    image.component = 1;
    image.bits = 16;
    image.pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    const uint16_t texels[2] = {0, 65535};
    image.image.resize(4);
    std::memcpy(image.image.data(), texels, 4);
    m.model.images.push_back(image);
    tinygltf::Texture tex;
    tex.source = 0;
    m.model.textures.push_back(tex);
    tinygltf::Material mat;
    mat.pbrMetallicRoughness.baseColorTexture.index = 0;
    mat.pbrMetallicRoughness.metallicRoughnessTexture.index = 0;
    mat.normalTexture.index = 0;
    mat.normalTexture.scale = 0.5;
    m.model.materials.push_back(mat);
    m.model.meshes[0].primitives[0].material = 0;

    const Scene s = loadGltfModel(m.model, "textures.gltf");
    ASSERT_EQ(s.textures.size(), 2u) << "one sRGB and one linear copy of the same glTF texture";
    const Material& out = s.materials[0];
    ASSERT_GE(out.baseColorTexture, 0);
    ASSERT_GE(out.metallicRoughnessTexture, 0);
    EXPECT_TRUE(s.textures[static_cast<size_t>(out.baseColorTexture)].srgb) << "base colour is sRGB";
    EXPECT_FALSE(s.textures[static_cast<size_t>(out.metallicRoughnessTexture)].srgb)
        << "metal-roughness is linear";
    EXPECT_EQ(out.normalTexture, out.metallicRoughnessTexture) << "linear uses share one copy";
    EXPECT_FLOAT_EQ(out.normalScale, 0.5f) << "normalTexture.scale";
    const Texture& t = s.textures[static_cast<size_t>(out.baseColorTexture)];
    ASSERT_EQ(t.rgba8.size(), 8u) << "2 texels x RGBA8";
    EXPECT_EQ(t.rgba8, (std::vector<uint8_t>{0, 0, 0, 255, 255, 255, 255, 255}))
        << "grey expands to RGB, 16 bits map to 8, missing alpha is opaque";
}

TEST(GltfLights, PunctualLightsParsedWithRangeConesAndNodePlacement) {
    TestModel m = test::makeTriangleModel();
    const double h = std::sqrt(0.5);
    tinygltf::Light sun;
    sun.type = "directional";
    sun.intensity = 3.0;
    sun.color = {1.0, 0.9, 0.8};
    addLight(m, sun, {}, {-h, 0, 0, h}); // -90 deg about X: -Z turns to -Y (straight down)
    tinygltf::Light point;
    point.type = "point";
    point.intensity = 20.0;
    point.range = 4.0;
    addLight(m, point, {1, 2, 3}, {});
    tinygltf::Light spot;
    spot.type = "spot";
    spot.range = 6.0;
    spot.spot.innerConeAngle = 0.2;
    spot.spot.outerConeAngle = 0.5;
    addLight(m, spot, {0, 5, 0}, {0, h, 0, h}); // +90 deg about Y: -Z turns to -X

    const Scene s = loadGltfModel(m.model, "lights.gltf");
    ASSERT_EQ(s.lights.size(), 3u);
    const Light& d = s.lights[0];
    EXPECT_EQ(d.type, LightType::Directional);
    EXPECT_FLOAT_EQ(d.intensity, 3.0f);
    EXPECT_NEAR(d.direction.y, -1.0f, 1e-5f) << "directional light travels down the node's -Z";
    EXPECT_TRUE(d.castsShadows) << "with no extras anywhere, the first directional light casts shadows";
    const Light& p = s.lights[1];
    EXPECT_EQ(p.type, LightType::Point);
    EXPECT_FLOAT_EQ(p.range, 4.0f) << "point range";
    EXPECT_EQ(p.position, glm::vec3(1, 2, 3)) << "point position from the node translation";
    EXPECT_FALSE(p.castsShadows);
    const Light& sp = s.lights[2];
    EXPECT_EQ(sp.type, LightType::Spot);
    EXPECT_FLOAT_EQ(sp.range, 6.0f) << "spot range";
    EXPECT_FLOAT_EQ(sp.innerConeAngle, 0.2f) << "innerConeAngle";
    EXPECT_FLOAT_EQ(sp.outerConeAngle, 0.5f) << "outerConeAngle";
    EXPECT_NEAR(sp.direction.x, -1.0f, 1e-5f) << "spot direction from the node rotation";
    EXPECT_NEAR(sp.position.y, 5.0f, 1e-6f);
}

TEST(GltfLights, ExtrasCastsShadowsOverridesTheSunDefault) {
    TestModel m = test::makeTriangleModel();
    tinygltf::Light sun;
    sun.type = "directional";
    addLight(m, sun, {}, {});
    tinygltf::Light point;
    point.type = "point";
    point.extras = object({{"castsShadows", tinygltf::Value(true)}});
    addLight(m, point, {0, 1, 0}, {});
    const Scene s = loadGltfModel(m.model, "shadows.gltf");
    ASSERT_EQ(s.lights.size(), 2u);
    EXPECT_FALSE(s.lights[0].castsShadows)
        << "once any light says castsShadows, the sun default no longer applies";
    EXPECT_TRUE(s.lights[1].castsShadows) << "extras.castsShadows = true";
}

TEST(GltfLights, InvalidSpotConesAreClampedWithWarning) {
    TestModel m = test::makeTriangleModel();
    tinygltf::Light spot;
    spot.type = "spot";
    spot.spot.innerConeAngle = 1.0;
    spot.spot.outerConeAngle = 3.0; // > pi/2
    addLight(m, spot, {}, {});
    const Scene s = loadGltfModel(m.model, "cones.gltf");
    ASSERT_EQ(s.lights.size(), 1u);
    EXPECT_LE(s.lights[0].outerConeAngle, 1.5707964f) << "outer cone clamped to pi/2";
    EXPECT_LT(s.lights[0].innerConeAngle, s.lights[0].outerConeAngle) << "inner < outer";
    EXPECT_FALSE(s.stats.warnings.empty()) << "the clamp must be reported";
}

} // namespace
} // namespace eng::scene
