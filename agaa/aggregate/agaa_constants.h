#pragma once
// Builds the AGAA uniform block (shared/agaa.h): the normal-decoding tables, the clustering
// constants of Equation 1 and the Toksvig reference exponent.

#include "agaa/common/effects.h"
#include "agaa/common/named_value.h"
#include "agaa/common/program_overrides.h"
#include "shared/agaa.h"
#include "shared/frame.h"

#include <cstdint>
#include <limits>

namespace agaa {

// Aggregates: the clustering made visible instead of the lighting; ShadingRate: the lit image in
// grey, the pixels --agaa-tolerance shades per sample in red.
enum class AggregateDebugView : uint32_t { None = 0, Aggregates = 1, ShadingRate = 2 };
// Where an aggregate is shaded from: the mean of its samples' view positions (default), or the
// UE4 shortcut (seed 004): its mean depth on the pixel centre's ray.
enum class AggregatePosition : uint32_t { SampleMean = 0, PixelCentre = 1 };
inline constexpr NamedValue<AggregatePosition> kAggregatePositionNames[] = {
    {"mean", AggregatePosition::SampleMean}, {"centre", AggregatePosition::PixelCentre}};
// How an aggregate's normals are filtered (shared/agaa.h layouts, same 24 bytes each): the
// isotropic Toksvig vector of paper section 3.5.2, or the anisotropic SGGX matrix (shared/sggx.h,
// the paper's choice for thin glossy rods) with the two-point tone-mapped resolve.
// Auto: SGGX where glossy metals that are not near mirrors are at least half of the drawn
// materials (eng::scene::SceneFeatures::anisotropicMetalsDominate), Toksvig elsewhere: its mean
// shading normal and first moment light diffuse aggregates better (issue 14), and on near mirrors
// SGGX bought no accuracy the converged truth could see, at more lighting time (about 1.15x
// Toksvig's on metal, twice before its decomposition by squaring; docs/decisions/ndf-auto.md,
// issue 49).
enum class AggregateNdf : uint32_t { Toksvig = 0, Sggx = 1, Auto = 2 };
inline constexpr NamedValue<AggregateNdf> kAggregateNdfNames[] = {
    {"auto", AggregateNdf::Auto}, {"sggx", AggregateNdf::Sggx}, {"toksvig", AggregateNdf::Toksvig}};
// How the lighting pass schedules its shading events (shaders/glsl/agaa/lighting.comp, step 3):
// Registers: each invocation shades its own pixel's aggregates (a SIMD group pays for its pixel
// with the most aggregates); Compact: aggregate 0 of every pixel in registers, every further
// aggregate of the tile appended to a list in shared memory and shaded with all lanes busy.
// Auto: Compact for c >= 2 on every device, Registers at c = 1, where there is nothing to compact
// (measured: docs/decisions/lighting-schedule.md).
enum class AggregateShading : uint32_t { Registers = 0, Compact = 1, Auto = 2 };
inline constexpr NamedValue<AggregateShading> kAggregateShadingNames[] = {
    {"auto", AggregateShading::Auto},
    {"compact", AggregateShading::Compact},
    {"registers", AggregateShading::Registers}};
// Which aggregate a generation fragment feeds (shaders/glsl/agaa/generation.frag): Samples, each
// visible sample its own metadata aggregate (AG-buffer counts equal the metadata's); Fragment,
// Algorithm 2 as the paper writes it: the whole fragment to its first visible sample's aggregate.
enum class AggregateRouting : uint32_t { Samples = 0, Fragment = 1 };
inline constexpr NamedValue<AggregateRouting> kAggregateRoutingNames[] = {
    {"samples", AggregateRouting::Samples}, {"fragment", AggregateRouting::Fragment}};
// The generation pass's integer atomics: 32-bit per word, or 64-bit on pairs of words (3 atomics
// per aggregate instead of 5; device feature shaderBufferInt64Atomics). Auto: 64 where offered.
enum class AggregateAtomics : uint32_t { Bits32 = 0, Bits64 = 1, Auto = 2 };
inline constexpr NamedValue<AggregateAtomics> kAggregateAtomicsNames[] = {
    {"auto", AggregateAtomics::Auto}, {"32", AggregateAtomics::Bits32}, {"64", AggregateAtomics::Bits64}};
// Subgroup pre-reduction of the generation atomics that target the same pixel and aggregate.
// Auto: on for GPUs with fragment-stage ballot + arithmetic subgroups, off on CPU devices such
// as lavapipe, whose fragment subgroups never hold two primitives' fragments of one pixel.
enum class SubgroupReduction : uint32_t { Off = 0, On = 1, Auto = 2 };
inline constexpr NamedValue<SubgroupReduction> kSubgroupReductionNames[] = {
    {"auto", SubgroupReduction::Auto}, {"on", SubgroupReduction::On}, {"off", SubgroupReduction::Off}};
// The position term of the clustering distance (shared/clustering.h): Position, Equation 1's
// |(p_a - p_b)/k|^2; Plane, the mean of the squared distances of each sample to the other's
// tangent plane, ((p_a - p_b).n_a/k)^2 and ((p_a - p_b).n_b/k)^2, zero for samples on one plane
// however far apart (SBAA's plane predicate), so a flat surface at grazing angles stays one
// aggregate.
enum class AggregateDistance : uint32_t { Position = 0, Plane = 1 };
inline constexpr NamedValue<AggregateDistance> kAggregateDistanceNames[] = {
    {"position", AggregateDistance::Position}, {"plane", AggregateDistance::Plane}};
// How the aggregates are generated (agaa/aggregate/README.md, "Generation paths"):
//  - Accumulate: the visibility prepass, Algorithm 1 on its depth and face normals, then the
//    accumulation kernel rasterises the scene again and sums each fragment into the AG-buffer
//    (paper sections 3.3-3.4): 2 raster passes, c x 24 bytes per pixel of aggregates;
//  - Samples: the UE4 variant (seed 004): one raster pass writes the per-sample G-buffer (the
//    reference's, agaa/common/sample_gbuffer.h), Algorithm 1 runs on its depth and shading normal
//    with metal and dielectric kept apart, and the lighting pass averages each aggregate's samples
//    at the top of its tile: 1 raster pass, the whole per-sample G-buffer in memory;
//  - Coverage: the paper's blend-based coverage routing into c-sample targets. It needs mixed
//    attachment samples and a sample-mask override (VK_NV_framebuffer_mixed_samples or
//    VK_AMD_mixed_attachment_samples, and VK_NV_sample_mask_override_coverage); it is not built:
//    no device that offers both was available to test it, so it is refused by name;
//  - Auto: the rule of planAggregate (aggregate_plan.cpp; measured in the README).
enum class AggregateGeneration : uint32_t { Accumulate = 0, Samples = 1, Coverage = 2, Auto = 3 };
inline constexpr NamedValue<AggregateGeneration> kAggregateGenerationNames[] = {
    {"auto", AggregateGeneration::Auto},
    {"accumulate", AggregateGeneration::Accumulate},
    {"samples", AggregateGeneration::Samples},
    {"coverage", AggregateGeneration::Coverage}};
// AggregateSettings::tolerance: no pixel is shaded per sample.
inline constexpr float kToleranceNever = -1.0f;
// AggregateSettings::tolerance: the path's default. The samples path takes kDefaultTolerance; the
// accumulate path takes never: with a tolerance it keeps 12 bytes of material per sample, which
// costs it more memory than the samples path's whole G-buffer (docs/decisions/
// shading-rate-estimate.md, step 6).
inline constexpr float kToleranceAuto = -2.0f;
// The samples path's default tolerance, measured against the converged truth at n = 8 on every
// scene of the quality suite (docs/decisions/shading-rate-estimate.md, "The default"): with the
// alias limit it takes metal from 0.0442 to 0.0383 display RMSE and hard-mirror from 0.0186 to
// 0.0112, both by more than their truths' own errors, loses no scene more than 0.0003 and flags no
// pixel of furball or foliage. Below it, at 30, the gains are within the truths' own errors and
// the easy scenes start to pay for them.
inline constexpr float kDefaultTolerance = 100.0f;
// AggregateSettings::aliasLimit. Above this estimate the pixel's normals spread over so many lobe
// widths that its n samples alias the highlight (each hits or misses it) where the aggregate's
// filtered lobe integrates it, so shading them one by one is no closer to the truth. Measured at
// n = 8 against the converged truth (docs/decisions/shading-rate-estimate.md, step 3): the gold
// rods of spikes and glints estimate above 10^4 and lose energy shaded per sample (+15 % becomes
// +185 % on spikes); hard-mirror's pixels, whose per-sample shading halves its error, lie between
// 10^3 and 10^4. At n = 16 the rods' display errors cannot tell the limit from none (the
// decision record's "The alias limit at n = 16").
inline constexpr float kDefaultAliasLimit = 5000.0f;
// Above the alias limit a pixel is still shaded per sample where its aggregates' resolved, exposed
// radiance reaches this: far past the tone map's shoulder (ACES gives 0.97 at 4, 0.99 at 16) each
// aliased highlight sample clips on its own, which the aggregate's spread energy does not. Measured
// in the same step (shadows off): at the metered exposure 16 takes glints from 0.331 to 0.131
// display RMSE (the reference (8): 0.121) and spikes from 0.185 to 0.146 (0.141), and at exposure
// 1 it flags 0 % of spikes and 1 % of glints. 4 flagged 14 % of glints at exposure 1 and put
// spikes (c = 4, shadows on) at +177 % of the truth's energy.
inline constexpr float kAliasedSaturation = 16.0f;
// At c = 1, above the alias limit, a pixel is still shaded per sample where its aggregate's mean
// normal lies in a gap between its members' normals: where the nearest member is at least this
// share of their mean distance from it (agaa/lighting/shading_rate.glsl meanNormalInGap; 1 when
// every member is equally far). Two walls at +-45 degrees split 4 / 4 give 1 and 5 / 3 give 0.53; eight
// samples along one rod give far less. Measured at n = 8 against the converged truth
// (docs/decisions/shading-rate-estimate.md, step 4): it takes hard-mirror-vgroove at c = 1 from
// 0.170 to 0.0035 display RMSE, the reference (8)'s, and moves spikes and glints by at most 0.0007
// at exposure 1, a thirtieth of their truths' own errors (their means by 3 to 9 points, glints'
// towards the truth); at 0.3 glints' energy goes from +48 % to +157 %. Only at c = 1 (step 8):
// from c = 2 the grooves' walls are aggregates of their own (0 % flagged without the rule, the
// reference's error), and on spikes and glints at 320x180 with shadows the rule flagged 6.4 and
// 6.6 % of the pixels, a per-sample pass that took glints' frame under Simple/Complex (8)'s, for
// at most 0.0049 of error, a quarter of their truths' own.
inline constexpr float kMeanNormalGap = 0.5f;
inline constexpr float kAliasLimitNone = std::numeric_limits<float>::infinity();

// AGAA's own choices: the options of the method table only AGAA reads, held as they are by
// MethodSettings::agaa (agaa/method_settings.h) and by AggregateSettings, which adds what AGAA
// shares with every method. A new choice is a field here, its enum and names above, and its row
// in the option table.
struct AggregateChoices {
    AggregateNdf ndf = AggregateNdf::Auto;
    AggregateShading shading = AggregateShading::Auto;
    AggregateRouting routing = AggregateRouting::Samples;
    AggregateAtomics atomics = AggregateAtomics::Auto;
    SubgroupReduction subgroupReduction = SubgroupReduction::Auto;
    AggregateDistance distance = AggregateDistance::Plane;
    AggregateGeneration generation = AggregateGeneration::Auto;
    // The error-driven shading rate (samples path; docs/decisions/shading-rate-estimate.md): a
    // pixel whose aggregates' normal spread, against their sharpest member's lobe, reaches this is
    // shaded per sample as the reference shades it; 0 shades every pixel so. Below 0: never (AGAA
    // as the paper has it); kToleranceAuto: the path's default.
    float tolerance = kToleranceAuto;
    // A tolerance above 0 shades per sample only the pixels whose estimate lies in
    // [tolerance, aliasLimit); kAliasLimitNone: no limit. A tolerance of 0 ignores it (every pixel).
    float aliasLimit = kDefaultAliasLimit;
    // Builds to run in place of AGAA's shipping programs, by name (agaa/common/program_overrides.h);
    // a name AGAA does not run is refused. Empty: the shipping builds. Not an option: a tool's (such
    // as agaa-timings' part-removed builds), set in code.
    ProgramOverrides programs;
};

struct AggregateSettings : AggregateChoices {
    uint32_t samples = 8;              // n
    uint32_t aggregates = 2;           // c
    float characteristicLength = 0.1f; // k, metres (paper: 10 cm)
    // t in Equation 1 units: a further aggregate is only created from samples farther than t
    // from every seed. Default measured on the scenegen scenes (agaa/aggregate/README.md).
    float seedThreshold = 0.05f;
    AggregateDebugView debugView = AggregateDebugView::None;
    AggregatePosition position = AggregatePosition::SampleMean;
    // Samples path only: sample-rate shading in the fill pass (every sample runs the material).
    bool sampleRateShading = false;
    EffectSettings effects; // scene-driven shadows (taps: the footprint filter), alpha-to-coverage, ...
};

// The shared BRDF's GGX alpha range, as kMinGgxAlpha / kMaxGgxAlpha in
// shaders/glsl/common/epsilon.glsl.
inline constexpr float kMinGgxAlpha = 1.0e-3f;
inline constexpr float kMaxGgxAlpha = 0.9f;

// Throws std::invalid_argument naming the setting and its allowed range.
void validate(const AggregateSettings&);

shared::AgaaConstants makeAgaaConstants(const AggregateSettings&, const shared::FrameConstants&,
                                        bool hasEmissive);

} // namespace agaa
