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
//   agaa.lighting.perSample  with a tolerance (--agaa-tolerance): the samples of the aggregates the
//                    lighting pass distrusted, each lit and resolved as the reference does
// With --debug aggregates the lighting is replaced by a view of the clustering, and the graph
// culls the generation passes nothing reads any more.

#include "agaa/aggregate/aggregate_plan.h"
#include "agaa/common/sample_gbuffer.h"
#include "agaa/common/technique.h"
#include "engine/frame/uniform_ring.h"
#include "engine/vk/device.h"
#include "engine/vk/pipeline.h"

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

// Its passes (agaa/aggregate/passes/, not installed), one object each.
class AccumulationPass;
class AggregateLightingPass;
class AggregatesViewPass;
class ClusterPass;
class PerSampleShadingPass;
class ShadowMapPass;
class VisibilityPass;

class AggregateAA final : public Technique {
  public:
    AggregateAA(eng::vk::Device& device, const TechniqueContent& content, const AggregateSettings& settings);
    ~AggregateAA() override;

    std::string name() const override { return "agaa"; }
    uint32_t samples() const override { return m_plan.settings.samples; }
    FrameTargets addPasses(eng::rg::Graph& graph, const FrameInputs& inputs) override;
    bool isStorage(const std::string& resourceName) const override;
    std::string storageCategory(const std::string& resourceName) const override;
    std::vector<VariantChoice> variants() const override;
    const eng::scene::SceneFeatures& features() const { return m_plan.features; }

    const AggregatePlan& plan() const { return m_plan; }
    // The GpuScene it was created with; null for a host's content (TechniqueContent).
    const eng::frame::GpuScene* scene() const { return m_scene; }
    const AggregateSettings& settings() const { return m_plan.settings; }
    const AggregateResources& resources() const { return m_resources; }
    // The constants the last addPasses() wrote (into its FrameInputs::frameSlot).
    const shared::AgaaConstants& constants() const { return m_constants; }
    VkFormat depthFormat() const { return m_plan.depthFormat; }

    // The lighting pass's SPIR-V and specialisation for this path, scene and settings: what a
    // test build of the pass must match (tests/support/aggregate_instrumentation.h).
    std::span<const uint32_t> lightingCode() const;
    eng::vk::Specialization lightingVariant() const;
    // The accumulate path's generation pass as a drawer draws it (agaa/common/raster_pass.h; a
    // test build of the pass draws with the same state; accumulate path only).
    const RasterPass& generationRasterPass() const;

  private:
    eng::vk::Device& m_device;
    const SceneTraits m_traits;
    const eng::frame::GpuScene* m_scene; // null for a host's content
    const AggregatePlan m_plan;
    eng::frame::UniformRing m_constantsRing; // shared::AgaaConstants per FrameInputs::frameSlot
    shared::AgaaConstants m_constants{};
    AggregateResources m_resources;
    struct Sampler {
        eng::vk::Device& device;
        VkSampler sampler;
        ~Sampler();
    };
    Sampler m_fetchSampler; // nearest, clamped: every compute pass's texel fetches
    // The passes, in the order a frame adds them; a path's passes only.
    std::unique_ptr<SampleGBufferPass> m_gbuffer; // samples path
    std::unique_ptr<VisibilityPass> m_visibility; // accumulate path
    std::unique_ptr<ClusterPass> m_cluster;
    std::unique_ptr<ShadowMapPass> m_shadow;
    std::unique_ptr<AggregatesViewPass> m_aggregatesView; // --debug aggregates
    std::unique_ptr<AccumulationPass> m_accumulation;     // accumulate path
    std::unique_ptr<AggregateLightingPass> m_lighting;
    std::unique_ptr<PerSampleShadingPass> m_perSample; // with a tolerance
};

} // namespace agaa
