#include "agaa/common/frame_inputs.h"

#include <algorithm>

namespace agaa {

namespace {
// At least one light's worth: content without lights still binds a buffer.
VkDeviceSize lightBytes(size_t lights) {
    return std::max<VkDeviceSize>(1, lights) * sizeof(shared::GpuLight);
}
} // namespace

void checkFrameInputs(const FrameInputs& in) {
    if (in.constants) eng::frame::requireCameraRelative(*in.constants);
}

FrameInputWriter::FrameInputWriter(eng::vk::Device& device, const TechniqueContent& content)
    : m_cameras(content.traits.cameras), m_lights(content.traits.lights),
      m_constantsRing(device, sizeof(shared::FrameConstants), "frame.constants"),
      m_lightsRing(device, lightBytes(m_lights.size()), "frame.lights", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {}

FrameInputs FrameInputWriter::write(eng::rg::Graph& graph, const eng::frame::ViewSettings& view,
                                    uint32_t samples, uint32_t frameSlot) {
    const shared::FrameConstants constants = eng::frame::makeFrameConstants(
        m_cameras, m_lights.size(), view, eng::frame::makeSamplePattern(samples));
    std::vector<shared::GpuLight> lights = eng::frame::makeGpuLights(m_lights, constants.view);
    lights.resize(lightBytes(m_lights.size()) /
                  sizeof(shared::GpuLight)); // the padding light is never counted
    FrameInputs in;
    in.frameConstants = m_constantsRing.write(graph, frameSlot, std::as_bytes(std::span(&constants, 1)));
    in.lights = m_lightsRing.write(graph, frameSlot, std::as_bytes(std::span(lights)));
    m_values[frameSlot] = constants; // frameSlot < kMaxSlots: the ring refused it otherwise
    in.constants = &m_values[frameSlot];
    in.width = view.width;
    in.height = view.height;
    in.frameSlot = frameSlot;
    return in;
}

} // namespace agaa
