#version 460
#extension GL_GOOGLE_include_directive : require
// agaa-timings --breakdown's build of AGAA's lighting pass (tools/agaa_timings/CMakeLists.txt): the
// shipping pass (agaa/lighting.comp) with every shadowed light's footprint fully lit, so that no
// shadow-map tap runs (agaa/lighting/shadow_footprint.glsl left out). Against the shipping pass it
// times the footprint's taps: at n <= 9 the adaptive footprint taps every one of an aggregate's
// samples, where the reference taps once per sample it shades. Built for the shadowed variants only.
#include "agaa/lighting/lighting_pass.glsl"
#include "agaa/lighting/shade_aggregates.glsl"

float shadowVisibilityFootprint(uint light, Aggregate ag, float pixelSize) {
    return 1.0;
}

void exportSample(uint pixelIndex, uint s, vec4 a, vec4 b, vec4 c, vec4 d) {}
void exportAggregate(uint pixelIndex, uint a, vec4 m0, vec4 m1, vec4 m2, vec4 m3) {}
