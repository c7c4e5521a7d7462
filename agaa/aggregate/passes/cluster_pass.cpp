// agaa.cluster (agaa/aggregate/passes/cluster_pass.h).

#include "agaa/aggregate/passes/cluster_pass.h"

#include "agaa/aggregate/passes/aggregate_programs.h"
#include "engine/vk/descriptors.h"
#include "shared/clustering.h"

#include <algorithm>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

ClusterPass::ClusterPass(vk::Device& device, const AggregatePlan& plan, VkSampler fetchSampler)
    : m_device(device), m_plan(plan), m_fetchSampler(fetchSampler),
      m_program(device, programCode(plan.settings.programs, clusterProgram(plan.samplesPath())),
                {{},
                 {{shared::kSpecClusterSamples, plan.settings.samples},
                  {shared::kSpecClusterAggregates, plan.settings.aggregates},
                  {shared::kSpecClusterDistance, uint32_t(plan.settings.distance)}}},
                "agaa.cluster") {}

void ClusterPass::add(rg::Graph& graph, AggregateFrame& frame) const {
    struct Cluster {
        rg::Buffer frame, agaa, metadata;
        rg::Texture depth, normal, albedoMetal, count;
    };
    const FrameInputs& in = frame.in;
    const bool samplesPath = m_plan.samplesPath();
    const uint32_t words = shared::metadataWords(m_plan.settings.samples, m_plan.settings.aggregates);
    const Cluster& pass = graph.addCompute<Cluster>(
        "agaa.cluster",
        [&](rg::Builder& b, Cluster& d) {
            d.frame = b.read(in.frameConstants, rg::Use::UniformRead);
            d.agaa = b.read(frame.constants, rg::Use::UniformRead);
            d.depth = b.read(frame.depth, rg::Use::SampledCompute);
            d.normal = b.read(frame.normal, rg::Use::SampledCompute);
            if (samplesPath) d.albedoMetal = b.read(frame.gbuffer.albedoMetal, rg::Use::SampledCompute);
            // c = 1 needs no metadata bits; keep a minimal buffer so the binding stays valid.
            const VkDeviceSize bytes = VkDeviceSize(in.width) * in.height * words * 4;
            d.metadata = b.write(b.create("agaa.metadata", {std::max<VkDeviceSize>(4, bytes)}),
                                 rg::Use::StorageWriteCompute);
            d.count = b.write(b.create("agaa.aggregateCount", frame.pixelDesc(VK_FORMAT_R8_UINT)),
                              rg::Use::StorageImageWriteCompute);
        },
        [=, this, width = in.width, height = in.height](const rg::Context& ctx, const Cluster& d) {
            VkCommandBuffer cmd = ctx.cmd();
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_program.pipeline());
            vk::PushDescriptors pd;
            pd.uniform(0, ctx.buffer(d.frame).buffer)
                .uniform(1, ctx.buffer(d.agaa).buffer)
                .sampled(2, m_fetchSampler, ctx.texture(d.depth).sampledView)
                .sampled(3, m_fetchSampler, ctx.texture(d.normal).sampledView)
                .storage(4, ctx.buffer(d.metadata).buffer)
                .storageImage(5, ctx.texture(d.count).view);
            if (samplesPath) pd.sampled(6, m_fetchSampler, ctx.texture(d.albedoMetal).sampledView);
            pd.push(m_device, cmd, VK_PIPELINE_BIND_POINT_COMPUTE, m_program.layout());
            vkCmdDispatch(cmd, groupCount(width, 8), groupCount(height, 8), 1);
        });
    frame.clusters = {pass.metadata, pass.count};
}

} // namespace agaa
