#version 460
#extension GL_GOOGLE_include_directive : require
#define AGAA_GBUFFER_INPUT 1
#include "agaa/cluster.glsl"
