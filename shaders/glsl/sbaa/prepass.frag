#version 460
#extension GL_GOOGLE_include_directive : require
#define SBAA_PREPASS_SAMPLE_RATE 0
#include "sbaa/prepass.glsl"
