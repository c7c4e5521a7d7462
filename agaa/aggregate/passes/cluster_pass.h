#pragma once
// agaa.cluster: Algorithm 1 per pixel on its samples' depth and normals (the accumulate path's
// face normals, or the samples path's G-buffer, with metal and dielectric kept apart), written as
// bit-packed metadata and an aggregate count. Its CPU reference is agaa/aggregate/clustering.h.

#include "agaa/aggregate/passes/aggregate_frame.h"
#include "engine/vk/compute_program.h"

namespace agaa {

class ClusterPass {
  public:
    ClusterPass(eng::vk::Device& device, const AggregatePlan& plan, VkSampler fetchSampler);
    ClusterPass(const ClusterPass&) = delete;
    ClusterPass& operator=(const ClusterPass&) = delete;

    // Adds the pass: reads frame.depth and frame.normal (and the G-buffer's metallic on the samples
    // path), sets frame.clusters.
    void add(eng::rg::Graph& graph, AggregateFrame& frame) const;

  private:
    eng::vk::Device& m_device;
    const AggregatePlan& m_plan;
    VkSampler m_fetchSampler;
    eng::vk::ComputeProgram m_program;
};

} // namespace agaa
