#pragma once
// agaa.clear and agaa.generation, the accumulate path's AG-buffer generation (paper sections 3.3
// and 3.4, Algorithm 2): the scene rasterised again against the visibility depth (EQUAL, the
// stencil keeping each sample's first fragment), each fragment summed into its aggregates with
// fixed-point integer atomics (32- or 64-bit, with or without a subgroup pre-reduction). With a
// tolerance it also keeps each covered sample's material for the per-sample pass.

#include "agaa/aggregate/passes/aggregate_frame.h"
#include "agaa/common/raster_pass.h"
#include "agaa/common/scene_drawer.h"

namespace agaa {

class AccumulationPass {
  public:
    AccumulationPass(eng::vk::Device& device, const TechniqueContent& content, const AggregatePlan& plan);
    ~AccumulationPass();
    AccumulationPass(const AccumulationPass&) = delete;
    AccumulationPass& operator=(const AccumulationPass&) = delete;

    static constexpr VkFormat kEmissiveFormat = VK_FORMAT_B10G11R11_UFLOAT_PACK32;

    // Adds the two passes, generation drawn by frame.in.geometry or the scene's drawer: reads
    // frame.depth (the visibility prepass's) and frame.clusters, sets frame.accumulation and
    // frame.depth to the depth with generation's stencil.
    void add(eng::rg::Graph& graph, AggregateFrame& frame);
    // What a host's drawer draws: output AggregateAccumulation; set 0 bindings 0 the frame, 2
    // AGAA's constants, 3 the metadata, 4 (and 6 under AGAA_INT64) the AG-buffer, 7 the per-sample
    // materials; specialisation ids 0, 1 and 20; the defines of the build. A test build of the pass
    // draws with the same state.
    const RasterPass& rasterPass() const { return m_raster; }

  private:
    eng::vk::Device& m_device;
    const AggregatePlan& m_plan;
    RasterPass m_raster;
    std::unique_ptr<SceneDrawer> m_sceneDrawer; // the content's GpuScene's, when the host gives no drawer
};

} // namespace agaa
