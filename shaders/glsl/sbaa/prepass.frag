#version 460
#extension GL_GOOGLE_include_directive : require
#define GBUFFER_SAMPLE_RATE 0
#include "sbaa/prepass.glsl"
