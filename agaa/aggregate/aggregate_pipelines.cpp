// Pipeline layouts and pipelines of the AGAA passes (agaa/aggregate/aggregate.cpp adds the passes).

#include "agaa/aggregate/aggregate.h"

#include "engine/vk/check.h"
#include "engine/vk/reflection.h"
#include "shaders/agaa/cluster_comp.h"
#include "shaders/agaa/cluster_gbuffer_comp.h"
#include "shaders/agaa/debug_aggregates_comp.h"
#include "shaders/agaa/generation_emissive_frag.h"
#include "shaders/agaa/generation_emissive_int64_frag.h"
#include "shaders/agaa/generation_emissive_int64_subgroup_frag.h"
#include "shaders/agaa/generation_emissive_subgroup_frag.h"
#include "shaders/agaa/generation_frag.h"
#include "shaders/agaa/generation_int64_frag.h"
#include "shaders/agaa/generation_int64_subgroup_frag.h"
#include "shaders/agaa/generation_subgroup_frag.h"
#include "shaders/agaa/lighting_comp.h"
#include "shaders/agaa/lighting_emissive_comp.h"
#include "shaders/agaa/lighting_emissive_shadow_comp.h"
#include "shaders/agaa/lighting_gbuffer_comp.h"
#include "shaders/agaa/lighting_gbuffer_emissive_comp.h"
#include "shaders/agaa/lighting_gbuffer_emissive_shadow_comp.h"
#include "shaders/agaa/lighting_gbuffer_shadow_comp.h"
#include "shaders/agaa/lighting_per_sample_accumulate_comp.h"
#include "shaders/agaa/lighting_per_sample_accumulate_emissive_comp.h"
#include "shaders/agaa/lighting_per_sample_accumulate_emissive_shadow_comp.h"
#include "shaders/agaa/lighting_per_sample_accumulate_shadow_comp.h"
#include "shaders/agaa/lighting_per_sample_comp.h"
#include "shaders/agaa/lighting_per_sample_shadow_comp.h"
#include "shaders/agaa/lighting_shadow_comp.h"
#include "shaders/agaa/scene_vert.h"
#include "shaders/agaa/visibility_frag.h"
#include "shared/shadow.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace agaa {
namespace vk = eng::vk;

namespace {

std::string shortNumber(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v));
    return text;
}

std::string shadowFootprintName(EffectSettings::ShadowFootprint footprint, uint32_t samples, uint32_t taps) {
    switch (footprint) {
    case EffectSettings::ShadowFootprint::Statistics:
        return " along the aggregate's depth-variance vector";
    case EffectSettings::ShadowFootprint::Samples:
        return " at the aggregate's sample positions";
    case EffectSettings::ShadowFootprint::Adaptive:
        break;
    }
    // agaa/lighting/shadowed_lights.glsl shadowVisibilityFootprint: the test's taps against n.
    const uint32_t testTaps = shared::kAdaptiveCornerTaps + taps;
    if (samples <= testTaps)
        return ", none of them used at n = " + std::to_string(samples) +
               ": adaptive taps every one of the aggregate's samples, no more than its penumbra test's " +
               std::to_string(testTaps);
    return " along the aggregate's depth-variance vector and at its footprint's corners, at every sample "
           "where they disagree";
}

// AGAA's programs by their names in the shader table (shaders/CMakeLists.txt): the names
// AggregateSettings::programs replaces them by.
const NamedProgram kVisibilityProgram{"agaa/visibility.frag", kAgaaVisibilityFrag};
const NamedProgram kClusterPrograms[2] = {{"agaa/cluster.comp", kAgaaClusterComp},
                                          {"agaa/cluster_gbuffer.comp", kAgaaClusterGbufferComp}};
// [emissive][int64][subgroup]
const NamedProgram kGenerationPrograms[2][2][2] = {
    {{{"agaa/generation.frag", kAgaaGenerationFrag},
      {"agaa/generation_subgroup.frag", kAgaaGenerationSubgroupFrag}},
     {{"agaa/generation_int64.frag", kAgaaGenerationInt64Frag},
      {"agaa/generation_int64_subgroup.frag", kAgaaGenerationInt64SubgroupFrag}}},
    {{{"agaa/generation_emissive.frag", kAgaaGenerationEmissiveFrag},
      {"agaa/generation_emissive_subgroup.frag", kAgaaGenerationEmissiveSubgroupFrag}},
     {{"agaa/generation_emissive_int64.frag", kAgaaGenerationEmissiveInt64Frag},
      {"agaa/generation_emissive_int64_subgroup.frag", kAgaaGenerationEmissiveInt64SubgroupFrag}}}};
// [gbuffer][emissive][shadows]
const NamedProgram kLightingPrograms[2][2][2] = {
    {{{"agaa/lighting.comp", kAgaaLightingComp}, {"agaa/lighting_shadow.comp", kAgaaLightingShadowComp}},
     {{"agaa/lighting_emissive.comp", kAgaaLightingEmissiveComp},
      {"agaa/lighting_emissive_shadow.comp", kAgaaLightingEmissiveShadowComp}}},
    {{{"agaa/lighting_gbuffer.comp", kAgaaLightingGbufferComp},
      {"agaa/lighting_gbuffer_shadow.comp", kAgaaLightingGbufferShadowComp}},
     {{"agaa/lighting_gbuffer_emissive.comp", kAgaaLightingGbufferEmissiveComp},
      {"agaa/lighting_gbuffer_emissive_shadow.comp", kAgaaLightingGbufferEmissiveShadowComp}}}};
// [path][emissive][shadows]: the flagged pixels' per-sample shading (--agaa-tolerance), path 0 the
// samples path's G-buffer (whose emissive it holds), 1 the accumulate path's per-sample material.
const NamedProgram kPerSamplePrograms[2][2][2] = {
    {{{"agaa/lighting_per_sample.comp", kAgaaLightingPerSampleComp},
      {"agaa/lighting_per_sample_shadow.comp", kAgaaLightingPerSampleShadowComp}},
     {{"agaa/lighting_per_sample.comp", kAgaaLightingPerSampleComp},
      {"agaa/lighting_per_sample_shadow.comp", kAgaaLightingPerSampleShadowComp}}},
    {{{"agaa/lighting_per_sample_accumulate.comp", kAgaaLightingPerSampleAccumulateComp},
      {"agaa/lighting_per_sample_accumulate_shadow.comp", kAgaaLightingPerSampleAccumulateShadowComp}},
     {{"agaa/lighting_per_sample_accumulate_emissive.comp", kAgaaLightingPerSampleAccumulateEmissiveComp},
      {"agaa/lighting_per_sample_accumulate_emissive_shadow.comp",
       kAgaaLightingPerSampleAccumulateEmissiveShadowComp}}}};
const NamedProgram kDebugProgram{"agaa/debug_aggregates.comp", kAgaaDebugAggregatesComp};

// Refuses a replacement for a program AGAA does not run, by name (a misspelt name would
// otherwise replace nothing and time the shipping build).
void checkProgramOverrides(const ProgramOverrides& overrides) {
    std::vector<std::string_view> known = {kVisibilityProgram.name, kClusterPrograms[0].name,
                                           kClusterPrograms[1].name, kDebugProgram.name};
    for (const auto& table : {kGenerationPrograms, kLightingPrograms, kPerSamplePrograms})
        for (int i = 0; i < 8; ++i)
            known.push_back(table[i / 4][i / 2 % 2][i % 2].name);
    for (const auto& [name, code] : overrides) {
        if (std::find(known.begin(), known.end(), name) != known.end()) continue;
        std::string list;
        for (std::string_view k : known)
            list += (list.empty() ? "" : ", ") + std::string(k);
        throw std::invalid_argument("agaa: a replacement for program '" + name +
                                    "', which AGAA does not run (its programs: " + list + ")");
    }
}
} // namespace

AggregateAA::AggregateAA(vk::Device& device, const eng::frame::GpuScene& scene,
                         const AggregateSettings& settings)
    : m_device(device), m_constantsRing(device, sizeof(shared::AgaaConstants), "agaa.constants"),
      m_settings(settings), m_requested(settings), m_scene(scene.scene()),
      m_features(effectiveFeatures(scene.scene(), settings.effects)), m_requestedNdf(settings.ndf),
      m_hasEmissive(m_features.hasEmissive()),
      m_visibilityPipelines(device, [this](const DrawVariant& v) { return makeVisibilityPipeline(v); }),
      m_generationPipelines(device, [this](const DrawVariant& v) { return makeGenerationPipeline(v); }) {
    validate(settings);
    checkProgramOverrides(settings.programs);
    if (m_settings.ndf == AggregateNdf::Auto)
        m_settings.ndf = m_features.anisotropicMetalsDominate() ? AggregateNdf::Sggx : AggregateNdf::Toksvig;
    m_shadow = std::make_unique<ShadowMapPass>(device, scene, m_features, settings.effects, "agaa");
    const vk::Capabilities& caps = device.caps();
    if (!caps.supportsSamples(4))
        throw vk::MissingCapability(caps.deviceName +
                                    " lacks 4x MSAA (AGAA rasterises n >= 4 samples as 4x layers)");
    resolveGeneration();
    resolveTolerance();
    const bool samplesPath = m_settings.generation == AggregateGeneration::Samples;
    if (!samplesPath && !caps.postDepthCoverage)
        throw vk::MissingCapability(caps.deviceName +
                                    " lacks VK_EXT_post_depth_coverage (the accumulation kernel needs the "
                                    "post-depth-test sample mask; allowed here: --agaa-generation samples)");
    // The visibility depth has the reference's precision: D32_SFLOAT with stencil where offered at
    // 4x (issue 14: with D24_UNORM, reversed Z gained nothing, visibility differences against the
    // reference's D32 counted as AGAA's error, and a fragment whose depth rounded to 0 near the far
    // plane was sky in the prepass but passed EQUAL in generation). D24S8 only as a fallback
    // (reported in the variants). The samples path uses the G-buffer's D32 depth.
    const VkImageUsageFlags depthUsage =
        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    if (samplesPath)
        m_depthFormat = SampleGBufferPass::kDepthFormat;
    else if (vk::supportsImage(device, VK_FORMAT_D32_SFLOAT_S8_UINT, depthUsage, VK_SAMPLE_COUNT_4_BIT))
        m_depthFormat = VK_FORMAT_D32_SFLOAT_S8_UINT;
    else if (vk::supportsImage(device, VK_FORMAT_D24_UNORM_S8_UINT, depthUsage, VK_SAMPLE_COUNT_4_BIT))
        m_depthFormat = VK_FORMAT_D24_UNORM_S8_UINT;
    else
        throw vk::MissingCapability(caps.deviceName +
                                    " offers no 4x sampled depth-stencil format (D32S8 or D24S8)");

    // Generation atomics and their subgroup pre-reduction: what the device offers, or what was asked.
    const bool fragmentSubgroups =
        (caps.subgroupStages & VK_SHADER_STAGE_FRAGMENT_BIT) != 0 &&
        (caps.subgroupOperations & (VK_SUBGROUP_FEATURE_BALLOT_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT)) ==
            (VK_SUBGROUP_FEATURE_BALLOT_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT);
    if (m_settings.atomics == AggregateAtomics::Bits64 && !caps.bufferInt64Atomics)
        throw vk::MissingCapability(
            caps.deviceName + " lacks shaderBufferInt64Atomics (--agaa-atomics 64; allowed here: 32, auto)");
    if (m_settings.atomics == AggregateAtomics::Auto)
        m_settings.atomics = caps.bufferInt64Atomics ? AggregateAtomics::Bits64 : AggregateAtomics::Bits32;
    if (m_settings.subgroupReduction == SubgroupReduction::On && !fragmentSubgroups)
        throw vk::MissingCapability(
            caps.deviceName +
            " lacks fragment-stage subgroup ballot and arithmetic (--agaa-subgroup-reduce on; "
            "allowed here: off, auto)");
    if (m_settings.subgroupReduction == SubgroupReduction::Auto)
        m_settings.subgroupReduction = fragmentSubgroups && caps.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU
                                           ? SubgroupReduction::On
                                           : SubgroupReduction::Off;
    // Rule (docs/decisions/lighting-schedule.md): one aggregate per pixel has nothing to
    // compact; from c = 2 the list pays on lavapipe too (its SIMD groups of 8 otherwise shade a
    // second aggregate wherever one lane has one), and a GPU's wider waves gain more.
    if (m_settings.shading == AggregateShading::Auto)
        m_settings.shading =
            m_settings.aggregates >= 2 ? AggregateShading::Compact : AggregateShading::Registers;

    // A later step that throws (out of memory) takes what was made before it along.
    try {
        m_fetchSampler = vk::createSampler(device, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                                           0.0f, "agaa.fetchSampler");
        if (samplesPath)
            m_gbuffer = std::make_unique<SampleGBufferPass>(
                device, scene, settings.samples, "agaa", m_features,
                GBufferOptions{settings.sampleRateShading, settings.curvatureRoughness,
                               settings.curvatureMaxFootprint, settings.curvatureBoost});
        createLayouts(scene);

        m_clusterPipeline = vk::createComputePipeline(
            device, program(kClusterPrograms[samplesPath ? 1 : 0]), m_clusterLayout.layout,
            {{},
             {{shared::kSpecClusterSamples, settings.samples},
              {shared::kSpecClusterAggregates, settings.aggregates},
              {shared::kSpecClusterDistance, uint32_t(settings.distance)}}},
            "agaa.cluster");
        m_lightingPipeline = vk::createComputePipeline(device, lightingCode(), m_lightingLayout.layout,
                                                       lightingVariant(), "agaa.lighting");
        m_debugPipeline = vk::createComputePipeline(device, program(kDebugProgram), m_debugLayout.layout, {},
                                                    "agaa.debug.aggregates");
        if (m_settings.tolerance >= 0.0f)
            m_perSamplePipeline = vk::createComputePipeline(
                device, perSampleCode(), m_perSampleLayout.layout,
                gbufferLightingSpecialization(
                    m_features, m_settings.samples,
                    {{shared::kSpecPerSampleShadingRateView,
                      m_settings.debugView == AggregateDebugView::ShadingRate ? 1u : 0u}}),
                "agaa.lighting.perSample");
    } catch (...) {
        release();
        throw;
    }
}

void AggregateAA::resolveGeneration() {
    const vk::Capabilities& caps = m_device.caps();
    if (m_settings.generation == AggregateGeneration::Coverage) {
        std::string missing;
        if (!caps.mixedSamples)
            missing = "mixed attachment samples (VK_NV_framebuffer_mixed_samples or "
                      "VK_AMD_mixed_attachment_samples)";
        if (!caps.coverageOverride)
            missing += (missing.empty() ? "" : " and ") + std::string("VK_NV_sample_mask_override_coverage");
        if (!missing.empty())
            throw vk::MissingCapability(
                caps.deviceName + " lacks " + missing +
                " (--agaa-generation coverage; allowed here: accumulate, samples, auto)");
        throw vk::MissingCapability(
            "--agaa-generation coverage is not built: " + caps.deviceName +
            " offers mixed samples and the coverage override, but the blend-based route was never run on "
            "such a device (allowed: accumulate, samples, auto)");
    }
    // The per-sample rate shades flagged pixels from their own samples' materials: the samples
    // path's G-buffer, or the per-sample material the accumulation kernel then keeps, written per
    // sample, so every sample must have been routed to its own aggregate.
    const bool perSampleRate = m_settings.tolerance >= 0.0f;
    if (perSampleRate && m_settings.generation == AggregateGeneration::Accumulate &&
        m_settings.routing == AggregateRouting::Fragment)
        throw std::invalid_argument(
            "--agaa-tolerance on the accumulate path needs --agaa-routing samples: whole-fragment routing "
            "mixes aggregates' members, which the shading rate's estimate reads (allowed: --agaa-routing "
            "samples, or --agaa-tolerance never)");
    if (m_settings.generation != AggregateGeneration::Auto) {
        m_generationCause = "setting --agaa-generation";
        return;
    }
    if (perSampleRate) {
        m_settings.generation = AggregateGeneration::Samples;
        m_generationCause = "--agaa-tolerance: flagged pixels are shaded from the per-sample G-buffer";
        return;
    }
    // Rule (agaa/aggregate/README.md, "Generation paths"; agaa-timings at 320x180 and 640x360 on
    // foliage, furball and metal): the samples path rasterises the scene once instead of twice and
    // its frame was faster than the accumulate path's at every n measured on lavapipe (1.1x to
    // 1.6x at n = 8, 16 and 32). What it costs is memory: the whole per-sample G-buffer, 20 n + 5
    // bytes per pixel against about 10 n + 53. Up to n = 16 that is at most 325 B/px (670 MB at
    // 1920x1080); at n = 32 it is 645 B/px, 1.7x the accumulate path's 373, so above
    // kSamplesPathMaxSamples the rule keeps the accumulate path's memory, as the paper's design does.
    constexpr uint32_t kSamplesPathMaxSamples = 16;
    const bool samples = m_settings.samples <= kSamplesPathMaxSamples;
    m_settings.generation = samples ? AggregateGeneration::Samples : AggregateGeneration::Accumulate;
    m_generationCause = "n = " + std::to_string(m_settings.samples) + (samples ? " <= " : " > ") +
                        std::to_string(kSamplesPathMaxSamples) +
                        (samples ? ": one raster pass, per-sample G-buffer memory affordable"
                                 : ": the per-sample G-buffer would be 1.7x the accumulate path's memory");
}

void AggregateAA::resolveTolerance() {
    if (m_settings.tolerance != kToleranceAuto) {
        m_toleranceCause = "setting --agaa-tolerance";
        return;
    }
    if (m_settings.generation == AggregateGeneration::Samples) {
        m_settings.tolerance = kDefaultTolerance;
        m_toleranceCause = "the samples path's default (docs/decisions/shading-rate-estimate.md)";
    } else {
        m_settings.tolerance = kToleranceNever;
        m_toleranceCause =
            "the accumulate path's default: a tolerance keeps 12 bytes of material per sample, "
            "more than the samples path's whole G-buffer saves (docs/decisions/"
            "shading-rate-estimate.md, step 6)";
        if (m_settings.debugView == AggregateDebugView::ShadingRate)
            throw std::invalid_argument(
                "--debug shading-rate shows the pixels shaded per sample, and the accumulate path shades "
                "none at its default (set --agaa-tolerance, or use --method agaa-samples)");
    }
}

std::span<const uint32_t> AggregateAA::program(const NamedProgram& shipping) const {
    return programCode(m_settings.programs, shipping);
}

std::span<const uint32_t> AggregateAA::perSampleCode() const {
    const bool accumulate = m_settings.generation == AggregateGeneration::Accumulate;
    return program(kPerSamplePrograms[accumulate ? 1 : 0][accumulate && m_hasEmissive ? 1 : 0]
                                     [m_shadow->enabled() ? 1 : 0]);
}

std::span<const uint32_t> AggregateAA::lightingCode() const {
    return program(kLightingPrograms[m_settings.generation == AggregateGeneration::Samples ? 1 : 0]
                                    [m_hasEmissive ? 1 : 0][m_shadow->enabled() ? 1 : 0]);
}

eng::vk::Specialization AggregateAA::lightingVariant() const {
    vk::Specialization spec = lightingSpecialization(
        effectSpecialization(m_features, m_settings.effects.shadowTaps, m_settings.effects.shadowFootprint),
        m_features);
    spec.byId.insert(
        spec.byId.end(),
        {{shared::kSpecLightingSamples, m_settings.samples},
         {shared::kSpecLightingAggregates, m_settings.aggregates},
         {shared::kSpecLightingCompact, m_settings.shading == AggregateShading::Compact ? 1u : 0u},
         {shared::kSpecLightingNdf, uint32_t(m_settings.ndf)},
         {shared::kSpecLightingRouting, uint32_t(m_settings.routing)},
         {shared::kSpecLightingViewFootprint, m_features.hasNearMirrors() ? 1u : 0u},
         {shared::kSpecLightingShadingRate, m_settings.tolerance >= 0.0f ? 1u : 0u},
         {shared::kSpecLightingShadingRateView,
          m_settings.debugView == AggregateDebugView::ShadingRate ? 1u : 0u}});
    return spec;
}

void AggregateAA::createLayouts(const eng::frame::GpuScene& scene) {
    // Set 0 of every layout is read from the SPIR-V the layout serves (engine/vk/reflection.h).
    constexpr auto kVs = VK_SHADER_STAGE_VERTEX_BIT;
    constexpr auto kFs = VK_SHADER_STAGE_FRAGMENT_BIT;
    constexpr auto kCs = VK_SHADER_STAGE_COMPUTE_BIT;
    vk::LayoutDesc visibility;
    visibility.pushBindings =
        vk::reflectBindings({{kAgaaSceneVert, kVs}, {program(kVisibilityProgram), kFs}});
    visibility.extraSets = {scene.textureSetLayout()};
    visibility.pushConstantBytes = 4;
    m_visibilityLayout = vk::createPipelineLayout(m_device, visibility, "agaa.visibility.layout");

    vk::LayoutDesc generation;
    generation.extraSets = {scene.textureSetLayout()};
    generation.pushConstantBytes = 4;
    generation.pushBindings = vk::reflectBindings({{kAgaaSceneVert, kVs}, {generationCode(), kFs}});
    m_generationLayout = vk::createPipelineLayout(m_device, generation, "agaa.generation.layout");

    const bool samplesPath = m_settings.generation == AggregateGeneration::Samples;
    vk::LayoutDesc cluster;
    cluster.pushBindings = vk::reflectBindings({{program(kClusterPrograms[samplesPath ? 1 : 0]), kCs}});
    m_clusterLayout = vk::createPipelineLayout(m_device, cluster, "agaa.cluster.layout");

    vk::LayoutDesc lighting;
    lighting.pushBindings = vk::reflectBindings({{lightingCode(), kCs}});
    m_lightingLayout = vk::createPipelineLayout(m_device, lighting, "agaa.lighting.layout");

    if (m_settings.tolerance >= 0.0f) {
        vk::LayoutDesc perSample;
        perSample.pushBindings = vk::reflectBindings({{perSampleCode(), kCs}});
        m_perSampleLayout = vk::createPipelineLayout(m_device, perSample, "agaa.lighting.perSample.layout");
    }

    vk::LayoutDesc debug;
    debug.pushBindings = vk::reflectBindings({{program(kDebugProgram), kCs}});
    m_debugLayout = vk::createPipelineLayout(m_device, debug, "agaa.debug.layout");
}

AggregateAA::~AggregateAA() {
    release();
}

void AggregateAA::release() {
    VkDevice d = m_device.device();
    vkDeviceWaitIdle(d);
    m_visibilityPipelines.release();
    m_generationPipelines.release();
    for (VkPipeline p : {m_clusterPipeline, m_lightingPipeline, m_perSamplePipeline, m_debugPipeline})
        if (p) vkDestroyPipeline(d, p, nullptr);
    vkDestroySampler(d, m_fetchSampler, nullptr);
    for (vk::PipelineLayout* l : {&m_visibilityLayout, &m_generationLayout, &m_clusterLayout,
                                  &m_lightingLayout, &m_perSampleLayout, &m_debugLayout})
        vk::destroyPipelineLayout(m_device, *l);
}

VkPipeline AggregateAA::makeVisibilityPipeline(const DrawVariant& variant) {
    const AlphaPath alpha = variant.alpha;
    const bool doubleSided = variant.doubleSided;
    vk::GraphicsPipelineDesc d;
    d.vertex = kAgaaSceneVert;
    d.fragment = program(kVisibilityProgram);
    d.layout = m_visibilityLayout.layout;
    // Paper section 3.6: masked materials sample alpha here only, with alpha-to-coverage; the
    // generation pass inherits the coverage through its depth EQUAL test.
    d.specialization.byId = {{shared::kSpecVisibilityAlphaPath, uint32_t(alpha)}};
    addMaterialSpecialization(d.specialization, m_features);
    d.alphaToCoverage = usesAlphaToCoverage(alpha);
    d.colorFormats = {VK_FORMAT_R8G8_UNORM};
    d.depthFormat = m_depthFormat;
    d.samples = VK_SAMPLE_COUNT_4_BIT;
    d.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    d.depthCompare = VK_COMPARE_OP_GREATER; // reversed Z
    return vk::createGraphicsPipeline(m_device, d,
                                      std::string("agaa.visibility") + alphaPathName(alpha) +
                                          (doubleSided ? ".twoSided" : ""));
}

std::span<const uint32_t> AggregateAA::generationCode() const {
    return program(
        kGenerationPrograms[m_hasEmissive ? 1 : 0][m_settings.atomics == AggregateAtomics::Bits64 ? 1 : 0]
                           [m_settings.subgroupReduction == SubgroupReduction::On ? 1 : 0]);
}

eng::vk::GraphicsPipelineDesc AggregateAA::generationPipelineDesc(bool doubleSided) const {
    vk::GraphicsPipelineDesc d;
    d.vertex = kAgaaSceneVert;
    d.fragment = generationCode();
    d.layout = m_generationLayout.layout;
    d.specialization = effectSpecialization(m_features, 1);
    d.specialization.byId.insert(
        d.specialization.byId.end(),
        {{shared::kSpecGenerationNdf, uint32_t(m_settings.ndf)},
         {shared::kSpecGenerationRouting, uint32_t(m_settings.routing)},
         {shared::kSpecGenerationSampleMaterial, m_settings.tolerance >= 0.0f ? 1u : 0u}});
    addMaterialSpecialization(d.specialization, m_features);
    if (m_hasEmissive) d.colorFormats = {VK_FORMAT_B10G11R11_UFLOAT_PACK32};
    d.depthFormat = m_depthFormat;
    d.samples = VK_SAMPLE_COUNT_4_BIT;
    d.cullMode = doubleSided ? VK_CULL_MODE_NONE : VK_CULL_MODE_BACK_BIT;
    // Algorithm 2 step 1: depth EQUAL without writes; stencil keeps the first fragment per sample
    // (GREATER against reference 1 passes while the sample's stencil is 0; INCREMENT_AND_CLAMP on pass).
    d.depthCompare = VK_COMPARE_OP_EQUAL;
    d.depthWrite = false;
    d.stencilTest = true;
    d.stencil = {VK_STENCIL_OP_KEEP,
                 VK_STENCIL_OP_INCREMENT_AND_CLAMP,
                 VK_STENCIL_OP_KEEP,
                 VK_COMPARE_OP_GREATER,
                 0xFF,
                 0xFF,
                 1};
    return d;
}

VkPipeline AggregateAA::makeGenerationPipeline(const DrawVariant& variant) {
    return vk::createGraphicsPipeline(m_device, generationPipelineDesc(variant.doubleSided),
                                      std::string("agaa.generation") +
                                          (variant.doubleSided ? ".twoSided" : ""));
}

std::vector<VariantChoice> AggregateAA::variants() const {
    std::vector<VariantChoice> v =
        effectVariants(m_features, m_scene, m_settings.samples, m_settings.effects.shadowTaps);
    for (VariantChoice& choice : v)
        if (choice.effect == "shadows" && m_features.hasShadows())
            choice.variant += shadowFootprintName(m_settings.effects.shadowFootprint, m_settings.samples,
                                                  m_settings.effects.shadowTaps);
    const bool sggx = m_settings.ndf == AggregateNdf::Sggx;
    v.push_back({"normal-distribution", sggx ? "sggx, two-point tone-mapped resolve" : "toksvig",
                 m_requestedNdf != AggregateNdf::Auto
                     ? std::string("setting --agaa-ndf")
                     : std::to_string(m_features.anisotropicMetalMaterials) + " of " +
                           std::to_string(m_features.drawnMaterials) +
                           " drawn materials glossy metal at roughness 0.1 to 0.4 (SGGX from half of them: "
                           "on near mirrors and mixed scenes it measured no more accurate, at twice the "
                           "lighting time)"});
    v.push_back({"near-mirror-view-footprint", m_features.hasNearMirrors() ? "on" : "off",
                 m_features.forced ? std::string("forced")
                                   : std::to_string(m_features.nearMirrorMaterials) + " of " +
                                         std::to_string(m_features.drawnMaterials) +
                                         " drawn materials below roughness 0.1 or roughness-textured"});
    const vk::Capabilities& caps = m_device.caps();
    const bool compact = m_settings.shading == AggregateShading::Compact;
    v.push_back({"lighting-schedule",
                 compact ? "compacted per-tile list (aggregate 0 in registers)" : "registers (per pixel)",
                 m_requested.shading != AggregateShading::Auto ? std::string("setting --agaa-lighting")
                 : m_settings.aggregates < 2
                     ? std::string("c = 1: nothing to compact")
                     : std::string("c >= 2: a SIMD group would otherwise shade a second aggregate wherever "
                                   "one of its pixels has one")});
    const bool samplesPath = m_settings.generation == AggregateGeneration::Samples;
    v.push_back({"generation",
                 samplesPath ? "samples: one G-buffer pass, aggregated at the top of each tile"
                             : "accumulate: visibility prepass + accumulation kernel",
                 m_generationCause});
    v.push_back({"shading-rate",
                 m_settings.tolerance < 0.0f ? std::string("one shading event per aggregate")
                 : m_settings.tolerance == 0.0f || std::isinf(m_settings.aliasLimit)
                     ? "per sample where the aggregates' normal spread over their sharpest lobe reaches " +
                           shortNumber(m_settings.tolerance)
                     : "per sample where the aggregates' normal spread over their sharpest lobe reaches " +
                           shortNumber(m_settings.tolerance) + " and stays below " +
                           shortNumber(m_settings.aliasLimit),
                 m_toleranceCause});
    if (samplesPath) {
        v.push_back({"fill-shading",
                     m_settings.sampleRateShading ? "sample rate (supersampled materials)"
                                                  : "pixel rate, per-sample coverage",
                     "setting --sample-rate-shading"});
        v.push_back({"curvature-roughness", m_settings.curvatureRoughness ? "on" : "off",
                     "setting --curvature-roughness"});
        v.push_back(
            {"clustering-distance",
             m_settings.distance == AggregateDistance::Plane ? "tangent-plane distance" : "Equation 1",
             "setting --agaa-distance"});
        return v; // routing, atomics and subgroup reduction belong to the accumulation kernel
    }
    v.push_back({"visibility-depth",
                 m_depthFormat == VK_FORMAT_D32_SFLOAT_S8_UINT
                     ? "D32_SFLOAT_S8_UINT (the reference's precision)"
                     : "D24_UNORM_S8_UINT (fallback)",
                 m_depthFormat == VK_FORMAT_D32_SFLOAT_S8_UINT ? "device offers D32S8 at 4x"
                                                               : "device lacks D32S8 at 4x"});
    v.push_back(
        {"generation-routing",
         m_settings.routing == AggregateRouting::Fragment ? "per fragment (Algorithm 2)" : "per sample",
         "setting --agaa-routing"});
    const bool int64 = m_settings.atomics == AggregateAtomics::Bits64;
    v.push_back({"generation-atomics", int64 ? "64-bit (3 per aggregate)" : "32-bit (6 per aggregate)",
                 m_requested.atomics != AggregateAtomics::Auto
                     ? std::string("setting --agaa-atomics")
                     : std::string(caps.bufferInt64Atomics ? "device has" : "device lacks") +
                           " shaderBufferInt64Atomics"});
    const bool reduce = m_settings.subgroupReduction == SubgroupReduction::On;
    v.push_back(
        {"subgroup-reduction", reduce ? "on" : "off",
         m_requested.subgroupReduction != SubgroupReduction::Auto
             ? std::string("setting --agaa-subgroup-reduce")
         : caps.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU
             ? std::string("CPU device: fragment subgroups hold one primitive's pixels")
             : std::string("GPU with fragment subgroup ballot + arithmetic: ") + (reduce ? "yes" : "no")});
    v.push_back({"clustering-distance",
                 m_settings.distance == AggregateDistance::Plane ? "tangent-plane distance" : "Equation 1",
                 "setting --agaa-distance"});
    return v;
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
