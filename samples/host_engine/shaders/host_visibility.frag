#version 460
#extension GL_GOOGLE_include_directive : require
// A host's own shader for RasterOutput::AggregateVisibility (tests/node/test_host_geometry.cpp):
// opaque materials, so full coverage.
#include "raster/aggregate_visibility_output.glsl"

layout(location = 1) in vec3 inViewPosition; // at the pixel centre: the face normal's derivatives

void main() {
    writeAggregateVisibility(aggregateVisibilityNormal(inViewPosition), 1.0);
}
