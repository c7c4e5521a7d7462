#pragma once
// FXAA (Lottes 2009, FXAA 3.11 quality) on the no-AA image (DESIGN section 5): the
// cheap end of the chart. The no-AA passes (the reference technique at n = 1) run
// first, in the same graph; one compute pass then filters their tone-mapped display
// target. The HDR target and the shading events are the no-AA ones (FXAA works on
// display values only and shades nothing).

#include "agaa/common/technique.h"
#include "agaa/fxaa/fxaa_reference.h"
#include "agaa/reference/reference.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"

#include <string>

namespace agaa {

class Fxaa final : public Technique {
  public:
    // Throws std::invalid_argument for settings out of range (naming the setting). effects: the
    // no-AA frame's, which FXAA filters.
    Fxaa(eng::vk::Device& device, const TechniqueContent& content, const FxaaSettings& settings,
         const EffectSettings& effects = {}, std::string name = "fxaa");
    ~Fxaa() override;

    std::string name() const override { return m_name; }
    uint32_t samples() const override { return 1; }
    FrameTargets addPasses(eng::rg::Graph& graph, const FrameInputs& inputs) override;
    bool isStorage(const std::string& resourceName) const override { return m_noaa.isStorage(resourceName); }
    std::vector<VariantChoice> variants() const override { return m_noaa.variants(); }

    // The FXAA pass alone, on any tone-mapped RGBA32F image of width x height; returns the filtered image.
    eng::rg::Texture addFxaaPass(eng::rg::Graph& graph, eng::rg::Texture display, uint32_t width,
                                 uint32_t height);

  private:
    eng::vk::Device& m_device;
    FxaaSettings m_settings;
    std::string m_name;
    Reference m_noaa; // n = 1, resources "<name>.noaa.*"
    eng::vk::PipelineLayout m_layout;
    VkPipeline m_pipeline = VK_NULL_HANDLE;
    VkSampler m_fetchSampler = VK_NULL_HANDLE;
};

} // namespace agaa
