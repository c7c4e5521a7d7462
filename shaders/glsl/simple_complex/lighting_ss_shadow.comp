#version 460
#extension GL_GOOGLE_include_directive : require
#define GBUFFER_MS 0
#define GBUFFER_SHADOWS 1
#include "simple_complex/lighting.glsl"
