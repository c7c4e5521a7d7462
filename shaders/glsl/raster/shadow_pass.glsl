#ifndef AGAA_RASTER_SHADOW_PASS_GLSL
#define AGAA_RASTER_SHADOW_PASS_GLSL
// For a drawer's shaders (agaa/common/raster_pass.h): set 0 of the shadow-map pass
// (RasterOutput::ShadowDepth), which the module pushes, and its vertex transform. Instance l of a
// draw renders shadowed light l's map, layer l:
//     gl_Position = shadowClipPosition(worldPosition); gl_Layer = int(gl_InstanceIndex);
// Depth only; a masked material discards below its cutoff in the drawer's fragment shader.
#include "shared/shadow.h"
layout(set = 0, binding = 0) uniform Shadow { ShadowConstants shadow; };

vec4 shadowClipPosition(vec3 worldPosition) {
    // Camera-relative, as the lighting's lookups (ShadowConstants::relativeToShadow).
    return shadow.relativeToShadow[uint(gl_InstanceIndex)] * vec4(worldPosition - shadow.eye.xyz, 1.0);
}
#endif
