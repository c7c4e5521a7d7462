#ifndef AGAA_SBAA_GBUFFER_FETCH_GLSL
#define AGAA_SBAA_GBUFFER_FETCH_GLSL
// SBAA's compute passes over the prepass (sbaa/prepass.frag: depth, geometric normal, primitive id,
// 4x layered): sample s of a pixel is hardware sample s % 4 of layer s / 4
// (engine/frame/sample_pattern.h). Requires `frame` (FrameConstants).
layout(set = 0, binding = 2) uniform sampler2DMSArray gDepth;
layout(set = 0, binding = 3) uniform sampler2DMSArray gGeometricNormal;
layout(set = 0, binding = 11) uniform sampler2DMSArray gPrimitive;
#define SBAA_FETCH(tex, p, s) texelFetch(tex, ivec3(p, int((s) / frame.counts.y)), int((s) % frame.counts.y))
// The geometric normal as stored (RG8_UNORM, octahedral v * 0.5 + 0.5), decoded.
vec3 sbaaGeometricNormal(ivec2 p, uint s) {
    return decodeOctahedral(SBAA_FETCH(gGeometricNormal, p, s).xy * 2.0 - 1.0);
}
#endif
