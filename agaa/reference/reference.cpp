#include "agaa/reference/reference.h"
#include "agaa/common/frame_inputs.h"

#include "engine/vk/check.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "engine/vk/resources.h"
#include "shaders/reference/lighting_ms_comp.h"
#include "shaders/reference/lighting_ms_shadow_comp.h"
#include "shaders/reference/lighting_ss_comp.h"
#include "shaders/reference/lighting_ss_shadow_comp.h"
#include "shared/frame.h"

#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

Reference::Reference(vk::Device& device, const TechniqueContent& content, const ReferenceSettings& settings,
                     std::string name)
    : m_device(device), m_settings(settings), m_name(std::move(name)), m_traits(content.traits),
      m_scene(content.scene), m_features(effectiveFeatures(content.traits, settings.effects)),
      m_gbuffer(device, content, settings.samples, m_name, m_features,
                GBufferOptions{.sampleRateShading = settings.sampleRateShading, // validates n, 4x MSAA, SRS
                               .curvature = settings.effects.curvatureRoughness}),
      m_shadow(device, content, m_features, settings.effects, m_name) {

    const bool shadows = m_shadow.enabled();
    std::span<const uint32_t> code =
        settings.samples > 1 ? (shadows ? kReferenceLightingMsShadowComp : kReferenceLightingMsComp)
                             : (shadows ? kReferenceLightingSsShadowComp : kReferenceLightingSsComp);
    vk::LayoutDesc lighting;
    lighting.pushBindings = vk::reflectBindings({{code, VK_SHADER_STAGE_COMPUTE_BIT}});
    m_lightingLayout = vk::createPipelineLayout(device, lighting, m_name + ".lighting.layout");
    // Specialisation: id 1 = n (common/gbuffer_lighting.glsl); id 0 is unused here; 2.. the
    // scene's effects, one shadow tap per shading event (agaa/common/effects.h).
    m_lightingPipeline = vk::createComputePipeline(
        device, code, m_lightingLayout.layout, gbufferLightingSpecialization(m_features, settings.samples),
        m_name + ".lighting");
    m_fetchSampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                       m_name + ".fetchSampler");
}

Reference::~Reference() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    vkDestroyPipeline(d, m_lightingPipeline, nullptr);
    vkDestroySampler(d, m_fetchSampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_lightingLayout);
}

bool Reference::isStorage(const std::string& resourceName) const {
    return m_gbuffer.isStorage(resourceName);
}

std::vector<VariantChoice> Reference::variants() const {
    std::vector<VariantChoice> v = effectVariants(m_features, m_traits, m_settings.samples, 1);
    if (m_settings.samples > 1)
        v.push_back({"fill-shading",
                     m_settings.sampleRateShading ? "sample rate (supersampled materials)"
                                                  : "pixel rate, per-sample coverage",
                     "setting --sample-rate-shading"});
    return v;
}

FrameTargets Reference::addPasses(rg::Graph& graph, const FrameInputs& in) {
    checkFrameInputs(in);
    const SampleGBuffer g = m_gbuffer.add(graph, in);
    // Added only for a scene with a shadowed light; lighting then reads it.
    const bool shadows = m_shadow.enabled();
    ShadowMaps shadowMaps;
    if (shadows) shadowMaps = m_shadow.add(graph, in);

    struct Lighting {
        rg::Buffer frame, lights;
        SampleGBuffer g;
        ShadowMaps shadow;
        rg::Texture hdr, display, events;
    };
    const rg::TextureDesc out{VK_FORMAT_R32G32B32A32_SFLOAT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    const rg::TextureDesc eventsDesc{VK_FORMAT_R32_UINT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    const Lighting& l = graph.addCompute<Lighting>(
        m_name + ".lighting",
        [&](rg::Builder& b, Lighting& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.lights = b.read(in.lights, rg::Use::StorageReadCompute);
            d.g = readSampleGBuffer(b, g);
            if (shadows) d.shadow = ShadowMapPass::read(b, shadowMaps);
            d.hdr = b.write(b.create(m_name + ".hdr", out), rg::Use::StorageImageWriteCompute);
            d.display = b.write(b.create(m_name + ".display", out), rg::Use::StorageImageWriteCompute);
            d.events =
                b.write(b.create(m_name + ".shadingEvents", eventsDesc), rg::Use::StorageImageWriteCompute);
        },
        [this, shadows, environment = frameEnvironment(in, m_scene, name()), w = in.width,
         h = in.height](const rg::Context& ctx, const Lighting& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingPipeline);
            vk::PushDescriptors pd;
            pushEnvironment(pd, environment);
            if (shadows) m_shadow.push(pd, ctx, d.shadow, 9, 10);
            pd.uniform(0, ctx.buffer(d.frame).buffer).storage(1, ctx.buffer(d.lights).buffer);
            pushSampleGBuffer(pd, ctx, m_fetchSampler, d.g);
            pushLightingTargets(pd, ctx, d.hdr, d.display, d.events);
            pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingLayout.layout);
            vkCmdDispatch(cmd, (w + shared::kTileSize - 1) / shared::kTileSize,
                          (h + shared::kTileSize - 1) / shared::kTileSize, 1);
        });
    return {l.hdr, l.display, l.events, {}, g.depth};
}

} // namespace agaa
