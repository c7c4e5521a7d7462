#version 460
#extension GL_GOOGLE_include_directive : require
#define AGAA_EMISSIVE 0
#include "agaa/generation.glsl"
