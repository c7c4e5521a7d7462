// AGAA's visibility prepass fragment, shared by the shipping pass (agaa/visibility.frag) and
// agaa-timings --breakdown's build without the normals (breakdown/visibility_no_normals.frag): its
// declarations, and the coverage of masked materials. Its target and the face normal are the
// include a host's shaders use (raster/aggregate_visibility_output.glsl).
#include "shared/frame.h"
#include "shared/specialization.h"

// Masked materials: 0 opaque, 1 discard, 2 alpha-to-coverage (common/alpha_coverage.glsl).
layout(constant_id = kSpecVisibilityAlphaPath) const uint kAlphaPath = 0u;

#include "raster/aggregate_visibility_output.glsl"
#include "common/scene_materials.glsl"
layout(push_constant) uniform Push { uint material; } pc;

#include "common/material.glsl"
#include "common/alpha_coverage.glsl"

// Centroid for what the material reads (the alpha coverage here must be the fill passes', which read
// at the centroid: reference/gbuffer_inputs.glsl). The view position stays at the pixel centre: the
// face normal is its screen derivatives, exact only for centre-interpolated values.
layout(location = 0) centroid in vec3 inNormal;
layout(location = 1) centroid in vec4 inTangent;
layout(location = 2) centroid in vec4 inUvs; // xy TEXCOORD_0, zw TEXCOORD_1
layout(location = 3) flat in uint inLayer;
layout(location = 4) in vec3 inViewPosition;
layout(location = 5) centroid in vec4 inColor;

// The fragment's coverage alpha for alpha-to-coverage (1 for opaque materials); a masked material's
// fragment below its cutoff is discarded at one sample per pixel.
float visibilityCoverage() {
    if (kAlphaPath == 0u) return 1.0;
    GpuMaterial m = materials[pc.material];
    return maskedCoverage(kAlphaPath, materialAlpha(m, inUvs, inColor), m.emissive.w);
}
