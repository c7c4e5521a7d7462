#version 460
// agaa-timings --breakdown's build of AGAA's accumulation kernel (tools/agaa_timings/CMakeLists.txt):
// the shipping pass (agaa/generation.frag) with its atomics into the AG-buffer left out. The
// material is still evaluated and quantised, and kept per sample with a tolerance.
#extension GL_GOOGLE_include_directive : require
#include "agaa/generation/fragment.glsl"

void main() {
    uvec2 pixel;
    uint pixelIndex, mask;
    MaterialSample m;
    AgQuantized f;
    if (!generationFragment(pixel, pixelIndex, mask, m, f)) return;
    // Keep the material's evaluation alive without the atomics: an add no value reaches (an atomic,
    // as every other access to the AG-buffer here: a plain store would make the synchronisation
    // validation see writes racing between draws).
    if (f.q[0] + f.q[6] + f.q[9] == 0xFFFFFFFFu) atomicAdd(agBuffer[0], 1u);
    if (kSampleMaterial != 0u) writeSampleMaterial(inLayer, pixelIndex, mask, m);
}
