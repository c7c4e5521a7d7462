#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_ARB_shader_viewport_layer_array : require
// A host's own shadow-map vertex shader (tests/node/test_host_geometry.cpp): depth only.
#include "raster/shadow_pass.glsl"

layout(location = 0) in vec3 inPosition; // world space
layout(location = 1) in vec3 inNormal;   // in the host's vertex, unused here

void main() {
    gl_Position = shadowClipPosition(inPosition);
    gl_Layer = gl_InstanceIndex;
}
