#include "engine/vk/device.h"

#include "engine/vk/check.h"
#include "engine/vk/device_setup.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

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
        // A host device: only the wrapper's own objects go (submitAndWait() waited on its work).
        if (m_ownsDevice) vkDeviceWaitIdle(m_device);
        vkDestroyFence(m_device, m_fence, nullptr);
        vkDestroyCommandPool(m_device, m_commandPool, nullptr);
        if (m_ownsDevice) vkDestroyDevice(m_device, nullptr);
    }
    if (m_messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(m_instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(m_instance, m_messenger, nullptr);
    }
    if (m_instance && m_ownsDevice) vkDestroyInstance(m_instance, nullptr);
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

    createMessenger();
}

void Device::createMessenger() {
    if (!m_debugUtils) return;
    VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messengerInfo.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                                VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messengerInfo.pfnUserCallback = &Device::onMessage;
    messengerInfo.pUserData = this;
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

void Device::pickQueueFamily() {
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(m_physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(m_physical, &familyCount, families.data());
    for (uint32_t i = 0; i < familyCount; ++i) {
        VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
        if ((families[i].queueFlags & need) == need && families[i].timestampValidBits > 0) {
            m_queueFamily = i;
            m_caps.timestampValidBits = families[i].timestampValidBits;
            return;
        }
    }
    throw MissingCapability(m_caps.deviceName + ": no queue family with graphics + compute + timestamps");
}

void Device::createDevice(bool swapchain) {
    // What the device enables is also what a host creating its own device must enable
    // (device_setup.h); the capabilities are probed from exactly that.
    const DeviceSetup setup(m_physical, swapchain);
    m_caps = probeCapabilities(m_physical, setup.features(), supportedDeviceExtensions(m_physical));
    pickQueueFamily();

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = m_queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    setup.fill(info);
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queueInfo;
    VK_CHECK(vkCreateDevice(m_physical, &info, nullptr, &m_device));
    vkGetDeviceQueue(m_device, m_queueFamily, 0, &m_queue);
    createSubmitObjects();
}

Device::Device(const HostDevice& host) {
    if (!host.instance || !host.physical || !host.device || !host.queue)
        throw std::invalid_argument("HostDevice: instance, physical, device and queue must all be set");
    m_ownsDevice = false;
    m_quiet = host.quiet;
    m_instance = host.instance;
    m_physical = host.physical;
    m_device = host.device;
    m_queue = host.queue;
    m_validation = host.validation;
    m_debugUtils = host.debugUtils;
    m_failAllocation = envCount("AGAA_FAIL_ALLOCATION");
    m_loseDeviceAtSubmit = envCount("AGAA_LOSE_DEVICE");
    const std::vector<std::string> extensions(host.enabledExtensions.begin(), host.enabledExtensions.end());
    const FeatureChain enabled = FeatureChain::fromCreateInfoChain(host.enabledFeatures);
    // The host's enables decide what the renderer may use, not what the hardware offers.
    checkHostEnables(m_physical, enabled, extensions);
    m_caps = probeCapabilities(m_physical, enabled, extensions);
    uint32_t familyCount = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(m_physical, &familyCount, nullptr);
    std::vector<VkQueueFamilyProperties> families(familyCount);
    vkGetPhysicalDeviceQueueFamilyProperties(m_physical, &familyCount, families.data());
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if (host.queueFamily >= familyCount || (families[host.queueFamily].queueFlags & need) != need ||
        families[host.queueFamily].timestampValidBits == 0)
        throw MissingCapability("host queue family " + std::to_string(host.queueFamily) + " of " +
                                m_caps.deviceName + " lacks graphics + compute + timestamps");
    m_queueFamily = host.queueFamily;
    m_caps.timestampValidBits = families[host.queueFamily].timestampValidBits;
    createMessenger();
    createSubmitObjects();
}

void Device::createSubmitObjects() {
    m_pushDescriptorSet = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
        vkGetDeviceProcAddr(m_device, "vkCmdPushDescriptorSetKHR"));
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT | VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    poolInfo.queueFamilyIndex = m_queueFamily;
    VK_CHECK(vkCreateCommandPool(m_device, &poolInfo, nullptr, &m_commandPool));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(m_device, &fenceInfo, nullptr, &m_fence));
    if (m_ownsDevice) setName(VK_OBJECT_TYPE_QUEUE, m_queue, "agaa.queue"); // the host's queue keeps its name
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
