#pragma once
// A technique's frame recorded into a host's own command buffer (issue 50), for a host that has
// its own render graph, or none, and never builds an eng::rg::Graph: record() writes the view's
// frame constants and lights, adds the technique's passes and writes its display (and resolved
// depth) into the host's images (host_targets.h), and records all of it, barriers included, into
// the command buffer the host began. The host ends and submits it.
//
// The host's images: HostTarget::initial is the state each is in when the command buffer reaches
// the frame, HostTarget::final the state it is left in (an eng::rg::Use: its image layout, stages
// and access are engine/graph/use.h's table row for that Use; nullopt initial: contents undefined,
// nullopt final: the writer's last use, TransferDst for colour). Between the two every barrier is
// this recorder's. Before the frame the host makes its own writes to the images available to
// that initial state; after it, its own passes wait for the final one.
//
// Lifetimes: what a frame uses (its graph's transients) stays allocated until the same frameSlot
// is recorded again or the recorder is destroyed: a host records slot s again only after the
// fence of the submission that last used it signalled, as for the technique's own ring
// (technique.h), and keeps the recorder and the technique alive until then. Threads: one
// recording thread at a time.

#include "agaa/common/frame_inputs.h"
#include "agaa/common/host_targets.h"
#include "engine/frame/transient_pool.h"
#include "engine/frame/uniform_ring.h"

#include <array>
#include <memory>

namespace agaa {

// What a host's content adds to each frame, as FrameInputs' fields of the same names: its drawer,
// its environment and its shadow maps, each optional (null: the GpuScene's the technique was
// created with, or the module's own maps).
struct HostFrameInputs {
    GeometryDrawer* geometry = nullptr;
    const EnvironmentBindings* environment = nullptr;
    const HostShadowMaps* shadowMaps = nullptr;
};

class FrameRecorder {
  public:
    FrameRecorder(eng::vk::Device& device, const TechniqueContent& content);
    ~FrameRecorder();
    FrameRecorder(const FrameRecorder&) = delete;
    FrameRecorder& operator=(const FrameRecorder&) = delete;

    // Records one view of `technique` into `cmd` through frame slot `frameSlot` (< kMaxSlots),
    // with the host's content (`host`). Throws std::invalid_argument naming what is wrong with a
    // target or a missing input, std::out_of_range for the slot; nothing is recorded then.
    void record(VkCommandBuffer cmd, Technique& technique, const eng::frame::ViewSettings& view,
                const HostTargets& targets, uint32_t frameSlot = 0, const HostFrameInputs& host = {});

    static constexpr uint32_t kMaxSlots = eng::frame::UniformRing::kMaxSlots;

  private:
    eng::vk::Device& m_device;
    FrameInputWriter m_inputs;
    HostTargetWriter m_writer;
    eng::frame::TransientPool m_pool;
    std::array<std::unique_ptr<eng::rg::Graph>, kMaxSlots> m_frames; // each slot's last frame
};

} // namespace agaa
