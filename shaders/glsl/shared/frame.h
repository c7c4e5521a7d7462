#ifndef AGAA_SHARED_FRAME_H
#define AGAA_SHARED_FRAME_H
#include "shared/glsl_cpp.h"

SHARED_BEGIN

SHARED_CONST kMaxSamples = 32u; // highest emulated rate (8 layers of 4x)
SHARED_CONST kMaxLayers = 8u;
SHARED_CONST kMaxLights = 1024u; // tile light lists live in shared memory
// lavapipe: maxPerStageDescriptorSamplers = 32; the rest is left for the passes' own bindings.
SHARED_CONST kMaxSceneTextures = 24u;
SHARED_CONST kTileSize = 16u; // tiled lighting: 16x16 pixels per workgroup

SHARED_CONST kLightDirectional = 0u;
SHARED_CONST kLightPoint = 1u;
SHARED_CONST kLightSpot = 2u;

SHARED_CONST kAlphaOpaque = 0u;
SHARED_CONST kAlphaMask = 1u;
SHARED_CONST kAlphaBlend = 2u;

// Per-frame constants, one uniform buffer read by every pass.
struct FrameConstants {
    mat4 view; // world -> view (looking down -Z)
    mat4 proj; // view -> clip, reversed Z (near -> 1, far -> 0), Y flipped for Vulkan
    mat4 viewProj;
    // Camera-relative transforms: viewProjRelative = proj * the rotation of view, applied to a
    // world position minus eye.xyz (the camera's world position; w unused). viewProj * p sums
    // terms as large as the coordinates and cancels them: 1e5 m from the origin its fp32 rounding
    // moved vertices by pixels (hard-far). p - eye is exact wherever p is within a factor 2 of
    // the eye (Sterbenz), so what is left is the rounding of a short vector.
    mat4 viewProjRelative;
    vec4 eye;
    // Sample-rate emulation (DESIGN section 3): layer l rasterises the scene shifted by
    // layerOffsets[l].xy pixels, so its hardware sample at q sees the point q - offset.
    vec4 layerOffsets[kMaxLayers];
    // Position of sample s (= layer * samplesPerLayer + hardware sample) inside its pixel, in [0,1)^2.
    vec4 samplePositions[kMaxSamples];
    vec4 skyRadiance; // rgb: radiance of uncovered samples
    vec4 extent;      // width, height, 1/width, 1/height
    vec4 depthParams; // znear, zfar, exposure, unused
    // proj[0][0], proj[1][1], proj[2][0], proj[2][1]: zw are 0 except in a tile of a larger view
    // (engine/frame/frame_constants.h ViewTile), whose rays are off the axis.
    vec4 projParams;
    uvec4 counts; // samples n, samples per layer, layers, light count
    // x: the tile scale (1 = this frame is the whole view); the shadow maps are fitted to the
    // whole view's frustum, so every tile of a view sees the same ones. yzw unused.
    vec4 viewTile;
};

// A punctual light in view space. Intensity already multiplied into colour.
struct GpuLight {
    vec4 positionRange; // xyz view-space position; w: range (0 = infinite)
    vec4 directionType; // xyz view-space direction the light travels; w: type as float
    vec4 radiance;      // rgb colour * intensity (lux or candela); w unused
    vec4 spot;          // x cos(outer), y 1/max(cos(inner)-cos(outer), eps), zw unused
};

struct GpuMaterial {
    vec4 baseColorFactor;
    vec4 emissive;  // rgb emissiveFactor * strength; w alphaCutoff
    vec4 params;    // x metallic, y roughness, z normalScale, w alphaMode as float
    ivec4 textures; // base colour, metal-roughness, normal, emissive (-1 = none)
    // KHR_texture_transform per slot (same order): uv' = M uv + offset, M = R(rotation) S(scale)
    // stored column-major as (m00, m10, m01, m11); offsets of slots 0, 1 in uvOffset[0].xy, .zw
    // and of slots 2, 3 in uvOffset[1].
    vec4 uvMatrix[4];
    vec4 uvOffset[2];
    ivec4 texCoords; // per slot: the UV set it reads, 0 (TEXCOORD_0) or 1 (TEXCOORD_1)
};

SHARED_END
#endif
