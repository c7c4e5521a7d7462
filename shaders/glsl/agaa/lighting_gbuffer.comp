#version 460
#extension GL_GOOGLE_include_directive : require
#define AGAA_GBUFFER 1
#define AGAA_EMISSIVE 0
#define AGAA_SHADOWS 0
#include "agaa/lighting.glsl"
