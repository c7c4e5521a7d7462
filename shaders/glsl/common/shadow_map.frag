#version 460
#extension GL_GOOGLE_include_directive : require
// Masked casters of the shadow-map pass: the alpha test of the material (1 sample per texel:
// discard, no coverage). Opaque casters use no fragment shader at all.
#include "shared/frame.h"

#include "common/scene_materials.glsl"
layout(push_constant) uniform Push { uint material; } pc;

#include "common/material.glsl"

layout(location = 0) in vec4 inUvs;
layout(location = 1) in vec4 inColor;

void main() {
    GpuMaterial m = materials[pc.material];
    if (materialAlpha(m, inUvs, inColor) < m.emissive.w) discard;
}
