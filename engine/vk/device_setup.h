#pragma once
// What the renderer needs of a VkDevice, in one place for both ways a Device comes to be:
//  - created by eng::vk::Device itself: DeviceSetup is what it enables;
//  - created by a host engine and wrapped (HostDevice): the host enables what DeviceSetup lists
//    (or fills its own VkDeviceCreateInfo from it), and the wrapper checks the host's enables
//    against it, naming any required feature the host left out.
// probeCapabilities() turns the features and extensions a device has enabled into Capabilities,
// so a path a device lacks is refused by the technique that needs it, never crashed into.

#include "engine/vk/capabilities.h"

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace eng::vk {

// The feature structs the renderer reads, linked as one VkPhysicalDeviceFeatures2 chain.
// Copies relink their own chain (the pNext pointers point into the object itself).
struct FeatureChain {
    VkPhysicalDeviceFeatures2 core{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    VkPhysicalDeviceVulkan11Features v11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceVulkan12Features v12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicFloat{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    VkPhysicalDeviceFragmentShaderInterlockFeaturesEXT interlock{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FRAGMENT_SHADER_INTERLOCK_FEATURES_EXT};
    bool hasAtomicFloat = false, hasInterlock = false; // the EXT structs are in the chain

    FeatureChain() { link(); }
    FeatureChain(const FeatureChain& other);
    FeatureChain& operator=(const FeatureChain& other);
    VkPhysicalDeviceFeatures2* head() { return &core; }
    const VkPhysicalDeviceFeatures2* head() const { return &core; }

    // What the physical device supports (vkGetPhysicalDeviceFeatures2).
    static FeatureChain supported(VkPhysicalDevice physical, bool atomicFloatExtension,
                                  bool interlockExtension);
    // What a host enabled: the pNext chain it gave vkCreateDevice (VkPhysicalDeviceFeatures2 and
    // the Vulkan 1.1/1.2/1.3 structs, plus the two EXT structs above; other structs are skipped).
    static FeatureChain fromCreateInfoChain(const void* pNext);
    // Rebuilds the pNext chain (after hasAtomicFloat / hasInterlock changed).
    void link();
};

// What the renderer enables on a device: the required features (MissingCapability naming the
// first one missing) and every optional one the device offers.
class DeviceSetup {
  public:
    DeviceSetup(VkPhysicalDevice physical, bool swapchain);
    const FeatureChain& features() const { return m_features; }
    const std::vector<const char*>& extensions() const { return m_extensions; }
    // Points info.pNext at the feature chain and lists the extensions; the caller adds queues.
    // `*this` must outlive the vkCreateDevice call.
    void fill(VkDeviceCreateInfo& info) const;

  private:
    FeatureChain m_features;
    std::vector<const char*> m_extensions;
};

// Capabilities from what a device has enabled. `extensions`: its enabled device extensions
// (those the renderer reads are its own, the rest are reported only). Fills everything but
// the queue-family fields; throws MissingCapability naming a required feature that is off.
Capabilities probeCapabilities(VkPhysicalDevice physical, const FeatureChain& enabled,
                               const std::vector<std::string>& extensions);

// Throws MissingCapability naming the first feature DeviceSetup would enable on `physical` that
// `enabled` lacks, except the optional ones behind a capability (the probe turns those off).
void checkHostEnables(VkPhysicalDevice physical, const FeatureChain& enabled,
                      const std::vector<std::string>& extensions);

std::vector<std::string> supportedDeviceExtensions(VkPhysicalDevice physical);

} // namespace eng::vk
