#include "agaa/common/effects.h"

#include "engine/frame/gpu_scene.h"
#include "shared/environment.h"

#include <bit>
#include <cmath>
#include <stdexcept>

namespace agaa {

void validate(const EffectSettings& s) {
    if (s.shadowMapSize < 64 || s.shadowMapSize > 4096)
        throw std::invalid_argument("--shadow-map-size " + std::to_string(s.shadowMapSize) +
                                    " is out of range (64..4096)");
    if (s.shadowTaps < 1 || s.shadowTaps > 8)
        throw std::invalid_argument("--shadow-taps " + std::to_string(s.shadowTaps) +
                                    " is out of range (1..8)");
    if (uint32_t(s.shadowFootprint) > uint32_t(EffectSettings::ShadowFootprint::Adaptive))
        throw std::invalid_argument("shadow footprint " + std::to_string(uint32_t(s.shadowFootprint)) +
                                    " is not one of: statistics (0), samples (1), adaptive (2)");
    const CurvatureRoughness& c = s.curvatureRoughness;
    if (!(c.maxFootprint >= 0.0f && c.maxFootprint <= 1.0f))
        throw std::invalid_argument("curvature roughness: max footprint must be in [0, 1] (GGX alpha^2)");
    if (!(c.boost >= 0.0f) || !std::isfinite(c.boost))
        throw std::invalid_argument("curvature roughness: boost must be a finite number >= 0");
}

std::vector<std::pair<uint32_t, uint32_t>> curvatureSpecialization(const CurvatureRoughness& c) {
    return {{shared::kSpecFillCurvatureRoughness, c.enabled ? 1u : 0u},
            {shared::kSpecFillCurvatureMaxFootprint, std::bit_cast<uint32_t>(c.maxFootprint)},
            {shared::kSpecFillCurvatureBoost, std::bit_cast<uint32_t>(c.boost)}};
}

eng::scene::SceneFeatures effectiveFeatures(const SceneTraits& traits, const EffectSettings& settings) {
    validate(settings);
    return settings.forceAll
               ? eng::scene::forceAllSceneFeatures(traits.features, traits.lights, traits.materials)
               : traits.features;
}

std::vector<VariantChoice> effectVariants(const eng::scene::SceneFeatures& f, const SceneTraits& scene,
                                          uint32_t samples, uint32_t shadowTaps) {
    const std::string forced = f.forced ? "forced on; " : "";
    auto count = [](uint32_t n, const char* what) { return std::to_string(n) + " " + what; };
    std::vector<VariantChoice> v;
    if (f.hasShadows()) {
        std::string names;
        for (uint32_t i : f.shadowedLights)
            names += (names.empty() ? "" : ", ") + (scene.lights[i].name.empty()
                                                        ? "light " + std::to_string(i)
                                                        : "'" + scene.lights[i].name + "'");
        v.push_back({"shadows",
                     "shadow map x" + std::to_string(f.shadowedLights.size()) + ", " +
                         std::to_string(shadowTaps) + (shadowTaps == 1 ? " tap" : " taps") +
                         " per shading event",
                     forced + "casts shadows: " + names});
    } else {
        v.push_back({"shadows", "off", "no directional or spot light casts shadows"});
    }
    if (f.hasMasked())
        v.push_back({"alpha",
                     maskedAlphaPath(samples) == AlphaPath::Coverage ? "alpha-to-coverage" : "discard",
                     forced + count(f.maskedMaterials, "masked materials") +
                         (samples > 1 ? "" : "; 1 sample per pixel: no coverage to dither")});
    else
        v.push_back({"alpha", "opaque only", "no masked materials"});
    if (f.blendedMaterials > 0)
        v.push_back({"blend",
                     blendedAlphaPath(samples) == AlphaPath::BlendCoverage
                         ? "alpha-to-coverage of the alpha"
                         : "4x4 ordered dither of the alpha",
                     count(f.blendedMaterials, "blended materials") +
                         (samples > 1 ? "" : "; 1 sample per pixel: dithered")});
    v.push_back({"emissive", f.hasEmissive() ? "per-sample emissive" : "off",
                 f.hasEmissive() ? forced + count(f.emissiveMaterials, "emissive materials")
                                 : "no emissive materials"});
    v.push_back({"normal-maps", f.hasNormalMaps() ? "fetch + Toksvig roughness" : "off",
                 f.hasNormalMaps() ? forced + count(f.normalMappedMaterials, "normal-mapped materials")
                                   : "no normal-mapped materials"});
    v.push_back({"texture-transform", f.hasTextureTransforms() ? "KHR_texture_transform" : "off",
                 f.hasTextureTransforms()
                     ? count(f.transformedMaterials, "materials with transformed textures")
                     : "no transformed textures"});
    v.push_back({"lighting", scene.lightingMode, scene.lightingCause});
    v.push_back({"environment",
                 f.hasEnvironment() ? "SH9 irradiance + " + std::to_string(shared::kEnvironmentLevels) +
                                          " pre-filtered specular levels"
                                    : "off",
                 f.hasEnvironment() ? scene.environmentSource : "no environment: a constant sky colour"});
    v.push_back({"light-culling", f.needsLightCulling() ? "tiled" : "off",
                 f.needsLightCulling() ? forced + count(f.pointLights + f.spotLights, "point/spot lights")
                                       : "directional lights only: every light touches every tile"});
    return v;
}

eng::vk::Specialization effectSpecialization(const eng::scene::SceneFeatures& f, uint32_t shadowTaps,
                                             EffectSettings::ShadowFootprint footprint) {
    eng::vk::Specialization s;
    s.byId = {{kSpecTileLightCulling, f.needsLightCulling() ? 1u : 0u},
              {kSpecNormalMaps, f.hasNormalMaps() ? 1u : 0u},
              {kSpecEmissive, f.hasEmissive() ? 1u : 0u},
              {kSpecShadowTaps, shadowTaps},
              {kSpecShadowFootprint, uint32_t(footprint)}};
    return s;
}

eng::vk::Specialization lightingSpecialization(eng::vk::Specialization s,
                                               const eng::scene::SceneFeatures& features) {
    s.byId.push_back({kSpecEnvironment, features.hasEnvironment() ? 1u : 0u});
    return s;
}

eng::vk::Specialization gbufferLightingSpecialization(const eng::scene::SceneFeatures& features,
                                                      uint32_t samples,
                                                      std::vector<std::pair<uint32_t, uint32_t>> own) {
    eng::vk::Specialization s = lightingSpecialization(effectSpecialization(features, 1), features);
    s.byId.push_back({shared::kSpecGBufferLightingSamples, samples});
    s.byId.insert(s.byId.end(), own.begin(), own.end());
    return s;
}

EnvironmentBindings environmentBindings(const eng::frame::GpuEnvironment& e) {
    return {e.sampler(), e.view(), e.constants().buffer, e.dfgSampler(), e.dfgView()};
}

EnvironmentBindings environmentBindings(const eng::frame::GpuScene& scene) {
    return environmentBindings(scene.environment());
}

void pushEnvironment(eng::vk::PushDescriptors& descriptors, const EnvironmentBindings& e) {
    descriptors.sampled(15, e.sampler, e.prefiltered)
        .uniform(16, e.constants)
        .sampled(17, e.dfgSampler, e.dfg);
}

} // namespace agaa
