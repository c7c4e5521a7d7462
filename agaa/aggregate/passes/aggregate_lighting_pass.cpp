// agaa.lighting (agaa/aggregate/passes/aggregate_lighting_pass.h).

#include "agaa/aggregate/passes/aggregate_lighting_pass.h"

#include "agaa/aggregate/flagged_tiles.h"
#include "agaa/aggregate/passes/aggregate_programs.h"
#include "engine/vk/descriptors.h"

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

AggregateLightingPass::AggregateLightingPass(vk::Device& device, const AggregatePlan& plan,
                                             const ShadowMapPass& shadow, VkSampler fetchSampler)
    : m_device(device), m_plan(plan), m_shadow(shadow), m_fetchSampler(fetchSampler),
      m_program(device, code(), variant(), "agaa.lighting") {}

std::span<const uint32_t> AggregateLightingPass::code() const {
    return programCode(m_plan.settings.programs,
                       lightingProgram(m_plan.samplesPath(), m_plan.emissive(), m_shadow.enabled()));
}

vk::Specialization AggregateLightingPass::variant() const {
    const AggregateSettings& s = m_plan.settings;
    const eng::scene::SceneFeatures& f = m_plan.features;
    vk::Specialization spec =
        lightingSpecialization(effectSpecialization(f, s.effects.shadowTaps, s.effects.shadowFootprint), f);
    spec.byId.insert(
        spec.byId.end(),
        {{shared::kSpecLightingSamples, s.samples},
         {shared::kSpecLightingAggregates, s.aggregates},
         {shared::kSpecLightingCompact, s.shading == AggregateShading::Compact ? 1u : 0u},
         {shared::kSpecLightingNdf, uint32_t(s.ndf)},
         {shared::kSpecLightingRouting, uint32_t(s.routing)},
         {shared::kSpecLightingViewFootprint, f.hasNearMirrors() ? 1u : 0u},
         {shared::kSpecLightingShadingRate, m_plan.shadingRate() ? 1u : 0u},
         {shared::kSpecLightingShadingRateView, s.debugView == AggregateDebugView::ShadingRate ? 1u : 0u}});
    return spec;
}

LitAggregates AggregateLightingPass::add(rg::Graph& graph, const AggregateFrame& frame) const {
    struct Lighting {
        rg::Buffer frame, lights, agaa, metadata, agBuffer, sampleMaterial, flaggedTiles;
        ShadowMaps shadow;
        rg::Texture depth, count, emissive, hdr, display, events, perSampleShaded;
        rg::Texture normal, albedoMetal; // samples path: the G-buffer (emissive: its emissive + roughness)
    };
    const FrameInputs& in = frame.in;
    const bool samplesPath = m_plan.samplesPath(), shadingRate = m_plan.shadingRate();
    const bool emissive = m_plan.emissive(), shadows = m_shadow.enabled();
    const rg::Buffer flaggedTiles =
        shadingRate ? addFlaggedTileList(graph, in.width, in.height, "agaa.flaggedTiles") : rg::Buffer{};
    const Lighting& lit = graph.addCompute<Lighting>(
        "agaa.lighting",
        [&](rg::Builder& b, Lighting& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.lights = b.read(in.lights, rg::Use::StorageReadCompute);
            d.agaa = b.read(frame.constants, rg::Use::UniformRead);
            d.depth = b.read(frame.depth, rg::Use::SampledCompute);
            d.metadata = b.read(frame.clusters.metadata, rg::Use::StorageReadCompute);
            d.count = b.read(frame.clusters.count, rg::Use::StorageImageReadCompute);
            if (samplesPath) {
                d.normal = b.read(frame.gbuffer.normal, rg::Use::SampledCompute);
                d.albedoMetal = b.read(frame.gbuffer.albedoMetal, rg::Use::SampledCompute);
                d.emissive = b.read(frame.gbuffer.emissiveRoughness, rg::Use::SampledCompute);
            } else {
                d.agBuffer = b.read(frame.accumulation.agBuffer, rg::Use::StorageReadCompute);
                d.sampleMaterial = b.read(frame.accumulation.sampleMaterial, rg::Use::StorageReadCompute);
                if (emissive) d.emissive = b.read(frame.accumulation.emissive, rg::Use::SampledCompute);
            }
            if (shadows) d.shadow = ShadowMapPass::read(b, frame.shadow);
            const rg::TextureDesc out = frame.pixelDesc(VK_FORMAT_R32G32B32A32_SFLOAT);
            const rg::TextureDesc events = frame.pixelDesc(VK_FORMAT_R32_UINT);
            d.hdr = b.write(b.create("agaa.hdr", out), rg::Use::StorageImageWriteCompute);
            d.display = b.write(b.create("agaa.display", out), rg::Use::StorageImageWriteCompute);
            d.events = b.write(b.create("agaa.shadingEvents", events), rg::Use::StorageImageWriteCompute);
            // Without a tolerance the shader never writes it, but binding 18 is in the layout (the
            // validation layer counts it as used whatever the specialisation): one texel then.
            const rg::TextureDesc flags =
                shadingRate ? events : rg::TextureDesc{VK_FORMAT_R32_UINT, 1, 1, 1, VK_SAMPLE_COUNT_1_BIT};
            d.perSampleShaded =
                b.write(b.create("agaa.perSampleShaded", flags), rg::Use::StorageImageWriteCompute);
            // Binding 19 likewise: a 16-byte stand-in without a tolerance.
            d.flaggedTiles = shadingRate
                                 ? b.readWrite(flaggedTiles, rg::Use::StorageReadWriteCompute)
                                 : b.write(b.create("agaa.flaggedTiles", {16}), rg::Use::StorageWriteCompute);
        },
        [=, this, environment = frame.environment, width = in.width,
         height = in.height](const rg::Context& ctx, const Lighting& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_program.pipeline());
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer)
                .storage(1, ctx.buffer(d.lights).buffer)
                .uniform(2, ctx.buffer(d.agaa).buffer)
                .sampled(3, m_fetchSampler, ctx.texture(d.depth).sampledView)
                .storage(4, ctx.buffer(d.metadata).buffer)
                .storageImage(5, ctx.texture(d.count).view)
                .storageImage(7, ctx.texture(d.hdr).view)
                .storageImage(8, ctx.texture(d.display).view)
                .storageImage(9, ctx.texture(d.events).view);
            pd.storageImage(18, ctx.texture(d.perSampleShaded).view)
                .storage(19, ctx.buffer(d.flaggedTiles).buffer);
            if (samplesPath) {
                pd.sampled(6, m_fetchSampler, ctx.texture(d.normal).sampledView)
                    .sampled(10, m_fetchSampler, ctx.texture(d.emissive).sampledView)
                    .sampled(13, m_fetchSampler, ctx.texture(d.albedoMetal).sampledView);
            } else {
                pd.storage(6, ctx.buffer(d.agBuffer).buffer).storage(20, ctx.buffer(d.sampleMaterial).buffer);
                if (emissive) pd.sampled(10, m_fetchSampler, ctx.texture(d.emissive).sampledView);
            }
            if (shadows) m_shadow.push(pd, ctx, d.shadow, 11, 12);
            pushEnvironment(pd, environment);
            pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_program.layout());
            vkCmdDispatch(cmd, groupCount(width, shared::kTileSize), groupCount(height, shared::kTileSize),
                          1);
        });
    return {lit.hdr, lit.display, lit.events, lit.perSampleShaded, lit.flaggedTiles};
}

} // namespace agaa
