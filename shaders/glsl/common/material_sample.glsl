#ifndef AGAA_MATERIAL_SAMPLE_GLSL
#define AGAA_MATERIAL_SAMPLE_GLSL
// A material evaluated at a fragment: what this project's materials produce (common/material.glsl)
// and what a host's material shader hands AGAA's accumulation kernel
// (raster/aggregate_accumulation_output.glsl).
struct MaterialSample {
    vec3 albedo;
    float alpha;
    float metallic;
    float roughness;
    vec3 emissive; // radiance, linear
    vec3 normal; // shading normal, view space, unit
};
#endif
