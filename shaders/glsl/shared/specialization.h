#ifndef AGAA_SHARED_SPECIALIZATION_H
#define AGAA_SHARED_SPECIALIZATION_H
#include "shared/glsl_cpp.h"

// Specialisation-constant ids, named once for the shaders (layout(constant_id = kSpec...)) and for
// the C++ that fills them (agaa/common/effects.cpp, each pass's pipeline). A constant, not a
// uniform, wherever a choice selects code: lavapipe executes both sides of every branch whose
// condition is not known at compile time.
SHARED_BEGIN

// ---- The scene's effects: the same id in every shader that reads them -------------------
// Ids 0 and 1 belong to each pass (n, and c or the pass's own choice).
SHARED_CONST kSpecTileLightCulling = 2u; // common/tile_culling.glsl: point or spot lights to cull
SHARED_CONST kSpecNormalMaps = 3u;       // common/material.glsl
SHARED_CONST kSpecEmissive = 4u;         // common/material.glsl
SHARED_CONST kSpecShadowTaps = 5u;       // common/shadow.glsl: taps per aggregate footprint
SHARED_CONST kSpecShadowFootprint = 6u;  // AGAA lighting: agaa/common/effects.h ShadowFootprint
SHARED_CONST kSpecEnvironment = 16u;     // common/environment.glsl: an environment map
SHARED_CONST kSpecTextureTransforms = 18u; // common/material.glsl: KHR_texture_transform
SHARED_CONST kSpecVertexColors = 19u;      // common/material.glsl: COLOR_0

// ---- The AGAA lighting pass (agaa/lighting.glsl) ------------------------------------------
SHARED_CONST kSpecLightingSamples = 0u;       // n
SHARED_CONST kSpecLightingAggregates = 1u;    // c
SHARED_CONST kSpecLightingCompact = 7u;       // AggregateShading: 1 the per-tile list
SHARED_CONST kSpecLightingSkipShading = 8u;   // agaa-timings --breakdown: 1 skips step 3
SHARED_CONST kSpecLightingNdf = 9u;           // AggregateNdf: kNdfToksvig or kNdfSggx
SHARED_CONST kSpecLightingRouting = 10u;      // AggregateRouting: 1 whole fragments
SHARED_CONST kSpecLightingViewFootprint = 11u; // SceneFeatures::hasNearMirrors
SHARED_CONST kSpecLightingShadingRate = 12u;  // AggregateSettings::tolerance: 1 the per-sample rate
SHARED_CONST kSpecLightingShadingRateView = 13u; // --debug shading-rate

SHARED_END
#endif
