#include "agaa/common/frame_inputs.h"

#include <algorithm>

namespace agaa {

namespace {
// At least one light's worth: a scene without lights still binds a buffer.
VkDeviceSize lightBytes(const eng::scene::Scene& scene) {
    return std::max<VkDeviceSize>(1, scene.lights.size()) * sizeof(shared::GpuLight);
}
} // namespace

void checkFrameInputs(const FrameInputs& in) {
    if (in.constants) eng::frame::requireCameraRelative(*in.constants);
}

FrameInputWriter::FrameInputWriter(eng::vk::Device& device, const eng::frame::GpuScene& scene)
    : m_scene(scene), m_constants(device, sizeof(shared::FrameConstants), "frame.constants"),
      m_lights(device, lightBytes(scene.scene()), "frame.lights", VK_BUFFER_USAGE_STORAGE_BUFFER_BIT) {}

FrameInputs FrameInputWriter::write(eng::rg::Graph& graph, const eng::frame::ViewSettings& view,
                                    uint32_t samples, uint32_t frameSlot) {
    const eng::scene::Scene& scene = m_scene.scene();
    const shared::FrameConstants constants =
        eng::frame::makeFrameConstants(scene, view, eng::frame::makeSamplePattern(samples));
    std::vector<shared::GpuLight> lights = eng::frame::makeGpuLights(scene, constants.view);
    lights.resize(lightBytes(scene) / sizeof(shared::GpuLight)); // the padding light is never counted
    FrameInputs in;
    in.frameConstants = m_constants.write(graph, frameSlot, std::as_bytes(std::span(&constants, 1)));
    in.lights = m_lights.write(graph, frameSlot, std::as_bytes(std::span(lights)));
    m_values[frameSlot] = constants; // frameSlot < kMaxSlots: the ring refused it otherwise
    in.scene = &m_scene;
    in.constants = &m_values[frameSlot];
    in.width = view.width;
    in.height = view.height;
    in.frameSlot = frameSlot;
    return in;
}

} // namespace agaa
