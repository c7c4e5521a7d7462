#pragma once
// One frame of AGAA's samples path with the test build of its lighting pass exporting what step 1
// read and built (tests/support/aggregate_instrumentation.h AggregateExportPass;
// shaders/glsl/tests/agaa_lighting_export.comp): kExportRecordFloats floats per record, each sample of
// pixel p at p * n + s, then each aggregate at pixels * n + p * c + a. The export build has no
// shadow maps and no emissive term. The frame's result is the shipping lighting pass's.

#include "agaa/aggregate/aggregate.h"
#include "engine/vk/resources.h"
#include "tests/support/aggregate_instrumentation.h"
#include "tools/harness/frame_renderer.h"

#include <cstring>
#include <vector>

namespace agaa::test {

// `exporter` keeps its pipelines between calls (one per specialisation met).
inline std::vector<float> renderAggregateExport(AggregateExportPass& exporter, FrameRenderer& renderer,
                                                RenderRequest r, RenderResult* result = nullptr,
                                                shared::AgaaConstants* constants = nullptr) {
    eng::vk::Device& device = exporter.device();
    const uint32_t pixels = r.view.width * r.view.height;
    const VkDeviceSize bytes = VkDeviceSize(pixels) * (r.settings.samples + r.settings.aggregates) *
                               kExportRecordFloats * sizeof(float);
    eng::vk::Buffer host = eng::vk::createBuffer(device, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                                 eng::vk::MemoryUse::Readback, "test.export");
    auto earlier = r.extraPasses;
    r.extraPasses = [&](eng::rg::Graph& graph, Technique& tech, const FrameInputs& in) {
        if (earlier) earlier(graph, tech, in);
        auto& aggregate = dynamic_cast<AggregateAA&>(tech);
        exporter.add(graph, aggregate, in, host);
        if (constants) *constants = aggregate.constants();
    };
    RenderResult frame = renderer.render(r);
    vkDeviceWaitIdle(device.device());
    std::vector<float> out(bytes / sizeof(float));
    std::memcpy(out.data(), host.mapped, bytes);
    if (result) *result = std::move(frame);
    eng::vk::destroyBuffer(device, host);
    return out;
}

} // namespace agaa::test
