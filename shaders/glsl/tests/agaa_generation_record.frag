#version 460
// Test build of AGAA's accumulation kernel (tests/support/aggregate_instrumentation.h; tests/agaa/
// test_agaa_gpu.cpp, test_agaa_reference_gpu.cpp): every fragment of the pixels in the central
// kRecordWindow^2 block of the frame appends what the shipping pass (agaa/generation.frag)
// accumulates from it, so the CPU can re-accumulate the same fragments and compare with the
// AG-buffer: the quantised fields (the replay), then the material inputs before quantisation (the
// double-precision reference).
#extension GL_GOOGLE_include_directive : require
#define AGAA_SAMPLE_MATERIAL 0 // records here, binding 5, instead
#include "agaa/generation/fragment.glsl"

const uint kRecordWindow = 16u;
// pixel, layer, mask, the quantised fields, then as float bits: normal xyz, roughness, albedo rgb, metallic
const uint kRecordWords = 3u + kQuantizedFields + 8u;
layout(set = 0, binding = 5, std430) buffer FragmentRecords { uint recordCount; uint recordCapacity; uint records[]; };

void recordFragment(uvec2 pixel, uint pixelIndex, uint mask, AgQuantized f, MaterialSample m) {
    uvec2 origin = uvec2(frame.extent.xy) / 2u - kRecordWindow / 2u;
    if (any(lessThan(pixel, origin)) || any(greaterThanEqual(pixel, origin + kRecordWindow))) return;
    uint slot = atomicAdd(recordCount, 1u);
    if (slot >= recordCapacity) return;
    uint r = slot * kRecordWords;
    records[r + 0u] = pixelIndex;
    records[r + 1u] = inLayer;
    records[r + 2u] = mask;
    for (uint j = 0u; j < kQuantizedFields; ++j) records[r + 3u + j] = f.q[j];
    uint inputs = r + 3u + kQuantizedFields;
    records[inputs + 0u] = floatBitsToUint(m.normal.x);
    records[inputs + 1u] = floatBitsToUint(m.normal.y);
    records[inputs + 2u] = floatBitsToUint(m.normal.z);
    records[inputs + 3u] = floatBitsToUint(m.roughness);
    records[inputs + 4u] = floatBitsToUint(m.albedo.r);
    records[inputs + 5u] = floatBitsToUint(m.albedo.g);
    records[inputs + 6u] = floatBitsToUint(m.albedo.b);
    records[inputs + 7u] = floatBitsToUint(m.metallic);
}

void main() {
    uvec2 pixel;
    uint pixelIndex, mask;
    MaterialSample m;
    AgQuantized f;
    if (generationFragment(pixel, pixelIndex, mask, m, f)) recordFragment(pixel, pixelIndex, mask, f, m);
}
