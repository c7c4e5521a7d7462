#ifndef AGAA_SHARED_TEMPORAL_H
#define AGAA_SHARED_TEMPORAL_H
#include "shared/glsl_cpp.h"
// Temporal anti-aliasing's resolve (temporal/resolve.comp, agaa/temporal/temporal_aa.h): what it is
// pushed each frame, and its guards.

SHARED_BEGIN

// The neighbourhood box's smallest half-extent in YCoCg (exposed radiance): a flat neighbourhood
// (every pixel alike) clips the history to its colour instead of dividing by zero.
SHARED_CONST_FLOAT kTemporalMinExtent = 1.0e-6f;
// A reprojected point must lie this far in front of the previous camera (clip w): behind it or on
// its plane it has no pixel there.
SHARED_CONST_FLOAT kTemporalMinClipW = 1.0e-6f;

struct TemporalParams {
    // The current frame's view space into the previous frame's clip space, unjittered
    // (agaa/temporal/reprojection.h): the pixel centre's position from this frame's depth goes in,
    // a direction (w = 0) for the sky.
    mat4 reprojection;
    // x: the current frame's weight alpha, 1 / (frames in the history + 1) down to the floor;
    // y: 1 when a history exists; z: the clip box's gamma (mean +- gamma sigma); w: 1 for the
    // motion view (--debug motion) instead of the colour: the HDR image holds the reprojected pixel
    // position (x, y), found (z) and the point's distance along the previous camera's axis (w); the
    // display holds its distance along this camera's (r). Distances are 0 for the sky; together
    // they tell a disoccluded pixel (tools/agaa_bench/disocclusion.h).
    vec4 blend;
};

SHARED_END
#endif
