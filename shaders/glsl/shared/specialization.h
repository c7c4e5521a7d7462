#ifndef AGAA_SHARED_SPECIALIZATION_H
#define AGAA_SHARED_SPECIALIZATION_H
#include "shared/glsl_cpp.h"

// Specialisation-constant ids, named once for the shaders (layout(constant_id = kSpec...)) and for
// the C++ that fills them by name (agaa/common/effects.cpp, each pass's pipeline): no id is
// assigned by its position in a list. A constant, not a
// uniform, wherever a choice selects code: lavapipe executes both sides of every branch whose
// condition is not known at compile time.
SHARED_BEGIN

// ---- The scene's effects: the same id in every shader that reads them -------------------
SHARED_CONST kSpecTileLightCulling = 2u; // common/tile_culling.glsl: point or spot lights to cull
SHARED_CONST kSpecNormalMaps = 3u;       // common/material.glsl
SHARED_CONST kSpecEmissive = 4u;         // common/material.glsl
SHARED_CONST kSpecShadowTaps = 5u;       // common/shadow.glsl: taps per aggregate footprint
SHARED_CONST kSpecShadowFootprint = 6u;  // AGAA lighting: agaa/common/effects.h ShadowFootprint
SHARED_CONST kSpecEnvironment = 16u;     // common/environment.glsl: an environment map
SHARED_CONST kSpecTextureTransforms = 18u; // common/material.glsl: KHR_texture_transform
SHARED_CONST kSpecVertexColors = 19u;      // common/material.glsl: COLOR_0

// ---- Each pass's own ------------------------------------------------------------------
// An id below means something else in each pass, and may reuse an effect id above that the
// pass's shaders do not read (the cluster's 2, the fill's 8 to 10, FXAA's 1 to 12): a pass must
// never declare both.
// The AGAA lighting pass (agaa/lighting.comp)
SHARED_CONST kSpecLightingSamples = 0u;       // n
SHARED_CONST kSpecLightingAggregates = 1u;    // c
SHARED_CONST kSpecLightingCompact = 7u;       // AggregateShading: 1 the per-tile list
SHARED_CONST kSpecLightingNdf = 9u;           // AggregateNdf: kNdfToksvig or kNdfSggx
SHARED_CONST kSpecLightingRouting = 10u;      // AggregateRouting: 1 whole fragments
SHARED_CONST kSpecLightingViewFootprint = 11u; // SceneFeatures::hasNearMirrors
SHARED_CONST kSpecLightingShadingRate = 12u;  // AggregateSettings::tolerance: 1 the per-sample rate
SHARED_CONST kSpecLightingShadingRateView = 13u; // --debug shading-rate
// AGAA's clustering (agaa/cluster.comp)
SHARED_CONST kSpecClusterSamples = 0u;    // n
SHARED_CONST kSpecClusterAggregates = 1u; // c
SHARED_CONST kSpecClusterDistance = 2u;   // AggregateDistance: 0 Equation 1, 1 the tangent plane
// AGAA's visibility prepass (agaa/visibility.frag)
SHARED_CONST kSpecVisibilityAlphaPath = 0u;  // agaa/common/effects.h AlphaPath
// AGAA's accumulation kernel (agaa/generation.frag)
SHARED_CONST kSpecGenerationNdf = 0u;       // AggregateNdf
SHARED_CONST kSpecGenerationRouting = 1u;   // AggregateRouting: 1 whole fragments (Algorithm 2)
SHARED_CONST kSpecGenerationSampleMaterial = 20u; // AggregateSettings::tolerance: 1 keeps it
// The per-sample G-buffer fill (reference/gbuffer.frag; SBAA's prepass and fill)
SHARED_CONST kSpecFillAlphaPath = 0u;             // agaa/common/effects.h AlphaPath
SHARED_CONST kSpecFillCurvatureRoughness = 8u;    // GBufferOptions::curvatureRoughness
SHARED_CONST kSpecFillCurvatureMaxFootprint = 9u; // float bits
SHARED_CONST kSpecFillCurvatureBoost = 10u;       // float bits
SHARED_CONST kSpecFillSbaaSurfaces = 24u;         // SBAA's fill: S surfaces per pixel
// The per-sample G-buffer's lighting (common/gbuffer_lighting.glsl: reference, Simple/Complex,
// SBAA, streaming)
SHARED_CONST kSpecGBufferLightingSamples = 1u;  // n
SHARED_CONST kSpecSimpleComplexSchedule = 0u;   // SimpleComplexSchedule (simple_complex/lighting.comp)
SHARED_CONST kSpecPerSampleShadingRateView = 13u; // AGAA's flagged pixels (agaa/lighting_per_sample.comp)
// FXAA (fxaa/fxaa.comp): the preset's search steps, then its step table
SHARED_CONST kSpecFxaaSearchSteps = 0u;
SHARED_CONST kSpecFxaaStepTable = 1u; // ids 1..kFxaaMaxSteps (shared/fxaa.h): each search step's offset

SHARED_END
#endif
