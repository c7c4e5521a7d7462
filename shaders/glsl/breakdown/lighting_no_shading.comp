#version 460
#extension GL_GOOGLE_include_directive : require
// agaa-timings --breakdown's build of AGAA's lighting pass (tools/agaa_timings/CMakeLists.txt): the
// shipping pass (agaa/lighting.comp) with step 3 left out, every aggregate resolved unlit.
#include "agaa/lighting/lighting_pass.glsl"
#include "agaa/lighting/shadow_footprint.glsl"

void shadeAggregates(OffLayer off, bool inside, uint firstEntry, out OffLayerShading offShaded) {
    shaded = Shading[](noShading(), noShading(), noShading(), noShading());
    offShaded = noOffLayerShading();
}

void exportSample(uint pixelIndex, uint s, vec4 a, vec4 b, vec4 c, vec4 d) {}
void exportAggregate(uint pixelIndex, uint a, vec4 m0, vec4 m1, vec4 m2, vec4 m3) {}
