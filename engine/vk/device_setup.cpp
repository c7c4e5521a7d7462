#include "engine/vk/device_setup.h"

#include "engine/vk/check.h"

#include <algorithm>
#include <cstring>

namespace eng::vk {
namespace {

bool contains(const std::vector<std::string>& list, const char* name) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

// Copies a struct the host chained into ours, keeping our pNext.
template <class T> void copyKeepingNext(T& into, const void* from) {
    void* next = into.pNext;
    std::memcpy(&into, from, sizeof(T));
    into.pNext = next;
}

// A feature by name. `capability`: for an optional feature, whether a probe turns the dependent
// path off when it is missing (true), or the renderer relies on it silently wherever the device
// offers it (false: a host that left it out is refused, naming it).
struct FeatureRef {
    const char* name;
    VkBool32 (*get)(const FeatureChain&);
    VkBool32* (*set)(FeatureChain&);
    bool capability;
};

#define AGAA_FEATURE(path, cap)                                                                              \
    FeatureRef {                                                                                             \
#path, [](const FeatureChain& f) { return f.path; }, [](FeatureChain & f) { return &f.path; }, cap   \
    }

// Every optional feature DeviceSetup enables when supported.
const FeatureRef kOptional[] = {
    AGAA_FEATURE(v13.maintenance4, false),
    AGAA_FEATURE(v13.subgroupSizeControl, false),
    AGAA_FEATURE(v12.scalarBlockLayout, false),
    AGAA_FEATURE(v12.shaderFloat16, false),
    AGAA_FEATURE(v12.storageBuffer8BitAccess, false),
    AGAA_FEATURE(v12.shaderBufferInt64Atomics, true),
    AGAA_FEATURE(v11.multiview, true),
    AGAA_FEATURE(core.features.sampleRateShading, true),
    AGAA_FEATURE(core.features.geometryShader, true), // gl_PrimitiveID in SBAA's prepass
    AGAA_FEATURE(core.features.multiViewport, true),
    AGAA_FEATURE(core.features.vertexPipelineStoresAndAtomics, false),
    AGAA_FEATURE(core.features.shaderInt64, true),
    AGAA_FEATURE(core.features.independentBlend, false),
    AGAA_FEATURE(core.features.shaderStorageImageMultisample, false),
    AGAA_FEATURE(core.features.samplerAnisotropy, false),
    AGAA_FEATURE(atomicFloat.shaderBufferFloat32Atomics, true),
    AGAA_FEATURE(atomicFloat.shaderBufferFloat32AtomicAdd, true),
    AGAA_FEATURE(atomicFloat.shaderImageFloat32Atomics, true),
    AGAA_FEATURE(atomicFloat.shaderImageFloat32AtomicAdd, true),
    AGAA_FEATURE(interlock.fragmentShaderSampleInterlock, true),
    AGAA_FEATURE(interlock.fragmentShaderPixelInterlock, true),
};

// The features the renderer cannot run without, with the name a message gives.
const FeatureRef kRequired[] = {
    {"Vulkan 1.3 dynamicRendering", [](const FeatureChain& f) { return f.v13.dynamicRendering; },
     [](FeatureChain& f) { return &f.v13.dynamicRendering; }, false},
    {"Vulkan 1.3 synchronization2", [](const FeatureChain& f) { return f.v13.synchronization2; },
     [](FeatureChain& f) { return &f.v13.synchronization2; }, false},
    {"Vulkan 1.2 hostQueryReset", [](const FeatureChain& f) { return f.v12.hostQueryReset; },
     [](FeatureChain& f) { return &f.v12.hostQueryReset; }, false},
    {"fragmentStoresAndAtomics",
     [](const FeatureChain& f) { return f.core.features.fragmentStoresAndAtomics; },
     [](FeatureChain& f) { return &f.core.features.fragmentStoresAndAtomics; }, false},
    {"Vulkan 1.2 shaderOutputLayer (layered sample-rate emulation)",
     [](const FeatureChain& f) { return f.v12.shaderOutputLayer; },
     [](FeatureChain& f) { return &f.v12.shaderOutputLayer; }, false},
    {"Vulkan 1.2 shaderOutputViewportIndex (layered sample-rate emulation)",
     [](const FeatureChain& f) { return f.v12.shaderOutputViewportIndex; },
     [](FeatureChain& f) { return &f.v12.shaderOutputViewportIndex; }, false},
};

void requireAll(const FeatureChain& features, const std::vector<std::string>& extensions,
                const std::string& deviceName, const char* how) {
    for (const FeatureRef& r : kRequired)
        if (!r.get(features)) throw MissingCapability(deviceName + how + r.name);
    if (!contains(extensions, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME))
        throw MissingCapability(deviceName + how + VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
}

std::string deviceName(VkPhysicalDevice physical) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(physical, &p);
    return p.deviceName;
}

} // namespace

FeatureChain::FeatureChain(const FeatureChain& other) {
    *this = other;
}

FeatureChain& FeatureChain::operator=(const FeatureChain& other) {
    core = other.core;
    v11 = other.v11;
    v12 = other.v12;
    v13 = other.v13;
    atomicFloat = other.atomicFloat;
    interlock = other.interlock;
    hasAtomicFloat = other.hasAtomicFloat;
    hasInterlock = other.hasInterlock;
    link();
    return *this;
}

void FeatureChain::link() {
    core.pNext = &v11;
    v11.pNext = &v12;
    v12.pNext = &v13;
    void** tail = &v13.pNext;
    *tail = nullptr;
    atomicFloat.pNext = nullptr;
    interlock.pNext = nullptr;
    if (hasAtomicFloat) {
        *tail = &atomicFloat;
        tail = &atomicFloat.pNext;
    }
    if (hasInterlock) *tail = &interlock;
}

FeatureChain FeatureChain::supported(VkPhysicalDevice physical, bool atomicFloatExtension,
                                     bool interlockExtension) {
    FeatureChain f;
    f.hasAtomicFloat = atomicFloatExtension;
    f.hasInterlock = interlockExtension;
    f.link();
    vkGetPhysicalDeviceFeatures2(physical, f.head());
    return f;
}

FeatureChain FeatureChain::fromCreateInfoChain(const void* pNext) {
    FeatureChain f;
    for (auto* s = static_cast<const VkBaseInStructure*>(pNext); s; s = s->pNext) {
        switch (s->sType) {
        case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2:
            copyKeepingNext(f.core, s);
            break;
        case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES:
            copyKeepingNext(f.v11, s);
            break;
        case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES:
            copyKeepingNext(f.v12, s);
            break;
        case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES:
            copyKeepingNext(f.v13, s);
            break;
        case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT:
            copyKeepingNext(f.atomicFloat, s);
            f.hasAtomicFloat = true;
            break;
        case VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FRAGMENT_SHADER_INTERLOCK_FEATURES_EXT:
            copyKeepingNext(f.interlock, s);
            f.hasInterlock = true;
            break;
        default:
            break;
        }
    }
    f.link();
    return f;
}

std::vector<std::string> supportedDeviceExtensions(VkPhysicalDevice physical) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> props(count);
    vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, props.data());
    std::vector<std::string> names;
    for (const VkExtensionProperties& e : props)
        names.emplace_back(e.extensionName);
    return names;
}

DeviceSetup::DeviceSetup(VkPhysicalDevice physical, bool swapchain) {
    const std::vector<std::string> exts = supportedDeviceExtensions(physical);
    const bool atomicFloat = contains(exts, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    const bool interlockExt = contains(exts, VK_EXT_FRAGMENT_SHADER_INTERLOCK_EXTENSION_NAME);
    const FeatureChain offered = FeatureChain::supported(physical, atomicFloat, interlockExt);
    requireAll(offered, exts, deviceName(physical), " lacks ");
    // Interlock is only worth its extension with sample interlock (what the streaming method uses).
    const bool interlock = interlockExt && offered.interlock.fragmentShaderSampleInterlock;

    m_features.hasAtomicFloat = atomicFloat;
    m_features.hasInterlock = interlock;
    for (const FeatureRef& r : kRequired)
        *r.set(m_features) = VK_TRUE;
    m_features.core.features.fragmentStoresAndAtomics = VK_TRUE;
    for (const FeatureRef& o : kOptional)
        *o.set(m_features) = o.get(offered);
    if (!interlock)
        m_features.interlock = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FRAGMENT_SHADER_INTERLOCK_FEATURES_EXT};
    // Int64 buffer atomics are used only with 64-bit integers in shaders.
    m_features.v12.shaderBufferInt64Atomics =
        offered.v12.shaderBufferInt64Atomics && offered.core.features.shaderInt64 ? VK_TRUE : VK_FALSE;
    m_features.link();

    m_extensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (contains(exts, VK_EXT_POST_DEPTH_COVERAGE_EXTENSION_NAME))
        m_extensions.push_back(VK_EXT_POST_DEPTH_COVERAGE_EXTENSION_NAME);
    if (atomicFloat) m_extensions.push_back(VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    if (interlock) m_extensions.push_back(VK_EXT_FRAGMENT_SHADER_INTERLOCK_EXTENSION_NAME);
    if (swapchain) {
        if (!contains(exts, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
            throw MissingCapability(deviceName(physical) + " lacks " + VK_KHR_SWAPCHAIN_EXTENSION_NAME);
        m_extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    }
}

void DeviceSetup::fill(VkDeviceCreateInfo& info) const {
    info.pNext = m_features.head();
    info.enabledExtensionCount = uint32_t(m_extensions.size());
    info.ppEnabledExtensionNames = m_extensions.data();
}

void checkHostEnables(VkPhysicalDevice physical, const FeatureChain& enabled,
                      const std::vector<std::string>& extensions) {
    const std::string name = deviceName(physical);
    requireAll(enabled, extensions, "host device " + name, " was created without ");
    const DeviceSetup wanted(physical, false);
    for (const FeatureRef& o : kOptional)
        if (!o.capability && o.get(wanted.features()) && !o.get(enabled))
            throw MissingCapability("host device " + name + " was created without " + o.name +
                                    ", which it supports and the renderer relies on (enable what "
                                    "eng::vk::DeviceSetup lists)");
}

Capabilities probeCapabilities(VkPhysicalDevice physical, const FeatureChain& f,
                               const std::vector<std::string>& exts) {
    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    subgroup.pNext = &driver;
    VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    p2.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(physical, &p2);
    const VkPhysicalDeviceLimits& limits = p2.properties.limits;

    Capabilities caps;
    caps.deviceName = p2.properties.deviceName;
    caps.driverName = std::string(driver.driverName) + " " + driver.driverInfo;
    caps.apiVersion = p2.properties.apiVersion;
    caps.deviceType = p2.properties.deviceType;
    caps.colorSampleCounts = limits.framebufferColorSampleCounts & limits.sampledImageColorSampleCounts;
    caps.depthSampleCounts = limits.framebufferDepthSampleCounts & limits.sampledImageDepthSampleCounts &
                             limits.framebufferStencilSampleCounts;
    caps.sampleRateShading = f.core.features.sampleRateShading;
    caps.fragmentPrimitiveId = f.core.features.geometryShader; // SPIR-V PrimitiveId in fragments: Geometry
    caps.postDepthCoverage = contains(exts, VK_EXT_POST_DEPTH_COVERAGE_EXTENSION_NAME);
    const bool atomicFloat = f.hasAtomicFloat && contains(exts, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    caps.bufferFloatAtomicAdd = atomicFloat && f.atomicFloat.shaderBufferFloat32AtomicAdd;
    caps.imageFloatAtomicAdd = atomicFloat && f.atomicFloat.shaderImageFloat32AtomicAdd;
    caps.bufferInt64Atomics = f.v12.shaderBufferInt64Atomics && f.core.features.shaderInt64;
    caps.subgroupSize = subgroup.subgroupSize;
    caps.subgroupStages = subgroup.supportedStages;
    caps.subgroupOperations = subgroup.supportedOperations;
    caps.fragmentShaderInterlock = f.hasInterlock &&
                                   contains(exts, VK_EXT_FRAGMENT_SHADER_INTERLOCK_EXTENSION_NAME) &&
                                   f.interlock.fragmentShaderSampleInterlock;
    caps.mixedSamples = contains(exts, "VK_AMD_mixed_attachment_samples") ||
                        contains(exts, "VK_NV_framebuffer_mixed_samples");
    caps.coverageOverride = contains(exts, "VK_NV_sample_mask_override_coverage");
    caps.sampleLocations = contains(exts, VK_EXT_SAMPLE_LOCATIONS_EXTENSION_NAME);
    caps.multiview = f.v11.multiview;
    caps.layeredOutput = f.v12.shaderOutputLayer && f.v12.shaderOutputViewportIndex;
    caps.multiViewport = f.core.features.multiViewport;
    caps.pushDescriptors = contains(exts, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
    caps.calibratedTimestamps = contains(exts, VK_EXT_CALIBRATED_TIMESTAMPS_EXTENSION_NAME);
    caps.timestampPeriodNs = limits.timestampPeriod;
    caps.maxComputeSharedMemory = limits.maxComputeSharedMemorySize;
    caps.maxImageArrayLayers = limits.maxImageArrayLayers;
    requireAll(f, exts, caps.deviceName, " lacks ");
    if (limits.timestampComputeAndGraphics != VK_TRUE)
        throw MissingCapability(caps.deviceName + " lacks timestampComputeAndGraphics");
    return caps;
}

} // namespace eng::vk
