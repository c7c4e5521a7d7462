#pragma once
// The scene-driven effects every technique shares (issue 8): which of shadows, alpha-to-
// coverage, emissive, normal maps and tile light culling a frame simulates, derived from the
// scene (engine/scene/scene_features.h) or forced on for the benchmark, and how each choice is
// reported: a VariantChoice names the variant and the scene feature that caused it.

#include "agaa/common/named_value.h"
#include "agaa/common/scene_traits.h"
#include "engine/frame/gpu_environment.h"
#include "engine/scene/scene_features.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "shared/specialization.h"

#include <cstdint>
#include <string>
#include <vector>

namespace agaa {

// Geometric specular anti-aliasing (Kaplanyan et al. 2016; Tokuyoshi and Kaplanyan 2019), an
// option of every method's material evaluation: GGX's alpha^2 is widened by the screen-space
// variance of the geometric normal, clamped (common/curvature_roughness.glsl; the form is
// Tokuyoshi and Kaplanyan's kernel min(2 sigma^2 (|dN/dx|^2 + |dN/dy|^2), kappa), sigma^2 = 1/4).
// The converged truth never applies it: it is what the filter approximates.
struct CurvatureRoughness {
    bool enabled = false;
    // kappa, GGX alpha^2 units, 0..1: the UE4 AGAA talk's AgaaKaplanyanRoughnessMaxFootprint (seed
    // 004); Tokuyoshi and Kaplanyan (2019) suggest 0.18.
    float maxFootprint = 0.3f;
    float boost = 2.0f; // AgaaKaplanyanRoughnessBoost: Tokuyoshi and Kaplanyan's factor 2, >= 0
};

struct EffectSettings {
    bool forceAll = false;         // every effect on, whatever the scene holds (benchmark baseline)
    uint32_t shadowMapSize = 1024; // texels per side of each shadow map, 64..4096
    // AGAA: taps inside the aggregate's footprint (paper section 3.5.3), 1..8. The per-sample
    // methods take one tap per shading event (their samples are points).
    uint32_t shadowTaps = 4;
    // AGAA: where the taps go. Statistics: along the aggregate's variance vector from its mean
    // position and depth variance (paper section 3.5.3). Samples: at up to shadowTaps of the
    // aggregate's own sample positions (the paper's "more precise filtering"). Adaptive: the
    // statistical taps, and where they disagree (a shadow edge crosses the aggregate) a tap at
    // every one of the aggregate's samples; the default (issue 14, goal P8).
    enum class ShadowFootprint : uint32_t {
        Statistics = 0,
        Samples = 1,
        Adaptive = 2
    } shadowFootprint = ShadowFootprint::Adaptive;
    CurvatureRoughness curvatureRoughness; // --curvature-roughness: every method's G-buffer or kernel
};
inline constexpr NamedValue<EffectSettings::ShadowFootprint> kShadowFootprintNames[] = {
    {"adaptive", EffectSettings::ShadowFootprint::Adaptive},
    {"statistics", EffectSettings::ShadowFootprint::Statistics},
    {"samples", EffectSettings::ShadowFootprint::Samples}};

// Throws std::invalid_argument naming the setting and its range.
void validate(const EffectSettings& settings);

// The curvature roughness's specialisation constants (ids kSpecFillCurvature*, shaders/glsl/shared/
// specialization.h) for a raster pass whose material evaluation takes it
// (raster/sample_gbuffer_output.glsl's sampleGBufferRoughness).
std::vector<std::pair<uint32_t, uint32_t>> curvatureSpecialization(const CurvatureRoughness& c);

struct VariantChoice {
    std::string effect;  // "shadows", "alpha", "emissive", "normal-maps", "light-culling"
    std::string variant; // what runs, e.g. "alpha-to-coverage", "off"
    std::string cause;   // the scene feature behind it, e.g. "2 masked materials"
};

// The content's features, or every effect forced on (EffectSettings::forceAll).
eng::scene::SceneFeatures effectiveFeatures(const SceneTraits& traits, const EffectSettings& settings);

// The choices the shared effects make for a technique rasterising `samples` per pixel;
// `prefix` names the technique's passes ("reference", "agaa"). shadowTaps: taps per shading
// event of this technique.
std::vector<VariantChoice> effectVariants(const eng::scene::SceneFeatures& features,
                                          const SceneTraits& traits, uint32_t samples, uint32_t shadowTaps);

// Specialisation-constant ids shared by every shader that reads a scene effect: named once, for
// GLSL and C++ alike, in shaders/glsl/shared/specialization.h.
using shared::kSpecEmissive;
using shared::kSpecEnvironment;
using shared::kSpecNormalMaps;
using shared::kSpecShadowFootprint;
using shared::kSpecShadowTaps;
using shared::kSpecTextureTransforms;
using shared::kSpecTileLightCulling;
using shared::kSpecVertexColors;
// Every raster pass that evaluates materials: ids 18 and 19 from the scene's features.
inline void addMaterialSpecialization(eng::vk::Specialization& s, const eng::scene::SceneFeatures& f) {
    s.byId.push_back({kSpecTextureTransforms, f.hasTextureTransforms() ? 1u : 0u});
    s.byId.push_back({kSpecVertexColors, f.vertexColors ? 1u : 0u});
}

// The environment every lighting pass binds (issue 16; engine/frame/environment_maps.h): 15 its
// pre-filtered specular levels (an RGBA16F 2D array, one layer per level; u repeats, v clamps), 16
// its constants (uniform, shared::EnvironmentConstants), 17 the split sum's BRDF table (RG16F,
// clamped). Images in SHADER_READ_ONLY_OPTIMAL for the whole frame. Content without an environment
// binds a 1x1 black array and constants with params.x = 0 (what our GpuScene holds then): lighting
// skips the term by specialisation (kSpecEnvironment), so no pass exists for it.
struct EnvironmentBindings {
    VkSampler sampler = VK_NULL_HANDLE;
    VkImageView prefiltered = VK_NULL_HANDLE;
    VkBuffer constants = VK_NULL_HANDLE;
    VkSampler dfgSampler = VK_NULL_HANDLE;
    VkImageView dfg = VK_NULL_HANDLE;
};
// An environment's (a host's own, or the stand-in of content without one: GpuEnvironment(device,
// nullptr)), and our scene's.
EnvironmentBindings environmentBindings(const eng::frame::GpuEnvironment& environment);
EnvironmentBindings environmentBindings(const eng::frame::GpuScene& scene);

// Every lighting pass: the environment's specialisation (kSpecEnvironment) added to `s`.
eng::vk::Specialization lightingSpecialization(eng::vk::Specialization s,
                                               const eng::scene::SceneFeatures& features);
void pushEnvironment(eng::vk::PushDescriptors& descriptors, const EnvironmentBindings& environment);
// A lighting pass of the per-sample G-buffer (common/gbuffer_lighting.glsl: n, one shadow tap per
// shading event), with the pass's own ids.
eng::vk::Specialization gbufferLightingSpecialization(const eng::scene::SceneFeatures& features,
                                                      uint32_t samples,
                                                      std::vector<std::pair<uint32_t, uint32_t>> own = {});

// Alpha handling of a material in a raster pass (specialisation constant 0 of
// reference/gbuffer.frag and agaa/visibility.frag; common/alpha_coverage.glsl). MASK: discard at
// one sample per pixel, alpha-to-coverage sharpened at the cutoff with MSAA. BLEND (issue 16):
// translucency as coverage, as the paper does (section 3.6): alpha-to-coverage with the alpha
// itself, so a surface of alpha a covers about a of each pixel's samples and the resolve blends
// it with what lies behind; at one sample per pixel an ordered 4x4 dither of the alpha. No sorted
// blending: a stack of translucent layers resolves by coverage, not by over-compositing.
enum class AlphaPath : uint32_t { Opaque = 0, Discard = 1, Coverage = 2, BlendCoverage = 3, BlendDither = 4 };
inline constexpr uint32_t kAlphaPaths = 5;
inline AlphaPath maskedAlphaPath(uint32_t samples) {
    return samples > 1 ? AlphaPath::Coverage : AlphaPath::Discard;
}
inline AlphaPath blendedAlphaPath(uint32_t samples) {
    return samples > 1 ? AlphaPath::BlendCoverage : AlphaPath::BlendDither;
}
// A draw's path: forced effects alpha-test every draw (the benchmark's baseline).
inline AlphaPath materialAlphaPath(const eng::scene::Material& m, bool forced, uint32_t samples) {
    if (m.alphaMode == eng::scene::AlphaMode::Blend) return blendedAlphaPath(samples);
    if (m.alphaMode == eng::scene::AlphaMode::Mask || forced) return maskedAlphaPath(samples);
    return AlphaPath::Opaque;
}
// The variant key of a raster pass that draws the scene's materials (a pass's pipelines come from
// an eng::vk::PipelineCache keyed by it): the draw's alpha path and its sidedness.
struct DrawVariant {
    AlphaPath alpha = AlphaPath::Opaque;
    bool doubleSided = false;
    auto operator<=>(const DrawVariant&) const = default;
};
inline bool usesAlphaToCoverage(AlphaPath p) {
    return p == AlphaPath::Coverage || p == AlphaPath::BlendCoverage;
}
inline const char* alphaPathName(AlphaPath p) {
    return p == AlphaPath::Coverage        ? ".alphaToCoverage"
           : p == AlphaPath::Discard       ? ".discard"
           : p == AlphaPath::BlendCoverage ? ".blendCoverage"
           : p == AlphaPath::BlendDither   ? ".blendDither"
                                           : ".opaque";
}

// The scene's effects by their ids (light culling, normal maps, emissive, shadow taps and
// footprint), to which each pass adds its own by name.
eng::vk::Specialization
effectSpecialization(const eng::scene::SceneFeatures& features, uint32_t shadowTaps,
                     EffectSettings::ShadowFootprint footprint = EffectSettings::ShadowFootprint::Adaptive);

} // namespace agaa
