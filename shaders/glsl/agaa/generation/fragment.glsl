// The accumulation kernel's fragment over this project's scene, shared by every build of
// agaa/generation.frag: the shipping pass (agaa/generation.frag), the test build that records its
// fragments (tests/agaa_generation_record.frag) and agaa-timings --breakdown's part-removed builds
// (breakdown/generation_*.frag). The kernel itself is the include a host's shaders use
// (raster/aggregate_accumulation_output.glsl); here: the scene's material set and inputs, and
// generationFragment, which evaluates the fragment's material and quantises it.
#include "raster/aggregate_accumulation_output.glsl"
#include "common/scene_materials.glsl"
layout(push_constant) uniform Push { uint material; } pc;

#include "common/material.glsl"
// Geometric specular anti-aliasing (agaa/common/effects.h CurvatureRoughness), as every method's
// per-sample G-buffer takes it: the constants and sampleGBufferRoughness, no targets.
#define SAMPLE_GBUFFER_TARGETS 0
#include "raster/sample_gbuffer_output.glsl"

// Centroid: a fragment that covers only some samples reads its attributes inside the triangle, as
// the reference's per-sample G-buffer does (reference/gbuffer_inputs.glsl), never extrapolated to
// an uncovered pixel centre.
layout(location = 0) centroid in vec3 inNormal;
layout(location = 1) centroid in vec4 inTangent;
layout(location = 2) centroid in vec4 inUvs; // xy TEXCOORD_0, zw TEXCOORD_1
layout(location = 3) flat in uint inLayer;
layout(location = 5) centroid in vec4 inColor;

// The fragment's material, evaluated here. Call it in uniform control flow (the geometric
// normal's screen derivatives), as the kernel's main does first.
MaterialSample generationMaterial() {
    float glen = length(inNormal);
    vec3 geometric = glen > kMinNormalLength ? inNormal / glen : vec3(0.0, 0.0, 1.0);
    vec3 dNdx = kCurvatureRoughness != 0u ? dFdx(geometric) : vec3(0.0);
    vec3 dNdy = kCurvatureRoughness != 0u ? dFdy(geometric) : vec3(0.0);
    MaterialSample m =
        evaluateMaterial(materials[pc.material], inUvs, inColor, inNormal, inTangent, gl_FrontFacing);
    m.roughness = sampleGBufferRoughness(m.roughness, dNdx, dNdy);
    return m;
}

// The material evaluated at the fragment, then aggregateFragment (its pixel, covered samples and
// fixed-point fields; false for a fragment the depth test left no sample of).
bool generationFragment(out uvec2 pixel, out uint pixelIndex, out uint mask, out MaterialSample m,
                        out AgQuantized f) {
    m = generationMaterial();
    return aggregateFragment(m, pixel, pixelIndex, mask, f);
}
