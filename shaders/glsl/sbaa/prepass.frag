#version 460
#extension GL_GOOGLE_include_directive : require
// SBAA step 1, the visibility prepass (Salvi and Vidimce 2012, section 3.1): per sample only what
// the surface selection needs, no material:
//   depth            D32, reversed Z (fixed function)
//   RT0 RG8_UNORM    the geometric normal (the interpolated vertex normal, no normal map; flipped
//                    on back faces as the material flips it), octahedral, view space, as
//                    v * 0.5 + 0.5: the orientation MERGE compares (the paper merges samples "of
//                    similar planes"); A the coverage alpha alpha-to-coverage reads
//   RT1 R32_SFLOAT   the scene-wide triangle number + 1 as an exact float (0 = nothing; integer
//                    MSAA colour is 1x only on lavapipe)
// The material runs later, once per kept surface, in the fill pass (sbaa/fill*.frag). The vertex
// shader is the reference's (reference/gbuffer.vert), so both passes rasterise the same depths
// and the fill's EQUAL test passes exactly where this pass won.
#include "shared/frame.h"
#include "shared/specialization.h"

// Masked materials (agaa/common/effects.h AlphaPath): 0 opaque, 1 discard below the cutoff,
// 2 alpha-to-coverage (common/alpha_coverage.glsl).
layout(constant_id = kSpecFillAlphaPath) const uint kAlphaPath = 0u;

layout(set = 0, binding = 0) uniform Frame { FrameConstants frame; };
#include "common/scene_materials.glsl"
layout(push_constant) uniform Push { uint material; uint firstTriangle; } pc;

#include "common/material.glsl"
#include "common/octahedral.glsl"
#include "common/alpha_coverage.glsl"
#include "common/depth.glsl"
#include "common/face_normal.glsl"

// GBUFFER_SAMPLE_RATE 1 (prepass_sample_rate.frag): the alpha per sample.
#include "reference/gbuffer_inputs.glsl"

layout(location = 0) out vec4 outNormal;
layout(location = 1) out float outPrimitive;

void main() {
    // The face normal stands in where the vertex normal is degenerate (zero-length, as a mesh
    // without normals can give). The view position on the triangle's plane comes from the
    // fragment's depth at its unshifted pixel position (layer l is drawn shifted by
    // frame.layerOffsets[l] pixels, common/scene_vertex.glsl). Derivatives first: in uniform
    // control flow, before any discard.
    vec2 q = gl_FragCoord.xy - frame.layerOffsets[gl_Layer].xy;
    vec3 P = viewPositionFromDepth(q, gl_FragCoord.z, frame.extent, frame.depthParams, frame.projParams);
    vec3 face = viewFaceNormal(P, normalize(-P));
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
    outNormal = vec4(encodeOctahedral(N) * 0.5 + 0.5, 0.0, coverage);
    outPrimitive = float(pc.firstTriangle + uint(gl_PrimitiveID) + 1u);
}
