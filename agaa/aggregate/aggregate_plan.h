#pragma once
// What AggregateAA runs, decided once at construction: every Auto setting resolved from the device
// and the scene, each with its cause, the scene's effects, and the depth format of the visibility
// samples. The passes (agaa/aggregate/passes/) build from it and never re-read the requested
// settings; variants() is what the stats and the graph dump print of it.

#include "agaa/aggregate/agaa_constants.h"
#include "agaa/common/effects.h"
#include "engine/scene/scene.h"
#include "engine/vk/device.h"

#include <string>
#include <vector>

namespace agaa {

struct AggregatePlan {
    AggregateSettings settings;  // every Auto resolved
    AggregateSettings requested; // as the caller asked (the variants say which were automatic)
    eng::scene::SceneFeatures features;
    VkFormat depthFormat = VK_FORMAT_D32_SFLOAT_S8_UINT; // the visibility samples' depth
    std::string generationCause;                         // why this generation path
    std::string toleranceCause;                          // why this shading rate

    bool samplesPath() const { return settings.generation == AggregateGeneration::Samples; }
    // Flagged pixels are shaded per sample (agaa/lighting/shading_rate.glsl).
    bool shadingRate() const { return settings.tolerance >= 0.0f; }
    bool emissive() const { return features.hasEmissive(); }
    // The 4x layers that emulate n samples (common/scene_vertex.glsl).
    uint32_t layers() const { return settings.samples / 4; }
};

// Resolves `settings` for this device and scene. Throws std::invalid_argument for a setting out of
// range or a combination that cannot run, naming it, and eng::vk::MissingCapability for a device
// feature a requested setting needs, naming the feature and the values allowed on this device.
AggregatePlan planAggregate(const eng::vk::Device& device, const SceneTraits& traits,
                            const AggregateSettings& settings);

// Each resolved choice of the plan, what runs and why (Technique::variants()).
std::vector<VariantChoice> planVariants(const AggregatePlan& plan, const SceneTraits& traits,
                                        const eng::vk::Capabilities& caps);

} // namespace agaa
