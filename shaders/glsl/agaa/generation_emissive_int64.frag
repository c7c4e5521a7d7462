#version 460
#extension GL_GOOGLE_include_directive : require
#define AGAA_EMISSIVE 1
#define AGAA_INT64 1
#define AGAA_SUBGROUP 0
#include "agaa/generation.glsl"
