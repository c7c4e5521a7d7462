#pragma once
// Shared by the node tests: one host view (its own frame constants, lights and readback
// buffers, as a host keeps them per frame slot) recorded through a technique into a graph.

#include "agaa/common/technique.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/frame_runner.h"
#include "engine/frame/gpu_scene.h"
#include "engine/frame/readback.h"
#include "engine/vk/resources.h"

#include <cstring>
#include <span>
#include <vector>

namespace agaa::test {

class HostView {
  public:
    HostView(eng::vk::Device& device, const eng::scene::Scene& scene, const eng::frame::ViewSettings& view,
             uint32_t samples)
        : m_device(device), m_width(view.width), m_height(view.height) {
        constants = eng::frame::makeFrameConstants(scene, view, eng::frame::makeSamplePattern(samples));
        const auto lights = eng::frame::makeGpuLights(scene, constants.view);
        namespace vk = eng::vk;
        m_frame = vk::createBuffer(device, sizeof constants, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                   vk::MemoryUse::Upload, "host.frame");
        m_lights = vk::createBuffer(device, lights.size() * sizeof(shared::GpuLight),
                                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload, "host.lights");
        vk::writeBuffer(device, m_frame, std::as_bytes(std::span(&constants, 1)));
        vk::writeBuffer(device, m_lights, std::as_bytes(std::span(lights)));
        m_hdr = eng::frame::createReadbackBuffer(device, m_width, m_height, VK_FORMAT_R32G32B32A32_SFLOAT,
                                                 "host.hdr");
        m_display = eng::frame::createReadbackBuffer(device, m_width, m_height, VK_FORMAT_R32G32B32A32_SFLOAT,
                                                     "host.display");
    }
    ~HostView() {
        vkDeviceWaitIdle(m_device.device());
        for (eng::vk::Buffer* b : {&m_frame, &m_lights, &m_hdr, &m_display})
            eng::vk::destroyBuffer(m_device, *b);
    }
    HostView(const HostView&) = delete;
    HostView& operator=(const HostView&) = delete;

    // Imports this view's buffers, adds the technique's passes writing frame slot `slot`, and
    // reads HDR and display back into this view's buffers.
    // Returns the inputs it handed the technique; lastTargets holds what the technique returned.
    // `geometry`, `shadowMaps`, `environment`: the host's drawer, shadow maps and environment
    // (FrameInputs::geometry, ::shadowMaps, ::environment), or none.
    FrameInputs record(eng::rg::Graph& graph, Technique& technique, uint32_t slot, const std::string& prefix,
                       GeometryDrawer* geometry = nullptr, const HostShadowMaps* shadowMaps = nullptr,
                       const EnvironmentBindings* environment = nullptr) {
        FrameInputs in;
        in.geometry = geometry;
        in.shadowMaps = shadowMaps;
        in.environment = environment;
        in.constants = &constants;
        in.width = m_width;
        in.height = m_height;
        in.frameSlot = slot;
        in.frameConstants =
            graph.importBuffer(prefix + ".frame", {m_frame.buffer, m_frame.size}, std::nullopt, std::nullopt);
        in.lights = graph.importBuffer(prefix + ".lights", {m_lights.buffer, m_lights.size}, std::nullopt,
                                       std::nullopt);
        lastTargets = technique.addPasses(graph, in);
        eng::frame::addReadbackPass(graph, lastTargets.hdr, m_hdr, prefix + ".readback.hdr");
        eng::frame::addReadbackPass(graph, lastTargets.display, m_display, prefix + ".readback.display");
        return in;
    }

    // HDR then display, as floats, after the GPU finished.
    std::vector<float> read() const {
        const size_t floats = size_t(m_width) * m_height * 4;
        std::vector<float> out(2 * floats);
        eng::vk::invalidateBuffer(m_device, m_hdr);
        eng::vk::invalidateBuffer(m_device, m_display);
        std::memcpy(out.data(), m_hdr.mapped, floats * 4);
        std::memcpy(out.data() + floats, m_display.mapped, floats * 4);
        return out;
    }

    shared::FrameConstants constants{};
    FrameTargets lastTargets;

  private:
    eng::vk::Device& m_device;
    uint32_t m_width, m_height;
    eng::vk::Buffer m_frame, m_lights, m_hdr, m_display;
};

// The view renderFrame renders: scene camera 0 at 64x64.
inline eng::frame::ViewSettings frameView() {
    eng::frame::ViewSettings view;
    view.width = view.height = 64;
    return view;
}

// One frameView() frame through `technique`, drawn by `geometry` (FrameInputs::geometry; null: the
// scene's own drawer), with the host's `shadowMaps` or the module's and the host's `environment`
// or the scene's: HDR then display, as HostView::read.
inline std::vector<float> renderFrame(eng::vk::Device& device, const eng::frame::GpuScene& scene,
                                      Technique& technique, GeometryDrawer* geometry,
                                      const HostShadowMaps* shadowMaps = nullptr,
                                      const EnvironmentBindings* environment = nullptr) {
    HostView host(device, scene.scene(), frameView(), technique.samples());
    eng::rg::Graph graph;
    host.record(graph, technique, 0, "host", geometry, shadowMaps, environment);
    eng::frame::FrameRunner runner(device);
    runner.run(graph);
    return host.read();
}

// Values that differ bit for bit (NaN-safe: compares the bits, not the floats).
inline size_t countDifferentBits(const std::vector<float>& a, const std::vector<float>& b) {
    if (a.size() != b.size()) return std::max(a.size(), b.size());
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i)
        n += std::memcmp(&a[i], &b[i], sizeof(float)) != 0 ? 1 : 0;
    return n;
}

} // namespace agaa::test
