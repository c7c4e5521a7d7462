#version 460
#extension GL_GOOGLE_include_directive : require
#define GBUFFER_SAMPLE_RATE 1
#define GBUFFER_SURFACE_FILL 1
#include "reference/gbuffer.glsl"
