#pragma once
// agaa.visibility, the accumulate path's visibility prepass: every sample's depth (with the
// stencil generation counts first fragments in) and 8-bit face normal, n samples as 4x layers;
// masked materials run alpha-to-coverage here only (paper section 3.6).

#include "agaa/aggregate/passes/aggregate_frame.h"
#include "agaa/common/raster_pass.h"
#include "agaa/common/scene_drawer.h"

namespace agaa {

class VisibilityPass {
  public:
    VisibilityPass(eng::vk::Device& device, const TechniqueContent& content, const AggregatePlan& plan);
    ~VisibilityPass();
    VisibilityPass(const VisibilityPass&) = delete;
    VisibilityPass& operator=(const VisibilityPass&) = delete;

    static constexpr VkFormat kNormalFormat = VK_FORMAT_R8G8_UNORM;

    // Adds the pass, drawn by frame.in.geometry or the scene's drawer: reads frame.constants, sets
    // frame.depth and frame.normal.
    void add(eng::rg::Graph& graph, AggregateFrame& frame);
    // What a host's drawer draws: output AggregateVisibility; set 0 binding 0 the frame, 2 AGAA's
    // constants.
    const RasterPass& rasterPass() const { return m_raster; }

  private:
    eng::vk::Device& m_device;
    const AggregatePlan& m_plan;
    RasterPass m_raster;
    std::unique_ptr<SceneDrawer> m_sceneDrawer; // the content's GpuScene's, when the host gives no drawer
};

} // namespace agaa
