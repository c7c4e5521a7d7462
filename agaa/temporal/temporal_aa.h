#pragma once
// Temporal anti-aliasing on the no-AA path (issue 51), as engines ship it: the no-AA frame is
// rendered with a sub-pixel jitter that changes every frame (Halton (2, 3), 8 phases), and one
// compute pass (temporal/resolve.comp) blends it into a history reprojected from the previous
// frame by depth and the camera's motion, clipped to the current neighbourhood (Karis 2014; Yang,
// Liu and Salvi 2020). One shading event per pixel per frame; the history is two RGBA32F images
// the technique keeps (storage "taa.history").
//
// A temporal method: every frame records anew (Technique::temporal), in order, and its state (the
// history, the previous camera, the jitter index) moves on when addPasses records a frame. Still
// frames converge towards the pixel's average over the jitter pattern; a moving camera sees the
// history lag (ghosting) and the clip's loss of detail.

#include "agaa/common/technique.h"
#include "agaa/reference/reference.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/resources.h"

#include <array>
#include <optional>
#include <string>

namespace agaa {

struct TemporalSettings {
    EffectSettings effects; // the no-AA frame's
    // The current frame's weight once the history is full (Karis 2014: 0.04 to 0.1): the first
    // frames average uniformly (1 / frames), then the history keeps 1 - minimumWeight.
    float minimumWeight = 0.1f;
    float clipGamma = 1.0f;    // the neighbourhood box: mean +- gamma sigma (Salvi's variance clip)
    uint32_t jitterPhases = 8; // Halton (2, 3) points before the sequence repeats, 1..256
    bool motionView = false;   // --debug motion: the reprojected pixel position (x, y), found (z)
};

class TemporalAA final : public Technique {
  public:
    // Throws std::invalid_argument naming a setting out of range.
    TemporalAA(eng::vk::Device& device, const TechniqueContent& content, const TemporalSettings& settings,
               std::string name = "taa");
    ~TemporalAA() override;
    TemporalAA(const TemporalAA&) = delete;
    TemporalAA& operator=(const TemporalAA&) = delete;

    std::string name() const override { return m_name; }
    uint32_t samples() const override { return 1; }
    FrameTargets addPasses(eng::rg::Graph& graph, const FrameInputs& inputs) override;
    bool isStorage(const std::string& resourceName) const override;
    std::vector<VariantChoice> variants() const override;
    bool temporal() const override { return true; }
    glm::vec2 subpixelJitter() const override;
    void resetHistory() override;

    // Frames blended into the history so far (0 before the first frame; reset by a new size).
    uint32_t framesInHistory() const { return m_framesInHistory; }

  private:
    void allocateHistory(uint32_t width, uint32_t height);
    void releaseHistory();

    eng::vk::Device& m_device;
    TemporalSettings m_settings;
    std::string m_name;
    Reference m_noaa; // n = 1, resources "<name>.noaa.*"
    eng::vk::PipelineLayout m_layout;
    VkPipeline m_pipeline = VK_NULL_HANDLE;
    VkSampler m_fetchSampler = VK_NULL_HANDLE;
    std::array<eng::vk::Image, 2> m_history{}; // read one, write the other; swapped every frame
    uint32_t m_write = 0;                      // the history image this frame writes
    uint64_t m_frame = 0;                      // jitter index of the next frame
    uint32_t m_framesInHistory = 0;
    std::optional<shared::FrameConstants> m_previous; // the previous frame's camera
};

} // namespace agaa
