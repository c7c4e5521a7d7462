#ifndef AGAA_SHARED_SBAA_H
#define AGAA_SHARED_SBAA_H
#include "shared/glsl_cpp.h"
// Surface Based Anti-Aliasing (Salvi and Vidimce 2012): the per-surface G-buffer record the
// surface pass writes (sbaa/surfaces.comp) and the lighting pass reads (sbaa/lighting.comp), and
// the CPU twin of the selection (agaa/sbaa/surface_selection.cpp) reproduces.

SHARED_BEGIN

SHARED_CONST kSbaaMaxSurfaces = 6u; // --surfaces 1..6
// One surface of one pixel: 8 words (32 bytes), at ((y * width + x) * S + slot) * 8 in the buffer.
SHARED_CONST kSbaaSurfaceWords = 8u;
// word 0: coverage mask (bit s = sample s belongs to the surface; 0 = an empty slot)
// Words 0, 1 and 7 are the surface pass's (sbaa/surfaces.comp), words 2..6 the fill pass's
// (sbaa/fill*.frag: the material of the representative primitive at the representative sample).
// word 1: the raw depth of the surface's representative sample (its first sample), float bits
// word 2: its shading normal, octahedral, packSnorm2x16
// word 3: albedo r, g (packHalf2x16); word 4: albedo b, metallic
// word 5: emissive r, g; word 6: emissive b, roughness
// word 7: representative sample index (bits 0..7) | primitive id (bits 8..31, 24 bits)
SHARED_CONST kSbaaWordMask = 0u;
SHARED_CONST kSbaaWordDepth = 1u;
SHARED_CONST kSbaaWordNormal = 2u;
SHARED_CONST kSbaaWordAlbedoRg = 3u;
SHARED_CONST kSbaaWordAlbedoBMetal = 4u;
SHARED_CONST kSbaaWordEmissiveRg = 5u;
SHARED_CONST kSbaaWordEmissiveBRoughness = 6u;
SHARED_CONST kSbaaWordSampleAndPrimitive = 7u;

struct SbaaParams {
    // x: min cosine between two primitives' normals for MERGE; y: depth tolerance in units of the
    // surface's plane slope |dz/dx| + |dz/dy| (simple_complex/classify.glsl planeDepthTolerance);
    // zw unused.
    vec4 merge;
    uvec4 counts; // x: S, the surfaces kept per pixel; y: merge on (1) / off (0); zw unused
};

SHARED_END
#endif
