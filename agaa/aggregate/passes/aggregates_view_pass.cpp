// agaa.debug.aggregates (agaa/aggregate/passes/aggregates_view_pass.h).

#include "agaa/aggregate/passes/aggregates_view_pass.h"

#include "agaa/aggregate/passes/aggregate_programs.h"
#include "engine/vk/descriptors.h"

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

AggregatesViewPass::AggregatesViewPass(vk::Device& device, const AggregatePlan& plan, VkSampler fetchSampler)
    : m_device(device), m_fetchSampler(fetchSampler),
      m_program(device, programCode(plan.settings.programs, aggregatesViewProgram()), {},
                "agaa.debug.aggregates") {}

FrameTargets AggregatesViewPass::add(rg::Graph& graph, const AggregateFrame& frame) const {
    struct Debug {
        rg::Buffer frame, agaa, metadata;
        rg::Texture count, depth, hdr, display, events;
    };
    const FrameInputs& in = frame.in;
    const Debug& pass = graph.addCompute<Debug>(
        "agaa.debug.aggregates",
        [&](rg::Builder& b, Debug& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.agaa = b.read(frame.constants, rg::Use::UniformRead);
            d.metadata = b.read(frame.clusters.metadata, rg::Use::StorageReadCompute);
            d.count = b.read(frame.clusters.count, rg::Use::StorageImageReadCompute);
            d.depth = b.read(frame.depth, rg::Use::SampledCompute);
            const rg::TextureDesc out = frame.pixelDesc(VK_FORMAT_R32G32B32A32_SFLOAT);
            d.hdr = b.write(b.create("agaa.debug.hdr", out), rg::Use::StorageImageWriteCompute);
            d.display = b.write(b.create("agaa.debug.display", out), rg::Use::StorageImageWriteCompute);
            d.events = b.write(b.create("agaa.debug.events", frame.pixelDesc(VK_FORMAT_R32_UINT)),
                               rg::Use::StorageImageWriteCompute);
        },
        [=, this, width = in.width, height = in.height](const rg::Context& ctx, const Debug& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_program.pipeline());
            vk::PushDescriptors()
                .uniform(0, ctx.buffer(d.frame).buffer)
                .uniform(1, ctx.buffer(d.agaa).buffer)
                .storage(2, ctx.buffer(d.metadata).buffer)
                .storageImage(3, ctx.texture(d.count).view)
                .sampled(4, m_fetchSampler, ctx.texture(d.depth).sampledView)
                .storageImage(5, ctx.texture(d.hdr).view)
                .storageImage(6, ctx.texture(d.display).view)
                .storageImage(7, ctx.texture(d.events).view)
                .push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_program.layout());
            vkCmdDispatch(cmd, groupCount(width, 8), groupCount(height, 8), 1);
        });
    return {pass.hdr, pass.display, pass.events, {}, frame.depth};
}

} // namespace agaa
