#pragma once
// Runs benchmark jobs on one device: renders the method (warm-up, then timed
// frames), measures its error against the converged truth (and, as the shading
// error at fixed visibility, against the reference at the same n) and its
// temporal stability along a short orbit, writes its images, and returns the
// numbers. Truths are rendered once per scene and kept in memory and in the
// disk cache; a scene's renderer lives until the next scene starts, so a sweep
// ordered by scene uploads each once.

#include "image_error.h"
#include "result_io.h"
#include "sweep_plan.h"

#include "engine/scene/scene.h"
#include "engine/vk/device.h"
#include "tools/harness/converged_truth.h"
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
        std::map<uint32_t, eng::io::ImageF> referenceAtSamples; // display, sRGB-encoded, sweep size
        std::optional<ConvergedTruth> truth;                    // at the sweep size
        eng::io::ImageF truthDisplay;                           // its display, sRGB-encoded
        std::vector<eng::io::ImageF> pathTruth; // converged truth along the orbit, sRGB, temporal size
        std::string truthImage;                 // relative path of the truth PNG
        // Per path frame, the pixels its predecessor did not see (disocclusion.h); frame 0's empty.
        std::vector<std::vector<uint8_t>> pathDisocclusion;
    };

    void selectScene(const std::string& name);
    // The job's frame: its method with the sweep's given settings, then its axes; pathFrame > 0 is
    // that frame of the camera path (SweepSettings::temporalPath), 0 the scene's camera.
    RenderRequest request(const Job& job, uint32_t width, uint32_t height, uint32_t pathFrame) const;
    const eng::io::ImageF& referenceAtSamples(uint32_t samples);
    const ConvergedTruth& truth();
    const std::vector<eng::io::ImageF>& pathTruth();
    const std::vector<std::vector<uint8_t>>& pathDisocclusion();
    std::vector<eng::io::ImageF> renderPath(const Job& job);
    RenderResult renderTruth(const RenderRequest& request);
    ConvergedTruth renderConverged(const RenderRequest& request);

    eng::vk::Device& m_device;
    SweepSettings m_settings;
    std::filesystem::path m_outDir;
    SceneState m_scene;
    uint32_t m_truthValidationErrors = 0;
    TruthCache m_truthCache;
};

} // namespace agaa::bench
