#version 460
// AGAA step 3, AG-buffer generation by the accumulation kernel (paper section 3.4,
// Algorithm 2, section 4.2). The scene is rasterised again at n samples over the prepass
// depth: depth EQUAL without writes, early fragment tests and post-depth coverage, so
// gl_SampleMaskIn holds exactly the samples this fragment is visible at; the stencil keeps
// the first fragment per sample (section 4.2.2: coplanar duplicates never count twice).
// Each fragment evaluates the material as a classic G-buffer would and adds, with integer
// atomics on fixed-point values (order-independent: bit-identical frames), its normal
// distribution (Toksvig vector or SGGX matrix, shared/agaa.h), albedo, metallic and sample count
// into its pixel's aggregates. With a tolerance it also keeps each covered sample's material for
// the shading rate (writeSampleMaterial, shared/sample_material.h).
//
// Routing (specialisation id 1, agaa/aggregate/agaa_constants.h AggregateRouting):
//  - samples (default): each aggregate present in the fragment's mask receives the fragment's
//    values weighted by its own number of samples, so the AG-buffer's sample counts equal the
//    metadata's exactly (a fragment straddling two clusters would otherwise count all its
//    samples in one);
//  - fragment: Algorithm 2 as the paper writes it: the whole fragment goes to the aggregate of
//    its first visible sample, one set of atomics per fragment. The lighting pass then weights
//    each aggregate by the samples it received, not by the metadata's assignment.
// Atomics (variants built from this file):
//  - AGAA_INT64 (shaderBufferInt64Atomics): the 6 words of an aggregate as three 64-bit adds
//    (an aggregate starts on an even word: 6 words each). No field ever carries out of its word
//    (layout proof in shared/agaa.h), so a 64-bit add of two words equals two 32-bit adds: the
//    AG-buffer is bit-identical.
//  - AGAA_SUBGROUP: fragments of one subgroup that target the same (pixel, aggregate) first sum
//    their increments with subgroupAdd, and one lane adds the sum (integer sums: order-free,
//    bit-identical). It saves atomics only where a subgroup holds fragments of several primitives
//    covering one pixel (GPUs pack quads of several triangles into one wave); lavapipe's fragment
//    subgroups are the pixels of one triangle, so there it only adds the loop.
#extension GL_GOOGLE_include_directive : require
#include "agaa/generation/fragment.glsl"
#include "agaa/generation/sample_material.glsl"

// Adds k samples of the fragment's values to aggregate slot `slot` (pixel * c + aggregate).
void addToAggregate(uint slot, uint k, uint ndf, AgQuantized f) {
    uint base = slot * kAggregateWords;
    uint inc[kAggregateWords];
    for (uint w = 0u; w < kAggregateWords; ++w)
        inc[w] = aggregateIncrement(ndf, w, k, f);
#if AGAA_SUBGROUP
    // Lanes with the same slot sum their increments; the lowest of them adds the sum. Each pass
    // of the loop retires the lanes of the first remaining lane's slot.
    bool retired = false, adds = false;
    for (uint lap = 0u; lap < gl_SubgroupSize && !retired; ++lap) {
        uint leader = subgroupBroadcastFirst(slot);
        if (slot == leader) {
            for (uint w = 0u; w < kAggregateWords; ++w) inc[w] = subgroupAdd(inc[w]);
            adds = subgroupElect();
            retired = true;
        }
    }
    if (!adds) return;
#endif
#if AGAA_INT64
    // base = 6 slot is even: the words pair on 8-byte boundaries.
    for (uint p = 0u; p < kAggregateWords / 2u; ++p)
        atomicAdd(agBuffer64[base / 2u + p], uint64_t(inc[2u * p]) | (uint64_t(inc[2u * p + 1u]) << 32u));
#else
    for (uint w = 0u; w < kAggregateWords; ++w) atomicAdd(agBuffer[base + w], inc[w]);
#endif
}

// c = 1: the k of the fragment's samples off the aggregate's layer (shared/clustering.h
// kOffLayer) add their diffuse colour, normal, F0 and alpha to the pixel's off-layer words
// (shared/ag_buffer.h kOffLayerWords), apart from the aggregate's fields.
void addToOffLayer(uint pixelIndex, uint k, MaterialSample m, uint n) {
    uint scale = unitScale(kOffLayerFieldBits, n);
    vec3 diffuse = m.albedo * (1.0 - m.metallic);
    uint at = offLayerWord(uint(frame.extent.x) * uint(frame.extent.y), pixelIndex);
    atomicAdd(agBuffer[at], k * quantizeUnit(diffuse.r, scale) + ((k * quantizeUnit(diffuse.g, scale)) << 16u));
    atomicAdd(agBuffer[at + 1u], k * quantizeUnit(diffuse.b, scale) + ((k * quantizeSigned(m.normal.x, scale)) << 16u));
    atomicAdd(agBuffer[at + 2u], k * quantizeSigned(m.normal.y, scale) + ((k * quantizeSigned(m.normal.z, scale)) << 16u));
    vec3 f0 = mix(vec3(0.04), m.albedo, m.metallic);
    float alpha = min(m.roughness * m.roughness, 1.0);
    atomicAdd(agBuffer[at + 3u], k * quantizeUnit(f0.r, scale) + ((k * quantizeUnit(f0.g, scale)) << 16u));
    atomicAdd(agBuffer[at + 4u], k * quantizeUnit(f0.b, scale) + ((k * quantizeUnit(alpha, scale)) << 16u));
}

// Sample s's aggregate id (0 where the clustering stored no metadata: c = 1 without a layer split).
uint sampleAggregate(uint s, uint pixelIndex) {
    uint c = agaa.shape.x, words = agaa.shape.z;
    return words > 0u ? unpackMetadata(metadata[pixelIndex * words + (s * metadataBits(c)) / 32u], s, c) : 0u;
}

// The fragment's k covered samples into its pixel's aggregates, as the routing says.
void accumulateFragment(uint pixelIndex, uint mask, AgQuantized f, MaterialSample m) {
    uint c = agaa.shape.x;
    uint n = agaa.shape.w;
    if (kRouteFragment != 0u) {
        // Algorithm 2: the first visible sample's aggregate takes the whole fragment. c = 1: whole
        // fragments cannot follow the per-sample layer flag; everything to aggregate 0 (the
        // lighting pass still takes the aggregate's position from its layer's samples).
        uint id = sampleAggregate(inLayer * 4u + uint(findLSB(mask)), pixelIndex);
        addToAggregate(pixelIndex * c + min(id, c - 1u), uint(bitCount(mask)), kNdf, f);
        return;
    }
    // Per sample: each covered sample to its own aggregate (c = 1: kOffLayer counts in slot 1).
    uint perAggregate[kMaxAggregates] = uint[](0u, 0u, 0u, 0u);
    for (uint hw = 0u; hw < 4u; ++hw) perAggregate[sampleAggregate(inLayer * 4u + hw, pixelIndex)] += (mask >> hw) & 1u;
    if (c == 1u && perAggregate[1] > 0u) addToOffLayer(pixelIndex, perAggregate[1], m, n);
    // Only the aggregates the fragment touches: a loop over their bits ends for a SIMD group
    // once every lane's are done (most fragments touch one), where a loop over all c with a
    // per-aggregate test would issue every aggregate's atomics masked (lavapipe runs both sides
    // of a branch, and a masked atomic still walks its lanes).
    uint touched = 0u;
    for (uint a = 0u; a < c; ++a) touched |= perAggregate[a] > 0u ? 1u << a : 0u;
    while (touched != 0u) {
        uint a = uint(findLSB(touched));
        touched &= touched - 1u;
        addToAggregate(pixelIndex * c + a, perAggregate[a], kNdf, f);
    }
}

void main() {
    uvec2 pixel;
    uint pixelIndex, mask;
    MaterialSample m;
    AgQuantized f;
    if (!generationFragment(pixel, pixelIndex, mask, m, f)) return;
    accumulateFragment(pixelIndex, mask, f, m);
    if (kSampleMaterial != 0u) writeSampleMaterial(pixelIndex, mask, m);
}
