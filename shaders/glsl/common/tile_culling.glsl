#ifndef AGAA_TILE_CULLING_GLSL
#define AGAA_TILE_CULLING_GLSL
#include "common/depth.glsl"
#include "shared/specialization.h"
// Tiled deferred light culling (one workgroup of kTileSize^2 invocations per tile):
// tile depth bounds from the samples' view distances, then every point/spot light
// tested against the tile's view-space box. Surviving lights are recorded as bits,
// not appended, so every invocation walks them in increasing index order and the
// sums are bit-identical run to run (an atomic append would order them by timing).
// Requires: `frame` (FrameConstants) and `lights` (GpuLight[]) declared by the includer.
// TILE_COORD: the tile's coordinates in tiles; the workgroup's own unless the includer maps
// workgroups to tiles itself (agaa/lighting_per_sample.comp dispatches only listed tiles).
#ifndef TILE_COORD
#define TILE_COORD gl_WorkGroupID.xy
#endif

// Specialisation id 2 (agaa/common/effects.h): 0 when the scene has no point or spot light,
// so every light touches every tile and the per-tile frustum box is not built.
layout(constant_id = kSpecTileLightCulling) const uint kTileLightCulling = 1u;

shared uint sTileMinBits;
shared uint sTileMaxBits;
shared uint sLightMask[kMaxLights / 32u];
#ifdef AGAA_SHADOW_GLSL
// With shadow maps (common/shadow.glsl included before this file) the lights that cast shadows
// go to a mask of their own, and lighting loops walk the two masks one after the other: a loop
// over every light that asked `does this one cast a shadow?` would make every light pay for the
// shadow taps on lavapipe, which executes both sides of any branch it cannot resolve at compile
// time. sLightMask then holds only the unshadowed lights.
shared uint sShadowedLightMask[kMaxLights / 32u];
#endif

void tileBoundsBegin() {
    if (gl_LocalInvocationIndex == 0u) {
        sTileMinBits = 0x7f7fffffu; // FLT_MAX: positive floats order like their bits
        sTileMaxBits = 0u;
    }
    for (uint i = gl_LocalInvocationIndex; i < kMaxLights / 32u; i += kTileSize * kTileSize) {
        sLightMask[i] = 0u;
#ifdef AGAA_SHADOW_GLSL
        sShadowedLightMask[i] = 0u;
#endif
    }
    barrier();
}

// Called by each invocation with the min/max view distance of its own non-sky samples
// (min > max when it has none).
void tileBoundsAdd(float tmin, float tmax) {
    if (tmin <= tmax) {
        atomicMin(sTileMinBits, floatBitsToUint(tmin));
        atomicMax(sTileMaxBits, floatBitsToUint(tmax));
    }
    barrier();
}

bool tileHasGeometry() { return sTileMinBits <= sTileMaxBits; }

bool sphereTouchesBox(vec3 c, float r, vec3 lo, vec3 hi) {
    vec3 d = max(max(lo - c, c - hi), vec3(0.0));
    return dot(d, d) <= r * r;
}

// Records light i as touching the tile, in the mask its shadow decides.
void tileAddLight(uint i) {
#ifdef AGAA_SHADOW_GLSL
    if (shadowLayer(i) >= 0) {
        atomicOr(sShadowedLightMask[i / 32u], 1u << (i % 32u));
        return;
    }
#endif
    atomicOr(sLightMask[i / 32u], 1u << (i % 32u));
}

// Culls every light against this workgroup's tile (TILE_COORD).
void tileCullLights() {
    if (!tileHasGeometry()) return; // sky-only tile: nothing is lit
    if (kTileLightCulling == 0u) {
        for (uint i = gl_LocalInvocationIndex; i < frame.counts.w; i += kTileSize * kTileSize)
            tileAddLight(i);
        return;
    }
    float tmin = uintBitsToFloat(sTileMinBits);
    float tmax = uintBitsToFloat(sTileMaxBits);
    vec2 lo = viewRayNdc(vec2(TILE_COORD * kTileSize), frame.extent, frame.projParams);
    vec2 hi = viewRayNdc(vec2((TILE_COORD + 1u) * kTileSize), frame.extent, frame.projParams);
    // View-space box of the tile's frustum slice: x = ndc.x t / P00, y = ndc.y t / P11.
    vec3 boxLo = vec3(1e30), boxHi = vec3(-1e30);
    for (int c = 0; c < 8; ++c) {
        vec2 ndc = vec2((c & 1) != 0 ? hi.x : lo.x, (c & 2) != 0 ? hi.y : lo.y);
        float t = (c & 4) != 0 ? tmax : tmin;
        vec3 p = vec3(ndc.x * t / frame.projParams.x, ndc.y * t / frame.projParams.y, -t);
        boxLo = min(boxLo, p);
        boxHi = max(boxHi, p);
    }
    uint count = frame.counts.w;
    for (uint i = gl_LocalInvocationIndex; i < count; i += kTileSize * kTileSize) {
        GpuLight light = lights[i];
        uint type = uint(light.directionType.w);
        float range = light.positionRange.w;
        bool touches = type == kLightDirectional || range <= 0.0 ||
                       sphereTouchesBox(light.positionRange.xyz, range, boxLo, boxHi);
        if (touches) tileAddLight(i);
    }
}

// Next culled light index at or after `start`, or kMaxLights when none. With shadow maps: the
// next light that casts no shadow (nextTileShadowedLight walks the others).
uint nextTileLight(uint start) {
    for (uint w = start / 32u; w < kMaxLights / 32u; ++w) {
        uint bits = sLightMask[w];
        if (w == start / 32u) bits &= ~0u << (start % 32u);
        if (bits != 0u) return w * 32u + uint(findLSB(bits));
    }
    return kMaxLights;
}

#ifdef AGAA_SHADOW_GLSL
uint nextTileShadowedLight(uint start) {
    for (uint w = start / 32u; w < kMaxLights / 32u; ++w) {
        uint bits = sShadowedLightMask[w];
        if (w == start / 32u) bits &= ~0u << (start % 32u);
        if (bits != 0u) return w * 32u + uint(findLSB(bits));
    }
    return kMaxLights;
}
#endif
#endif
