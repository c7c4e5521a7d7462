#version 460
#extension GL_GOOGLE_include_directive : require
#define AGAA_GBUFFER 1
#define AGAA_EMISSIVE 1
#define AGAA_SHADOWS 1
#include "agaa/lighting.glsl"
