#version 460
#extension GL_GOOGLE_include_directive : require
// The one vertex shader of both AGAA raster passes (visibility prepass and AG-buffer
// generation): the generation pass tests depth EQUAL against the prepass, so both must
// compute bit-identical positions (common/scene_vertex.glsl, `invariant gl_Position`).
#include "shared/frame.h"
#include "common/scene_vertex.glsl"

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent;
layout(location = 3) in vec2 inUv;
layout(location = 4) in vec2 inUv1; // glTF TEXCOORD_1
layout(location = 5) in vec4 inColor; // glTF COLOR_0 (1 without)

layout(location = 0) out vec3 outNormal; // view space, interpolated (shading normal)
layout(location = 1) out vec4 outTangent;
layout(location = 2) out vec4 outUvs; // xy TEXCOORD_0, zw TEXCOORD_1
layout(location = 5) out vec4 outColor;
layout(location = 3) flat out uint outLayer; // emulation layer (gl_Layer is not readable in fragment shaders without geometry shaders)
layout(location = 4) out vec3 outViewPosition;

void main() {
    uint layer = uint(gl_InstanceIndex);
    gl_Position = sceneClipPosition(inPosition, layer, frame);
    gl_Layer = int(layer);
    outNormal = mat3(frame.view) * inNormal;
    outTangent = vec4(mat3(frame.view) * inTangent.xyz, inTangent.w);
    outUvs = vec4(inUv, inUv1);
    outColor = inColor;
    outLayer = layer;
    outViewPosition = sceneViewPosition(inPosition, frame);
}
