// The host's material (tests/node/test_host_geometry.cpp): a constant per draw, in its own push
// constant, evaluated as its own code does for every pass it draws.
#include "common/material_sample.glsl"

layout(push_constant) uniform HostDrawConstants {
    vec4 albedoRoughness;
    vec4 metallic; // x
    // The draw's first triangle in the host's index buffer: triangle numbers for the passes that
    // key on them (SBAA's prepass and fill, streaming's G-buffer), the same in every pass.
    uint firstTriangle;
} material;

const float kHostShortestNormal = 1e-6;

vec3 hostNormal(vec3 interpolated) {
    float len = length(interpolated);
    return len > kHostShortestNormal ? interpolated / len : vec3(0.0, 0.0, 1.0);
}

// n: unit, view space; flipped for a back face (two-sided materials shade both).
MaterialSample hostMaterial(vec3 n, float roughness) {
    MaterialSample m;
    m.albedo = material.albedoRoughness.rgb;
    m.alpha = 1.0;
    m.metallic = clamp(material.metallic.x, 0.0, 1.0);
    m.roughness = roughness;
    m.emissive = vec3(0.0);
    m.normal = gl_FrontFacing ? n : -n;
    return m;
}

uint hostTriangle() {
    return material.firstTriangle + uint(gl_PrimitiveID);
}
