#pragma once
// Runs benchmark jobs on one device: renders the method (warm-up, then timed
// frames), measures its error against the two ground truths and its temporal
// stability along a short orbit, writes its images, and returns the numbers.
// Truths are rendered once per scene and cached; a scene's renderer lives
// until the next scene starts, so a sweep ordered by scene uploads each once.

#include "image_error.h"
#include "result_io.h"
#include "sweep_plan.h"

#include "engine/scene/scene.h"
#include "engine/vk/device.h"
#include "tools/harness/frame_renderer.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace agaa::bench {

class JobRunner {
  public:
    JobRunner(eng::vk::Device& device, const SweepSettings& settings, std::filesystem::path outDir);
    ~JobRunner();

    // Throws eng::vk::MissingCapability when the device lacks what the method needs.
    JobResult run(const Job& job);

    // Validation errors seen while rendering truths (a job's own count excludes them).
    uint32_t truthValidationErrors() const { return m_truthValidationErrors; }

  private:
    struct SceneState {
        std::string name;
        std::unique_ptr<eng::scene::Scene> scene;
        std::unique_ptr<FrameRenderer> renderer;
        std::map<uint32_t, eng::io::ImageF> truthAtSamples; // reference display, sRGB-encoded, sweep size
        std::vector<eng::io::ImageF> pathTruth;             // high-rate truth along the orbit, temporal size
        std::string truthImage;                             // relative path of the high-rate truth PNG
        std::optional<eng::io::ImageF> supersampledTruth;   // the high-rate truth at sample rate
    };

    void selectScene(const std::string& name);
    RenderRequest request(const std::string& method, uint32_t samples, uint32_t aggregates, uint32_t width,
                          uint32_t height, float orbitDegrees, uint32_t surfaces = 0) const;
    const eng::io::ImageF& truth(uint32_t samples);
    const eng::io::ImageF* supersampledTruth(); // nullptr where it is not measured
    const std::vector<eng::io::ImageF>& pathTruth();
    std::vector<eng::io::ImageF> renderPath(const std::string& method, uint32_t samples, uint32_t aggregates,
                                            uint32_t surfaces);
    RenderResult renderTruth(const RenderRequest& request);

    eng::vk::Device& m_device;
    SweepSettings m_settings;
    std::filesystem::path m_outDir;
    SceneState m_scene;
    uint32_t m_truthValidationErrors = 0;
};

} // namespace agaa::bench
