#version 460
#extension GL_GOOGLE_include_directive : require
// Test support: the samples path without emissive or shadows, exporting what step 1 built.
#define AGAA_GBUFFER 1
#define AGAA_EXPORT 1
#define AGAA_EMISSIVE 0
#define AGAA_SHADOWS 0
#include "agaa/lighting.glsl"
