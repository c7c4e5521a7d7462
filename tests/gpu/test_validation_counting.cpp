// The harness itself (issue 19): a validation message counts up to and including the device's
// destruction, where the layer reports leaked objects after every check a test body makes.

#include "engine/vk/resources.h"
#include "gpu_test_support.h"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

namespace {

TEST(ValidationCounting, AnObjectLeakedPastTheDeviceFailsTheTest) {
    EXPECT_NONFATAL_FAILURE(
        {
            auto device = agaa::test::makeValidatedDevice();
            // Never destroyed: vkDestroyDevice reports it, after the test body's own checks.
            eng::vk::createBuffer(*device, 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                  eng::vk::MemoryUse::GpuOnly, "test.leaked");
            agaa::test::expectNoValidationErrors(*device); // nothing yet: the leak shows at destruction
        },
        "validation errors raised while the device was destroyed");
}

TEST(ValidationCounting, ACleanDeviceLeavesNoMessage) {
    auto device = agaa::test::makeValidatedDevice();
    eng::vk::Buffer b = eng::vk::createBuffer(*device, 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                              eng::vk::MemoryUse::GpuOnly, "test.freed");
    eng::vk::destroyBuffer(*device, b);
    agaa::test::expectNoValidationErrors(*device);
} // the deleter checks the destruction

} // namespace
