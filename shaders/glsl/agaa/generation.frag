#version 460
// AGAA step 3, AG-buffer generation by the accumulation kernel (paper section 3.4,
// Algorithm 2, section 4.2). The scene is rasterised again at n samples over the prepass
// depth: depth EQUAL without writes, early fragment tests and post-depth coverage, so
// gl_SampleMaskIn holds exactly the samples this fragment is visible at; the stencil keeps
// the first fragment per sample (section 4.2.2: coplanar duplicates never count twice).
// Each fragment evaluates the material as a classic G-buffer would and adds, with integer
// atomics on fixed-point values (order-independent: bit-identical frames), its normal
// distribution (Toksvig vector or SGGX matrix, shared/agaa.h), albedo, metallic and sample count
// into its pixel's aggregates. With a tolerance it also keeps each covered sample's material for
// the shading rate (writeSampleMaterial, shared/sample_material.h).
// The kernel is the include a host's shaders use (raster/aggregate_accumulation_output.glsl, with
// the routing and atomics variants); this build draws this project's scene.
#extension GL_GOOGLE_include_directive : require
#include "agaa/generation/fragment.glsl"

void main() {
    accumulateAggregateFragment(inLayer, generationMaterial());
}
