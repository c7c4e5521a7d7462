#pragma once
// Every anti-aliasing method agaa-render, the benchmark and the hard-case suite
// know, in one table: adding a technique here is all it takes for the tools
// and the report to pick it up.

#include "agaa/common/technique.h"
#include "agaa/method_settings.h"
#include "engine/vk/device.h"

#include <memory>
#include <string>
#include <vector>

namespace agaa {

struct MethodInfo {
    std::string name;
    std::string summary;
    bool usesSamples = true;             // --samples matters
    bool usesAggregates = false;         // --aggregates matters
    std::vector<std::string> debugViews; // values --debug accepts for this method
    uint32_t maxSurfaces = 0;            // --surfaces matters when > 0: S in 1..maxSurfaces
    uint32_t defaultSurfaces = 0;        // S when --surfaces is not given
};

const std::vector<MethodInfo>& knownMethods();
std::string knownMethodNames(); // "reference, noaa" for messages
bool isKnownMethod(const std::string& name);

// Throws std::invalid_argument naming the method or setting and the allowed values,
// eng::vk::MissingCapability when the device lacks what the method needs. `content`: our
// GpuScene, or a host's SceneTraits alone (agaa/common/scene_traits.h; its frames then give
// FrameInputs::geometry and ::environment).
std::unique_ptr<Technique> createTechnique(const std::string& method, eng::vk::Device& device,
                                           const TechniqueContent& content, const MethodSettings& settings);

} // namespace agaa
