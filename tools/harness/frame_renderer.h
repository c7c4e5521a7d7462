#pragma once
// Renders one frame of a scene with one method, headless, and brings back what
// the tools, the benchmark and the tests look at: the images, per-pass GPU
// times, shading events, the technique's storage from its real allocations,
// the compiled graph and the validation count. The same code path for all.

#include "agaa/common/technique.h"
#include "agaa/methods.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/frame_runner.h"
#include "engine/frame/gpu_scene.h"
#include "engine/io/image.h"
#include "engine/vk/resources.h"

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace agaa {

struct RenderRequest {
    std::string method = "reference";
    MethodSettings settings;
    eng::frame::ViewSettings view;
    uint32_t warmupFrames = 0; // lavapipe JIT-compiles pipelines on first use: warm up before timing
    uint32_t timedFrames = 1;  // per-pass times are the median over these
    // Tools and tests add their own passes (readbacks of intermediate resources) after the
    // technique's; they run in every frame of this request.
    std::function<void(eng::rg::Graph&, Technique&, const FrameInputs&)> extraPasses;
    // view.exposure replaced by the metered one (engine/frame/exposure.h): the log-average
    // luminance of the covered pixels of a no-AA frame of the same view, so every method of a
    // comparison gets the same exposure. Metered once per view and cached.
    bool autoExposure = false;
};

struct RenderResult {
    eng::io::ImageF hdr;                        // linear radiance
    eng::io::ImageF display;                    // tone-mapped resolve, linear [0,1] (sRGB-encode for viewing)
    std::vector<uint32_t> shadingEvents;        // per pixel
    std::vector<eng::frame::PassTiming> passes; // median gpu ms per pass
    std::vector<std::vector<double>> passSamples; // every timed frame's ms, per pass
    double frameGpuMs = 0.0;                      // median
    std::vector<std::string> culledPasses;
    std::map<std::string, uint64_t> storageBytes; // the technique's own resources
    double bytesPerPixel = 0.0;
    // The technique's storage split into per-sample / per-aggregate / metadata, and the
    // frame's other transient allocations (outputs, scratch), in bytes per pixel.
    std::map<std::string, double> bytesPerPixelSplit;
    double transientBytesPerPixel = 0.0;
    // Every transient's memory requirement summed (what the frame would take without aliasing),
    // the device memory the aliased blocks take, and the difference, in bytes.
    uint64_t transientBytesRequested = 0;
    uint64_t transientBytesAllocated = 0;
    uint64_t aliasingSavedBytes = 0;
    double shadingEventsMean = 0.0;
    uint32_t shadingEventsMax = 0;
    std::vector<uint64_t> shadingEventsHistogram; // [k] = pixels with k shading events
    // Methods that drop coverage (FrameTargets::lostSamples, SBAA): the share of all n w h samples
    // that were covered but whose surface was not kept, and how many pixels lost any.
    std::optional<double> lostCoverageFraction;
    uint64_t pixelsWithLostCoverage = 0;
    // AGAA with a shading-rate tolerance (FrameTargets::perSampleShaded): the share of the pixels
    // the per-sample pass shaded any sample of, the share of all n w h samples it shaded, and the
    // share of the frame's shading events those pixels took.
    struct PerSampleShading {
        double pixels = 0.0, samples = 0.0, events = 0.0;
    };
    std::optional<PerSampleShading> perSampleShading;
    // Per pixel, the samples the per-sample pass shaded (FrameTargets::perSampleShaded): 0 for a
    // pixel lit by its aggregates alone, all n bits where the pass wrote the whole pixel, else the
    // members of the aggregates the estimate distrusted. Empty without a tolerance.
    std::vector<uint32_t> perSampleMembers;
    uint32_t samples = 0;
    std::string graphDot, graphJson;
    // The shader/pass variants the technique chose from the scene's features, with their causes
    // (agaa/common/effects.h), and the features themselves in one line.
    std::vector<VariantChoice> variants;
    std::string features;
    float exposure = 1.0f;              // the one the frame was rendered at
    std::optional<double> meteredEv100; // autoExposure only
};

class FrameRenderer {
  public:
    FrameRenderer(eng::vk::Device& device, const eng::scene::Scene& scene);
    ~FrameRenderer();
    RenderResult render(const RenderRequest& request);
    eng::vk::Device& device() { return m_device; }
    // The technique a request renders with (created on first use, then cached).
    Technique& technique(const RenderRequest& request);
    const eng::scene::Scene& scene() const { return m_scene; }
    // The exposure `request` renders at: its own, or the metered one when it asks for auto.
    float exposureFor(const RenderRequest& request);

  private:
    float meteredExposure(const eng::frame::ViewSettings& view, double& ev100);

    eng::vk::Device& m_device;
    const eng::scene::Scene& m_scene;
    eng::frame::GpuScene m_gpuScene;
    eng::frame::FrameRunner m_runner;
    eng::vk::Buffer m_frameConstants, m_lights;
    std::map<std::string, std::unique_ptr<Technique>> m_techniques;    // keyed by method and settings
    std::map<std::string, std::pair<float, double>> m_meteredExposure; // keyed by view: exposure, EV100
};

// The median of v (the mean of the middle two for an even count; 0 for none): the per-pass times
// over the timed frames, and agaa-timings' ratios over its rounds.
double median(std::vector<double> v);

} // namespace agaa
