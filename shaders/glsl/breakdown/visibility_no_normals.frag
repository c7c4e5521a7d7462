#version 460
#extension GL_GOOGLE_include_directive : require
// agaa-timings --breakdown's build of AGAA's visibility prepass (tools/agaa_timings/CMakeLists.txt):
// the shipping pass (agaa/visibility.frag) without the face normal's derivation and encoding.
#include "agaa/visibility/fragment.glsl"

void main() {
    writeAggregateVisibility(vec2(0.0), visibilityCoverage());
}
