#pragma once
// agaa-timings --breakdown: AGAA's programs with one part compiled out (tools/agaa_timings/
// CMakeLists.txt), as replacements for the shipping programs of every variant
// (AggregateSettings::programs). A run with one set against a run with none is that part's cost.

#include "agaa/common/program_overrides.h"

namespace agaa::timings {

// The lighting pass without step 3 (every aggregate's and flagged sample's shading).
ProgramOverrides lightingWithoutShading();
// The lighting pass with every shadowed light's footprint fully lit: no shadow-map tap (the
// shadowed variants only; a scene without shadows runs its shipping pass).
ProgramOverrides lightingWithoutShadowFilter();
// The accumulation kernel evaluating the material but adding nothing to the AG-buffer, and the
// visibility prepass without its face-normal encoding.
ProgramOverrides generationWithoutAtomicsVisibilityWithoutNormals();
// The accumulation kernel as an empty fragment shader: its raster, depth and stencil cost alone.
ProgramOverrides generationEmpty();

} // namespace agaa::timings
