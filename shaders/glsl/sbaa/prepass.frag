#version 460
#extension GL_GOOGLE_include_directive : require
// SBAA step 1, the visibility prepass (Salvi and Vidimce 2012, section 3.1), this project's scene
// written through the include a host's shaders use (raster/surface_visibility_output.glsl, which
// lists the targets). The material runs later, once per kept surface, in the fill pass
// (sbaa/fill*.frag). The vertex shader is the reference's (reference/gbuffer.vert), so both passes
// rasterise the same depths and the fill's EQUAL test passes exactly where this pass won.
#include "shared/frame.h"
#include "shared/specialization.h"

// Masked materials (agaa/common/effects.h AlphaPath): 0 opaque, 1 discard below the cutoff,
// 2 alpha-to-coverage (common/alpha_coverage.glsl).
layout(constant_id = kSpecFillAlphaPath) const uint kAlphaPath = 0u;

#include "raster/surface_visibility_output.glsl"
#include "common/scene_materials.glsl"
layout(push_constant) uniform Push { uint material; uint firstTriangle; } pc;

#include "common/material.glsl"
#include "common/alpha_coverage.glsl"

// GBUFFER_SAMPLE_RATE 1 (prepass_sample_rate.frag): the alpha per sample.
#include "reference/gbuffer_inputs.glsl"

void main() {
    // The face normal stands in where the vertex normal is degenerate. Derivatives first: in
    // uniform control flow, before any discard.
    vec3 face = surfaceVisibilityFaceNormal();
    // Measured against the face normal (furball 64x64, n = 8, S = 4, display RMSE against the
    // reference; agaa/sbaa/README.md): 0.0140 with this normal, 0.0151 with the face normal (a
    // variant not in the tree), whose test splits a smooth
    // tessellated strand at every triangle edge (the shading normals of its triangles agree; their
    // planes differ by the tessellation angle).
    float len = length(inNormal);
    vec3 N = len > kMinNormalLength ? inNormal / len : face;
    if (len > kMinNormalLength && !gl_FrontFacing) N = -N;
    float coverage = 1.0;
    if (kAlphaPath != 0u) {
        GpuMaterial m = materials[pc.material];
        coverage = maskedCoverage(kAlphaPath, materialAlpha(m, inUvs, inColor), m.emissive.w);
    }
    writeSurfaceVisibility(N, coverage, pc.firstTriangle + uint(gl_PrimitiveID));
}
