#pragma once
// Temporal anti-aliasing (issue 51), as engines ship it: an inner method's frame is rendered with a
// sub-pixel jitter that changes every frame (Halton (2, 3), 8 phases), and one compute pass
// (temporal/resolve.comp) blends its HDR into a history reprojected from the previous frame by
// depth and the camera's motion, clipped to the current neighbourhood (Karis 2014; Yang, Liu and
// Salvi 2020), and its display (its shading events tone-mapped, as the truth's display is) into a
// display history the same way. The inner method is no-AA (`taa`: one shading event per pixel per frame) or
// AGAA
// (`agaa-taa`: AGAA's resolve through the same pass, as the Unreal AGAA talk combined them; its
// whole sample pattern moves by the jitter). The histories are four RGBA32F images the technique
// keeps (storage "<name>.history.*").
//
// A temporal method: every frame records anew (Technique::temporal), in order, and its state (the
// history, the previous camera, the jitter index) moves on when addPasses records a frame. Still
// frames converge towards the pixel's average over the jitter pattern; a moving camera sees the
// history lag (ghosting) and the clip's loss of detail.

#include "agaa/common/technique.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/resources.h"

#include <array>
#include <memory>
#include <optional>
#include <string>

namespace agaa {

struct TemporalSettings {
    // The current frame's weight once the history is full (Karis 2014: 0.04 to 0.1): the first
    // frames average uniformly (1 / frames), then the history keeps 1 - minimumWeight.
    float minimumWeight = 0.1f;
    float clipGamma = 1.0f;    // the neighbourhood box: mean +- gamma sigma (Salvi's variance clip)
    uint32_t jitterPhases = 8; // Halton (2, 3) points before the sequence repeats, 1..256
    bool motionView = false;   // --debug motion: position and depths (shared::TemporalParams)
};

class TemporalAA final : public Technique {
  public:
    // inner: the method whose frames it blends (its passes record inside this one's). Throws
    // std::invalid_argument naming a setting out of range.
    TemporalAA(eng::vk::Device& device, std::unique_ptr<Technique> inner, const TemporalSettings& settings,
               std::string name = "taa");
    ~TemporalAA() override;
    TemporalAA(const TemporalAA&) = delete;
    TemporalAA& operator=(const TemporalAA&) = delete;

    std::string name() const override { return m_name; }
    uint32_t samples() const override { return m_inner->samples(); }
    FrameTargets addPasses(eng::rg::Graph& graph, const FrameInputs& inputs) override;
    bool isStorage(const std::string& resourceName) const override;
    std::string storageCategory(const std::string& resourceName) const override;
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
    std::unique_ptr<Technique> m_inner;
    eng::vk::PipelineLayout m_layout;
    VkPipeline m_pipeline = VK_NULL_HANDLE;
    VkSampler m_fetchSampler = VK_NULL_HANDLE;
    // The HDR pair [0, 1] and the display pair [2, 3]: each frame reads one of a pair and writes
    // the other (m_write, 2 + m_write), and the next frame swaps them.
    std::array<eng::vk::Image, 4> m_history{};
    uint32_t m_write = 0;
    uint64_t m_frame = 0; // jitter index of the next frame
    uint32_t m_framesInHistory = 0;
    std::optional<shared::FrameConstants> m_previous; // the previous frame's camera
};

} // namespace agaa
