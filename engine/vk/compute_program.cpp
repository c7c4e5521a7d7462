// eng::vk::ComputeProgram (engine/vk/compute_program.h).

#include "engine/vk/compute_program.h"

#include "engine/vk/reflection.h"

namespace eng::vk {

ComputeProgram::ComputeProgram(const Device& device, std::span<const uint32_t> spirv,
                               const Specialization& specialization, const std::string& name)
    : m_device(device) {
    LayoutDesc layout;
    layout.pushBindings = reflectBindings({{spirv, VK_SHADER_STAGE_COMPUTE_BIT}});
    m_layout = createPipelineLayout(device, layout, name + ".layout");
    try {
        m_pipeline = createComputePipeline(device, spirv, m_layout.layout, specialization, name);
    } catch (...) {
        destroyPipelineLayout(device, m_layout);
        throw;
    }
}

ComputeProgram::~ComputeProgram() {
    vkDestroyPipeline(m_device.device(), m_pipeline, nullptr);
    destroyPipelineLayout(m_device, m_layout);
}

} // namespace eng::vk
