#ifndef AGAA_SHARED_STREAMING_H
#define AGAA_SHARED_STREAMING_H
#include "shared/glsl_cpp.h"
// Streaming G-buffer compression (Kerzner and Salvi 2014, seed 001): the per-surface record the
// compression pass writes (streaming/compress.comp), the lighting pass reads
// (streaming/lighting.comp), and the CPU reference (agaa/streaming/streaming_compression.cpp)
// reproduces.

SHARED_BEGIN

SHARED_CONST kStreamingMaxSurfaces = 3u; // --surfaces 1..3 (the paper: three are enough)
// One surface of one pixel: 9 words (36 bytes), at ((y * width + x) * S + slot) * 9 in the buffer,
// the slots in front-to-back order of zView. The paper's figure 2 record is 20 bytes (depth,
// half2 derivatives, two 8-bit masks, albedo and normal words); ours also keeps emissive,
// metallic and roughness (every method's material inputs) and 32-bit masks (n up to 32).
SHARED_CONST kStreamingSurfaceWords = 9u;
// word 0: coverage (raster coverage mask; 0 = an empty slot)
// word 1: depth-tested coverage (the samples it still owns after occluder fusion, section 3.2.1)
// word 2: zView, view-space depth at the pixel centre in metres (the minimum over merges), float bits
// word 3: dz/dx, dz/dy per pixel step (packHalf2x16)
// word 4: the averaged normal, view space, octahedral (packSnorm2x16)
// word 5: albedo r, g (packHalf2x16); word 6: albedo b, metallic
// word 7: emissive r, g; word 8: emissive b, roughness
SHARED_CONST kStreamingWordCoverage = 0u;
SHARED_CONST kStreamingWordDepthTested = 1u;
SHARED_CONST kStreamingWordZView = 2u;
SHARED_CONST kStreamingWordDepthDerivatives = 3u;
SHARED_CONST kStreamingWordNormal = 4u;
SHARED_CONST kStreamingWordAlbedoRg = 5u;
SHARED_CONST kStreamingWordAlbedoBMetal = 6u;
SHARED_CONST kStreamingWordEmissiveRg = 7u;
SHARED_CONST kStreamingWordEmissiveBRoughness = 8u;

// Largest finite half float: depth derivatives of grazing planes are clamped to it before
// packHalf2x16 (word 3), so the record never holds an infinity.
SHARED_CONST_FLOAT kStreamingMaxDerivative = 65504.0f;

// Smallest |cos| between a fragment's normal and its view ray when its depth derivatives are
// taken from the plane through its sample with that normal. The G-buffer normal is the shading
// normal: thin geometry (fur, grass blades) has shading normals near-perpendicular to the ray at
// its silhouettes while its triangles' depth slope is bounded; without the floor such a fragment's
// depth range spans the pixel's whole depth and merges it with what lies behind (on lavapipe the
// replayed fragments are depth-tested, so their coverage is always disjoint and only the depth and
// normal tests keep surfaces apart).
SHARED_CONST_FLOAT kStreamingMinFacing = 0.25f;

// zView is the fragment's plane at the pixel centre (section 3: "depth computed at the pixel
// center"), extrapolated from its first sample by the derivatives; the extrapolation is kept
// within [1/2, 2] times the sample's depth so a steep plane cannot reach the camera.
SHARED_CONST_FLOAT kStreamingCentreDepthRange = 2.0f;

struct StreamingParams {
    // x: cos of the normal threshold (a fragment merges only if n0 . n1 > x; the paper's
    // alpha = pi/4 gives 0.7071); yzw unused.
    vec4 merge;
    uvec4 counts; // x: S, the surfaces kept per pixel; yzw unused
};

SHARED_END
#endif
