#ifndef AGAA_SHARED_SAMPLE_MATERIAL_H
#define AGAA_SHARED_SAMPLE_MATERIAL_H
// The accumulate path's per-sample material, for the error-driven shading rate
// (docs/decisions/shading-rate-estimate.md): with a tolerance the accumulation kernel
// (agaa/generation.frag) writes each covered sample's material here, the lighting pass reads the
// normals and roughness for its estimate and gap rule, and agaa/lighting_per_sample.comp shades a
// flagged pixel's samples from it. Three words per sample, 12 bytes, at the per-sample G-buffer's
// precision where it has one:
//   w0  octahedral shading normal, view space, packSnorm2x16 (the G-buffer's RG16_SNORM)
//   w1  albedo sRGB-encoded (common/srgb.glsl) and metallic, packUnorm4x8 (the G-buffer's RGBA8)
//   w2  perceptual roughness, packUnorm2x16; the upper half is 0
// Not half floats: llvmpipe's unpackHalf2x16 in the per-sample pass crashes LLVM 15 where the JIT
// is held to SSE4.1 (GALLIUM_OVERRIDE_CPU_CAPS=sse4.1, the goldens'); a unorm16 step (1.5e-5) is
// finer than the G-buffer's half-float roughness above 0.03.
// The material is the fragment's (pixel rate, centroid), as the aggregates' sums are: the rate
// shades the same surfaces the aggregates stand for, one by one.
#include "shared/glsl_cpp.h"

SHARED_BEGIN

SHARED_CONST kSampleMaterialWords = 3u;

// First word of sample s of pixel p at n samples per pixel.
inline_fn uint sampleMaterialWord(uint p, uint n, uint s) {
    return (p * n + s) * kSampleMaterialWords;
}

inline_fn uint sampleMaterialWords(uint pixels, uint n) {
    return pixels * n * kSampleMaterialWords;
}

SHARED_END
#endif
