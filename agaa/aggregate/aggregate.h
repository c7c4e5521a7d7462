#pragma once
// Aggregate G-Buffer Anti-Aliasing (Crassin et al.; DESIGN section 4) as a render-graph node.
// The accumulate generation path (AggregateGeneration::Accumulate):
//   agaa.visibility  n-sample depth + 8-bit face normals (layered 4x emulation above 4)
//   agaa.cluster     Algorithm 1 -> bit-packed metadata + aggregate count per pixel
//   agaa.generation  accumulation kernel: fixed-point integer atomics into c aggregates per pixel
//   agaa.lighting    tiled deferred, aggregates normalised at the top of each tile, each lit once
// The samples path (AggregateGeneration::Samples, the UE4 variant of seed 004):
//   agaa.gbuffer     the per-sample G-buffer (agaa/common/sample_gbuffer.h): the only raster pass
//   agaa.cluster     Algorithm 1 on the G-buffer's depth and shading normal, models kept apart
//   agaa.lighting    each aggregate averaged from its samples at the top of the tile, lit once
//   agaa.lighting.perSample  with a tolerance (--agaa-tolerance): the pixels the lighting pass
//                    flagged, each sample lit and resolved as the reference does
// With --debug aggregates the lighting is replaced by a view of the clustering, and the graph
// culls the generation passes nothing reads any more.

#include "agaa/aggregate/agaa_constants.h"
#include "agaa/common/sample_gbuffer.h"
#include "agaa/common/shadow_map.h"
#include "agaa/common/technique.h"
#include "engine/frame/uniform_ring.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/pipeline_cache.h"
#include "engine/vk/resources.h"

#include <array>
#include <map>
#include <memory>
#include <span>

namespace agaa {

// Handles of the passes' outputs from the last addPasses(), for tests and tools: valid in the
// graph that call recorded into.
struct AggregateResources {
    eng::rg::Texture depth, normal; // per-sample visibility (samples path: the G-buffer's)
    eng::rg::Buffer metadata;
    eng::rg::Texture aggregateCount;
    eng::rg::Buffer agBuffer;       // after generation (accumulate path only)
    eng::rg::Buffer sampleMaterial; // after generation (accumulate path with a tolerance only)
    eng::rg::Buffer agaaConstants;
    SampleGBuffer gbuffer; // samples path only
};

class AggregateAA final : public Technique {
  public:
    AggregateAA(eng::vk::Device& device, const eng::frame::GpuScene& scene,
                const AggregateSettings& settings);
    ~AggregateAA() override;

    std::string name() const override { return "agaa"; }
    uint32_t samples() const override { return m_settings.samples; }
    FrameTargets addPasses(eng::rg::Graph& graph, const FrameInputs& inputs) override;
    bool isStorage(const std::string& resourceName) const override;
    std::string storageCategory(const std::string& resourceName) const override;
    std::vector<VariantChoice> variants() const override;
    const eng::scene::SceneFeatures& features() const { return m_features; }

    const AggregateSettings& settings() const { return m_settings; }
    const AggregateResources& resources() const { return m_resources; }
    // The constants the last addPasses() wrote (into its FrameInputs::frameSlot).
    const shared::AgaaConstants& constants() const { return m_constants; }
    VkFormat depthFormat() const { return m_depthFormat; }

    // The lighting pass's SPIR-V and specialisation for this path, scene and settings: what a
    // test build of the pass must match (tests/support/aggregate_instrumentation.h).
    // The flagged pixels' per-sample shading program for this path, scene and device.
    std::span<const uint32_t> perSampleCode() const;
    std::span<const uint32_t> lightingCode() const;
    eng::vk::Specialization lightingVariant() const;
    // The accumulate path's generation pipeline for a material's sidedness, as this scene and
    // device run it (a test build of the pass draws with the same state).
    eng::vk::GraphicsPipelineDesc generationPipelineDesc(bool doubleSided) const;

  private:
    VkPipeline makeVisibilityPipeline(const DrawVariant& variant);
    VkPipeline makeGenerationPipeline(const DrawVariant& variant); // alpha: the prepass's, not read
    std::span<const uint32_t> generationCode() const;              // this scene's and device's variant
    std::span<const uint32_t> program(const NamedProgram& shipping) const; // or its replacement
    void resolveGeneration(); // Auto -> a path, or MissingCapability for a path the device lacks
    void resolveTolerance();  // kToleranceAuto -> the path's default
    void createLayouts(const eng::frame::GpuScene& scene);
    void release(); // the destructor's work, also for a constructor that throws

    eng::vk::Device& m_device;
    eng::frame::UniformRing m_constantsRing; // shared::AgaaConstants per FrameInputs::frameSlot
    AggregateSettings m_settings;            // every Auto resolved
    AggregateSettings m_requested;           // as the caller asked (the variants say which were automatic)
    const eng::scene::Scene& m_scene;
    eng::scene::SceneFeatures m_features;
    AggregateNdf m_requestedNdf; // m_settings.ndf is the resolved one (never Auto)
    bool m_hasEmissive = false;
    VkFormat m_depthFormat = VK_FORMAT_D32_SFLOAT_S8_UINT;
    shared::AgaaConstants m_constants{};
    eng::vk::PipelineLayout m_visibilityLayout, m_generationLayout, m_clusterLayout, m_lightingLayout,
        m_perSampleLayout, m_debugLayout;
    // The raster passes' pipelines, one per draw variant met, made on first use.
    eng::vk::PipelineCache<DrawVariant> m_visibilityPipelines, m_generationPipelines;
    std::unique_ptr<ShadowMapPass> m_shadow;
    std::unique_ptr<SampleGBufferPass> m_gbuffer; // samples path only
    VkPipeline m_clusterPipeline = VK_NULL_HANDLE, m_lightingPipeline = VK_NULL_HANDLE,
               m_debugPipeline = VK_NULL_HANDLE;
    // The flagged pixels' per-sample shading (agaa/lighting_per_sample.comp), with a tolerance only.
    VkPipeline m_perSamplePipeline = VK_NULL_HANDLE;
    VkSampler m_fetchSampler = VK_NULL_HANDLE;
    AggregateResources m_resources;
    std::string m_generationCause; // why this path (stats variants)
    std::string m_toleranceCause;  // why this shading rate (stats variants)
};

} // namespace agaa
