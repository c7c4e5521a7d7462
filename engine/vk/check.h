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

} // namespace eng::vk

#define VK_CHECK(expr)                                                                                       \
    do {                                                                                                     \
        VkResult vkCheckResult_ = (expr);                                                                    \
        if (vkCheckResult_ != VK_SUCCESS) ::eng::vk::checkFailed(#expr, __FILE__, __LINE__, vkCheckResult_); \
    } while (0)
