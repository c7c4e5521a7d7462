#pragma once
// The host's side of FrameInputs, for hosts that do not keep their own frame buffers: the
// camera (ViewSettings, which takes a host's own eng::scene::Camera) becomes the frame
// constants and the content's lights (SceneTraits::lights) in that view, written into
// per-frame-slot buffers (engine/frame/uniform_ring.h) and imported into the host's graph.
//
// Lifetimes: as the technique's own ring. Slot s may be written again once the fence of the
// submission that last read it signalled; several views or frames recorded before any executes
// each take their own slot (the same slot numbers as FrameInputs::frameSlot, which this sets).
// The returned FrameInputs point at this object's copy of the constants: valid until the next
// write() to the same slot. Threads: one recording thread at a time.

#include "agaa/common/technique.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/uniform_ring.h"

#include <array>
#include <vector>

namespace agaa {

// What every technique's addPasses checks first: FrameInputs::constants, where the host gives
// them, carry camera-relative fields that follow from their view and proj (FrameConstants::eye;
// eng::frame::requireCameraRelative). Throws std::invalid_argument naming the field.
void checkFrameInputs(const FrameInputs&);

class FrameInputWriter {
  public:
    FrameInputWriter(eng::vk::Device& device, const TechniqueContent& content);

    // `samples`: the technique's (Technique::samples()), which selects the sample pattern.
    FrameInputs write(eng::rg::Graph& graph, const eng::frame::ViewSettings& view, uint32_t samples,
                      uint32_t frameSlot);

  private:
    std::vector<eng::scene::Camera> m_cameras;
    std::vector<eng::scene::Light> m_lights;
    eng::frame::UniformRing m_constantsRing, m_lightsRing;
    std::array<shared::FrameConstants, eng::frame::UniformRing::kMaxSlots> m_values{};
};

} // namespace agaa
