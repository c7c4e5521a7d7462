#version 460
#extension GL_GOOGLE_include_directive : require
#define SBAA_PREPASS_SAMPLE_RATE 1
#include "sbaa/prepass.glsl"
