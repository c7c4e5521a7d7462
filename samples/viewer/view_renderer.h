#pragma once
// One viewer frame on the GPU, from the scene to the swapchain image, in one render graph: the
// method's passes, the per-sample reference at the same n for the split or difference view (and
// the difference kernel), the display blit into the acquired swapchain image (1:1, nearest; the SRGB
// swapchain format does the sRGB encode), the UI pass on top, and the present transition. Nothing is read
// back per frame; the shading-event count (for the stats) and a screenshot only when asked for.

#include "agaa/method_settings.h"
#include "engine/frame/frame_runner.h"
#include "engine/frame/gpu_scene.h"
#include "engine/io/image.h"
#include "engine/scene/scene.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/resources.h"
#include "samples/viewer/controls.h"
#include "samples/viewer/swapchain.h"
#include "tools/harness/frame_renderer.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace agaa::viewer {

struct ViewRequest {
    RenderRequest render;           // method, settings, view (size = the swapchain's), exposure
    Compare compare = Compare::Off; // against the reference at the same n (controls.h)
    float splitFraction = 0.5f;     // Split: of the width, (0, 1); right of it the reference
    float differenceGain = 4.0f;    // Difference: |method - reference| x gain
    // Swapchain pixels per rendered pixel, each way (1..4): 1 is 1:1; more renders pixelSize^2
    // times fewer pixels and shows each as an exact block (NEAREST, no blur), for interactivity.
    uint32_t pixelSize = 1;
    bool readShadingEvents = false;
    bool screenshot = false; // read the presented image back (needs Swapchain::canReadBack())
};

struct ViewFrame {
    eng::frame::FrameTiming timing; // every executed pass, in order, with its GPU ms
    uint32_t samples = 0;           // what the method rasterised
    double bytesPerPixel = 0.0;     // the method's own storage (Technique::isStorage)
    std::map<std::string, double> bytesPerPixelSplit;
    std::optional<double> shadingEventsPerPixel; // only when readShadingEvents
    std::optional<eng::io::ImageU8> screenshot;  // RGBA8 sRGB-encoded, only when screenshot
};

inline constexpr uint32_t kMaxPixelSize = 4;
// The rendered size along one axis for a swapchain of `size` pixels.
inline uint32_t renderSize(uint32_t size, uint32_t pixelSize) {
    return (size + pixelSize - 1) / pixelSize;
}

// Adds the UI's pass: reads and writes the swapchain image as a colour attachment, returns the
// new version.
using OverlayPass = std::function<eng::rg::Texture(eng::rg::Graph&, eng::rg::Texture)>;

class ViewRenderer {
  public:
    ViewRenderer(eng::vk::Device& device, const eng::scene::Scene& scene);
    ~ViewRenderer();
    ViewRenderer(const ViewRenderer&) = delete;
    ViewRenderer& operator=(const ViewRenderer&) = delete;

    // Renders into `target` and waits for the GPU; the caller presents it. Throws
    // std::invalid_argument for a setting the method refuses, eng::vk::MissingCapability for one
    // the device lacks (before anything is submitted).
    ViewFrame render(const ViewRequest& request, const AcquiredImage& target, const OverlayPass& overlay);

    // The window changed size: the pooled transients of the old size would never be asked for
    // again, so free them (the caller has waited for the GPU, as Swapchain::recreate does).
    void sizeChanged();

  private:
    Technique& technique(const std::string& method, const MethodSettings& settings);
    // "viewer.difference": |method - reference| x gain into a new RGBA32F image.
    eng::rg::Texture addDifferencePass(eng::rg::Graph& graph, eng::rg::Texture method,
                                       eng::rg::Texture reference, float gain, uint32_t width,
                                       uint32_t height);

    eng::vk::Device& m_device;
    const eng::scene::Scene& m_scene;
    eng::frame::GpuScene m_gpuScene;
    eng::frame::FrameRunner m_runner;
    // [0] the method's, [1] the reference's (its own sample pattern when the method has 1 sample).
    eng::vk::Buffer m_frameConstants[2], m_lights;
    eng::vk::Buffer m_events, m_screenshot; // host readbacks, sized on demand
    std::map<std::string, std::unique_ptr<Technique>> m_techniques;
    eng::vk::PipelineLayout m_differenceLayout;
    VkPipeline m_difference = VK_NULL_HANDLE;
    VkSampler m_fetchSampler = VK_NULL_HANDLE;
};

} // namespace agaa::viewer
