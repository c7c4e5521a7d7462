#ifndef AGAA_SHARED_FXAA_H
#define AGAA_SHARED_FXAA_H
#include "shared/glsl_cpp.h"
// FXAA 3.11 quality (Lottes 2009/2011) parameters, pushed to fxaa/fxaa.comp (agaa/fxaa).
// The quality preset's end-of-edge search steps are specialisation constants
// (0: step count, 1..kFxaaMaxSteps: step lengths in pixels), from the one table in
// agaa/fxaa/fxaa_reference.cpp.

SHARED_BEGIN

SHARED_CONST kFxaaMaxSteps = 12u;

struct FxaaParams {
    vec4 thresholds; // x: subpixel blend amount, y: edge threshold (relative), z: edge threshold min
                     // (absolute luma), w unused
};

SHARED_END
#endif
