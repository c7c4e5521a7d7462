#include "agaa/streaming/streaming.h"
#include "agaa/common/frame_inputs.h"

#include "engine/vk/check.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/reflection.h"
#include "engine/vk/resources.h"
#include "shaders/streaming/compress_comp.h"
#include "shaders/streaming/lighting_comp.h"
#include "shaders/streaming/lighting_shadow_comp.h"
#include "shared/frame.h"
#include "shared/streaming.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

constexpr VkShaderStageFlagBits kCompute = VK_SHADER_STAGE_COMPUTE_BIT;

const StreamingSettings& checked(const StreamingSettings& s) {
    if (s.samples < 4)
        throw std::invalid_argument("streaming: --samples " + std::to_string(s.samples) +
                                    " is not supported (allowed: 4, 8, 16, 32)");
    if (s.surfaces < 1 || s.surfaces > shared::kStreamingMaxSurfaces)
        throw std::invalid_argument("streaming: --surfaces " + std::to_string(s.surfaces) +
                                    " is out of range (allowed: 1.." +
                                    std::to_string(shared::kStreamingMaxSurfaces) + ")");
    if (!(s.normalAngleDegrees > 0.0f && s.normalAngleDegrees <= 90.0f))
        throw std::invalid_argument("streaming: --streaming-normal-angle " +
                                    std::to_string(s.normalAngleDegrees) +
                                    " is out of range (allowed: degrees in (0, 90]; the paper's pi/4 = 45)");
    return s;
}

shared::StreamingParams params(const StreamingSettings& s) {
    shared::StreamingParams p{};
    // Section 3.1: n0 . n1 > cos(alpha).
    p.merge = {std::cos(s.normalAngleDegrees * 3.14159265358979f / 180.0f), 0.0f, 0.0f, 0.0f};
    p.counts = {s.surfaces, 0u, 0u, 0u};
    return p;
}

} // namespace

StreamingCompression::StreamingCompression(vk::Device& device, const TechniqueContent& content,
                                           const StreamingSettings& settings)
    : m_device(device), m_settings(checked(settings)), m_traits(content.traits), m_scene(content.scene),
      m_features(effectiveFeatures(content.traits, settings.effects)),
      m_gbuffer(device, content, settings.samples, "streaming", m_features,
                GBufferOptions{.sampleRateShading = settings.sampleRateShading,
                               .curvature = settings.effects.curvatureRoughness,
                               .primitiveIds = true}),
      m_shadow(device, content, m_features, settings.effects, "streaming") {
    vk::LayoutDesc compress;
    compress.pushBindings = vk::reflectBindings({{kStreamingCompressComp, kCompute}});
    compress.pushConstantBytes = sizeof(shared::StreamingParams);
    m_compressLayout = vk::createPipelineLayout(device, compress, "streaming.compress.layout");
    m_compressPipeline = vk::createComputePipeline(device, kStreamingCompressComp, m_compressLayout.layout,
                                                   {}, "streaming.compress");

    const std::span<const uint32_t> lightingCode =
        m_shadow.enabled() ? kStreamingLightingShadowComp : kStreamingLightingComp;
    vk::LayoutDesc lighting;
    lighting.pushBindings = vk::reflectBindings({{lightingCode, kCompute}});
    lighting.pushConstantBytes = sizeof(shared::StreamingParams);
    m_lightingLayout = vk::createPipelineLayout(device, lighting, "streaming.lighting.layout");
    // Specialisation: id 1 = n (common/gbuffer_lighting.glsl); 2.. the scene's effects, one shadow
    // tap per shading event (agaa/common/effects.h).
    m_lightingPipeline = vk::createComputePipeline(
        device, lightingCode, m_lightingLayout.layout,
        gbufferLightingSpecialization(m_features, settings.samples), "streaming.lighting");
    m_fetchSampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                       "streaming.fetchSampler");
}

StreamingCompression::~StreamingCompression() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    vkDestroyPipeline(d, m_compressPipeline, nullptr);
    vkDestroyPipeline(d, m_lightingPipeline, nullptr);
    vkDestroySampler(d, m_fetchSampler, nullptr);
    vk::destroyPipelineLayout(m_device, m_compressLayout);
    vk::destroyPipelineLayout(m_device, m_lightingLayout);
}

bool StreamingCompression::isStorage(const std::string& resourceName) const {
    return m_gbuffer.isStorage(resourceName) || resourceName == "streaming.surfaces";
}

// The compressed G-buffer (S surface records per pixel) is the method's storage; the recorded
// fragments (the per-sample G-buffer with primitive ids) are the transient list the missing
// interlock costs: bytes_per_pixel_split reports the two apart.
std::string StreamingCompression::storageCategory(const std::string& resourceName) const {
    if (resourceName == "streaming.surfaces") return "per-aggregate";
    return isStorage(resourceName) ? "fragment-list" : "transient";
}

std::vector<VariantChoice> StreamingCompression::variants() const {
    std::vector<VariantChoice> v = effectVariants(m_features, m_traits, m_settings.samples, 1);
    v.push_back({"surfaces", std::to_string(m_settings.surfaces), "setting --surfaces"});
    char angle[48];
    std::snprintf(angle, sizeof angle, "%.4g degrees (cos %.4f)", m_settings.normalAngleDegrees,
                  std::cos(m_settings.normalAngleDegrees * 3.14159265358979f / 180.0f));
    v.push_back({"normal-threshold", angle, "setting --streaming-normal-angle"});
    v.push_back({"primitive-order",
                 "recorded fragments replayed in compute (no fragment-shader interlock path)",
                 "not built: lavapipe has no VK_EXT_fragment_shader_interlock"});
    v.push_back({"fill-shading",
                 m_settings.sampleRateShading ? "sample rate (supersampled materials)"
                                              : "pixel rate, per-sample coverage",
                 "setting --sample-rate-shading"});
    return v;
}

FrameTargets StreamingCompression::addPasses(rg::Graph& graph, const FrameInputs& in) {
    checkFrameInputs(in);
    const SampleGBuffer g = addFragments(graph, in);
    return addLighting(graph, in, g, addCompression(graph, in, g));
}

StreamingCompression::Surfaces StreamingCompression::addCompression(rg::Graph& graph, const FrameInputs& in,
                                                                    const SampleGBuffer& g) {
    struct Data {
        rg::Buffer frame;
        SampleGBuffer g;
        rg::Buffer surfaces;
        rg::Texture lost;
    };
    const VkDeviceSize bytes =
        VkDeviceSize(in.width) * in.height * m_settings.surfaces * shared::kStreamingSurfaceWords * 4;
    const rg::TextureDesc lostDesc{VK_FORMAT_R32_UINT, in.width, in.height, 1, VK_SAMPLE_COUNT_1_BIT};
    const shared::StreamingParams p = params(m_settings);
    const Data& out = graph.addCompute<Data>(
        "streaming.compress",
        [&](rg::Builder& b, Data& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.g = readSampleGBuffer(b, g);
            d.g.primitive = b.read(g.primitive, rg::Use::SampledCompute);
            d.surfaces =
                b.write(b.create("streaming.surfaces", rg::BufferDesc{bytes}), rg::Use::StorageWriteCompute);
            d.lost = b.write(b.create("streaming.lostSamples", lostDesc), rg::Use::StorageImageWriteCompute);
        },
        [this, p, w = in.width, h = in.height](const rg::Context& ctx, const Data& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_compressPipeline);
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer);
            pushSampleGBuffer(pd, ctx, m_fetchSampler, d.g);
            pd.sampled(11, m_fetchSampler, ctx.texture(d.g.primitive).sampledView)
                .storage(12, ctx.buffer(d.surfaces).buffer)
                .storageImage(13, ctx.texture(d.lost).view)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_compressLayout.layout);
            vkCmdPushConstants(cmd, m_compressLayout.layout, VK_SHADER_STAGE_ALL, 0, sizeof(p), &p);
            vkCmdDispatch(cmd, (w + 7) / 8, (h + 7) / 8, 1);
        });
    return {out.surfaces, out.lost};
}

FrameTargets StreamingCompression::addLighting(rg::Graph& graph, const FrameInputs& in,
                                               const SampleGBuffer& g, const Surfaces& surfaces) {
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
    const shared::StreamingParams p = params(m_settings);
    const Lighting& l = graph.addCompute<Lighting>(
        "streaming.lighting",
        [&](rg::Builder& b, Lighting& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.lights = b.read(in.lights, rg::Use::StorageReadCompute);
            d.surfaces = b.read(surfaces.surfaces, rg::Use::StorageReadCompute);
            d.g = readSampleGBuffer(b, g);
            if (shadows) d.shadow = ShadowMapPass::read(b, shadowMaps);
            d.hdr = b.write(b.create("streaming.hdr", out), rg::Use::StorageImageWriteCompute);
            d.display = b.write(b.create("streaming.display", out), rg::Use::StorageImageWriteCompute);
            d.events =
                b.write(b.create("streaming.shadingEvents", eventsDesc), rg::Use::StorageImageWriteCompute);
        },
        [this, p, shadows, environment = frameEnvironment(in, m_scene, name()), w = in.width,
         h = in.height](const rg::Context& ctx, const Lighting& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingPipeline);
            vk::PushDescriptors pd;
            pushEnvironment(pd, environment);
            if (shadows) m_shadow.push(pd, ctx, d.shadow, 9, 10);
            pd.uniform(0, ctx.buffer(d.frame).buffer).storage(1, ctx.buffer(d.lights).buffer);
            pushSampleGBuffer(pd, ctx, m_fetchSampler, d.g);
            pushLightingTargets(pd, ctx, d.hdr, d.display, d.events);
            pd.storage(12, ctx.buffer(d.surfaces).buffer)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_lightingLayout.layout);
            vkCmdPushConstants(cmd, m_lightingLayout.layout, VK_SHADER_STAGE_ALL, 0, sizeof(p), &p);
            vkCmdDispatch(cmd, (w + shared::kTileSize - 1) / shared::kTileSize,
                          (h + shared::kTileSize - 1) / shared::kTileSize, 1);
        });
    FrameTargets t{l.hdr, l.display, l.events};
    t.lostSamples = surfaces.lostSamples;
    return t;
}

} // namespace agaa
