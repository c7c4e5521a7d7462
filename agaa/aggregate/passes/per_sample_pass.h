#pragma once
// agaa.lighting.perSample, the error-driven shading rate's second half (docs/decisions/
// shading-rate-estimate.md): one workgroup per tile the lighting pass listed, dispatched
// indirectly, lights and resolves each flagged sample as the reference does, into the lighting
// pass's images (shaders/glsl/agaa/lighting_per_sample.comp). Made with a tolerance only.

#include "agaa/aggregate/passes/aggregate_lighting_pass.h"
#include "engine/vk/compute_program.h"

#include <span>

namespace agaa {

class PerSampleShadingPass {
  public:
    PerSampleShadingPass(eng::vk::Device& device, const AggregatePlan& plan, const ShadowMapPass& shadow,
                         VkSampler fetchSampler);
    PerSampleShadingPass(const PerSampleShadingPass&) = delete;
    PerSampleShadingPass& operator=(const PerSampleShadingPass&) = delete;

    // Adds the pass: reads the lighting's flags and list, the G-buffer or the accumulate path's
    // per-sample material, and frame.shadow; returns the frame's targets.
    FrameTargets add(eng::rg::Graph& graph, const AggregateFrame& frame, const LitAggregates& lit) const;

    std::span<const uint32_t> code() const; // for this path, scene and device

  private:
    eng::vk::Device& m_device;
    const AggregatePlan& m_plan;
    const ShadowMapPass& m_shadow;
    VkSampler m_fetchSampler;
    eng::vk::ComputeProgram m_program;
};

} // namespace agaa
