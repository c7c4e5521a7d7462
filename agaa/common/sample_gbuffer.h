#pragma once
// The per-sample G-buffer raster pass (DESIGN section 5): 16 bytes per sample plus
// 4 bytes depth, at n = 1, 4 natively and 8, 16, 32 by layered 4x emulation. Shared by the
// methods that light a per-sample G-buffer (the reference, no-AA, Simple/Complex, streaming,
// AGAA's samples path), so they all see exactly the same samples; SBAA's visibility prepass is
// its material-free variant (GBufferOptions::visibilityOnly). The draws are the host's
// (FrameInputs::geometry, agaa/common/raster_pass.h) or, without one, the scene's with this
// project's shaders (agaa::SceneDrawer: reference/gbuffer.vert, .frag).

#include "agaa/common/raster_pass.h"
#include "agaa/common/scene_drawer.h"
#include "agaa/common/technique.h"
#include "engine/graph/graph.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/device.h"

#include <array>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace agaa {

struct SampleGBuffer {
    eng::rg::Texture depth;             // D32, reversed Z, 0 = sky
    eng::rg::Texture normal;            // RG16_SNORM octahedral, view space
    eng::rg::Texture albedoMetal;       // RGBA8_UNORM written sRGB-encoded, sampled as RGBA8_SRGB
    eng::rg::Texture emissiveRoughness; // RGBA16F
    eng::rg::Texture primitive;         // R32_SFLOAT triangle number + 1 (GBufferOptions::primitiveIds only)
    eng::rg::Texture
        geometricNormal; // RG8_UNORM octahedral geometric normal (GBufferOptions::visibilityOnly only)
};

// Bindings 2..5 of every compute pass that fetches the per-sample G-buffer (the lighting passes
// of the reference, Simple/Complex, SBAA and streaming, and their surface and export passes):
// depth, normal, albedo + metallic, emissive + roughness, each through `sampler`.
void pushSampleGBuffer(eng::vk::PushDescriptors& pd, const eng::rg::Context& ctx, VkSampler sampler,
                       const SampleGBuffer& g);
// Bindings 6..8 of the same passes (and AGAA's per-sample pass): the lighting's targets, HDR,
// display and shading events, as storage images.
void pushLightingTargets(eng::vk::PushDescriptors& pd, const eng::rg::Context& ctx, eng::rg::Texture hdr,
                         eng::rg::Texture display, eng::rg::Texture events);
// The four images pushSampleGBuffer binds, read by a compute pass (the primitive ids are not).
SampleGBuffer readSampleGBuffer(eng::rg::Builder& b, const SampleGBuffer& g);

// How the fill pass runs. The defaults are the reference's: one material evaluation per pixel
// written to every covered sample, and the material's own roughness.
struct GBufferOptions {
    // Sample-rate shading (VkPhysicalDeviceFeatures::sampleRateShading, minSampleShading 1): every
    // sample runs the material, so textures and normal maps are supersampled too (the UE4 talk's
    // supersampled G-buffer, seed 004). Off: pixel-rate shading with per-sample coverage.
    bool sampleRateShading = false;
    // Geometric specular anti-aliasing (agaa/common/effects.h): a technique passes its
    // EffectSettings::curvatureRoughness.
    CurvatureRoughness curvature;
    // A fourth target with every sample's primitive: the scene-wide triangle number + 1 as an exact
    // float (SBAA's prepass; integer MSAA colour is 1x only on lavapipe). Needs the geometryShader
    // feature (gl_PrimitiveID in a fragment shader) and fewer than 2^24 triangles.
    bool primitiveIds = false;
    // SBAA's visibility prepass (sbaa/prepass.frag): depth, the geometric normal and the primitive id,
    // no material (the targets normal, albedoMetal and emissiveRoughness are not made). Implies
    // primitiveIds; sampleRateShading runs the alpha test per sample.
    bool visibilityOnly = false;
};

class SampleGBufferPass {
  public:
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
    static constexpr VkFormat kNormalFormat = VK_FORMAT_R16G16_SNORM;
    // Albedo is stored sRGB-encoded, but by the shader (common/srgb.glsl): lavapipe's fixed-function
    // encode is not the same on every x86 CPU, so an _SRGB attachment made the goldens differ
    // between machines. Readers sample the image through a view of kAlbedoMetalSampledFormat.
    static constexpr VkFormat kAlbedoMetalFormat = VK_FORMAT_R8G8B8A8_UNORM;
    static constexpr VkFormat kAlbedoMetalSampledFormat = VK_FORMAT_R8G8B8A8_SRGB;
    static constexpr VkFormat kEmissiveRoughnessFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
    static constexpr VkFormat kPrimitiveFormat = VK_FORMAT_R32_SFLOAT;
    static constexpr VkFormat kGeometricNormalFormat = VK_FORMAT_R8G8_UNORM;

    // Throws std::invalid_argument for an unsupported n, MissingCapability without 4x MSAA or,
    // when options.sampleRateShading asks for it, without sampleRateShading.
    // `name` prefixes the pass, its pipelines and its resources ("<name>.gbuffer.*").
    // `features`: the scene's (agaa/common/effects.h); they pick the alpha path of masked draws
    // (alpha-to-coverage at n > 1, discard at 1) and the normal-map / emissive fetch variants.
    SampleGBufferPass(eng::vk::Device& device, const TechniqueContent& content, uint32_t samples,
                      std::string name, const eng::scene::SceneFeatures& features,
                      const GBufferOptions& options = {});
    ~SampleGBufferPass();
    SampleGBufferPass(const SampleGBufferPass&) = delete;
    SampleGBufferPass& operator=(const SampleGBufferPass&) = delete;

    // Adds the "<name>.gbuffer" graphics pass, drawn by inputs.geometry or the scene's drawer.
    SampleGBuffer add(eng::rg::Graph& graph, const FrameInputs& inputs);
    bool isStorage(const std::string& resourceName) const;
    uint32_t samples() const { return m_samples; }
    const GBufferOptions& options() const { return m_options; }
    // What a host's drawer draws (agaa/common/raster_pass.h): output SampleGBuffer (with
    // primitiveIds SampleGBufferPrimitive, visibilityOnly SurfaceVisibility); set 0 binding 0 is
    // shared::FrameConstants; the curvature roughness's specialisation ids 8 to 10.
    const RasterPass& rasterPass() const { return m_raster; }

  private:
    eng::vk::Device& m_device;
    uint32_t m_samples;
    std::string m_name;
    GBufferOptions m_options;
    RasterPass m_raster;
    std::unique_ptr<SceneDrawer> m_sceneDrawer; // the content's GpuScene's, when the host gives no drawer
};

} // namespace agaa
