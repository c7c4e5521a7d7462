#version 460
#extension GL_GOOGLE_include_directive : require
#define DEPTH_MS 0
#include "common/depth_resolve.glsl"
