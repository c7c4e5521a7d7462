#pragma once
// agaa.lighting: tiled deferred lighting that normalises each pixel's aggregates at the top of its
// 16x16 tile (the accumulate path's AG-buffer, or the samples path's G-buffer averaged per
// aggregate, the UE4 variant) and lights each aggregate once (shaders/glsl/agaa/lighting.comp).
// With a tolerance it flags the pixels to shade per sample and lists their tiles instead.

#include "agaa/aggregate/passes/aggregate_frame.h"
#include "agaa/common/shadow_map.h"
#include "engine/vk/compute_program.h"

#include <span>

namespace agaa {

// The lighting's targets, and with a tolerance its flags and the flagged tiles' list.
struct LitAggregates {
    eng::rg::Texture hdr, display, events;
    eng::rg::Texture perSampleShaded; // R32_UINT flags (one texel without a tolerance)
    eng::rg::Buffer flaggedTiles;     // agaa/aggregate/flagged_tiles.h (a 16-byte stand-in without one)
};

class AggregateLightingPass {
  public:
    AggregateLightingPass(eng::vk::Device& device, const AggregatePlan& plan, const ShadowMapPass& shadow,
                          VkSampler fetchSampler);
    AggregateLightingPass(const AggregateLightingPass&) = delete;
    AggregateLightingPass& operator=(const AggregateLightingPass&) = delete;

    // Adds the pass (and with a tolerance the list's clear): reads frame.depth, frame.clusters,
    // the G-buffer or frame.accumulation, and frame.shadow.
    LitAggregates add(eng::rg::Graph& graph, const AggregateFrame& frame) const;

    // The program and specialisation for this path, scene and settings: what a test build of the
    // pass must match (tests/support/aggregate_instrumentation.h).
    std::span<const uint32_t> code() const;
    eng::vk::Specialization variant() const;

  private:
    eng::vk::Device& m_device;
    const AggregatePlan& m_plan;
    const ShadowMapPass& m_shadow;
    VkSampler m_fetchSampler;
    eng::vk::ComputeProgram m_program;
};

} // namespace agaa
