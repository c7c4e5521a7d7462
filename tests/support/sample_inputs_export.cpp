#include "tests/support/sample_inputs_export.h"

#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "engine/vk/resources.h"
#include "shaders/tests/sbaa_selection_inputs_comp.h"
#include "shaders/tests/simple_complex_classification_inputs_comp.h"
#include "shaders/tests/streaming_fragments_comp.h"

namespace agaa::test {
namespace rg = eng::rg;
namespace vk = eng::vk;

SampleInputsExport::SampleInputsExport(vk::Device& device, std::span<const uint32_t> kernel, std::string name)
    : m_device(device), m_name(std::move(name)) {
    vk::LayoutDesc desc;
    desc.pushBindings = vk::reflectBindings({{kernel, VK_SHADER_STAGE_COMPUTE_BIT}});
    m_layout = vk::createPipelineLayout(device, desc, m_name + ".layout");
    m_pipeline = vk::createComputePipeline(device, kernel, m_layout.layout, {}, m_name);
    m_sampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                  m_name + ".sampler");
}

SampleInputsExport::~SampleInputsExport() {
    vkDeviceWaitIdle(m_device.device());
    vkDestroyPipeline(m_device.device(), m_pipeline, nullptr);
    vkDestroySampler(m_device.device(), m_sampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_layout);
}

void SampleInputsExport::add(rg::Graph& graph, const FrameInputs& in,
                             const std::vector<std::pair<uint32_t, rg::Texture>>& textures,
                             uint32_t targetBinding, rg::Buffer target) {
    struct Data {
        rg::Buffer frame, target;
        std::vector<std::pair<uint32_t, rg::Texture>> textures;
    };
    graph.addCompute<Data>(
        m_name,
        [&](rg::Builder& b, Data& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            for (const auto& [binding, texture] : textures)
                d.textures.push_back({binding, b.read(texture, rg::Use::SampledCompute)});
            d.target = b.write(target, rg::Use::StorageWriteCompute);
        },
        [this, targetBinding, w = in.width, h = in.height](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline);
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer);
            for (const auto& [binding, texture] : d.textures)
                pd.sampled(binding, m_sampler, ctx.texture(texture).sampledView);
            pd.storage(targetBinding, ctx.buffer(d.target).buffer)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout.layout);
            vkCmdDispatch(cmd, (w + 7) / 8, (h + 7) / 8, 1);
        });
}

SampleInputsExport sbaaSelectionInputs(vk::Device& device) {
    return SampleInputsExport(device, kTestsSbaaSelectionInputsComp, "test.sbaaSelectionInputs");
}

SampleInputsExport streamingFragments(vk::Device& device) {
    return SampleInputsExport(device, kTestsStreamingFragmentsComp, "test.streamingFragments");
}

SampleInputsExport simpleComplexClassificationInputs(vk::Device& device) {
    return SampleInputsExport(device, kTestsSimpleComplexClassificationInputsComp,
                              "test.simpleComplexClassificationInputs");
}

} // namespace agaa::test
