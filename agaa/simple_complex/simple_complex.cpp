#include "agaa/simple_complex/simple_complex.h"
#include "agaa/common/frame_inputs.h"

#include "engine/vk/check.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "engine/vk/resources.h"
#include "shaders/simple_complex/lighting_ms_comp.h"
#include "shaders/simple_complex/lighting_ms_shadow_comp.h"
#include "shaders/simple_complex/lighting_ss_comp.h"
#include "shaders/simple_complex/lighting_ss_shadow_comp.h"
#include "shared/frame.h"
#include "shared/simple_complex.h"

#include <cmath>
#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

void checkSettings(const SimpleComplexSettings& s) {
    if (!(s.minNormalCos >= -1.0f && s.minNormalCos <= 1.0f))
        throw std::invalid_argument("simple-complex: minNormalCos " + std::to_string(s.minNormalCos) +
                                    " is out of range [-1, 1]");
    if (!(s.depthSlopeScale >= 0.0f && s.depthSlopeScale <= 1.0e3f))
        throw std::invalid_argument("simple-complex: depthSlopeScale " + std::to_string(s.depthSlopeScale) +
                                    " is out of range [0, 1000]");
    if (s.schedule != SimpleComplexSchedule::DeferPerSample && s.schedule != SimpleComplexSchedule::Naive)
        throw std::invalid_argument("simple-complex: unknown schedule");
    if (s.debugView != SimpleComplexDebugView::None && s.debugView != SimpleComplexDebugView::Complex)
        throw std::invalid_argument("simple-complex: unknown debug view");
}

} // namespace

SimpleComplex::SimpleComplex(vk::Device& device, const TechniqueContent& content,
                             const SimpleComplexSettings& settings, std::string name)
    : m_device(device), m_settings(settings), m_name(std::move(name)), m_traits(content.traits),
      m_scene(content.scene), m_features(effectiveFeatures(content.traits, settings.effects)),
      m_gbuffer(device, content, settings.samples, m_name, m_features,
                GBufferOptions{.sampleRateShading = settings.sampleRateShading,
                               .curvature = settings.effects.curvatureRoughness}),
      m_shadow(device, content, m_features, settings.effects, m_name) {
    checkSettings(settings);
    const bool shadows = m_shadow.enabled();
    std::span<const uint32_t> code =
        settings.samples > 1 ? (shadows ? kSimpleComplexLightingMsShadowComp : kSimpleComplexLightingMsComp)
                             : (shadows ? kSimpleComplexLightingSsShadowComp : kSimpleComplexLightingSsComp);
    vk::LayoutDesc lighting;
    lighting.pushBindings = vk::reflectBindings({{code, VK_SHADER_STAGE_COMPUTE_BIT}});
    lighting.pushConstantBytes = sizeof(shared::SimpleComplexParams);
    m_lightingLayout = vk::createPipelineLayout(device, lighting, m_name + ".lighting.layout");
    // One shadow tap per shading event, as the reference (agaa/common/effects.h).
    m_lightingPipeline = vk::createComputePipeline(
        device, code, m_lightingLayout.layout,
        gbufferLightingSpecialization(m_features, settings.samples,
                                      {{shared::kSpecSimpleComplexSchedule, uint32_t(settings.schedule)}}),
        m_name + ".lighting");
    m_fetchSampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                       m_name + ".fetchSampler");
}

SimpleComplex::~SimpleComplex() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    vkDestroyPipeline(d, m_lightingPipeline, nullptr);
    vkDestroySampler(d, m_fetchSampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_lightingLayout);
}

FrameTargets SimpleComplex::addPasses(rg::Graph& graph, const FrameInputs& in) {
    checkFrameInputs(in);
    return addLighting(graph, in, addGBuffer(graph, in));
}

std::vector<VariantChoice> SimpleComplex::variants() const {
    return effectVariants(m_features, m_traits, m_settings.samples, 1);
}

FrameTargets SimpleComplex::addLighting(rg::Graph& graph, const FrameInputs& in,
                                        const SampleGBuffer& gbuffer) {
    // Added only for a scene with a shadowed light; lighting then reads it.
    const bool shadows = m_shadow.enabled();
    ShadowMaps shadowMaps;
    if (shadows) shadowMaps = m_shadow.add(graph, in);
    struct Lighting {
        rg::Buffer frame, lights;
        ShadowMaps shadow;
        SampleGBuffer g;
        rg::Texture hdr, display, events;
    };
    const rg::TextureDesc out{VK_FORMAT_R32G32B32A32_SFLOAT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    const rg::TextureDesc eventsDesc{VK_FORMAT_R32_UINT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    shared::SimpleComplexParams params{};
    params.thresholds = {m_settings.minNormalCos, m_settings.depthSlopeScale, 0.0f, 0.0f};
    params.options = {uint32_t(m_settings.debugView), 0u, 0u, 0u};
    const Lighting& l = graph.addCompute<Lighting>(
        m_name + ".lighting",
        [&](rg::Builder& b, Lighting& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.lights = b.read(in.lights, rg::Use::StorageReadCompute);
            d.g = readSampleGBuffer(b, gbuffer);
            if (shadows) d.shadow = ShadowMapPass::read(b, shadowMaps);
            d.hdr = b.write(b.create(m_name + ".hdr", out), rg::Use::StorageImageWriteCompute);
            d.display = b.write(b.create(m_name + ".display", out), rg::Use::StorageImageWriteCompute);
            d.events =
                b.write(b.create(m_name + ".shadingEvents", eventsDesc), rg::Use::StorageImageWriteCompute);
        },
        [this, params, shadows, environment = frameEnvironment(in, m_scene, name()), w = in.width,
         h = in.height](const rg::Context& ctx, const Lighting& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingPipeline);
            eng::vk::PushDescriptors pd;
            pushEnvironment(pd, environment);
            if (shadows) m_shadow.push(pd, ctx, d.shadow, 9, 10);
            pd.uniform(0, ctx.buffer(d.frame).buffer).storage(1, ctx.buffer(d.lights).buffer);
            pushSampleGBuffer(pd, ctx, m_fetchSampler, d.g);
            pushLightingTargets(pd, ctx, d.hdr, d.display, d.events);
            pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingLayout.layout);
            vkCmdPushConstants(cmd, m_lightingLayout.layout, VK_SHADER_STAGE_ALL, 0, sizeof(params), &params);
            vkCmdDispatch(cmd, (w + shared::kTileSize - 1) / shared::kTileSize,
                          (h + shared::kTileSize - 1) / shared::kTileSize, 1);
        });
    return {l.hdr, l.display, l.events, {}, gbuffer.depth};
}

} // namespace agaa
