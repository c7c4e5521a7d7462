#pragma once
// Simple/Complex deferred MSAA (Lauritzen 2010, "Deferred Rendering for Current and
// Future Rendering Pipelines", SIGGRAPH course; DESIGN section 5), the paper's timing
// reference: the reference's per-sample G-buffer, then one tiled lighting pass that
// classifies each pixel (complex when any sample departs from sample 0 in depth or
// normal, or in sky vs geometry) and lights sample 0 of every pixel but the other
// samples only of complex pixels.

#include "agaa/common/sample_gbuffer.h"
#include "agaa/common/shadow_map.h"
#include "agaa/common/technique.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"

#include <string>

namespace agaa {

enum class SimpleComplexSchedule : uint32_t {
    // Lauritzen's "defer per-sample": the complex pixels' extra samples packed into a
    // per-tile list the whole workgroup shades. Measured faster on lavapipe (README.md).
    DeferPerSample = 0,
    Naive = 1, // each invocation loops over its own pixel's extra samples
};

enum class SimpleComplexDebugView : uint32_t {
    None = 0,
    Complex = 1, // display target: complex pixels red, simple pixels grey (hdr unchanged)
};

struct SimpleComplexSettings {
    uint32_t samples = 8;
    // Lauritzen's minNormalDot: cos below it makes the pixel complex. The classic 0.99 (8 degrees)
    // let facets of tessellated bars shade as one (railings n = 4: RMSE 1.11e-3 vs the reference);
    // 0.999 (2.6 degrees) is the paper's setting "with no quality degradation" (RMSE 6.4e-4).
    float minNormalCos = 0.999f;
    // Depth tolerance = scale * (|dz/dx| + |dz/dy|) of sample 0's plane (see
    // simple_complex/classify.glsl); 1 is Lauritzen's maxZDelta.
    float depthSlopeScale = 1.0f;
    SimpleComplexSchedule schedule = SimpleComplexSchedule::DeferPerSample;
    SimpleComplexDebugView debugView = SimpleComplexDebugView::None;
    EffectSettings effects;         // scene-driven shadows, alpha-to-coverage, emissive, normal maps
    bool sampleRateShading = false; // the fill pass at sample rate (agaa/common/sample_gbuffer.h)
};

class SimpleComplex final : public Technique {
  public:
    // Throws std::invalid_argument for settings out of range (naming the setting),
    // MissingCapability when n > 1 and the device lacks 4x MSAA.
    SimpleComplex(eng::vk::Device& device, const TechniqueContent& content,
                  const SimpleComplexSettings& settings, std::string name = "simple-complex");
    ~SimpleComplex() override;

    std::string name() const override { return m_name; }
    uint32_t samples() const override { return m_settings.samples; }
    FrameTargets addPasses(eng::rg::Graph& graph, const FrameInputs& inputs) override;
    bool isStorage(const std::string& resourceName) const override {
        return m_gbuffer.isStorage(resourceName);
    }
    const SimpleComplexSettings& settings() const { return m_settings; }
    std::vector<VariantChoice> variants() const override;

    // The two halves of addPasses, for hosts and tests that need the G-buffer itself.
    SampleGBuffer addGBuffer(eng::rg::Graph& graph, const FrameInputs& inputs) {
        return m_gbuffer.add(graph, inputs);
    }
    FrameTargets addLighting(eng::rg::Graph& graph, const FrameInputs& inputs, const SampleGBuffer& gbuffer);

  private:
    eng::vk::Device& m_device;
    SimpleComplexSettings m_settings;
    std::string m_name;
    const SceneTraits m_traits;
    const eng::frame::GpuScene* m_scene;  // null for a host's content
    eng::scene::SceneFeatures m_features; // before the passes built from it
    SampleGBufferPass m_gbuffer;
    ShadowMapPass m_shadow; // adds its pass in addLighting() when the scene has a shadowed light
    eng::vk::PipelineLayout m_lightingLayout;
    VkPipeline m_lightingPipeline = VK_NULL_HANDLE;
    VkSampler m_fetchSampler = VK_NULL_HANDLE;
};

} // namespace agaa
