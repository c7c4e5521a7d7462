#version 460
#extension GL_GOOGLE_include_directive : require
// AGAA step 1, the dense visibility prepass (paper section 3.2): depth (fixed-function) and
// the primitive's face normal as two 8-bit spherical angles (RG8) per sample. Opaque materials
// use the variant that samples nothing; masked ones sample base-colour alpha and discard.
#include "agaa/visibility/fragment.glsl"

void main() {
    // Derivatives first: they must be taken in uniform control flow, before any discard.
    vec3 V = pixelToCamera(uvec2(gl_FragCoord.xy), agaa.ndcParams);
    vec3 N = viewFaceNormal(inViewPosition, V);
    float coverage = visibilityCoverage();
    outNormal = vec4(vec2(encodeHemisphereNormal(N, V)) / 255.0, 0.0, coverage);
}
