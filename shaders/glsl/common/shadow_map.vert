#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_ARB_shader_viewport_layer_array : require
// Depth-only shadow-map pass (agaa/common/shadow_map.cpp): instance l of each draw renders
// into layer l of the shadow-map array, seen from shadowed light l.
#include "shared/frame.h"
#include "raster/shadow_pass.glsl"

layout(location = 0) in vec3 inPosition;
// The scene's vertex layout has all four attributes; declared so every one is consumed.
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv;
layout(location = 4) in vec2 inUv1;
layout(location = 5) in vec4 inColor;
layout(location = 0) out vec4 outUvs; // xy TEXCOORD_0, zw TEXCOORD_1
layout(location = 1) out vec4 outColor;

void main() {
    gl_Position = shadowClipPosition(inPosition);
    gl_Layer = gl_InstanceIndex;
    outUvs = vec4(inUv, inUv1);
    outColor = inColor;
}
