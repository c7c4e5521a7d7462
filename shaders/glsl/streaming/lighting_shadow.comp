#version 460
#extension GL_GOOGLE_include_directive : require
#define GBUFFER_SHADOWS 1
#include "streaming/lighting.glsl"
