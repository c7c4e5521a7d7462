#include "agaa/fxaa/fxaa.h"

#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "engine/vk/resources.h"
#include "shaders/fxaa/fxaa_comp.h"
#include "shared/frame.h"
#include "shared/fxaa.h"

#include <bit>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

// Specialisation constants of fxaa.comp: 0 the step count, 1..12 the step lengths (float bits).
vk::Specialization presetSpecialization(uint32_t preset) {
    std::span<const float> steps = fxaaPresetSteps(preset);
    vk::Specialization s;
    s.byId.push_back({shared::kSpecFxaaSearchSteps, uint32_t(steps.size())});
    for (uint32_t i = 0; i < shared::kFxaaMaxSteps; ++i)
        s.byId.push_back(
            {shared::kSpecFxaaStepTable + i, std::bit_cast<uint32_t>(i < steps.size() ? steps[i] : 0.0f)});
    return s;
}

FxaaSettings checked(const FxaaSettings& s) {
    checkFxaaSettings(s);
    return s;
}

} // namespace

Fxaa::Fxaa(vk::Device& device, const TechniqueContent& content, const FxaaSettings& settings,
           const EffectSettings& effects, std::string name)
    : m_device(device), m_settings(checked(settings)), m_name(std::move(name)),
      m_noaa(device, content, ReferenceSettings{1, effects}, m_name + ".noaa") {
    vk::LayoutDesc layout;
    layout.pushBindings = vk::reflectBindings({{kFxaaFxaaComp, VK_SHADER_STAGE_COMPUTE_BIT}});
    layout.pushConstantBytes = sizeof(shared::FxaaParams);
    m_layout = vk::createPipelineLayout(device, layout, m_name + ".layout");
    m_pipeline = vk::createComputePipeline(device, kFxaaFxaaComp, m_layout.layout,
                                           presetSpecialization(settings.preset), m_name + ".filter");
    m_fetchSampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                       m_name + ".fetchSampler");
}

Fxaa::~Fxaa() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    vkDestroyPipeline(d, m_pipeline, nullptr);
    vkDestroySampler(d, m_fetchSampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_layout);
}

FrameTargets Fxaa::addPasses(rg::Graph& graph, const FrameInputs& in) {
    FrameTargets noaa = m_noaa.addPasses(graph, in);
    return {
        noaa.hdr, addFxaaPass(graph, noaa.display, in.width, in.height), noaa.shadingEvents, {}, noaa.depth};
}

rg::Texture Fxaa::addFxaaPass(rg::Graph& graph, rg::Texture display, uint32_t width, uint32_t height) {
    struct Data {
        rg::Texture input, output;
    };
    shared::FxaaParams params{};
    params.thresholds = {m_settings.subpix, m_settings.edgeThreshold, m_settings.edgeThresholdMin, 0.0f};
    const Data& out = graph.addCompute<Data>(
        m_name + ".filter",
        [&](rg::Builder& b, Data& d) {
            d.input = b.read(display, rg::Use::SampledCompute);
            const rg::TextureDesc desc{VK_FORMAT_R32G32B32A32_SFLOAT, width, height, 1,
                                       VK_SAMPLE_COUNT_1_BIT};
            d.output = b.write(b.create(m_name + ".display", desc), rg::Use::StorageImageWriteCompute);
        },
        [this, params](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            const rg::PhysicalTexture& output = ctx.texture(d.output);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_pipeline);
            eng::vk::PushDescriptors()
                .sampled(0, m_fetchSampler, ctx.texture(d.input).sampledView)
                .storageImage(1, output.view)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_layout.layout);
            vkCmdPushConstants(cmd, m_layout.layout, VK_SHADER_STAGE_ALL, 0, sizeof(params), &params);
            vkCmdDispatch(cmd, (output.desc.width + shared::kTileSize - 1) / shared::kTileSize,
                          (output.desc.height + shared::kTileSize - 1) / shared::kTileSize, 1);
        });
    return out.output;
}

} // namespace agaa
