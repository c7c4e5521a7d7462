#pragma once
// SBAA step 3, the per-surface G-buffer (Salvi and Vidimce 2012, section 3.2): a second geometry
// pass over the scene, after the surface selection. Each kept surface's record (shared/sbaa.h)
// names its representative primitive and sample; the fragment of that primitive that covers that
// sample evaluates the material there, exactly as the per-sample G-buffer would, and stores it in
// the record's words 2..6 (reference/gbuffer.frag with GBUFFER_SURFACE_FILL). So the material
// runs for visible fragments only (EQUAL against the prepass depth, early) and is stored S times
// per pixel, not n times. Needs fragmentStoresAndAtomics (required by the device) and
// gl_PrimitiveID / gl_Layer in a fragment shader (geometryShader, probed by the prepass).

#include "agaa/common/raster_pass.h"
#include "agaa/common/scene_drawer.h"
#include "agaa/common/technique.h"
#include "engine/graph/graph.h"
#include "engine/vk/device.h"

namespace agaa {

class SurfaceFillPass {
  public:
    // samples: n; surfaces: S; sampleRate: the material at each sample's own position (the
    // supersampled G-buffer; needs sampleRateShading, checked by the prepass).
    SurfaceFillPass(eng::vk::Device& device, const TechniqueContent& content, uint32_t samples,
                    uint32_t surfaces, const eng::scene::SceneFeatures& features, bool sampleRate,
                    const CurvatureRoughness& curvature);
    ~SurfaceFillPass();
    SurfaceFillPass(const SurfaceFillPass&) = delete;
    SurfaceFillPass& operator=(const SurfaceFillPass&) = delete;

    // Adds "sbaa.fill", drawn by inputs.geometry or the scene's drawer: reads the prepass `depth`
    // (EQUAL, read-only) and writes the material words of `surfaces`; returns the buffer's new
    // version.
    eng::rg::Buffer add(eng::rg::Graph& graph, const FrameInputs& inputs, eng::rg::Texture depth,
                        eng::rg::Buffer surfaces);

    // What a host's drawer draws: output SurfaceFill; set 0 binding 0 shared::FrameConstants,
    // binding 2 the per-surface records; specialisation id 24 S.
    const RasterPass& rasterPass() const { return m_raster; }

  private:
    eng::vk::Device& m_device;
    RasterPass m_raster;
    std::unique_ptr<SceneDrawer> m_sceneDrawer; // the content's GpuScene's, when the host gives no drawer
};

} // namespace agaa
