// AggregatePlan: every Auto setting of AggregateAA resolved once, with its cause.

#include "agaa/aggregate/aggregate_plan.h"

#include "agaa/aggregate/passes/aggregate_programs.h"
#include "agaa/common/sample_gbuffer.h"
#include "engine/vk/check.h"
#include "engine/vk/resources.h"
#include "shared/shadow.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

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

// Auto -> a path, or MissingCapability for a path the device lacks.
void resolveGeneration(AggregatePlan& plan, const vk::Capabilities& caps) {
    if (plan.settings.generation == AggregateGeneration::Coverage) {
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
    const bool perSampleRate = plan.settings.tolerance >= 0.0f;
    if (perSampleRate && plan.settings.generation == AggregateGeneration::Accumulate &&
        plan.settings.routing == AggregateRouting::Fragment)
        throw std::invalid_argument(
            "--agaa-tolerance on the accumulate path needs --agaa-routing samples: whole-fragment routing "
            "mixes aggregates' members, which the shading rate's estimate reads (allowed: --agaa-routing "
            "samples, or --agaa-tolerance never)");
    if (plan.settings.generation != AggregateGeneration::Auto) {
        plan.generationCause = "setting --agaa-generation";
        return;
    }
    if (perSampleRate) {
        plan.settings.generation = AggregateGeneration::Samples;
        plan.generationCause = "--agaa-tolerance: flagged pixels are shaded from the per-sample G-buffer";
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
    const bool samples = plan.settings.samples <= kSamplesPathMaxSamples;
    plan.settings.generation = samples ? AggregateGeneration::Samples : AggregateGeneration::Accumulate;
    plan.generationCause = "n = " + std::to_string(plan.settings.samples) + (samples ? " <= " : " > ") +
                           std::to_string(kSamplesPathMaxSamples) +
                           (samples ? ": one raster pass, per-sample G-buffer memory affordable"
                                    : ": the per-sample G-buffer would be 1.7x the accumulate path's memory");
}

// kToleranceAuto -> the path's default.
void resolveTolerance(AggregatePlan& plan) {
    if (plan.settings.tolerance != kToleranceAuto) {
        plan.toleranceCause = "setting --agaa-tolerance";
        return;
    }
    if (plan.settings.generation == AggregateGeneration::Samples) {
        plan.settings.tolerance = kDefaultTolerance;
        plan.toleranceCause = "the samples path's default (docs/decisions/shading-rate-estimate.md)";
    } else {
        plan.settings.tolerance = kToleranceNever;
        plan.toleranceCause =
            "the accumulate path's default: a tolerance keeps 12 bytes of material per sample, "
            "more than the samples path's whole G-buffer saves (docs/decisions/"
            "shading-rate-estimate.md, step 6)";
        if (plan.settings.debugView == AggregateDebugView::ShadingRate)
            throw std::invalid_argument(
                "--debug shading-rate shows the pixels shaded per sample, and the accumulate path shades "
                "none at its default (set --agaa-tolerance, or use --method agaa-samples)");
    }
}

} // namespace

AggregatePlan planAggregate(const vk::Device& device, const SceneTraits& traits,
                            const AggregateSettings& settings) {
    validate(settings);
    checkProgramOverrides(settings.programs);
    AggregatePlan plan{settings, settings, effectiveFeatures(traits, settings.effects)};
    if (plan.settings.ndf == AggregateNdf::Auto)
        plan.settings.ndf =
            plan.features.anisotropicMetalsDominate() ? AggregateNdf::Sggx : AggregateNdf::Toksvig;
    const vk::Capabilities& caps = device.caps();
    if (!caps.supportsSamples(4))
        throw vk::MissingCapability(caps.deviceName +
                                    " lacks 4x MSAA (AGAA rasterises n >= 4 samples as 4x layers)");
    resolveGeneration(plan, caps);
    resolveTolerance(plan);
    const bool samplesPath = plan.samplesPath();
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
        plan.depthFormat = SampleGBufferPass::kDepthFormat;
    else if (vk::supportsImage(device, VK_FORMAT_D32_SFLOAT_S8_UINT, depthUsage, VK_SAMPLE_COUNT_4_BIT))
        plan.depthFormat = VK_FORMAT_D32_SFLOAT_S8_UINT;
    else if (vk::supportsImage(device, VK_FORMAT_D24_UNORM_S8_UINT, depthUsage, VK_SAMPLE_COUNT_4_BIT))
        plan.depthFormat = VK_FORMAT_D24_UNORM_S8_UINT;
    else
        throw vk::MissingCapability(caps.deviceName +
                                    " offers no 4x sampled depth-stencil format (D32S8 or D24S8)");

    // Generation atomics and their subgroup pre-reduction: what the device offers, or what was asked.
    const bool fragmentSubgroups =
        (caps.subgroupStages & VK_SHADER_STAGE_FRAGMENT_BIT) != 0 &&
        (caps.subgroupOperations & (VK_SUBGROUP_FEATURE_BALLOT_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT)) ==
            (VK_SUBGROUP_FEATURE_BALLOT_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT);
    if (plan.settings.atomics == AggregateAtomics::Bits64 && !caps.bufferInt64Atomics)
        throw vk::MissingCapability(
            caps.deviceName + " lacks shaderBufferInt64Atomics (--agaa-atomics 64; allowed here: 32, auto)");
    if (plan.settings.atomics == AggregateAtomics::Auto)
        plan.settings.atomics = caps.bufferInt64Atomics ? AggregateAtomics::Bits64 : AggregateAtomics::Bits32;
    if (plan.settings.subgroupReduction == SubgroupReduction::On && !fragmentSubgroups)
        throw vk::MissingCapability(
            caps.deviceName +
            " lacks fragment-stage subgroup ballot and arithmetic (--agaa-subgroup-reduce on; "
            "allowed here: off, auto)");
    if (plan.settings.subgroupReduction == SubgroupReduction::Auto)
        plan.settings.subgroupReduction = fragmentSubgroups && caps.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU
                                              ? SubgroupReduction::On
                                              : SubgroupReduction::Off;
    // Rule (docs/decisions/lighting-schedule.md): one aggregate per pixel has nothing to
    // compact; from c = 2 the list pays on lavapipe too (its SIMD groups of 8 otherwise shade a
    // second aggregate wherever one lane has one), and a GPU's wider waves gain more.
    if (plan.settings.shading == AggregateShading::Auto)
        plan.settings.shading =
            plan.settings.aggregates >= 2 ? AggregateShading::Compact : AggregateShading::Registers;

    return plan;
}

std::vector<VariantChoice> planVariants(const AggregatePlan& plan, const SceneTraits& traits,
                                        const vk::Capabilities& caps) {
    std::vector<VariantChoice> v =
        effectVariants(plan.features, traits, plan.settings.samples, plan.settings.effects.shadowTaps);
    for (VariantChoice& choice : v)
        if (choice.effect == "shadows" && plan.features.hasShadows())
            choice.variant += shadowFootprintName(plan.settings.effects.shadowFootprint,
                                                  plan.settings.samples, plan.settings.effects.shadowTaps);
    const bool sggx = plan.settings.ndf == AggregateNdf::Sggx;
    v.push_back({"normal-distribution", sggx ? "sggx, two-point tone-mapped resolve" : "toksvig",
                 plan.requested.ndf != AggregateNdf::Auto
                     ? std::string("setting --agaa-ndf")
                     : std::to_string(plan.features.anisotropicMetalMaterials) + " of " +
                           std::to_string(plan.features.drawnMaterials) +
                           " drawn materials glossy metal at roughness 0.1 to 0.4 (SGGX from half of them: "
                           "on near mirrors and mixed scenes it measured no more accurate, at about "
                           "1.15x the lighting time)"});
    v.push_back({"near-mirror-view-footprint", plan.features.hasNearMirrors() ? "on" : "off",
                 plan.features.forced ? std::string("forced")
                                      : std::to_string(plan.features.nearMirrorMaterials) + " of " +
                                            std::to_string(plan.features.drawnMaterials) +
                                            " drawn materials below roughness 0.1 or roughness-textured"});
    const bool compact = plan.settings.shading == AggregateShading::Compact;
    v.push_back({"lighting-schedule",
                 compact ? "compacted per-tile list (aggregate 0 in registers)" : "registers (per pixel)",
                 plan.requested.shading != AggregateShading::Auto ? std::string("setting --agaa-lighting")
                 : plan.settings.aggregates < 2
                     ? std::string("c = 1: nothing to compact")
                     : std::string("c >= 2: a SIMD group would otherwise shade a second aggregate wherever "
                                   "one of its pixels has one")});
    const bool samplesPath = plan.settings.generation == AggregateGeneration::Samples;
    v.push_back({"generation",
                 samplesPath ? "samples: one G-buffer pass, aggregated at the top of each tile"
                             : "accumulate: visibility prepass + accumulation kernel",
                 plan.generationCause});
    v.push_back({"shading-rate",
                 plan.settings.tolerance < 0.0f ? std::string("one shading event per aggregate")
                 : plan.settings.tolerance == 0.0f || std::isinf(plan.settings.aliasLimit)
                     ? "per sample where an aggregate's normal spread over its sharpest lobe reaches " +
                           shortNumber(plan.settings.tolerance) + " (its samples)"
                     : "per sample where an aggregate's normal spread over its sharpest lobe reaches " +
                           shortNumber(plan.settings.tolerance) + " and the pixel's stays below " +
                           shortNumber(plan.settings.aliasLimit) + " (its samples)",
                 plan.toleranceCause});
    v.push_back({"curvature-roughness", plan.settings.effects.curvatureRoughness.enabled ? "on" : "off",
                 "setting --curvature-roughness"});
    if (samplesPath) {
        v.push_back({"fill-shading",
                     plan.settings.sampleRateShading ? "sample rate (supersampled materials)"
                                                     : "pixel rate, per-sample coverage",
                     "setting --sample-rate-shading"});
        v.push_back(
            {"clustering-distance",
             plan.settings.distance == AggregateDistance::Plane ? "tangent-plane distance" : "Equation 1",
             "setting --agaa-distance"});
        return v; // routing, atomics and subgroup reduction belong to the accumulation kernel
    }
    v.push_back({"visibility-depth",
                 plan.depthFormat == VK_FORMAT_D32_SFLOAT_S8_UINT
                     ? "D32_SFLOAT_S8_UINT (the reference's precision)"
                     : "D24_UNORM_S8_UINT (fallback)",
                 plan.depthFormat == VK_FORMAT_D32_SFLOAT_S8_UINT ? "device offers D32S8 at 4x"
                                                                  : "device lacks D32S8 at 4x"});
    v.push_back(
        {"generation-routing",
         plan.settings.routing == AggregateRouting::Fragment ? "per fragment (Algorithm 2)" : "per sample",
         "setting --agaa-routing"});
    const bool int64 = plan.settings.atomics == AggregateAtomics::Bits64;
    v.push_back({"generation-atomics", int64 ? "64-bit (3 per aggregate)" : "32-bit (6 per aggregate)",
                 plan.requested.atomics != AggregateAtomics::Auto
                     ? std::string("setting --agaa-atomics")
                     : std::string(caps.bufferInt64Atomics ? "device has" : "device lacks") +
                           " shaderBufferInt64Atomics"});
    const bool reduce = plan.settings.subgroupReduction == SubgroupReduction::On;
    v.push_back(
        {"subgroup-reduction", reduce ? "on" : "off",
         plan.requested.subgroupReduction != SubgroupReduction::Auto
             ? std::string("setting --agaa-subgroup-reduce")
         : caps.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU
             ? std::string("CPU device: fragment subgroups hold one primitive's pixels")
             : std::string("GPU with fragment subgroup ballot + arithmetic: ") + (reduce ? "yes" : "no")});
    v.push_back({"clustering-distance",
                 plan.settings.distance == AggregateDistance::Plane ? "tangent-plane distance" : "Equation 1",
                 "setting --agaa-distance"});
    return v;
}

} // namespace agaa
