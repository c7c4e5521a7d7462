#pragma once
// Instance, physical-device choice, logical device and queue. One graphics +
// compute queue (lavapipe has exactly one family). The debug messenger counts
// validation errors: messages whose id starts with VUID-, UNASSIGNED- or SYNC-
// are errors (tests fail on them); anything else (Mesa's own SPIR-V warnings,
// performance hints) is logged only. See ../shared/LAVAPIPE.md, "Traps".

#include "engine/vk/capabilities.h"

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace eng::vk {

struct DeviceOptions {
    bool validation = false;               // also enabled by AGAA_VALIDATE=1 in the environment
    bool synchronizationValidation = true; // with validation: sync2 hazards are reported as SYNC-*
    std::string
        deviceName;     // case-insensitive substring of VkPhysicalDeviceProperties::deviceName; empty = best
    bool quiet = false; // do not print non-error messages
    // For windowed hosts (the sample viewer): instance extensions a window system needs, e.g.
    // from glfwGetRequiredInstanceExtensions(), and VK_KHR_swapchain on the device. Refused with
    // MissingCapability when absent. Headless by default.
    std::vector<const char*> instanceExtensions;
    bool swapchain = false;
    // Fault injection (tests; also AGAA_FAIL_ALLOCATION and AGAA_LOSE_DEVICE in the environment):
    // the failAllocation-th device memory allocation (1-based; 0 = none) returns
    // VK_ERROR_OUT_OF_DEVICE_MEMORY, and the loseDeviceAtSubmit-th submission reports
    // VK_ERROR_DEVICE_LOST.
    uint32_t failAllocation = 0;
    uint32_t loseDeviceAtSubmit = 0;
};

// A device a host engine created and keeps owning (issue 18). The wrapper never destroys these
// handles; the host keeps them alive until the Device wrapper and everything made with it are
// gone. The host must have enabled what eng::vk::DeviceSetup (device_setup.h) lists: a missing
// required feature is refused with MissingCapability naming it.
struct HostDevice {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE; // graphics + compute, with timestamps
    uint32_t queueFamily = 0;
    // What the host passed to vkCreateDevice: the pNext chain of VkDeviceCreateInfo
    // (VkPhysicalDeviceFeatures2 first) and ppEnabledExtensionNames.
    const void* enabledFeatures = nullptr;
    std::vector<const char*> enabledExtensions;
    // The instance has VK_EXT_debug_utils enabled: the wrapper then adds its own messenger (to
    // count validation errors, see Device) and names objects. validation: the host enabled the
    // Khronos validation layer (only reported by validationEnabled()).
    bool debugUtils = false;
    bool validation = false;
    bool quiet = true; // do not print non-error messages
};

class Device {
  public:
    explicit Device(const DeviceOptions& options);
    // Wraps the host's device (no instance or device is created, none destroyed). It creates
    // only its own command pool and fence for submitAndWait() (uploads), and a debug messenger
    // when host.debugUtils. Threads: submitAndWait() submits to the host's queue, which Vulkan
    // requires to be externally synchronised: the host must not submit to it from another
    // thread at the same time.
    explicit Device(const HostDevice& host);
    bool ownsDevice() const { return m_ownsDevice; }
    ~Device();
    Device(const Device&) = delete;
    Device& operator=(const Device&) = delete;

    VkInstance instance() const { return m_instance; }
    VkPhysicalDevice physical() const { return m_physical; }
    VkDevice device() const { return m_device; }
    VkQueue queue() const { return m_queue; }
    uint32_t queueFamily() const { return m_queueFamily; }
    const Capabilities& caps() const { return m_caps; }
    bool validationEnabled() const { return m_validation; }

    // Validation messages counted as errors since creation (or the last reset).
    uint32_t validationErrors() const { return m_validationErrors->load(); }
    // The same count, in a cell that outlives the device: messages raised while it is destroyed
    // (leaked objects reported by vkDestroyDevice) land there too, so a caller can check after
    // destruction.
    std::shared_ptr<const std::atomic<uint32_t>> validationErrorCounter() const { return m_validationErrors; }
    std::vector<std::string> validationMessages() const;
    // Buffers and images alive now (each with its memory and views), kept by engine/vk/resources:
    // the soak test's measure of what a long run holds on to.
    int64_t liveResources() const { return m_liveResources.load(); }
    void trackResource(int delta) const { m_liveResources.fetch_add(delta); }
    void resetValidationErrors();

    // Records with record(), submits, and waits on a fence. Used for whole frames
    // and uploads; this project renders headless, so one frame in flight is enough.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record);

    // VK_EXT_debug_utils naming and labels (no-ops when the extension is absent).
    void setName(VkObjectType type, uint64_t handle, const std::string& name) const;
    template <class T> void setName(VkObjectType type, T handle, const std::string& name) const {
        setName(type, reinterpret_cast<uint64_t>(handle), name);
    }
    PFN_vkCmdBeginDebugUtilsLabelEXT beginLabel() const { return m_beginLabel; }
    PFN_vkCmdEndDebugUtilsLabelEXT endLabel() const { return m_endLabel; }
    PFN_vkCmdPushDescriptorSetKHR pushDescriptorSet() const { return m_pushDescriptorSet; }

    uint32_t findMemoryType(uint32_t typeBits, VkMemoryPropertyFlags required,
                            VkMemoryPropertyFlags preferred) const;

    // vkAllocateMemory through the fault injector: every device memory allocation of
    // engine/vk/resources goes through here.
    VkResult allocateMemory(const VkMemoryAllocateInfo& info, VkDeviceMemory* memory) const;

    // Lists every Vulkan 1.3 device the loader sees (for error messages and --caps).
    static std::vector<std::string> listDevices();

  private:
    void createInstance(const DeviceOptions& options);
    void pickPhysicalDevice(const DeviceOptions& options);
    void createDevice(bool swapchain);
    void pickQueueFamily();     // graphics + compute + timestamps, or MissingCapability
    void createMessenger();     // the debug messenger and debug_utils entry points
    void createSubmitObjects(); // command pool and fence for submitAndWait()
    static VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                    VkDebugUtilsMessageTypeFlagsEXT type,
                                                    const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                    void* user);

    VkInstance m_instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT m_messenger = VK_NULL_HANDLE;
    VkPhysicalDevice m_physical = VK_NULL_HANDLE;
    VkDevice m_device = VK_NULL_HANDLE;
    VkQueue m_queue = VK_NULL_HANDLE;
    uint32_t m_queueFamily = 0;
    VkCommandPool m_commandPool = VK_NULL_HANDLE;
    VkFence m_fence = VK_NULL_HANDLE;
    Capabilities m_caps;
    bool m_validation = false;
    bool m_ownsDevice = true; // false: a HostDevice, whose instance and device the host destroys
    bool m_debugUtils = false;
    bool m_quiet = false;
    std::shared_ptr<std::atomic<uint32_t>> m_validationErrors = std::make_shared<std::atomic<uint32_t>>(0);
    mutable std::atomic<int64_t> m_liveResources{0};
    uint32_t m_failAllocation = 0, m_loseDeviceAtSubmit = 0;
    mutable std::atomic<uint32_t> m_allocations{0};
    uint32_t m_submits = 0;
    mutable std::mutex m_messagesMutex;
    std::vector<std::string> m_messages;
    PFN_vkSetDebugUtilsObjectNameEXT m_setObjectName = nullptr;
    PFN_vkCmdBeginDebugUtilsLabelEXT m_beginLabel = nullptr;
    PFN_vkCmdEndDebugUtilsLabelEXT m_endLabel = nullptr;
    PFN_vkCmdPushDescriptorSetKHR m_pushDescriptorSet = nullptr;
};

} // namespace eng::vk
