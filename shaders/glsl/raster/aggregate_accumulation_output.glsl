#ifndef AGAA_RASTER_AGGREGATE_ACCUMULATION_OUTPUT_GLSL
#define AGAA_RASTER_AGGREGATE_ACCUMULATION_OUTPUT_GLSL
// For a drawer's fragment shaders (agaa/common/raster_pass.h): RasterOutput::AggregateAccumulation,
// AGAA step 3, AG-buffer generation by the accumulation kernel (paper section 3.4, Algorithm 2,
// section 4.2). The scene is rasterised again at n samples over the prepass depth: depth EQUAL
// without writes, early fragment tests and post-depth coverage, so gl_SampleMaskIn holds exactly the
// samples this fragment is visible at; the stencil keeps the first fragment per sample (section
// 4.2.2: coplanar duplicates never count twice). Each fragment's material, evaluated by the drawer as
// a classic G-buffer would, is added with integer atomics on fixed-point values (order-independent:
// bit-identical frames) into its pixel's aggregates: its normal distribution (Toksvig vector or
// SGGX matrix, shared/agaa.h), albedo, metallic and sample count. With a tolerance it also keeps
// each covered sample's material for the shading rate (shared/sample_material.h).
//     accumulateAggregateFragment(layer, material);
// layer: the draw's instance (gl_InstanceIndex), passed from the vertex shader as a flat varying
// (gl_Layer is not readable in a fragment shader without the geometry-shader capability).
// Set 0: binding 0 the frame, 2 AGAA's constants, 3 the clustering's metadata, 4 the AG-buffer
// (6 the same as 64-bit words under AGAA_INT64), 7 the per-sample materials. The build's macros are
// RasterPass::defines: AGAA_EMISSIVE (location 0: the per-sample emissive target, B10G11R11),
// AGAA_INT64 (shaderBufferInt64Atomics) and AGAA_SUBGROUP (subgroup pre-reduction); its
// specialisation ids 0 to 2 are RasterPass::specialization.
//
// Routing (specialisation id 1, agaa/aggregate/agaa_constants.h AggregateRouting):
//  - samples (default): each aggregate present in the fragment's mask receives the fragment's
//    values weighted by its own number of samples, so the AG-buffer's sample counts equal the
//    metadata's exactly (a fragment straddling two clusters would otherwise count all its
//    samples in one);
//  - fragment: Algorithm 2 as the paper writes it: the whole fragment goes to the aggregate of
//    its first visible sample, one set of atomics per fragment. The lighting pass then weights
//    each aggregate by the samples it received, not by the metadata's assignment.
// Atomics:
//  - AGAA_INT64: the 6 words of an aggregate as three 64-bit adds (an aggregate starts on an even
//    word: 6 words each). No field ever carries out of its word (layout proof in shared/agaa.h), so
//    a 64-bit add of two words equals two 32-bit adds: the AG-buffer is bit-identical.
//  - AGAA_SUBGROUP: fragments of one subgroup that target the same (pixel, aggregate) first sum
//    their increments with subgroupAdd, and one lane adds the sum (integer sums: order-free,
//    bit-identical). It saves atomics only where a subgroup holds fragments of several primitives
//    covering one pixel (GPUs pack quads of several triangles into one wave); lavapipe's fragment
//    subgroups are the pixels of one triangle, so there it only adds the loop.
// AGAA_SAMPLE_MATERIAL 0 (this project's test build, which records fragments instead): no binding
// 7 and no accumulateAggregateFragment.
#extension GL_ARB_post_depth_coverage : require
#ifndef AGAA_EMISSIVE
#define AGAA_EMISSIVE 0
#endif
#ifndef AGAA_INT64
#define AGAA_INT64 0
#endif
#ifndef AGAA_SUBGROUP
#define AGAA_SUBGROUP 0
#endif
#ifndef AGAA_SAMPLE_MATERIAL
#define AGAA_SAMPLE_MATERIAL 1
#endif
#if AGAA_INT64
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#endif
#if AGAA_SUBGROUP
#extension GL_KHR_shader_subgroup_ballot : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#endif
#include "raster/frame.glsl"
#include "shared/agaa.h"
#include "shared/ag_buffer.h"
#include "shared/clustering.h"
#include "shared/sample_material.h"
#include "shared/specialization.h"
#include "common/epsilon.glsl"
#include "common/material_sample.glsl"
#include "common/octahedral.glsl"
#include "common/srgb.glsl"

layout(early_fragment_tests) in;
layout(post_depth_coverage) in;

layout(set = 0, binding = 2) uniform Agaa { AgaaConstants agaa; };
layout(set = 0, binding = 3, std430) readonly buffer Metadata { uint metadata[]; };
layout(set = 0, binding = 4, std430) buffer AgBuffer { uint agBuffer[]; };
#if AGAA_INT64
// The same AG-buffer seen as 64-bit words (bound twice: binding 6 aliases binding 4).
layout(set = 0, binding = 6, std430) buffer AgBuffer64 { uint64_t agBuffer64[]; };
#endif
// Specialisation ids 0 and 1: the normal distribution (kNdfToksvig, kNdfSggx) and the routing
// (0 per sample, 1 per fragment). Constants, not uniforms: lavapipe executes both sides of a
// branch it cannot resolve at compile time.
layout(constant_id = kSpecGenerationNdf) const uint kNdf = 0u;
layout(constant_id = kSpecGenerationRouting) const uint kRouteFragment = 0u;
// With a tolerance (AggregateSettings::tolerance): 1, and each covered sample's material is kept
// for the shading rate (shared/sample_material.h); without one binding 7 is a 16-byte stand-in
// this never touches.
layout(constant_id = kSpecGenerationSampleMaterial) const uint kSampleMaterial = 0u;
#if AGAA_EMISSIVE
// Emissive stays per sample (seed 004: no HDR fireflies): an MSAA target, resolved per sample.
layout(location = 0) out vec4 outEmissive;
#endif

// The fragment's values as the AG-buffer's fixed-point fields (shared/agaa.h), in either
// normal-distribution layout.
AgQuantized quantizeFragment(MaterialSample m, uint n) {
    float alpha = m.roughness * m.roughness;
    AgQuantized f;
    // The sample's own lobe, for the two-point resolve and the environment's level (shared/agaa.h
    // w5): not floored at kMinGgxAlpha, so that a near-mirror's level is its own (2^26 - 1 steps
    // resolve alpha to 1.5e-8; the lighting pass floors the mean where the BRDF needs it).
    f.q[10] = quantizeUnit(min(alpha, kMaxGgxAlpha), kMaterialAlphaScale);
    if (kNdf == kNdfSggx) {
        // The sample's GGX lobe as an SGGX matrix (shared/sggx.h), alpha in the BRDF's range.
        float a = clamp(alpha, kMinGgxAlpha, kMaxGgxAlpha);
        float a2 = a * a;
        vec3 N = m.normal * (1.0 - a2); // S = (1 - a^2) n n^T + a^2 I
        uint scale = unitScale(kSggxFieldBits, n);
        f.q[0] = quantizeUnit(N.x * m.normal.x + a2, scale);
        f.q[1] = quantizeUnit(N.y * m.normal.y + a2, scale);
        f.q[2] = quantizeUnit(N.z * m.normal.z + a2, scale);
        f.q[3] = quantizeUnit(N.x * m.normal.y + 0.5, scale); // off-diagonal: [-1/2, 1/2] + 1/2
        f.q[4] = quantizeUnit(N.x * m.normal.z + 0.5, scale);
        f.q[5] = quantizeUnit(N.y * m.normal.z + 0.5, scale);
        f.q[6] = quantizeUnit(m.albedo.r, scale);
        f.q[7] = quantizeUnit(m.albedo.g, scale);
        f.q[8] = quantizeUnit(m.albedo.b, scale);
        f.q[9] = quantizeUnit(m.metallic, unitScale(kSggxMetallicBits, n));
    } else {
        vec3 t = m.normal * toksvigLength(alpha, agaa.toksvig.x, agaa.toksvig.y, agaa.toksvig.z);
        f.q[0] = quantizeSigned(t.x, toksvigScaleX(n));
        f.q[1] = quantizeSigned(t.y, toksvigScaleYZ(n));
        f.q[2] = quantizeSigned(t.z, toksvigScaleYZ(n));
        f.q[3] = 0u;
        f.q[4] = 0u;
        f.q[5] = 0u;
        f.q[6] = quantizeUnit(m.albedo.r, kUnormScale);
        f.q[7] = quantizeUnit(m.albedo.g, kUnormScale);
        f.q[8] = quantizeUnit(m.albedo.b, kUnormScale);
        f.q[9] = quantizeUnit(m.metallic, kUnormScale);
    }
    return f;
}

// What every build of the pass does with the fragment's material first: its emissive written, then,
// for a fragment visible at one of its layer's samples at least, its pixel, its covered samples
// (mask) and its values in the AG-buffer's fixed-point fields. False for a fragment the depth test
// left no sample of.
bool aggregateFragment(MaterialSample m, out uvec2 pixel, out uint pixelIndex, out uint mask, out AgQuantized f) {
#if AGAA_EMISSIVE
    outEmissive = vec4(min(m.emissive, vec3(kMaxRadiance)), 1.0);
#endif
    mask = uint(gl_SampleMaskIn[0]) & 0xFu;
    if (mask == 0u) return false;
    pixel = uvec2(gl_FragCoord.xy);
    pixelIndex = pixel.y * uint(frame.extent.x) + pixel.x;
    f = quantizeFragment(m, agaa.shape.w);
    return true;
}

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
void accumulateFragment(uint layer, uint pixelIndex, uint mask, AgQuantized f, MaterialSample m) {
    uint c = agaa.shape.x;
    uint n = agaa.shape.w;
    if (kRouteFragment != 0u) {
        // Algorithm 2: the first visible sample's aggregate takes the whole fragment. c = 1: whole
        // fragments cannot follow the per-sample layer flag; everything to aggregate 0 (the
        // lighting pass still takes the aggregate's position from its layer's samples).
        uint id = sampleAggregate(layer * 4u + uint(findLSB(mask)), pixelIndex);
        addToAggregate(pixelIndex * c + min(id, c - 1u), uint(bitCount(mask)), kNdf, f);
        return;
    }
    // Per sample: each covered sample to its own aggregate (c = 1: kOffLayer counts in slot 1).
    uint perAggregate[kMaxAggregates] = uint[](0u, 0u, 0u, 0u);
    for (uint hw = 0u; hw < 4u; ++hw) perAggregate[sampleAggregate(layer * 4u + hw, pixelIndex)] += (mask >> hw) & 1u;
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


#if AGAA_SAMPLE_MATERIAL
// Binding 7 (shared/sample_material.h): each covered sample's material, for the shading rate.
layout(set = 0, binding = 7, std430) buffer SampleMaterials { uint sampleMaterial[]; };

// The fragment's material into each of its covered samples' words (shared/sample_material.h). The
// stencil's first-fragment test leaves one fragment per sample, so no word is written twice, and
// an add into the cleared word (agaa.clear) stores the value. Atomic all the same, as every access
// to the AG-buffer here: a plain store would make the synchronisation validation see writes racing
// between draws.
void writeSampleMaterial(uint layer, uint pixelIndex, uint mask, MaterialSample m) {
    uint words[kSampleMaterialWords] =
        uint[](packSnorm2x16(encodeOctahedral(m.normal)), packUnorm4x8(vec4(srgbEncode(m.albedo), m.metallic)),
               packUnorm2x16(vec2(m.roughness, 0.0)));
    for (uint hw = 0u; hw < 4u; ++hw) {
        if ((mask & (1u << hw)) == 0u) continue;
        uint at = sampleMaterialWord(pixelIndex, agaa.shape.w, layer * 4u + hw);
        for (uint w = 0u; w < kSampleMaterialWords; ++w) atomicAdd(sampleMaterial[at + w], words[w]);
    }
}

// The accumulation kernel for one fragment of `layer` with material m.
void accumulateAggregateFragment(uint layer, MaterialSample m) {
    uvec2 pixel;
    uint pixelIndex, mask;
    AgQuantized f;
    if (!aggregateFragment(m, pixel, pixelIndex, mask, f)) return;
    accumulateFragment(layer, pixelIndex, mask, f, m);
    if (kSampleMaterial != 0u) writeSampleMaterial(layer, pixelIndex, mask, m);
}
#endif
#endif
