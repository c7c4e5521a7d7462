#pragma once
// The commands execute() records itself (barriers, timestamps, and the begin/end of a pass's render
// pass with its full-area viewport and scissor; the passes record their own draws and dispatches),
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
    virtual void beginRendering(VkCommandBuffer cmd, const VkRenderingInfo& rendering) = 0;
    virtual void setViewport(VkCommandBuffer cmd, const VkViewport& viewport, const VkRect2D& scissor) = 0;
    virtual void endRendering(VkCommandBuffer cmd) = 0;
};

// vkCmdPipelineBarrier2, vkCmdWriteTimestamp2, vkCmdBeginRendering, vkCmdSetViewport and
// vkCmdSetScissor, vkCmdEndRendering.
CommandRecorder& vulkanRecorder();

} // namespace eng::rg
