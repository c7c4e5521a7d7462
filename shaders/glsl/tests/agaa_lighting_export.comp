#version 460
#extension GL_GOOGLE_include_directive : require
// Test build of AGAA's lighting pass (tests/support/aggregate_instrumentation.h): the shipping pass
// (agaa/lighting.comp) that also writes what step 1 read and built, for a CPU aggregation written
// apart from the shader. 16 floats per record: sample s of pixel p at p * n + s, aggregate a of
// pixel p at pixels * n + p * c + a.
#include "agaa/lighting/lighting_pass.glsl"
#include "agaa/lighting/shade_aggregates.glsl"
#include "agaa/lighting/shadow_footprint.glsl"

layout(set = 0, binding = 14, std430) writeonly buffer Export { float exportData[]; };

void exportRecord(uint record, vec4 a, vec4 b, vec4 c, vec4 d) {
    uint o = record * 16u;
    for (uint i = 0u; i < 4u; ++i) {
        exportData[o + i] = a[i];
        exportData[o + 4u + i] = b[i];
        exportData[o + 8u + i] = c[i];
        exportData[o + 12u + i] = d[i];
    }
}

void exportSample(uint pixelIndex, uint s, vec4 a, vec4 b, vec4 c, vec4 d) {
    exportRecord(pixelIndex * kSamples + s, a, b, c, d);
}

void exportAggregate(uint pixelIndex, uint a, vec4 m0, vec4 m1, vec4 m2, vec4 m3) {
    ivec2 size = ivec2(frame.extent.xy);
    exportRecord(uint(size.x * size.y) * kSamples + pixelIndex * kAggregates + a, m0, m1, m2, m3);
}
