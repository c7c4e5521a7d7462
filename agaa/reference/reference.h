#pragma once
// The per-sample deferred reference (DESIGN section 5): a full G-buffer per
// sample (16 bytes + 4 bytes depth) at n samples, 1 and 4 native, 8/16/32 by
// layered 4x emulation; then a tiled-deferred compute pass lights every sample.
// With n = 1 it is the no-AA method: one sample, one shading event per pixel.

#include "agaa/common/sample_gbuffer.h"
#include "agaa/common/shadow_map.h"
#include "agaa/common/technique.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"

#include <array>

namespace agaa {

struct ReferenceSettings {
    uint32_t samples = 8;
    EffectSettings effects; // scene-driven shadows, alpha-to-coverage, emissive, normal maps
    // Sample-rate shading in the fill pass: the ground truth with supersampled materials
    // (textures and normal maps evaluated at every sample), for AGAA's samples path with the same
    // switch. Off (default): the material once per pixel, written to its covered samples.
    bool sampleRateShading = false;
};

class Reference final : public Technique {
  public:
    Reference(eng::vk::Device& device, const TechniqueContent& content, const ReferenceSettings& settings,
              std::string name = "reference");
    ~Reference() override;

    std::string name() const override { return m_name; }
    uint32_t samples() const override { return m_settings.samples; }
    FrameTargets addPasses(eng::rg::Graph& graph, const FrameInputs& inputs) override;
    bool isStorage(const std::string& resourceName) const override;
    std::vector<VariantChoice> variants() const override;

  private:
    eng::vk::Device& m_device;
    ReferenceSettings m_settings;
    std::string m_name;
    const SceneTraits m_traits;
    const eng::frame::GpuScene* m_scene;  // null for a host's content
    eng::scene::SceneFeatures m_features; // before the passes built from it
    SampleGBufferPass m_gbuffer;
    ShadowMapPass m_shadow;
    eng::vk::PipelineLayout m_lightingLayout;
    VkPipeline m_lightingPipeline = VK_NULL_HANDLE;
    VkSampler m_fetchSampler = VK_NULL_HANDLE;
};

} // namespace agaa
