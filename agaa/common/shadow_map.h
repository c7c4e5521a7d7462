#pragma once
// Shadow maps for the scene's shadowed directional and spot lights (issue 8): one D32 layer
// per light in one array texture, rendered by one graph pass ("<name>.shadow", instanced: draw
// instance l goes to layer l) that techniques add only when the scene has a shadowed light
// (eng::scene::SceneFeatures). Lighting passes read the map and the ShadowConstants buffer and
// include shaders/glsl/common/shadow.glsl.
//
// Fitting (documented in agaa/common/README.md):
//  - directional: orthographic, looking along the light; x/y cover the intersection of the
//    camera frustum's and the scene bounds' boxes in light space, z covers the whole scene
//    bounds (casters outside the view still cast);
//  - spot: perspective from the light, field of view 2 x outer cone, far plane at the range or
//    the farthest scene-bounds corner.

#include "agaa/common/effects.h"
#include "agaa/common/raster_pass.h"
#include "agaa/common/scene_drawer.h"
#include "agaa/common/technique.h"
#include "engine/frame/uniform_ring.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/resources.h"
#include "shared/shadow.h"

#include <array>
#include <memory>
#include <span>
#include <string>

namespace agaa {

struct ShadowMaps {
    eng::rg::Texture map;      // D32 2D array, one layer per shadowed light (at least 2: array view)
    eng::rg::Buffer constants; // shared::ShadowConstants, uniform
};

class ShadowMapPass {
  public:
    static constexpr VkFormat kFormat = VK_FORMAT_D32_SFLOAT;

    ShadowMapPass(eng::vk::Device& device, const TechniqueContent& content,
                  const eng::scene::SceneFeatures& features, const EffectSettings& settings,
                  std::string name);
    ~ShadowMapPass();
    ShadowMapPass(const ShadowMapPass&) = delete;
    ShadowMapPass& operator=(const ShadowMapPass&) = delete;

    bool enabled() const { return m_mapCount > 0; }
    // Adds "<name>.shadow" (only call when enabled()), drawn by inputs.geometry or the scene's
    // drawer. Writes the frame's ShadowConstants into the ring slot inputs.frameSlot
    // (engine/frame/uniform_ring.h for its lifetime). With inputs.shadowMaps: imports the host's
    // maps instead and adds nothing (std::invalid_argument naming what they lack).
    ShadowMaps add(eng::rg::Graph& graph, const FrameInputs& inputs);
    VkSampler sampler() const { return m_sampler; }
    // The maps and their constants read by a lighting pass, and pushed at the bindings its shader
    // gives common/shadow.glsl (SHADOW_MAP_BINDING, SHADOW_CONSTANTS_BINDING).
    static ShadowMaps read(eng::rg::Builder& b, const ShadowMaps& maps);
    void push(eng::vk::PushDescriptors& pd, const eng::rg::Context& ctx, const ShadowMaps& maps,
              uint32_t mapBinding, uint32_t constantsBinding) const;
    const shared::ShadowConstants& constants() const { return m_constants; }
    // What a host's drawer draws (agaa/common/raster_pass.h): output ShadowDepth, one instance per
    // shadowed light, set 0 binding 0 the frame's shared::ShadowConstants.
    const RasterPass& rasterPass() const { return m_raster; }

    // The constants of the module's fit for a frame: one map per light of `lights` (scene light
    // indices, at most kMaxShadowMaps) of `size` texels, seen from the camera `view` (its
    // FrameConstants, or nullptr: the content's default view and its whole bounds). What add()
    // uploads, and what a host drawing its own maps (HostShadowMaps) can use.
    static shared::ShadowConstants makeConstants(const SceneTraits& traits, std::span<const uint32_t> lights,
                                                 uint32_t size, const shared::FrameConstants* view);

    // The light-space fit, exposed for tests: world -> shadow clip (z in [0, 1], 0 near).
    // frame: the camera (its view and proj), to fit a directional map to the visible part of the
    // scene; nullptr fits it to the whole scene bounds.
    static glm::dmat4 fitLight(const eng::scene::Bounds& bounds, const eng::scene::Light& light,
                               const shared::FrameConstants* frame, float* texelMetres);

  private:
    ShadowMaps importHostMaps(eng::rg::Graph& graph, const HostShadowMaps& host) const;
    void release(); // the destructor's work, also for a constructor that throws
    eng::vk::Device& m_device;
    std::string m_name;
    eng::frame::UniformRing m_constantsRing; // shared::ShadowConstants per FrameInputs::frameSlot
    EffectSettings m_settings;
    SceneTraits m_traits;           // the lights and bounds the maps are fitted to
    std::vector<uint32_t> m_lights; // scene light indices, one per layer
    uint32_t m_mapCount = 0;
    RasterPass m_raster;
    std::unique_ptr<SceneDrawer> m_sceneDrawer; // the scene's, when the host gives no drawer
    VkSampler m_sampler = VK_NULL_HANDLE;
    shared::ShadowConstants m_constants{}; // the last add()'s, for tests
};

} // namespace agaa
