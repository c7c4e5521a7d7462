// AggregateAA: the plan resolved once, its passes made for it, and a frame's passes added in order
// (each pass is an object of agaa/aggregate/passes/).

#include "agaa/aggregate/aggregate.h"

#include "agaa/aggregate/passes/accumulation_pass.h"
#include "agaa/aggregate/passes/aggregate_lighting_pass.h"
#include "agaa/aggregate/passes/aggregates_view_pass.h"
#include "agaa/aggregate/passes/cluster_pass.h"
#include "agaa/aggregate/passes/per_sample_pass.h"
#include "agaa/aggregate/passes/visibility_pass.h"
#include "agaa/common/frame_inputs.h"
#include "agaa/common/shadow_map.h"
#include "engine/vk/resources.h"

#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

AggregateAA::AggregateAA(vk::Device& device, const TechniqueContent& content,
                         const AggregateSettings& settings)
    : m_device(device), m_traits(content.traits), m_scene(content.scene),
      m_plan(planAggregate(device, content.traits, settings)),
      m_constantsRing(device, sizeof(shared::AgaaConstants), "agaa.constants"),
      m_fetchSampler{device,
                     vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, 0.0f,
                                       "agaa.fetchSampler")} {
    const AggregateSettings& s = m_plan.settings;
    const VkSampler fetch = m_fetchSampler.sampler;
    if (m_plan.samplesPath())
        m_gbuffer =
            std::make_unique<SampleGBufferPass>(device, content, s.samples, "agaa", m_plan.features,
                                                GBufferOptions{.sampleRateShading = s.sampleRateShading,
                                                               .curvature = s.effects.curvatureRoughness});
    else
        m_visibility = std::make_unique<VisibilityPass>(device, content, m_plan);
    m_cluster = std::make_unique<ClusterPass>(device, m_plan, fetch);
    m_shadow = std::make_unique<ShadowMapPass>(device, content, m_plan.features, s.effects, "agaa");
    if (s.debugView == AggregateDebugView::Aggregates)
        m_aggregatesView = std::make_unique<AggregatesViewPass>(device, m_plan, fetch);
    if (!m_plan.samplesPath()) m_accumulation = std::make_unique<AccumulationPass>(device, content, m_plan);
    m_lighting = std::make_unique<AggregateLightingPass>(device, m_plan, *m_shadow, fetch);
    if (m_plan.shadingRate())
        m_perSample = std::make_unique<PerSampleShadingPass>(device, m_plan, *m_shadow, fetch);
}

AggregateAA::~AggregateAA() {
    vkDeviceWaitIdle(m_device.device()); // the passes' pipelines may still be in flight
}

AggregateAA::Sampler::~Sampler() {
    vkDestroySampler(device.device(), sampler, nullptr);
}

FrameTargets AggregateAA::addPasses(rg::Graph& graph, const FrameInputs& in) {
    checkFrameInputs(in);
    m_constants = makeAgaaConstants(m_plan.settings, *in.constants, m_plan.emissive());
    // Per frame slot, so views and frames recorded before any executes keep their own (issue 18).
    AggregateFrame frame{
        in, m_plan, m_constantsRing.write(graph, in.frameSlot, std::as_bytes(std::span(&m_constants, 1))),
        frameEnvironment(in, m_scene, "agaa")};
    if (m_gbuffer) {
        frame.gbuffer = m_gbuffer->add(graph, in);
        frame.depth = frame.gbuffer.depth;
        frame.normal = frame.gbuffer.normal;
    } else {
        m_visibility->add(graph, frame);
    }
    m_cluster->add(graph, frame);
    // Added whenever the scene has a shadowed light: the aggregates view does not read the maps,
    // and the graph culls the pass.
    if (m_shadow->enabled()) frame.shadow = m_shadow->add(graph, in);
    m_resources = {frame.depth, frame.normal, frame.clusters.metadata, frame.clusters.count,
                   {},          {},           frame.constants,         frame.gbuffer};
    if (m_aggregatesView) return m_aggregatesView->add(graph, frame);

    if (m_accumulation) {
        m_accumulation->add(graph, frame);
        m_resources.depth = frame.depth;
        m_resources.agBuffer = frame.accumulation.agBuffer;
        if (m_plan.shadingRate()) m_resources.sampleMaterial = frame.accumulation.sampleMaterial;
    }
    const LitAggregates lit = m_lighting->add(graph, frame);
    if (!m_perSample) return {lit.hdr, lit.display, lit.events, {}, frame.depth, {}};
    return m_perSample->add(graph, frame, lit);
}

std::span<const uint32_t> AggregateAA::lightingCode() const {
    return m_lighting->code();
}

vk::Specialization AggregateAA::lightingVariant() const {
    return m_lighting->variant();
}

const RasterPass& AggregateAA::generationRasterPass() const {
    if (!m_accumulation)
        throw std::logic_error("agaa: generationRasterPass() on the samples path (no generation)");
    return m_accumulation->rasterPass();
}

std::vector<VariantChoice> AggregateAA::variants() const {
    return planVariants(m_plan, m_traits, m_device.caps());
}

bool AggregateAA::isStorage(const std::string& name) const {
    return storageCategory(name) != "transient";
}

std::string AggregateAA::storageCategory(const std::string& name) const {
    auto starts = [&](const char* prefix) { return name.rfind(prefix, 0) == 0; };
    // The samples path keeps the whole per-sample G-buffer (20 bytes per sample): it is storage.
    // So is the accumulate path's per-sample material with a tolerance (12 bytes per sample).
    if (starts("agaa.visibility.") || starts("agaa.emissive") || starts("agaa.gbuffer.") ||
        starts("agaa.sampleMaterial"))
        return "per-sample";
    if (starts("agaa.agBuffer")) return "per-aggregate";
    if (starts("agaa.metadata") || starts("agaa.aggregateCount")) return "metadata";
    return "transient";
}

} // namespace agaa
