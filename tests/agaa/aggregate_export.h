#pragma once
// One frame of AGAA's samples path with the lighting pass's test export on
// (AggregateAA::setAggregateExportTarget; shaders/glsl/agaa/lighting/export.glsl): kRecordFloats
// floats per record, each sample of pixel p at p * n + s, then each aggregate at
// pixels * n + p * c + a. The export variant has no shadow maps and no emissive term.

#include "agaa/aggregate/aggregate.h"
#include "engine/vk/resources.h"
#include "tools/harness/frame_renderer.h"

#include <cstring>
#include <vector>

namespace agaa::test {

inline constexpr uint32_t kExportRecordFloats = 16; // export.glsl exportRecord

inline std::vector<float> renderAggregateExport(eng::vk::Device& device, FrameRenderer& renderer,
                                                const RenderRequest& r, RenderResult* result = nullptr,
                                                shared::AgaaConstants* constants = nullptr) {
    const uint32_t pixels = r.view.width * r.view.height;
    const VkDeviceSize bytes = VkDeviceSize(pixels) * (r.settings.samples + r.settings.aggregates) *
                               kExportRecordFloats * sizeof(float);
    eng::vk::Buffer host = eng::vk::createBuffer(device, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                 eng::vk::MemoryUse::Readback, "test.export");
    auto& technique = dynamic_cast<AggregateAA&>(renderer.technique(r));
    technique.setAggregateExportTarget(&host);
    RenderResult frame = renderer.render(r);
    vkDeviceWaitIdle(device.device());
    std::vector<float> out(bytes / sizeof(float));
    std::memcpy(out.data(), host.mapped, bytes);
    if (result) *result = std::move(frame);
    if (constants) *constants = technique.constants();
    technique.setAggregateExportTarget(nullptr);
    eng::vk::destroyBuffer(device, host);
    return out;
}

} // namespace agaa::test
