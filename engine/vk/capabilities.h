#pragma once
// What the device can do, probed once at device creation. Techniques consult
// it to choose their path (for example the AG-buffer generation path) and
// report the choice; a path whose feature is missing is never taken silently.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace eng::vk {

struct Capabilities {
    std::string deviceName;
    std::string driverName;
    uint32_t apiVersion = 0;
    VkPhysicalDeviceType deviceType = VK_PHYSICAL_DEVICE_TYPE_OTHER;

    VkSampleCountFlags colorSampleCounts = 0; // framebufferColorSampleCounts & depth & storage-image
    VkSampleCountFlags depthSampleCounts = 0;
    bool sampleRateShading = false;
    bool fragmentPrimitiveId = false;  // geometryShader: gl_PrimitiveID readable in fragment shaders
    bool postDepthCoverage = false;    // VK_EXT_post_depth_coverage
    bool bufferFloatAtomicAdd = false; // VK_EXT_shader_atomic_float
    bool imageFloatAtomicAdd = false;
    bool bufferInt64Atomics = false; // Vulkan 1.2 shaderBufferInt64Atomics (with shaderInt64)
    uint32_t subgroupSize = 0;
    VkShaderStageFlags subgroupStages = 0;
    VkSubgroupFeatureFlags subgroupOperations = 0;
    bool fragmentShaderInterlock = false; // VK_EXT_fragment_shader_interlock
    bool mixedSamples = false;     // VK_AMD_mixed_attachment_samples or VK_NV_framebuffer_mixed_samples
    bool coverageOverride = false; // VK_NV_sample_mask_override_coverage
    bool sampleLocations = false;  // VK_EXT_sample_locations
    bool multiview = false;
    bool layeredOutput = false; // shaderOutputLayer (gl_Layer from the vertex shader)
    bool multiViewport = false;
    bool pushDescriptors = false; // VK_KHR_push_descriptor
    bool calibratedTimestamps = false;
    float timestampPeriodNs = 0.0f;
    uint32_t timestampValidBits = 0;
    uint32_t maxComputeSharedMemory = 0;
    uint32_t maxImageArrayLayers = 0;

    bool supportsSamples(uint32_t n) const { return (colorSampleCounts & depthSampleCounts & n) != 0; }
    // Human-readable multi-line report (agaa-render --caps).
    std::string describe() const;
};

} // namespace eng::vk
