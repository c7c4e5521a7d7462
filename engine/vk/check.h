#pragma once
// VK_CHECK for calls that must succeed: reports the expression, file, line and
// the VkResult name, then aborts. Results that are expected (OUT_OF_DATE,
// SUBOPTIMAL, out-of-memory...) are handled where they happen instead.

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace eng::vk {

const char* resultName(VkResult result);
[[noreturn]] void checkFailed(const char* expr, const char* file, int line, VkResult result);

// A required device feature or extension is missing: agaa-render exits with code 3.
struct MissingCapability : std::runtime_error {
    explicit MissingCapability(const std::string& what) : std::runtime_error(what) {}
};

// Device or host memory ran out while creating the named resource (VK_ERROR_OUT_OF_*_MEMORY from
// an allocation): the message names the resource and its size. Nothing is leaked by the throw.
struct OutOfMemory : std::runtime_error {
    explicit OutOfMemory(const std::string& what) : std::runtime_error(what) {}
};

// VK_ERROR_DEVICE_LOST from a submit or a wait: the device can do nothing more.
struct DeviceLost : std::runtime_error {
    explicit DeviceLost(const std::string& what) : std::runtime_error(what) {}
};

} // namespace eng::vk

#define VK_CHECK(expr)                                                                                       \
    do {                                                                                                     \
        VkResult vkCheckResult_ = (expr);                                                                    \
        if (vkCheckResult_ != VK_SUCCESS) ::eng::vk::checkFailed(#expr, __FILE__, __LINE__, vkCheckResult_); \
    } while (0)
