#pragma once
// agaa.visibility, the accumulate path's visibility prepass: every sample's depth (with the
// stencil generation counts first fragments in) and 8-bit face normal, n samples as 4x layers;
// masked materials run alpha-to-coverage here only (paper section 3.6).

#include "agaa/aggregate/passes/aggregate_frame.h"
#include "engine/vk/pipeline_cache.h"

namespace agaa {

class VisibilityPass {
  public:
    VisibilityPass(eng::vk::Device& device, const eng::frame::GpuScene& scene, const AggregatePlan& plan);
    ~VisibilityPass();
    VisibilityPass(const VisibilityPass&) = delete;
    VisibilityPass& operator=(const VisibilityPass&) = delete;

    // Adds the pass: reads frame.constants and frame.materials, sets frame.depth and frame.normal.
    void add(eng::rg::Graph& graph, AggregateFrame& frame);

  private:
    VkPipeline makePipeline(const DrawVariant& variant);

    eng::vk::Device& m_device;
    const AggregatePlan& m_plan;
    eng::vk::PipelineLayout m_layout;
    eng::vk::PipelineCache<DrawVariant> m_pipelines; // one per draw variant met, made on first use
};

} // namespace agaa
