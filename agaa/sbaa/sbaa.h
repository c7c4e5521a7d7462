#pragma once
// Surface Based Anti-Aliasing (Salvi and Vidimce 2012; DESIGN section 5): n visibility samples
// with a primitive id each, the S most covered surfaces per pixel kept (primitives on similar
// planes merged: the paper's MERGE mode), a G-buffer per surface, the S surfaces lit once per
// light and resolved by their coverage. The coverage of the surfaces not kept is lost, as in the
// paper; FrameTargets::lostSamples reports it per pixel.
//
// Passes, the paper's four: "sbaa.gbuffer" (the visibility prepass: depth, geometric normal and
// primitive id per sample, no material; sbaa/prepass.frag), "sbaa.surfaces" (the selection:
// coverage, representative sample and primitive of the kept surfaces), "sbaa.fill" (the second
// geometry pass: the material of each kept surface into the per-surface G-buffer, 32 bytes per
// surface; surface_fill.h), "sbaa.lighting" (tiled deferred over the surfaces).

#include "agaa/common/sample_gbuffer.h"
#include "agaa/common/shadow_map.h"
#include "agaa/common/technique.h"
#include "agaa/sbaa/surface_fill.h"
#include "agaa/sbaa/surface_selection.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"

namespace agaa {

struct SbaaSettings {
    uint32_t samples = 8;  // n: 4, 8, 16, 32
    uint32_t surfaces = 4; // S: 1..6 (the paper's comparison point is 4)
    // MERGE: primitives whose representative normals are within acos(0.9) = 25.8 degrees and whose
    // depths lie within one plane slope |dz/dx| + |dz/dy| of each other are one surface (a
    // tessellated surface is not split by its triangle edges).
    SbaaMergeTest merge;
    EffectSettings effects; // scene-driven shadows, alpha-to-coverage, emissive, normal maps
    // The fill's material at its representative sample's own position, and the prepass's alpha per
    // sample (agaa/common/sample_gbuffer.h); off: at the pixel's, as the per-sample G-buffer's.
    bool sampleRateShading = false;
};

class Sbaa final : public Technique {
  public:
    // Throws std::invalid_argument for n below 4 or S outside 1..6 (naming the setting),
    // MissingCapability without 4x MSAA or gl_PrimitiveID in fragment shaders.
    Sbaa(eng::vk::Device& device, const TechniqueContent& content, const SbaaSettings& settings);
    ~Sbaa() override;

    std::string name() const override { return "sbaa"; }
    uint32_t samples() const override { return m_settings.samples; }
    FrameTargets addPasses(eng::rg::Graph& graph, const FrameInputs& inputs) override;
    bool isStorage(const std::string& resourceName) const override;
    std::string storageCategory(const std::string& resourceName) const override;
    std::vector<VariantChoice> variants() const override;
    const SbaaSettings& settings() const { return m_settings; }

    // The passes one by one, for tests: the prepass, the selection (writes `surfaces`, the
    // per-surface G-buffer without its material, and `lostSamples`), the fill (the material), the
    // lighting.
    SampleGBuffer addGBuffer(eng::rg::Graph& graph, const FrameInputs& inputs) {
        return m_gbuffer.add(graph, inputs);
    }
    struct Surfaces {
        eng::rg::Buffer surfaces;     // kSbaaSurfaceWords uint per surface, S per pixel
        eng::rg::Texture lostSamples; // R32_UINT
    };
    Surfaces addSurfaces(eng::rg::Graph& graph, const FrameInputs& inputs, const SampleGBuffer& gbuffer);
    Surfaces addFill(eng::rg::Graph& graph, const FrameInputs& inputs, const SampleGBuffer& gbuffer,
                     const Surfaces& surfaces) {
        return {m_fill.add(graph, inputs, gbuffer.depth, surfaces.surfaces), surfaces.lostSamples};
    }
    FrameTargets addLighting(eng::rg::Graph& graph, const FrameInputs& inputs, const SampleGBuffer& gbuffer,
                             const Surfaces& surfaces);

  private:
    eng::vk::Device& m_device;
    SbaaSettings m_settings;
    const SceneTraits m_traits;
    const eng::frame::GpuScene* m_scene;  // null for a host's content
    eng::scene::SceneFeatures m_features; // before the passes built from it
    SampleGBufferPass m_gbuffer;
    SurfaceFillPass m_fill;
    ShadowMapPass m_shadow;
    eng::vk::PipelineLayout m_surfacesLayout, m_lightingLayout;
    VkPipeline m_surfacesPipeline = VK_NULL_HANDLE, m_lightingPipeline = VK_NULL_HANDLE;
    VkSampler m_fetchSampler = VK_NULL_HANDLE;
};

} // namespace agaa
