#pragma once
// A compute pass's program as one object: its pipeline layout, whose push-descriptor set is
// reflected from the SPIR-V (engine/vk/reflection.h), and its pipeline for one specialisation;
// both destroyed with it. The caller waits for the device to be idle before destroying it.

#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"

#include <span>
#include <string>

namespace eng::vk {

class ComputeProgram {
  public:
    // `name` names the pipeline; the layout is "<name>.layout".
    ComputeProgram(const Device& device, std::span<const uint32_t> spirv,
                   const Specialization& specialization, const std::string& name);
    ~ComputeProgram();
    ComputeProgram(const ComputeProgram&) = delete;
    ComputeProgram& operator=(const ComputeProgram&) = delete;

    VkPipeline pipeline() const { return m_pipeline; }
    VkPipelineLayout layout() const { return m_layout.layout; }

  private:
    const Device& m_device;
    PipelineLayout m_layout;
    VkPipeline m_pipeline = VK_NULL_HANDLE;
};

} // namespace eng::vk
