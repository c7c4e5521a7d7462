#version 460
#extension GL_GOOGLE_include_directive : require
// The test build of AGAA's lighting pass (tests/support/aggregate_instrumentation.h
// AggregateExportPass): the samples path without emissive or shadows, exporting what step 1 read
// and built into binding 14 (agaa/lighting/export.glsl). It runs beside the shipping lighting pass,
// on the same inputs; the shipping builds compile the export calls away and have no binding 14.
#define AGAA_GBUFFER 1
#define AGAA_EXPORT 1
#define AGAA_EMISSIVE 0
#define AGAA_SHADOWS 0
#include "agaa/lighting.glsl"
