#include "engine/scene/scene_features.h"

#include <algorithm>

namespace eng::scene {
namespace {

bool canCastShadows(const Light& light) {
    return light.type == LightType::Directional || light.type == LightType::Spot;
}

void countLights(const Scene& scene, SceneFeatures& f) {
    for (const Light& light : scene.lights) {
        if (light.type == LightType::Directional) ++f.directionalLights;
        if (light.type == LightType::Point) ++f.pointLights;
        if (light.type == LightType::Spot) ++f.spotLights;
    }
}

} // namespace

SceneFeatures deriveSceneFeatures(const Scene& scene) {
    SceneFeatures f;
    countLights(scene, f);
    f.environment = !scene.environment.empty();
    for (const Vertex& v : scene.vertices)
        if (v.color != glm::vec4(1.0f)) {
            f.vertexColors = true;
            break;
        }
    for (uint32_t i = 0; i < scene.lights.size(); ++i) {
        const Light& light = scene.lights[i];
        if (!light.castsShadows) continue;
        if (canCastShadows(light) && f.shadowedLights.size() < kMaxShadowedLights)
            f.shadowedLights.push_back(i);
        else
            ++f.shadowedLightsIgnored;
    }
    std::vector<bool> used(scene.materials.size(), false);
    for (const Draw& draw : scene.draws)
        if (draw.indexCount > 0 && draw.material < used.size()) used[draw.material] = true;
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        if (!used[m]) continue;
        const Material& mat = scene.materials[m];
        ++f.drawnMaterials;
        if (mat.alphaMode == AlphaMode::Mask) ++f.maskedMaterials;
        if (mat.alphaMode == AlphaMode::Blend) ++f.blendedMaterials;
        const glm::vec3 e = mat.emissiveFactor * mat.emissiveStrength;
        if (std::max({e.x, e.y, e.z}) > 0.0f) ++f.emissiveMaterials;
        if (mat.normalTexture >= 0) ++f.normalMappedMaterials;
        for (const TextureTransform& t : mat.textureTransforms)
            if (t.offset != glm::vec2(0.0f) || t.rotation != 0.0f || t.scale != glm::vec2(1.0f) ||
                t.texCoord != 0) {
                ++f.transformedMaterials;
                break;
            }
        const bool glossyMetal =
            mat.metallicFactor >= kGlossyMetallic && mat.roughnessFactor <= kGlossyRoughness;
        const bool nearMirror =
            mat.roughnessFactor < kNearMirrorRoughness || mat.metallicRoughnessTexture >= 0;
        if (glossyMetal) ++f.glossyMetalMaterials;
        if (glossyMetal && !nearMirror) ++f.anisotropicMetalMaterials;
        if (nearMirror) ++f.nearMirrorMaterials;
    }
    return f;
}

SceneFeatures forceAllSceneFeatures(SceneFeatures f, std::span<const Light> lights, uint32_t materials) {
    f.forced = true;
    f.shadowedLights.clear();
    f.shadowedLightsIgnored = 0;
    for (uint32_t i = 0; i < lights.size(); ++i)
        if (canCastShadows(lights[i]) && f.shadowedLights.size() < kMaxShadowedLights)
            f.shadowedLights.push_back(i);
    f.maskedMaterials = f.emissiveMaterials = f.normalMappedMaterials = std::max<uint32_t>(1, materials);
    return f;
}

SceneFeatures forceAllSceneFeatures(const Scene& scene) {
    return forceAllSceneFeatures(deriveSceneFeatures(scene), scene.lights, uint32_t(scene.materials.size()));
}

std::string describe(const SceneFeatures& f, const Scene& scene) {
    std::string names;
    for (uint32_t i : f.shadowedLights) {
        const std::string& n = scene.lights[i].name;
        names += (names.empty() ? "" : ", ") + (n.empty() ? "light " + std::to_string(i) : n);
    }
    std::string s = std::string(f.forced ? "forced: " : "") + "shadowed lights " +
                    std::to_string(f.shadowedLights.size());
    if (!names.empty()) s += " (" + names + ")";
    if (f.shadowedLightsIgnored) s += " +" + std::to_string(f.shadowedLightsIgnored) + " ignored";
    s += ", masked " + std::to_string(f.maskedMaterials) + ", blended " + std::to_string(f.blendedMaterials) +
         ", emissive " + std::to_string(f.emissiveMaterials) + ", normal-mapped " +
         std::to_string(f.normalMappedMaterials) + ", lights " + std::to_string(f.directionalLights) +
         " directional / " + std::to_string(f.pointLights) + " point / " + std::to_string(f.spotLights) +
         " spot, sky " + (f.skyVisible ? "visible (conservative)" : "hidden");
    return s;
}

} // namespace eng::scene
