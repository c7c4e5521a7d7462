#version 460
#extension GL_GOOGLE_include_directive : require
// Per-sample G-buffer fill (the per-sample deferred reference, DESIGN section 5): this project's
// scene's vertices through the camera passes' include a host's vertex shaders use.
#include "raster/camera_pass.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv;
layout(location = 4) in vec2 inUv1; // glTF TEXCOORD_1
layout(location = 5) in vec4 inColor; // glTF COLOR_0 (1 without)

layout(location = 0) out vec3 outNormal; // view space
layout(location = 1) out vec4 outTangent; // view space xyz, w bitangent sign
layout(location = 2) out vec4 outUvs; // xy TEXCOORD_0, zw TEXCOORD_1
layout(location = 3) out vec4 outColor;

void main() {
    gl_Position = cameraClipPosition(inPosition);
    gl_Layer = gl_InstanceIndex;
    outNormal = cameraViewDirection(inNormal);
    outTangent = vec4(mat3(frame.view) * inTangent.xyz, inTangent.w);
    outUvs = vec4(inUv, inUv1);
    outColor = inColor;
}
