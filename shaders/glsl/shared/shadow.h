#ifndef AGAA_SHARED_SHADOW_H
#define AGAA_SHARED_SHADOW_H
#include "shared/glsl_cpp.h"

SHARED_BEGIN

// One D32 layer of the shadow-map array per shadowed light (agaa/common/shadow_map.h).
SHARED_CONST kMaxShadowMaps = 4u;

// AGAA's adaptive shadow footprint (agaa/lighting/shadowed_lights.glsl): its penumbra test taps the
// footprint's four corners and centre besides the kShadowTaps statistical taps. Where n is no more
// than the test's taps, it taps every one of the aggregate's samples instead.
SHARED_CONST kAdaptiveCornerTaps = 5u;

// Written by the host with the frame (agaa/common/shadow_map.cpp), read by the shadow-map pass
// (relativeToShadow) and by lighting (viewToShadow). Shadow clip space: x, y in [-1, 1], z in
// [0, 1] with 0 nearest the light (standard depth: the map is cleared to 1, tested LESS).
// Camera-relative, as the scene's vertices (FrameConstants::eye): the shadow-map pass transforms
// a world position minus eye, so that no fp32 product cancels terms as large as the coordinates.
struct ShadowConstants {
    mat4 relativeToShadow[kMaxShadowMaps]; // (world position - eye) -> shadow clip
    mat4 viewToShadow[kMaxShadowMaps];
    vec4 eye; // xyz the camera's world position (FrameConstants::eye); w unused
    uvec4 lightIndex; // lights[] index of map l (kMaxLights when unused)
    // x maps in use, y 1/map size (texel in uv), z depth bias (shadow clip z units), w unused
    vec4 params;
    vec4 normalOffset; // per map: metres the receiver moves along its normal (1.5 texels)
};

SHARED_END
#endif
