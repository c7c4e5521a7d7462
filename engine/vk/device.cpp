#include "engine/vk/device.h"

#include "engine/vk/check.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace eng::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool hasExtension(const std::vector<VkExtensionProperties>& list, const char* name) {
    return std::any_of(list.begin(), list.end(), [&](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, name) == 0;
    });
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

bool envFlag(const char* name) {
    const char* v = std::getenv(name);
    return v && *v && std::strcmp(v, "0") != 0;
}

// A positive count from the environment (fault injection), 0 when unset or not a number.
uint32_t envCount(const char* name) {
    const char* v = std::getenv(name);
    if (!v || !*v) return 0;
    char* end = nullptr;
    unsigned long n = std::strtoul(v, &end, 10);
    return end && *end == '\0' && n <= 0xFFFFFFFFul ? uint32_t(n) : 0;
}

// Real GPUs before lavapipe; among equals the first enumerated.
int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return 3;
    default:
        return 4;
    }
}

bool isErrorId(const char* id) {
    if (!id) return false;
    return std::strncmp(id, "VUID-", 5) == 0 || std::strncmp(id, "UNASSIGNED-", 11) == 0 ||
           std::strncmp(id, "SYNC-", 5) == 0;
}

} // namespace

Device::Device(const DeviceOptions& options) {
    m_quiet = options.quiet;
    createInstance(options);
    pickPhysicalDevice(options);
    createDevice(options.swapchain);
}

Device::~Device() {
    if (m_device) {
        vkDeviceWaitIdle(m_device);
        vkDestroyFence(m_device, m_fence, nullptr);
        vkDestroyCommandPool(m_device, m_commandPool, nullptr);
        vkDestroyDevice(m_device, nullptr);
    }
    if (m_messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(m_instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(m_instance, m_messenger, nullptr);
    }
    if (m_instance) vkDestroyInstance(m_instance, nullptr);
}

void Device::createInstance(const DeviceOptions& options) {
    m_validation = options.validation || envFlag("AGAA_VALIDATE");
    m_failAllocation = options.failAllocation ? options.failAllocation : envCount("AGAA_FAIL_ALLOCATION");
    m_loseDeviceAtSubmit =
        options.loseDeviceAtSubmit ? options.loseDeviceAtSubmit : envCount("AGAA_LOSE_DEVICE");

    uint32_t layerCount = 0;
    vkEnumerateInstanceLayerProperties(&layerCount, nullptr);
    std::vector<VkLayerProperties> layers(layerCount);
    vkEnumerateInstanceLayerProperties(&layerCount, layers.data());
    bool haveValidation = std::any_of(layers.begin(), layers.end(), [](const VkLayerProperties& l) {
        return std::strcmp(l.layerName, kValidationLayer) == 0;
    });
    if (m_validation && !haveValidation)
        throw MissingCapability("validation was requested but VK_LAYER_KHRONOS_validation is not installed "
                                "(Debian package vulkan-validationlayers)");

    uint32_t extCount = 0;
    vkEnumerateInstanceExtensionProperties(nullptr, &extCount, nullptr);
    std::vector<VkExtensionProperties> exts(extCount);
    vkEnumerateInstanceExtensionProperties(nullptr, &extCount, exts.data());
    std::vector<const char*> enabled;
    m_debugUtils = hasExtension(exts, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    // Without the messenger no validation message would reach the counter: a validated run
    // would pass however many errors it raised.
    if (m_validation && !m_debugUtils)
        throw MissingCapability("validation was requested but the instance lacks VK_EXT_debug_utils, so "
                                "validation messages could not be counted");
    if (m_debugUtils) enabled.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    for (const char* name : options.instanceExtensions) {
        if (!hasExtension(exts, name))
            throw MissingCapability(std::string("instance extension ") + name + " is not available");
        auto same = [&](const char* e) { return std::strcmp(e, name) == 0; };
        const bool already = std::any_of(enabled.begin(), enabled.end(), same);
        if (!already) enabled.push_back(name);
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "agaa";
    app.pEngineName = "agaa";
    app.apiVersion = VK_API_VERSION_1_3;

    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &Device::onMessage;
    messengerInfo.pUserData = this;

    VkValidationFeatureEnableEXT syncValidation = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &syncValidation;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledExtensionCount = uint32_t(enabled.size());
    info.ppEnabledExtensionNames = enabled.data();
    if (m_validation) {
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = &kValidationLayer;
        if (options.synchronizationValidation) {
            features.pNext = m_debugUtils ? &messengerInfo : nullptr;
            info.pNext = &features;
        } else if (m_debugUtils) {
            info.pNext = &messengerInfo;
        }
    }
    VkResult result = vkCreateInstance(&info, nullptr, &m_instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw MissingCapability("no Vulkan 1.3 driver found (install mesa-vulkan-drivers for lavapipe)");
    VK_CHECK(result);

    if (m_debugUtils) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(m_instance, "vkCreateDebugUtilsMessengerEXT"));
        if (create) VK_CHECK(create(m_instance, &messengerInfo, nullptr, &m_messenger));
        m_setObjectName = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
            vkGetInstanceProcAddr(m_instance, "vkSetDebugUtilsObjectNameEXT"));
        m_beginLabel = reinterpret_cast<PFN_vkCmdBeginDebugUtilsLabelEXT>(
            vkGetInstanceProcAddr(m_instance, "vkCmdBeginDebugUtilsLabelEXT"));
        m_endLabel = reinterpret_cast<PFN_vkCmdEndDebugUtilsLabelEXT>(
            vkGetInstanceProcAddr(m_instance, "vkCmdEndDebugUtilsLabelEXT"));
    }
}

std::vector<std::string> Device::listDevices() {
    std::vector<std::string> names;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.apiVersion = VK_API_VERSION_1_3;
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    VkInstance instance = VK_NULL_HANDLE;
    if (vkCreateInstance(&info, nullptr, &instance) != VK_SUCCESS) return names;
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    for (VkPhysicalDevice d : devices) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(d, &p);
        names.emplace_back(p.deviceName);
    }
    vkDestroyInstance(instance, nullptr);
    return names;
}

void Device::pickPhysicalDevice(const DeviceOptions& options) {
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(m_instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(m_instance, &count, devices.data());

    std::string wanted = lower(options.deviceName);
    std::string seen;
    int bestRank = 1 << 30;
    for (VkPhysicalDevice d : devices) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(d, &p);
        seen += std::string(seen.empty() ? "" : ", ") + "'" + p.deviceName + "'";
        if (p.apiVersion < VK_API_VERSION_1_3) continue;
        if (!wanted.empty() && lower(p.deviceName).find(wanted) == std::string::npos) continue;
        int rank = typeRank(p.deviceType);
        if (rank < bestRank) {
            bestRank = rank;
            m_physical = d;
        }
    }
    if (!m_physical) {
        if (!wanted.empty())
            throw MissingCapability(
                "--device '" + options.deviceName +
                "' matches no Vulkan 1.3 device; devices: " + (seen.empty() ? std::string("none") : seen));
        throw MissingCapability(
            "no Vulkan 1.3 device (devices: " + (seen.empty() ? std::string("none") : seen) +
            "); install mesa-vulkan-drivers for lavapipe");
    }
}

void Device::createDevice(bool swapchain) {
    uint32_t extCount = 0;
    vkEnumerateDeviceExtensionProperties(m_physical, nullptr, &extCount, nullptr);
    std::vector<VkExtensionProperties> exts(extCount);
    vkEnumerateDeviceExtensionProperties(m_physical, nullptr, &extCount, exts.data());

    // --- capability probe -------------------------------------------------------------------
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicFloat{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    VkPhysicalDeviceFragmentShaderInterlockFeaturesEXT interlock{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FRAGMENT_SHADER_INTERLOCK_FEATURES_EXT};
    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceVulkan11Features f11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    VkPhysicalDeviceFeatures2 f2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    f2.pNext = &f11;
    f11.pNext = &f12;
    f12.pNext = &f13;
    bool hasAtomicFloat = hasExtension(exts, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    bool hasInterlock = hasExtension(exts, VK_EXT_FRAGMENT_SHADER_INTERLOCK_EXTENSION_NAME);
    void** tail = &f13.pNext;
    if (hasAtomicFloat) {
        *tail = &atomicFloat;
        tail = &atomicFloat.pNext;
    }
    if (hasInterlock) {
        *tail = &interlock;
        tail = &interlock.pNext;
    }
    vkGetPhysicalDeviceFeatures2(m_physical, &f2);

    VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    subgroup.pNext = &driver;
    VkPhysicalDeviceProperties2 p2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    p2.pNext = &subgroup;
    vkGetPhysicalDeviceProperties2(m_physical, &p2);
    const VkPhysicalDeviceLimits& limits = p2.properties.limits;

    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(m_physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(m_physical, &familyCount, families.data());
    bool foundFamily = false;
    for (uint32_t i = 0; i < familyCount; ++i) {
        VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & need) == need && families[i].timestampValidBits > 0) {
            m_queueFamily = i;
            m_caps.timestampValidBits = families[i].timestampValidBits;
            foundFamily = true;
            break;
        }
    }
    if (!foundFamily)
        throw MissingCapability(std::string(p2.properties.deviceName) +
                                ": no queue family with graphics + compute + timestamps");

    m_caps.deviceName = p2.properties.deviceName;
    m_caps.driverName = std::string(driver.driverName) + " " + driver.driverInfo;
    m_caps.apiVersion = p2.properties.apiVersion;
    m_caps.deviceType = p2.properties.deviceType;
    m_caps.colorSampleCounts = limits.framebufferColorSampleCounts & limits.sampledImageColorSampleCounts;
    m_caps.depthSampleCounts = limits.framebufferDepthSampleCounts & limits.sampledImageDepthSampleCounts &
                               limits.framebufferStencilSampleCounts;
    m_caps.sampleRateShading = f2.features.sampleRateShading;
    m_caps.fragmentPrimitiveId = f2.features.geometryShader; // SPIR-V PrimitiveId in fragments: Geometry
    m_caps.postDepthCoverage = hasExtension(exts, VK_EXT_POST_DEPTH_COVERAGE_EXTENSION_NAME);
    m_caps.bufferFloatAtomicAdd = hasAtomicFloat && atomicFloat.shaderBufferFloat32AtomicAdd;
    m_caps.imageFloatAtomicAdd = hasAtomicFloat && atomicFloat.shaderImageFloat32AtomicAdd;
    m_caps.bufferInt64Atomics = f12.shaderBufferInt64Atomics && f2.features.shaderInt64;
    m_caps.subgroupSize = subgroup.subgroupSize;
    m_caps.subgroupStages = subgroup.supportedStages;
    m_caps.subgroupOperations = subgroup.supportedOperations;
    m_caps.fragmentShaderInterlock = hasInterlock && interlock.fragmentShaderSampleInterlock;
    m_caps.mixedSamples = hasExtension(exts, "VK_AMD_mixed_attachment_samples") ||
                          hasExtension(exts, "VK_NV_framebuffer_mixed_samples");
    m_caps.coverageOverride = hasExtension(exts, "VK_NV_sample_mask_override_coverage");
    m_caps.sampleLocations = hasExtension(exts, VK_EXT_SAMPLE_LOCATIONS_EXTENSION_NAME);
    m_caps.multiview = f11.multiview;
    m_caps.layeredOutput = f12.shaderOutputLayer && f12.shaderOutputViewportIndex;
    m_caps.multiViewport = f2.features.multiViewport;
    m_caps.pushDescriptors = hasExtension(exts, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME);
    m_caps.calibratedTimestamps = hasExtension(exts, VK_EXT_CALIBRATED_TIMESTAMPS_EXTENSION_NAME);
    m_caps.timestampPeriodNs = limits.timestampPeriod;
    m_caps.maxComputeSharedMemory = limits.maxComputeSharedMemorySize;
    m_caps.maxImageArrayLayers = limits.maxImageArrayLayers;

    // --- required features: the renderer cannot run without these -------------------------
    struct Required {
        bool present;
        const char* name;
    };
    const Required required[] = {
        {f13.dynamicRendering == VK_TRUE, "Vulkan 1.3 dynamicRendering"},
        {f13.synchronization2 == VK_TRUE, "Vulkan 1.3 synchronization2"},
        {f12.hostQueryReset == VK_TRUE, "Vulkan 1.2 hostQueryReset"},
        {f2.features.fragmentStoresAndAtomics == VK_TRUE, "fragmentStoresAndAtomics"},
        {m_caps.pushDescriptors, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME},
        {m_caps.layeredOutput, "Vulkan 1.2 shaderOutputLayer (layered sample-rate emulation)"},
        {limits.timestampComputeAndGraphics == VK_TRUE, "timestampComputeAndGraphics"},
    };
    for (const Required& r : required)
        if (!r.present) throw MissingCapability(m_caps.deviceName + " lacks " + r.name);

    // --- enable what exists ------------------------------------------------------------------
    std::vector<const char*> enable = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (m_caps.postDepthCoverage) enable.push_back(VK_EXT_POST_DEPTH_COVERAGE_EXTENSION_NAME);
    if (hasAtomicFloat) enable.push_back(VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    if (m_caps.fragmentShaderInterlock) enable.push_back(VK_EXT_FRAGMENT_SHADER_INTERLOCK_EXTENSION_NAME);
    if (swapchain) {
        if (!hasExtension(exts, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
            throw MissingCapability(m_caps.deviceName + " lacks " + VK_KHR_SWAPCHAIN_EXTENSION_NAME);
        enable.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    }

    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicFloatOn{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    atomicFloatOn.shaderBufferFloat32Atomics = atomicFloat.shaderBufferFloat32Atomics;
    atomicFloatOn.shaderBufferFloat32AtomicAdd = atomicFloat.shaderBufferFloat32AtomicAdd;
    atomicFloatOn.shaderImageFloat32Atomics = atomicFloat.shaderImageFloat32Atomics;
    atomicFloatOn.shaderImageFloat32AtomicAdd = atomicFloat.shaderImageFloat32AtomicAdd;
    VkPhysicalDeviceFragmentShaderInterlockFeaturesEXT interlockOn{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FRAGMENT_SHADER_INTERLOCK_FEATURES_EXT};
    interlockOn.fragmentShaderSampleInterlock = interlock.fragmentShaderSampleInterlock;
    interlockOn.fragmentShaderPixelInterlock = interlock.fragmentShaderPixelInterlock;

    VkPhysicalDeviceVulkan13Features on13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    on13.dynamicRendering = VK_TRUE;
    on13.synchronization2 = VK_TRUE;
    on13.maintenance4 = f13.maintenance4;
    on13.subgroupSizeControl = f13.subgroupSizeControl;
    VkPhysicalDeviceVulkan12Features on12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    on12.hostQueryReset = VK_TRUE;
    on12.shaderOutputLayer = VK_TRUE;
    on12.shaderOutputViewportIndex = VK_TRUE;
    on12.scalarBlockLayout = f12.scalarBlockLayout;
    on12.shaderFloat16 = f12.shaderFloat16;
    on12.storageBuffer8BitAccess = f12.storageBuffer8BitAccess;
    on12.shaderBufferInt64Atomics = m_caps.bufferInt64Atomics ? VK_TRUE : VK_FALSE;
    VkPhysicalDeviceVulkan11Features on11{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES};
    on11.multiview = f11.multiview;
    VkPhysicalDeviceFeatures2 on2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    on2.features.sampleRateShading = f2.features.sampleRateShading;
    on2.features.geometryShader = f2.features.geometryShader; // gl_PrimitiveID in SBAA's prepass
    on2.features.multiViewport = f2.features.multiViewport;
    on2.features.fragmentStoresAndAtomics = VK_TRUE;
    on2.features.vertexPipelineStoresAndAtomics = f2.features.vertexPipelineStoresAndAtomics;
    on2.features.shaderInt64 = f2.features.shaderInt64;
    on2.features.independentBlend = f2.features.independentBlend;
    on2.features.shaderStorageImageMultisample = f2.features.shaderStorageImageMultisample;
    on2.features.samplerAnisotropy = f2.features.samplerAnisotropy;
    on2.pNext = &on11;
    on11.pNext = &on12;
    on12.pNext = &on13;
    void** onTail = &on13.pNext;
    if (hasAtomicFloat) {
        *onTail = &atomicFloatOn;
        onTail = &atomicFloatOn.pNext;
    }
    if (m_caps.fragmentShaderInterlock) {
        *onTail = &interlockOn;
        onTail = &interlockOn.pNext;
    }

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = m_queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    info.pNext = &on2;
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    info.enabledExtensionCount = uint32_t(enable.size());
    info.ppEnabledExtensionNames = enable.data();
    VK_CHECK(vkCreateDevice(m_physical, &info, nullptr, &m_device));
    vkGetDeviceQueue(m_device, m_queueFamily, 0, &m_queue);
    m_pushDescriptorSet = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
        vkGetDeviceProcAddr(m_device, "vkCmdPushDescriptorSetKHR"));

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT | VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = m_queueFamily;
    VK_CHECK(vkCreateCommandPool(m_device, &poolInfo, nullptr, &m_commandPool));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(m_device, &fenceInfo, nullptr, &m_fence));
    setName(VK_OBJECT_TYPE_QUEUE, m_queue, "agaa.queue");
    setName(VK_OBJECT_TYPE_COMMAND_POOL, m_commandPool, "agaa.commandPool");
}

VKAPI_ATTR VkBool32 VKAPI_CALL Device::onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                 void* user) {
    auto* self = static_cast<Device*>(user);
    const char* id = data->pMessageIdName ? data->pMessageIdName : "";
    bool error = isErrorId(id);
    if (error) {
        self->m_validationErrors->fetch_add(1);
        std::lock_guard lock(self->m_messagesMutex);
        if (self->m_messages.size() < 64) self->m_messages.emplace_back(data->pMessage ? data->pMessage : id);
    }
    if (error || (!self->m_quiet && severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT))
        std::fprintf(stderr, "[vulkan %s] %s\n", error ? "validation error" : "message",
                     data->pMessage ? data->pMessage : id);
    return VK_FALSE;
}

std::vector<std::string> Device::validationMessages() const {
    std::lock_guard lock(m_messagesMutex);
    return m_messages;
}

void Device::resetValidationErrors() {
    std::lock_guard lock(m_messagesMutex);
    m_messages.clear();
    m_validationErrors->store(0);
}

VkResult Device::allocateMemory(const VkMemoryAllocateInfo& info, VkDeviceMemory* memory) const {
    if (m_failAllocation != 0 && m_allocations.fetch_add(1) + 1 == m_failAllocation)
        return VK_ERROR_OUT_OF_DEVICE_MEMORY;
    return vkAllocateMemory(m_device, &info, nullptr, memory);
}

void Device::submitAndWait(const std::function<void(VkCommandBuffer)>& record) {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = m_commandPool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(m_device, &alloc, &cmd));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
    try {
        record(cmd);
    } catch (...) {
        vkFreeCommandBuffers(m_device, m_commandPool, 1, &cmd);
        throw;
    }
    VK_CHECK(vkEndCommandBuffer(cmd));
    VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cmdInfo.commandBuffer = cmd;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmdInfo;
    const bool injectLoss = m_loseDeviceAtSubmit != 0 && ++m_submits == m_loseDeviceAtSubmit;
    VkResult r = injectLoss ? VK_ERROR_DEVICE_LOST : vkQueueSubmit2(m_queue, 1, &submit, m_fence);
    const char* call = "vkQueueSubmit2";
    if (r == VK_SUCCESS) {
        call = "vkWaitForFences";
        r = vkWaitForFences(m_device, 1, &m_fence, VK_TRUE, UINT64_MAX);
        if (r == VK_SUCCESS) VK_CHECK(vkResetFences(m_device, 1, &m_fence));
    }
    // Expected failures are reported, not aborted on (STYLE.md, Errors): the caller unwinds and
    // releases what it holds; a lost device is the end of the run.
    if (r == VK_ERROR_DEVICE_LOST) {
        vkFreeCommandBuffers(m_device, m_commandPool, 1, &cmd);
        throw DeviceLost(
            std::string(call) + " returned VK_ERROR_DEVICE_LOST" +
            (injectLoss ? " (injected: AGAA_LOSE_DEVICE / DeviceOptions::loseDeviceAtSubmit)" : ""));
    }
    if (r == VK_ERROR_OUT_OF_HOST_MEMORY || r == VK_ERROR_OUT_OF_DEVICE_MEMORY) {
        vkFreeCommandBuffers(m_device, m_commandPool, 1, &cmd);
        throw OutOfMemory(std::string(call) + " returned " + resultName(r));
    }
    VK_CHECK(r);
    vkFreeCommandBuffers(m_device, m_commandPool, 1, &cmd);
}

void Device::setName(VkObjectType type, uint64_t handle, const std::string& name) const {
    if (!m_setObjectName || !handle) return;
    VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
    info.objectType = type;
    info.objectHandle = handle;
    info.pObjectName = name.c_str();
    m_setObjectName(m_device, &info);
}

uint32_t Device::findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                                VkMemoryPropertyFlags preferred) const {
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(m_physical, &props);
    for (VkMemoryPropertyFlags want : {required | preferred, required}) {
        for (uint32_t i = 0; i < props.memoryTypeCount; ++i) {
            if ((typeBits & (1u << i)) && (props.memoryTypes[i].propertyFlags & want) == want) return i;
        }
    }
    throw MissingCapability(m_caps.deviceName + ": no memory type with the required properties");
}

} // namespace eng::vk
