#version 460
#extension GL_GOOGLE_include_directive : require
// AGAA step 1, the dense visibility prepass (paper section 3.2): depth (fixed-function) and
// the primitive's face normal as two 8-bit spherical angles (RG8) per sample. Opaque materials
// use the variant that samples nothing; masked ones sample base-colour alpha and discard.
#include "agaa/visibility/fragment.glsl"

void main() {
    // Derivatives first: they must be taken in uniform control flow, before any discard.
    vec2 normal = aggregateVisibilityNormal(inViewPosition);
    float coverage = visibilityCoverage();
    writeAggregateVisibility(normal, coverage);
}
