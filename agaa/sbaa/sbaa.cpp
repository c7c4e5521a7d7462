#include "agaa/sbaa/sbaa.h"
#include "agaa/common/frame_inputs.h"

#include "engine/vk/check.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "engine/vk/resources.h"
#include "shaders/sbaa/lighting_comp.h"
#include "shaders/sbaa/lighting_shadow_comp.h"
#include "shaders/sbaa/surfaces_comp.h"
#include "shared/frame.h"
#include "shared/sbaa.h"

#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

constexpr VkShaderStageFlagBits kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

const SbaaSettings& checked(const SbaaSettings& s) {
    if (s.samples < 4)
        throw std::invalid_argument("sbaa: --samples " + std::to_string(s.samples) +
                                    " is not supported (allowed: 4, 8, 16, 32)");
    if (s.surfaces < 1 || s.surfaces > shared::kSbaaMaxSurfaces)
        throw std::invalid_argument("sbaa: --surfaces " + std::to_string(s.surfaces) +
                                    " is out of range (allowed: 1.." +
                                    std::to_string(shared::kSbaaMaxSurfaces) + ")");
    if (!(s.merge.minNormalCos >= -1.0f && s.merge.minNormalCos <= 1.0f))
        throw std::invalid_argument("sbaa: merge minNormalCos is out of range [-1, 1]");
    if (!(s.merge.depthSlopeScale >= 0.0f && s.merge.depthSlopeScale <= 1.0e3f))
        throw std::invalid_argument("sbaa: merge depthSlopeScale is out of range [0, 1000]");
    return s;
}

void pushPrepass(vk::PushDescriptors& pd, const rg::Context& ctx, VkSampler sampler, const SampleGBuffer& g) {
    pd.sampled(2, sampler, ctx.texture(g.depth).sampledView)
        .sampled(3, sampler, ctx.texture(g.geometricNormal).sampledView)
        .sampled(11, sampler, ctx.texture(g.primitive).sampledView);
}

shared::SbaaParams params(const SbaaSettings& s) {
    shared::SbaaParams p{};
    p.merge = {s.merge.minNormalCos, s.merge.depthSlopeScale, 0.0f, 0.0f};
    p.counts = {s.surfaces, s.merge.merge ? 1u : 0u, 0u, 0u};
    return p;
}

} // namespace

Sbaa::Sbaa(vk::Device& device, const TechniqueContent& content, const SbaaSettings& settings)
    : m_device(device), m_settings(checked(settings)), m_traits(content.traits), m_scene(content.scene),
      m_features(effectiveFeatures(content.traits, settings.effects)),
      m_gbuffer(device, content, settings.samples, "sbaa", m_features,
                GBufferOptions{.sampleRateShading = settings.sampleRateShading, .visibilityOnly = true}),
      m_fill(device, content, settings.samples, settings.surfaces, m_features, settings.sampleRateShading,
             settings.effects.curvatureRoughness),
      m_shadow(device, content, m_features, settings.effects, "sbaa") {
    vk::LayoutDesc surfaces;
    surfaces.pushBindings = vk::reflectBindings({{kSbaaSurfacesComp, kCompute}});
    surfaces.pushConstantBytes = sizeof(shared::SbaaParams);
    m_surfacesLayout = vk::createPipelineLayout(device, surfaces, "sbaa.surfaces.layout");
    m_surfacesPipeline =
        vk::createComputePipeline(device, kSbaaSurfacesComp, m_surfacesLayout.layout, {}, "sbaa.surfaces");

    const std::span<const uint32_t> lightingCode =
        m_shadow.enabled() ? kSbaaLightingShadowComp : kSbaaLightingComp;
    vk::LayoutDesc lighting;
    lighting.pushBindings = vk::reflectBindings({{lightingCode, kCompute}});
    lighting.pushConstantBytes = sizeof(shared::SbaaParams);
    m_lightingLayout = vk::createPipelineLayout(device, lighting, "sbaa.lighting.layout");
    // Specialisation: id 1 = n (common/gbuffer_lighting.glsl); 2.. the scene's effects, one shadow
    // tap per shading event (agaa/common/effects.h).
    m_lightingPipeline = vk::createComputePipeline(
        device, lightingCode, m_lightingLayout.layout,
        gbufferLightingSpecialization(m_features, settings.samples), "sbaa.lighting");
    m_fetchSampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                       "sbaa.fetchSampler");
}

Sbaa::~Sbaa() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    vkDestroyPipeline(d, m_surfacesPipeline, nullptr);
    vkDestroyPipeline(d, m_lightingPipeline, nullptr);
    vkDestroySampler(d, m_fetchSampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_surfacesLayout);
    vk::destroyPipelineLayout(m_device, m_lightingLayout);
}

bool Sbaa::isStorage(const std::string& resourceName) const {
    return m_gbuffer.isStorage(resourceName) || resourceName == "sbaa.surfaces";
}

std::string Sbaa::storageCategory(const std::string& resourceName) const {
    if (resourceName == "sbaa.surfaces") return "per-aggregate"; // per surface: S records per pixel
    return isStorage(resourceName) ? "per-sample" : "transient";
}

std::vector<VariantChoice> Sbaa::variants() const {
    std::vector<VariantChoice> v = effectVariants(m_features, m_traits, m_settings.samples, 1);
    v.push_back({"surfaces", std::to_string(m_settings.surfaces) + (m_settings.merge.merge ? ", merge" : ""),
                 "setting --surfaces"});
    v.push_back({"fill-shading",
                 m_settings.sampleRateShading ? "sample rate (the material at each surface's sample)"
                                              : "pixel rate (the material at the pixel's centre)",
                 "setting --sample-rate-shading"});
    return v;
}

FrameTargets Sbaa::addPasses(rg::Graph& graph, const FrameInputs& in) {
    checkFrameInputs(in);
    const SampleGBuffer g = addGBuffer(graph, in);
    return addLighting(graph, in, g, addFill(graph, in, g, addSurfaces(graph, in, g)));
}

Sbaa::Surfaces Sbaa::addSurfaces(rg::Graph& graph, const FrameInputs& in, const SampleGBuffer& g) {
    struct Data {
        rg::Buffer frame;
        SampleGBuffer g;
        rg::Buffer surfaces;
        rg::Texture lost;
    };
    const VkDeviceSize bytes =
        VkDeviceSize(in.width) * in.height * m_settings.surfaces * shared::kSbaaSurfaceWords * 4;
    const rg::TextureDesc lostDesc{VK_FORMAT_R32_UINT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    const shared::SbaaParams p = params(m_settings);
    const Data& out = graph.addCompute<Data>(
        "sbaa.surfaces",
        [&](rg::Builder& b, Data& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.g.depth = b.read(g.depth, rg::Use::SampledCompute);
            d.g.geometricNormal = b.read(g.geometricNormal, rg::Use::SampledCompute);
            d.g.primitive = b.read(g.primitive, rg::Use::SampledCompute);
            d.surfaces =
                b.write(b.create("sbaa.surfaces", rg::BufferDesc{bytes}), rg::Use::StorageWriteCompute);
            d.lost = b.write(b.create("sbaa.lostSamples", lostDesc), rg::Use::StorageImageWriteCompute);
        },
        [this, p, w = in.width, h = in.height](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_surfacesPipeline);
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer);
            pushPrepass(pd, ctx, m_fetchSampler, d.g);
            pd.storage(12, ctx.buffer(d.surfaces).buffer)
                .storageImage(13, ctx.texture(d.lost).view)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_surfacesLayout.layout);
            vkCmdPushConstants(cmd, m_surfacesLayout.layout, VK_SHADER_STAGE_ALL, 0, sizeof(p), &p);
            vkCmdDispatch(cmd, (w + 7) / 8, (h + 7) / 8, 1);
        });
    return {out.surfaces, out.lost};
}

FrameTargets Sbaa::addLighting(rg::Graph& graph, const FrameInputs& in, const SampleGBuffer& g,
                               const Surfaces& surfaces) {
    const bool shadows = m_shadow.enabled();
    ShadowMaps shadowMaps;
    if (shadows) shadowMaps = m_shadow.add(graph, in);
    struct Lighting {
        rg::Buffer frame, lights, surfaces;
        ShadowMaps shadow;
        SampleGBuffer g;
        rg::Texture hdr, display, events;
    };
    const rg::TextureDesc out{VK_FORMAT_R32G32B32A32_SFLOAT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    const rg::TextureDesc eventsDesc{VK_FORMAT_R32_UINT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    const shared::SbaaParams p = params(m_settings);
    const Lighting& l = graph.addCompute<Lighting>(
        "sbaa.lighting",
        [&](rg::Builder& b, Lighting& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.lights = b.read(in.lights, rg::Use::StorageReadCompute);
            d.surfaces = b.read(surfaces.surfaces, rg::Use::StorageReadCompute);
            d.g.depth = b.read(g.depth, rg::Use::SampledCompute); // the sky and the tile's depth bounds
            if (shadows) d.shadow = ShadowMapPass::read(b, shadowMaps);
            d.hdr = b.write(b.create("sbaa.hdr", out), rg::Use::StorageImageWriteCompute);
            d.display = b.write(b.create("sbaa.display", out), rg::Use::StorageImageWriteCompute);
            d.events = b.write(b.create("sbaa.shadingEvents", eventsDesc), rg::Use::StorageImageWriteCompute);
        },
        [this, p, shadows, environment = frameEnvironment(in, m_scene, name()), w = in.width,
         h = in.height](const rg::Context& ctx, const Lighting& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingPipeline);
            vk::PushDescriptors pd;
            pushEnvironment(pd, environment);
            if (shadows) m_shadow.push(pd, ctx, d.shadow, 9, 10);
            pd.uniform(0, ctx.buffer(d.frame).buffer).storage(1, ctx.buffer(d.lights).buffer);
            pd.sampled(2, m_fetchSampler, ctx.texture(d.g.depth).sampledView);
            pushLightingTargets(pd, ctx, d.hdr, d.display, d.events);
            pd.storage(12, ctx.buffer(d.surfaces).buffer)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingLayout.layout);
            vkCmdPushConstants(cmd, m_lightingLayout.layout, VK_SHADER_STAGE_ALL, 0, sizeof(p), &p);
            vkCmdDispatch(cmd, (w + shared::kTileSize - 1) / shared::kTileSize,
                          (h + shared::kTileSize - 1) / shared::kTileSize, 1);
        });
    FrameTargets t{l.hdr, l.display, l.events};
    t.lostSamples = surfaces.lostSamples;
    t.depth = g.depth;
    return t;
}

} // namespace agaa
