// agaa::FrameRecorder (agaa/common/frame_recorder.h).

#include "agaa/common/frame_recorder.h"

#include <stdexcept>
#include <string>

namespace agaa {

FrameRecorder::FrameRecorder(eng::vk::Device& device, const TechniqueContent& content)
    : m_device(device), m_inputs(device, content), m_writer(device), m_pool(device) {}

FrameRecorder::~FrameRecorder() {
    // The host waited for its submissions (the header's lifetimes); the transients go back first.
    for (std::unique_ptr<eng::rg::Graph>& frame : m_frames)
        if (frame) frame->releaseTransients();
}

void FrameRecorder::record(VkCommandBuffer cmd, Technique& technique, const eng::frame::ViewSettings& view,
                           const HostTargets& targets, uint32_t frameSlot, const HostFrameInputs& host) {
    if (frameSlot >= kMaxSlots)
        throw std::out_of_range("FrameRecorder: frame slot " + std::to_string(frameSlot) +
                                " (allowed: 0 to " + std::to_string(kMaxSlots - 1) + ")");
    // The slot's previous frame has completed (the host's fence): its transients are free again.
    std::unique_ptr<eng::rg::Graph>& frame = m_frames[frameSlot];
    if (frame) frame->releaseTransients();
    frame = std::make_unique<eng::rg::Graph>();
    eng::frame::ViewSettings jittered = view;
    if (technique.temporal()) jittered.jitter = technique.subpixelJitter(); // else the host's own
    FrameInputs in = m_inputs.write(*frame, jittered, technique.samples(), frameSlot);
    in.geometry = host.geometry;
    in.environment = host.environment;
    in.shadowMaps = host.shadowMaps;
    const HostTargetVersions out = m_writer.write(*frame, technique.addPasses(*frame, in), in, targets);
    frame->markOutput(out.color);
    if (out.depth.valid()) frame->markOutput(out.depth);
    if (out.hdr.valid()) frame->markOutput(out.hdr);
    frame->compile();
    eng::rg::Graph::ExecuteInfo info;
    info.cmd = cmd;
    info.allocator = &m_pool;
    info.beginLabel = m_device.beginLabel();
    info.endLabel = m_device.endLabel();
    frame->execute(info);
}

} // namespace agaa
