#include "engine/vk/check.h"

#include <cstdio>
#include <cstdlib>

namespace eng::vk {

// vk_enum_string_helper.h is not in Debian 12's Vulkan headers: the results a call can return.
const char* resultName(VkResult result) {
    switch (result) {
#define AGAA_RESULT(r)                                                                                       \
    case r:                                                                                                  \
        return #r;
        AGAA_RESULT(VK_SUCCESS)
        AGAA_RESULT(VK_NOT_READY)
        AGAA_RESULT(VK_TIMEOUT)
        AGAA_RESULT(VK_EVENT_SET)
        AGAA_RESULT(VK_EVENT_RESET)
        AGAA_RESULT(VK_INCOMPLETE)
        AGAA_RESULT(VK_ERROR_OUT_OF_HOST_MEMORY)
        AGAA_RESULT(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        AGAA_RESULT(VK_ERROR_INITIALIZATION_FAILED)
        AGAA_RESULT(VK_ERROR_DEVICE_LOST)
        AGAA_RESULT(VK_ERROR_MEMORY_MAP_FAILED)
        AGAA_RESULT(VK_ERROR_LAYER_NOT_PRESENT)
        AGAA_RESULT(VK_ERROR_EXTENSION_NOT_PRESENT)
        AGAA_RESULT(VK_ERROR_FEATURE_NOT_PRESENT)
        AGAA_RESULT(VK_ERROR_INCOMPATIBLE_DRIVER)
        AGAA_RESULT(VK_ERROR_TOO_MANY_OBJECTS)
        AGAA_RESULT(VK_ERROR_FORMAT_NOT_SUPPORTED)
        AGAA_RESULT(VK_ERROR_FRAGMENTED_POOL)
        AGAA_RESULT(VK_ERROR_UNKNOWN)
        AGAA_RESULT(VK_ERROR_OUT_OF_POOL_MEMORY)
        AGAA_RESULT(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        AGAA_RESULT(VK_ERROR_FRAGMENTATION)
        AGAA_RESULT(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        AGAA_RESULT(VK_PIPELINE_COMPILE_REQUIRED)
#undef AGAA_RESULT
    default:
        return "VkResult(unknown)";
    }
}

void checkFailed(const char* expr, const char* file, int line, VkResult result) {
    std::fprintf(stderr, "VK_CHECK failed: %s\n  at %s:%d\n  returned %s\n", expr, file, line,
                 resultName(result));
    std::fflush(stderr);
    std::abort();
}

} // namespace eng::vk
