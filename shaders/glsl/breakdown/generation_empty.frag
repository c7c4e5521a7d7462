#version 460
// agaa-timings --breakdown's build of AGAA's accumulation kernel (tools/agaa_timings/CMakeLists.txt):
// a fragment that returns at once, so the pass costs its raster, depth and stencil work alone. It
// declares the shipping pass's bindings (agaa/generation.frag), whose descriptors the pass pushes.
#extension GL_GOOGLE_include_directive : require
#include "agaa/generation/fragment.glsl"

void main() {}
