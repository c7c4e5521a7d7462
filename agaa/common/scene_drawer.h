#pragma once
// This project's scene as a client of the raster contract (agaa/common/raster_pass.h): draws an
// eng::frame::GpuScene with this project's material shaders (reference/gbuffer.*, sbaa/prepass.*,
// sbaa/fill*, common/shadow_map.*, agaa/scene.vert, agaa/visibility.frag, agaa/generation*.frag), one
// pipeline per draw variant (its alpha path and sidedness) and pass. Set 1 is the scene's material set
// (shaders/glsl/common/scene_materials.glsl); the push constant is the draw's material, then for the outputs
// with primitive ids its first triangle.
//
// `features` (agaa/common/effects.h): the scene's, which pick the alpha path of masked draws
// (forced effects alpha-test every draw) and the material fetch variants.

#include "agaa/common/effects.h"
#include "agaa/common/program_overrides.h"
#include "agaa/common/raster_pass.h"
#include "agaa/common/scene_traits.h"
#include "engine/frame/gpu_scene.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline_cache.h"

#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

namespace agaa {

class SceneDrawer final : public GeometryDrawer {
  public:
    // `overrides`: builds that run in place of the shipping programs, by their table names
    // (agaa-timings --breakdown's, a test's).
    SceneDrawer(eng::vk::Device& device, const eng::frame::GpuScene& scene,
                const eng::scene::SceneFeatures& features, ProgramOverrides overrides = {});
    ~SceneDrawer() override;
    SceneDrawer(const SceneDrawer&) = delete;
    SceneDrawer& operator=(const SceneDrawer&) = delete;

    void prepare(const RasterPass& pass) override;
    void recordDraws(VkCommandBuffer cmd, const RasterPass& pass,
                     const PushModuleSet& pushModuleSet) const override;
    size_t preparedPasses() const;

  private:
    struct Prepared;
    const Prepared* find(const RasterPass& pass) const;
    VkPipeline makePipeline(const RasterPass& pass, VkPipelineLayout layout,
                            const DrawVariant& variant) const;
    DrawVariant variantOf(const RasterPass& pass, const eng::scene::Material& m) const;
    std::span<const uint32_t> program(const std::string& name) const; // empty name: none

    eng::vk::Device& m_device;
    const eng::frame::GpuScene& m_scene;
    eng::scene::SceneFeatures m_features;
    ProgramOverrides m_overrides;
    mutable std::mutex m_mutex; // prepare may run while another thread records a prepared pass
    std::vector<std::unique_ptr<Prepared>> m_prepared;
};

// The drawer of a pass for content that is our GpuScene; null for a host's content (its frames
// give FrameInputs::geometry).
std::unique_ptr<SceneDrawer> makeSceneDrawer(eng::vk::Device& device, const TechniqueContent& content,
                                             const eng::scene::SceneFeatures& features,
                                             ProgramOverrides overrides = {});

} // namespace agaa
