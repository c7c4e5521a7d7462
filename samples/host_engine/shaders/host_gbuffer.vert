#version 460
#extension GL_GOOGLE_include_directive : require
// A host's own vertex shader for the camera's raster passes (tests/node/test_host_geometry.cpp):
// its own vertex format (interleaved position and normal), the module's set 0 and transform.
#include "raster/camera_pass.glsl"

layout(location = 0) in vec3 inPosition; // world space
layout(location = 1) in vec3 inNormal;
layout(location = 0) out vec3 outNormal;       // view space
layout(location = 1) out vec3 outViewPosition; // AGAA's visibility prepass
layout(location = 2) flat out uint outLayer;   // AGAA's accumulation

void main() {
    gl_Position = cameraClipPosition(inPosition);
    gl_Layer = gl_InstanceIndex;
    outNormal = cameraViewDirection(inNormal);
    outViewPosition = cameraViewPosition(inPosition);
    outLayer = uint(gl_InstanceIndex);
}
