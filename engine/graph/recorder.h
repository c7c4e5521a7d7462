#pragma once
// The commands execute() records itself (barriers and timestamps; the passes record their own),
// behind an interface so that tests/graph can check them on a mock, without a device. The Vulkan
// recorder is the default.

#include <vulkan/vulkan.h>

#include <cstdint>

namespace eng::rg {

class CommandRecorder {
  public:
    virtual ~CommandRecorder() = default;
    virtual void pipelineBarrier(VkCommandBuffer cmd, const VkDependencyInfo& dependency) = 0;
    virtual void writeTimestamp(VkCommandBuffer cmd, VkPipelineStageFlags2 stage, VkQueryPool pool,
                                uint32_t query) = 0;
};

// vkCmdPipelineBarrier2 and vkCmdWriteTimestamp2.
CommandRecorder& vulkanRecorder();

} // namespace eng::rg
