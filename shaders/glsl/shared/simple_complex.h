#ifndef AGAA_SHARED_SIMPLE_COMPLEX_H
#define AGAA_SHARED_SIMPLE_COMPLEX_H
#include "shared/glsl_cpp.h"
// Simple/Complex deferred MSAA (Lauritzen 2010): the classification thresholds and
// options, pushed to the lighting pass (agaa/simple_complex).

SHARED_BEGIN

// Lighting schedules (specialisation constant 0 of simple_complex/lighting_*.comp).
SHARED_CONST kScheduleDeferPerSample = 0u; // complex pixels' extra samples packed into a per-tile list
SHARED_CONST kScheduleNaive = 1u;          // each invocation loops over its own pixel's extra samples

SHARED_CONST kDebugViewNone = 0u;
SHARED_CONST kDebugViewComplex = 1u; // display target: complex pixels highlighted

struct SimpleComplexParams {
    vec4 thresholds; // x: min cos between a sample's normal and sample 0's; y: depth slope scale; zw unused
    uvec4 options;   // x: debug view; yzw unused
};

SHARED_END
#endif
