#pragma once
// agaa.debug.aggregates (--debug aggregates): the clustering made visible in place of the lighting,
// each aggregate of a pixel in its own colour (shaders/glsl/agaa/debug_aggregates.comp). The graph
// then culls the generation passes nothing reads.

#include "agaa/aggregate/passes/aggregate_frame.h"
#include "engine/vk/compute_program.h"

namespace agaa {

class AggregatesViewPass {
  public:
    AggregatesViewPass(eng::vk::Device& device, const AggregatePlan& plan, VkSampler fetchSampler);
    AggregatesViewPass(const AggregatesViewPass&) = delete;
    AggregatesViewPass& operator=(const AggregatesViewPass&) = delete;

    // Adds the pass: reads frame.clusters and frame.depth; returns the view as the frame's targets.
    FrameTargets add(eng::rg::Graph& graph, const AggregateFrame& frame) const;

  private:
    eng::vk::Device& m_device;
    VkSampler m_fetchSampler;
    eng::vk::ComputeProgram m_program;
};

} // namespace agaa
