#version 460
#extension GL_GOOGLE_include_directive : require
// The test build of AGAA's generation pass (tests/support/aggregate_instrumentation.h
// FragmentRecordPass): drawn again after the shipping pass over its depth and stencil, it sees
// the same first fragment per sample and records what that fragment accumulated, without
// accumulating. 32-bit, no emissive.
#define AGAA_EMISSIVE 0
#define AGAA_RECORD 1
#include "agaa/generation.glsl"
