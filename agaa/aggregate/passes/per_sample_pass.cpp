// agaa.lighting.perSample (agaa/aggregate/passes/per_sample_pass.h).

#include "agaa/aggregate/passes/per_sample_pass.h"

#include "agaa/aggregate/passes/aggregate_programs.h"
#include "engine/vk/descriptors.h"

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

PerSampleShadingPass::PerSampleShadingPass(vk::Device& device, const AggregatePlan& plan,
                                           const ShadowMapPass& shadow, VkSampler fetchSampler)
    : m_device(device), m_plan(plan), m_shadow(shadow), m_fetchSampler(fetchSampler),
      m_program(device, code(),
                gbufferLightingSpecialization(
                    plan.features, plan.settings.samples,
                    {{shared::kSpecPerSampleShadingRateView,
                      plan.settings.debugView == AggregateDebugView::ShadingRate ? 1u : 0u}}),
                "agaa.lighting.perSample") {}

std::span<const uint32_t> PerSampleShadingPass::code() const {
    return programCode(m_plan.settings.programs,
                       perSampleProgram(!m_plan.samplesPath(), m_plan.emissive(), m_shadow.enabled()));
}

FrameTargets PerSampleShadingPass::add(rg::Graph& graph, const AggregateFrame& frame,
                                       const LitAggregates& lit) const {
    struct PerSample {
        rg::Buffer frame, lights, tiles, sampleMaterial;
        SampleGBuffer g;             // samples path
        rg::Texture depth, emissive; // accumulate path
        ShadowMaps shadow;
        rg::Texture flags, hdr, display, events;
    };
    const FrameInputs& in = frame.in;
    const bool samplesPath = m_plan.samplesPath();
    const bool emissive = m_plan.emissive(), shadows = m_shadow.enabled();
    const PerSample& pass = graph.addCompute<PerSample>(
        "agaa.lighting.perSample",
        [&](rg::Builder& b, PerSample& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.lights = b.read(in.lights, rg::Use::StorageReadCompute);
            if (samplesPath) {
                d.g = readSampleGBuffer(b, frame.gbuffer);
            } else {
                d.depth = b.read(frame.depth, rg::Use::SampledCompute);
                d.sampleMaterial = b.read(frame.accumulation.sampleMaterial, rg::Use::StorageReadCompute);
                if (emissive) d.emissive = b.read(frame.accumulation.emissive, rg::Use::SampledCompute);
            }
            if (shadows) d.shadow = ShadowMapPass::read(b, frame.shadow);
            d.flags = b.read(lit.perSampleShaded, rg::Use::StorageImageReadCompute);
            d.tiles = b.read(lit.flaggedTiles, rg::Use::IndirectRead);
            b.read(lit.flaggedTiles, rg::Use::StorageReadCompute);
            // The lighting pass's images: this pass writes the flagged pixels and keeps the rest.
            d.hdr = b.readWrite(lit.hdr, rg::Use::StorageImageReadWriteCompute);
            d.display = b.readWrite(lit.display, rg::Use::StorageImageReadWriteCompute);
            d.events = b.readWrite(lit.events, rg::Use::StorageImageReadWriteCompute);
        },
        [=, this, environment = frame.environment](const rg::Context& ctx, const PerSample& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_program.pipeline());
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer).storage(1, ctx.buffer(d.lights).buffer);
            if (samplesPath) {
                pushSampleGBuffer(pd, ctx, m_fetchSampler, d.g);
            } else {
                pd.sampled(2, m_fetchSampler, ctx.texture(d.depth).sampledView)
                    .storage(3, ctx.buffer(d.sampleMaterial).buffer);
                if (emissive) pd.sampled(4, m_fetchSampler, ctx.texture(d.emissive).sampledView);
            }
            pushLightingTargets(pd, ctx, d.hdr, d.display, d.events);
            pd.storageImage(11, ctx.texture(d.flags).view).storage(12, ctx.buffer(d.tiles).buffer);
            if (shadows) m_shadow.push(pd, ctx, d.shadow, 9, 10);
            pushEnvironment(pd, environment);
            pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_program.layout());
            vkCmdDispatchIndirect(cmd, ctx.buffer(d.tiles).buffer, 0); // the listed tiles only
        });
    return {pass.hdr, pass.display, pass.events, {}, frame.depth, lit.perSampleShaded};
}

} // namespace agaa
