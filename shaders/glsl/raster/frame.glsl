#ifndef AGAA_RASTER_FRAME_GLSL
#define AGAA_RASTER_FRAME_GLSL
// Set 0 binding 0 of the camera's raster passes (agaa/common/raster_pass.h), pushed by the module:
// the frame's camera, sample pattern and layer offsets, for any stage.
#include "shared/frame.h"
layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
#endif
