#pragma once
// agaa.clear and agaa.generation, the accumulate path's AG-buffer generation (paper sections 3.3
// and 3.4, Algorithm 2): the scene rasterised again against the visibility depth (EQUAL, the
// stencil keeping each sample's first fragment), each fragment summed into its aggregates with
// fixed-point integer atomics (32- or 64-bit, with or without a subgroup pre-reduction). With a
// tolerance it also keeps each covered sample's material for the per-sample pass.

#include "agaa/aggregate/passes/aggregate_frame.h"
#include "engine/vk/pipeline_cache.h"

#include <span>

namespace agaa {

class AccumulationPass {
  public:
    AccumulationPass(eng::vk::Device& device, const eng::frame::GpuScene& scene, const AggregatePlan& plan);
    ~AccumulationPass();
    AccumulationPass(const AccumulationPass&) = delete;
    AccumulationPass& operator=(const AccumulationPass&) = delete;

    // Adds the two passes: reads frame.depth (the visibility prepass's) and frame.clusters, sets
    // frame.accumulation and frame.depth to the depth with generation's stencil.
    void add(eng::rg::Graph& graph, AggregateFrame& frame);

    // The generation program and pipeline for a material's sidedness, as this scene and device run
    // them (a test build of the pass draws with the same state).
    std::span<const uint32_t> code() const;
    eng::vk::GraphicsPipelineDesc pipelineDesc(bool doubleSided) const;

  private:
    eng::vk::Device& m_device;
    const AggregatePlan& m_plan;
    eng::vk::PipelineLayout m_layout;
    eng::vk::PipelineCache<DrawVariant> m_pipelines; // alpha: the prepass's, not read
};

} // namespace agaa
