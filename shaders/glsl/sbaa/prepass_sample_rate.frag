#version 460
#extension GL_GOOGLE_include_directive : require
#define GBUFFER_SAMPLE_RATE 1
#include "sbaa/prepass.glsl"
