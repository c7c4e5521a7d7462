#pragma once
// What a loaded scene calls for (DESIGN section 1, "simulate only the effects a scene calls
// for"): the techniques assemble their passes and pick their shader variants from this, and
// the stats report it. Pure CPU, derived from the scene's content only.

#include "engine/scene/scene.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace eng::scene {

// Shadow maps live in the layers of one array texture; at most this many lights get one.
inline constexpr uint32_t kMaxShadowedLights = 4;
// A material counts as a glossy metal from these factors on (scenegen's steel, brass and railing
// paint; fur, bark, bamboo, floors and walls stay below).
inline constexpr float kGlossyMetallic = 0.5f;
inline constexpr float kGlossyRoughness = 0.4f;
// A material counts as a near mirror below this roughness factor, or with a metallic-roughness
// texture (which can only lower it): AGAA's lighting then takes its near-mirror view footprint
// (agaa/lighting.comp addLightFootprint), which starts below alpha = theta / sqrt(2) for any
// footprint (sxx + syy <= 1/2): roughness 0.1, alpha 0.01, covers a 40-degree view down to 64
// pixels (theta 0.0114). Elsewhere the pass is compiled without it: its branch alone costs lavapipe
// about a fifth of the lighting pass.
inline constexpr float kNearMirrorRoughness = 0.1f;

struct SceneFeatures {
    // Indices into Scene::lights of the directional and spot lights with castsShadows, in light
    // order, at most kMaxShadowedLights. Point lights would need cube maps: not supported, counted
    // in shadowedLightsIgnored with the lights over the cap.
    std::vector<uint32_t> shadowedLights;
    uint32_t shadowedLightsIgnored = 0;
    // Materials used by at least one non-empty draw.
    uint32_t maskedMaterials = 0;       // AlphaMode::Mask: alpha-to-coverage / discard
    uint32_t blendedMaterials = 0;      // AlphaMode::Blend: alpha-to-coverage (no sorted transparency)
    uint32_t emissiveMaterials = 0;     // emissiveFactor * strength > 0
    uint32_t normalMappedMaterials = 0; // normalTexture >= 0
    // A texture slot with a KHR_texture_transform other than identity, or reading TEXCOORD_1.
    uint32_t transformedMaterials = 0;
    bool vertexColors = false; // a vertex colour (COLOR_0) other than white
    // Glossy metals (metallicFactor >= kGlossyMetallic, roughnessFactor <= kGlossyRoughness): the
    // thin bright highlights an isotropic normal distribution smears (AGAA picks SGGX for them).
    uint32_t glossyMetalMaterials = 0;
    // The glossy metals that are not near mirrors (roughnessFactor >= kNearMirrorRoughness, not
    // roughness-textured): where an anisotropic lobe (SGGX) measured more accurate than Toksvig's.
    uint32_t anisotropicMetalMaterials = 0;
    uint32_t drawnMaterials = 0;      // materials used by at least one non-empty draw
    uint32_t nearMirrorMaterials = 0; // roughnessFactor < kNearMirrorRoughness, or roughness-textured
    uint32_t directionalLights = 0, pointLights = 0, spotLights = 0;
    // Conservative: true unless the scene's geometry provably covers every view direction,
    // which this cheap estimate never claims (a prepass would be needed). Reported, never used
    // to skip work.
    bool skyVisible = true;
    bool forced = false; // every effect forced on (benchmark), not derived
    // The scene has an environment (Scene::environment: the default sky or a user's map): every
    // lighting pass adds its pre-filtered light (common/environment.glsl).
    bool environment = false;

    bool hasShadows() const { return !shadowedLights.empty(); }
    bool hasMasked() const { return maskedMaterials > 0; }
    bool hasEmissive() const { return emissiveMaterials > 0; }
    bool hasNormalMaps() const { return normalMappedMaterials > 0; }
    bool hasGlossyMetals() const { return glossyMetalMaterials > 0; }
    // At least half of the drawn materials are glossy metals that are not near mirrors: AGAA's
    // --agaa-ndf auto picks SGGX then (docs/decisions/ndf-auto.md). With the filtered diffuse,
    // Toksvig is the better distribution on mixed scenes (the default scene's one glossy metal
    // among five materials: 0.0262 against SGGX's 0.0324 at (8, 2)), SGGX on scenes made of glossy
    // metal tubes (metal, roughness 0.18 and 0.28: 0.0428 against 0.0568, the truth's own error
    // 0.0036); on near mirrors (spikes and glints, roughness 0.02; hard-mirror, 0) SGGX was no more
    // accurate than Toksvig, or less, at more lighting time (about 1.15x since the decomposition by
    // squaring, twice before; issue 49).
    bool anisotropicMetalsDominate() const {
        return anisotropicMetalMaterials > 0 && 2 * anisotropicMetalMaterials >= drawnMaterials;
    }
    bool hasEnvironment() const { return environment; }
    bool hasNearMirrors() const { return forced || nearMirrorMaterials > 0; }
    bool hasTextureTransforms() const { return transformedMaterials > 0; }
    // Tile light culling only prunes point and spot lights; directional lights touch every tile.
    bool needsLightCulling() const { return forced || pointLights + spotLights > 0; }
};

SceneFeatures deriveSceneFeatures(const Scene& scene);

// Every effect on, whatever the scene holds (the "force every effect" benchmark): every
// directional and spot light shadowed (up to the cap), every draw alpha-tested, normal-map and
// emissive paths and tile culling enabled. The image changes only where the forced shadows fall.
SceneFeatures forceAllSceneFeatures(const Scene& scene);
// The same from what a host describes (agaa/common/scene_traits.h): the derived features, the
// lights they index and the number of materials.
SceneFeatures forceAllSceneFeatures(SceneFeatures derived, std::span<const Light> lights, uint32_t materials);

// One line for logs: "shadowed lights 1 (sun), masked 2, blended 0, emissive 0, normal-mapped 0,
// lights 1 directional / 0 point / 0 spot, sky visible".
std::string describe(const SceneFeatures& features, const Scene& scene);

} // namespace eng::scene
