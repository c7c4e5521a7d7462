#ifndef AGAA_STREAMING_GBUFFER_FETCH_GLSL
#define AGAA_STREAMING_GBUFFER_FETCH_GLSL
// The recorded fragments streaming compression replays: the per-sample G-buffer with primitive
// ids (4x layered), n slots per pixel; sample s of a pixel is hardware sample s % 4 of layer
// s / 4 (engine/frame/sample_pattern.h). Requires `frame` (FrameConstants).
layout(set = 0, binding = 2) uniform sampler2DMSArray gDepth;
layout(set = 0, binding = 3) uniform sampler2DMSArray gNormal;
layout(set = 0, binding = 4) uniform sampler2DMSArray gAlbedoMetal;
layout(set = 0, binding = 5) uniform sampler2DMSArray gEmissiveRoughness;
layout(set = 0, binding = 11) uniform sampler2DMSArray gPrimitive;
#define STREAMING_FETCH(tex, p, s) texelFetch(tex, ivec3(p, int((s) / frame.counts.y)), int((s) % frame.counts.y))
#endif
