#pragma once
// Streaming G-buffer compression (Kerzner and Salvi 2014, seed 001; DESIGN section 5): at most
// S = 3 depth-sorted surfaces per pixel, fragments merged in primitive order by the three-part
// test (disjoint coverage, overlapping depth ranges zView +- (|dz/dx| + |dz/dy|), normals within
// alpha), a 4th surface resolved by dropping a fully covered one behind the others or else the one
// with the fewest depth-tested samples; each surface lit once, weighted by its depth-tested
// coverage, the sky taking the rest. FrameTargets::lostSamples reports what dropped surfaces
// leave to the sky.
//
// Primitive order without fragment-shader interlock (lavapipe has none): the paper's single pass
// needs a per-pixel critical section. Here "streaming.gbuffer" records each pixel's fragments as
// fixed per-pixel slots (the per-sample G-buffer with primitive ids: n slots, one per visible
// sample, so it cannot overflow; hidden fragments are not recorded, as behind a depth prepass) and
// "streaming.compress" replays them per pixel in primitive order through the streaming algorithm.
// The single-pass version with VK_EXT_fragment_shader_interlock is not built: lavapipe lacks the
// extension, so it could not be tested here.
//
// The normal threshold: the paper's alpha = pi/4 (45 degrees) by default; the authors' public
// code uses 0.78539816 directly as the cosine (about 38.2 degrees): set normalAngleDegrees to
// 38.2 (--streaming-normal-angle) to reproduce it.

#include "agaa/common/sample_gbuffer.h"
#include "agaa/common/shadow_map.h"
#include "agaa/common/technique.h"
#include "agaa/streaming/streaming_compression.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"

namespace agaa {

struct StreamingSettings {
    uint32_t samples = 8;                                           // n: 4, 8, 16, 32
    uint32_t surfaces = 3;                                          // S: 1..3 (the paper: three look right)
    float normalAngleDegrees = kStreamingDefaultNormalAngleDegrees; // alpha, (0, 90]
    EffectSettings effects;         // scene-driven shadows, alpha-to-coverage, emissive, normal maps
    bool sampleRateShading = false; // the prepass fill at sample rate (agaa/common/sample_gbuffer.h)
};

class StreamingCompression final : public Technique {
  public:
    // Throws std::invalid_argument for n below 4, S outside 1..3 or an angle outside (0, 90]
    // (naming the setting), MissingCapability without 4x MSAA or gl_PrimitiveID in fragment shaders.
    StreamingCompression(eng::vk::Device& device, const TechniqueContent& content,
                         const StreamingSettings& settings);
    ~StreamingCompression() override;

    std::string name() const override { return "streaming"; }
    uint32_t samples() const override { return m_settings.samples; }
    FrameTargets addPasses(eng::rg::Graph& graph, const FrameInputs& inputs) override;
    bool isStorage(const std::string& resourceName) const override;
    std::string storageCategory(const std::string& resourceName) const override;
    std::vector<VariantChoice> variants() const override;
    const StreamingSettings& settings() const { return m_settings; }

    // The passes one by one, for tests: the fragment recording, the compression (writes
    // `surfaces`, the compressed G-buffer, and `lostSamples`), the lighting.
    SampleGBuffer addFragments(eng::rg::Graph& graph, const FrameInputs& inputs) {
        return m_gbuffer.add(graph, inputs);
    }
    struct Surfaces {
        eng::rg::Buffer surfaces;     // kStreamingSurfaceWords uint per surface, S per pixel
        eng::rg::Texture lostSamples; // R32_UINT
    };
    Surfaces addCompression(eng::rg::Graph& graph, const FrameInputs& inputs, const SampleGBuffer& fragments);
    FrameTargets addLighting(eng::rg::Graph& graph, const FrameInputs& inputs, const SampleGBuffer& fragments,
                             const Surfaces& surfaces);

  private:
    eng::vk::Device& m_device;
    StreamingSettings m_settings;
    const SceneTraits m_traits;
    const eng::frame::GpuScene* m_scene;  // null for a host's content
    eng::scene::SceneFeatures m_features; // before the passes built from it
    SampleGBufferPass m_gbuffer;
    ShadowMapPass m_shadow;
    eng::vk::PipelineLayout m_compressLayout, m_lightingLayout;
    VkPipeline m_compressPipeline = VK_NULL_HANDLE, m_lightingPipeline = VK_NULL_HANDLE;
    VkSampler m_fetchSampler = VK_NULL_HANDLE;
};

} // namespace agaa
