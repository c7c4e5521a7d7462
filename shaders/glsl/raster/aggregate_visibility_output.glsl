#ifndef AGAA_RASTER_AGGREGATE_VISIBILITY_OUTPUT_GLSL
#define AGAA_RASTER_AGGREGATE_VISIBILITY_OUTPUT_GLSL
// For a drawer's fragment shaders (agaa/common/raster_pass.h): RasterOutput::AggregateVisibility,
// AGAA's dense visibility prepass (paper section 3.2): depth (fixed-function) and at location 0
// (RG8_UNORM) the primitive's face normal as two 8-bit angles about the view ray, coverage in w
// (1 for an opaque material; alpha-to-coverage reads it). Set 0: binding 0 the frame, binding 2
// AGAA's constants.
//     vec2 normal = aggregateVisibilityNormal(viewPosition); // first: screen derivatives
//     writeAggregateVisibility(normal, coverage);            // after the drawer's alpha test
// viewPosition: the fragment's view-space position interpolated at the pixel centre (not at the
// centroid): the face normal is its screen derivatives, exact only for centre-interpolated values.
#include "raster/frame.glsl"
#include "shared/agaa.h"
layout(set = 0, binding = 2) uniform Agaa { AgaaConstants agaa; };
#include "common/face_normal.glsl"
#include "common/hemisphere_normal.glsl"

layout(location = 0) out vec4 outNormal;

vec2 aggregateVisibilityNormal(vec3 viewPosition) {
    vec3 V = pixelToCamera(uvec2(gl_FragCoord.xy), agaa.ndcParams);
    vec3 N = viewFaceNormal(viewPosition, V);
    return vec2(encodeHemisphereNormal(N, V)) / 255.0;
}

void writeAggregateVisibility(vec2 normal, float coverage) {
    outNormal = vec4(normal, 0.0, coverage);
}
#endif
