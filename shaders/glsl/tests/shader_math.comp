#version 460
// Test kernel (tests/hard/test_shader_math.cpp): runs the shared shader math on edge inputs,
// one case per invocation, so the CPU can compare it with a double-precision twin. The
// functions are the production ones, included unchanged; only material textures are stubbed
// (every texture() reads a flat normal-map texel, so no descriptor set 1 is needed).
#extension GL_GOOGLE_include_directive : require

#include "shared/frame.h"
#include "shared/ag_buffer.h"
#include "shared/sggx.h"

// classify.glsl reads the frame constants and two G-buffer fetches; the kernel provides them
// per case (only planeDepthTolerance is called).
FrameConstants frame;
float gbufferDepth(ivec2 pixel, uint s) { return 0.5; }
vec3 gbufferNormal(ivec2 pixel, uint s) { return vec3(0.0, 0.0, 1.0); }

#define texture(sampler, uv) vec4(0.5, 0.5, 1.0, 1.0)
#include "common/brdf.glsl"
#include "common/curvature_roughness.glsl"
#define AGAA_NO_DERIVATIVES // face_normal.glsl's fragment-only part
#include "common/face_normal.glsl"
#include "common/depth.glsl"
#include "common/hemisphere_normal.glsl"
#include "common/lights.glsl"
#include "common/material.glsl"
#include "common/octahedral.glsl"
#include "common/tonemap.glsl"
#include "common/srgb.glsl"
#include "simple_complex/classify.glsl"
#undef texture

layout(local_size_x = 64) in;

// Keep in step with tests/hard/shader_math_cases.h (MathCase, MathResult, MathOp).
struct MathCase {
    uvec4 op; // x operation; y, z, w integer arguments
    vec4 a, b, c, d, e;
};
struct MathResult {
    vec4 r0, r1;
};

layout(set = 0, binding = 0, std430) readonly buffer Cases { MathCase cases[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Results { MathResult results[]; };
layout(push_constant) uniform Push { uint caseCount; };

const uint kOpOctahedral = 0u;   // a.xyz -> r0.xy encoded, r1.xyz decoded
const uint kOpOctDecode = 1u;    // a.xy -> r0.xyz
const uint kOpHemisphere = 2u;   // N a.xyz, V b.xyz -> r0.xy (theta, phi levels)
const uint kOpGgxD = 3u;         // NoH a.x, alpha a.y -> r0.x
const uint kOpSmith = 4u;        // NoV a.x, NoL a.y, alpha a.z -> r0.x
const uint kOpFresnel = 5u;      // f0 a.xyz, VoH a.w -> r0.xyz
const uint kOpBrdf = 6u;         // albedo a.xyz, metallic a.w, normal b.xyz, roughness b.w, V c.xyz, L d.xyz, E e.xyz
const uint kOpLight = 7u;        // GpuLight {a, b, c, d}, P e.xyz -> r0.xyz L, r1.xyz irradiance, r1.w reached
const uint kOpRangeWindow = 8u;  // d2 a.x, range a.y -> r0.x
const uint kOpToneMap = 9u;      // a.xyz -> r0.xyz
const uint kOpToksvig = 10u;     // alpha a.x, smax a.y, alphaMin a.z, alphaMax a.w -> r0.x
const uint kOpFiltered = 11u;    // length a.x, smax a.y -> r0.x
const uint kOpQuantize = 12u;    // v a.x, scale op.y -> r0.x unit, r0.y signed
const uint kOpMean = 13u;        // sum op.y, k op.z, scale op.w -> r0.x unit, r0.y signed
const uint kOpMaterial = 14u;    // GpuMaterial {a, b, c, textures (-1,-1,op.y,-1)}, geometric normal d.xyz, tangent e, front op.z
const uint kOpDepth = 15u;       // d a.x, near a.y, far a.z -> r0.x view distance
const uint kOpPlaneTolerance = 16u; // extent a, projParams b, pixelPos c.xy, t0 c.z, slopeScale c.w, n0 d.xyz -> r0.x
const uint kOpShadeEvent = 17u;  // brdf case, emissive e.w, exposure c.w: the capped, tone-mapped event
const uint kOpBrdfAniso = 18u;   // albedo a.xyz, metallic a.w, N b.xyz, V c.xyz, L d.xyz, T e.xyz, alphas (c.w, d.w)
                                 // -> r0.xyz radiance, r1.xyz its specular part (E = 1)
const uint kOpSggxLobe = 19u;    // S diagonal a.xyz, off-diagonal (xy, xz, yz) b.xyz, V c.xyz -> r0 (N, alphaT), r1 (T, alphaB)
const uint kOpToneMapAggregate = 20u; // L a.xyz, S b.xyz, variance c.xyz -> r0.xyz; r1.x spike ratio of (d.x, d.y)
const uint kOpPixelFootprint = 22u; // t a.x, extent b, projParams c -> r0.x
const uint kOpFaceNormal = 23u;  // dP/dx a.xyz, dP/dy b.xyz, towards camera c.xyz -> r0.xyz
const uint kOpFilteredCosine = 24u; // x a.x, spread a.y -> r0.x
const uint kOpMeanNormalLobe = 27u; // mean normal a.xyz -> r0 (direction, length)
const uint kOpViewFootprint = 28u; // theta a.x, alpha a.y, screen covariance b.xyz -> r0.x weight
const uint kOpAggregateWidth = 25u; // direction a.xyz, screen covariance b.xyz -> r0.x
const uint kOpEnvironmentRoughness = 26u; // filtered alpha a.x, material alpha a.y -> r0.x
const uint kOpBrdfFiltered = 29u; // as kOpBrdfAniso, spread e.w (evaluateBrdfAnisotropicFiltered) -> r0.xyz, r1.xyz
const uint kOpSrgbEncode = 30u; // linear a.xyz -> r0.xyz (srgbEncode, the G-buffer albedo's store)
const uint kOpSrgbDecode = 31u; // encoded a.xyz -> r0.xyz (srgbDecode, the kept material's albedo)
const uint kOpCurvature = 21u;   // dN/dx a.xyz, dN/dy b.xyz, roughness c.x, max footprint c.y, boost c.z -> r0.x

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= caseCount) return;
    MathCase k = cases[i];
    vec4 r0 = vec4(0.0), r1 = vec4(0.0);
    uint op = k.op.x;
    if (op == kOpOctahedral) {
        vec2 e = encodeOctahedral(k.a.xyz);
        r0.xy = e;
        r1.xyz = decodeOctahedral(e);
    } else if (op == kOpOctDecode) {
        r0.xyz = decodeOctahedral(k.a.xy);
    } else if (op == kOpHemisphere) {
        r0.xy = vec2(encodeHemisphereNormal(k.a.xyz, k.b.xyz));
    } else if (op == kOpGgxD) {
        r0.x = ggxD(k.a.x, k.a.y);
    } else if (op == kOpSmith) {
        r0.x = smithVisibility(k.a.x, k.a.y, k.a.z);
    } else if (op == kOpFresnel) {
        r0.xyz = fresnelSchlick(k.a.xyz, k.a.w);
    } else if (op == kOpBrdf || op == kOpShadeEvent) {
        SurfaceInputs s;
        s.albedo = k.a.xyz;
        s.metallic = k.a.w;
        s.normal = k.b.xyz;
        s.roughness = k.b.w;
        r0.xyz = evaluateBrdf(s, k.c.xyz, k.d.xyz, k.e.xyz);
        if (op == kOpShadeEvent) {
            // As shadeGBufferSurface: emissive added, exposure, the kMaxRadiance cap, tone map.
            vec3 radiance = min((r0.xyz + vec3(k.e.w)) * k.c.w, vec3(kMaxRadiance));
            r0.xyz = radiance;
            r1.xyz = toneMapAces(radiance);
        }
    } else if (op == kOpBrdfAniso) {
        SurfaceInputs s;
        s.albedo = k.a.xyz;
        s.metallic = k.a.w;
        s.normal = k.b.xyz;
        s.roughness = 0.5;
        vec3 spec;
        r0.xyz = evaluateBrdfAnisotropic(s, k.e.xyz, cross(k.b.xyz, k.e.xyz), k.c.w, k.d.w, k.c.xyz, k.d.xyz,
                                         vec3(1.0), spec);
        r1.xyz = spec;
    } else if (op == kOpBrdfFiltered) {
        SurfaceInputs s;
        s.albedo = k.a.xyz;
        s.metallic = k.a.w;
        s.normal = k.b.xyz;
        s.roughness = 0.5;
        vec3 spec;
        r0.xyz = evaluateBrdfAnisotropicFiltered(s, k.e.xyz, cross(k.b.xyz, k.e.xyz), k.c.w, k.d.w, k.e.w, k.c.xyz,
                                                 k.d.xyz, vec3(1.0), spec);
        r1.xyz = spec;
    } else if (op == kOpSggxLobe) {
        SggxLobe lobe = sggxLobe(k.a.x, k.a.y, k.a.z, k.b.x, k.b.y, k.b.z, k.c.xyz, kSggxDegenerate,
                                 kMinSggxEigenvalue);
        r0 = vec4(lobe.normal, lobe.alphaT);
        r1 = vec4(lobe.tangent, lobe.alphaB);
    } else if (op == kOpFaceNormal) {
        r0.xyz = faceNormalFromDerivatives(k.a.xyz, k.b.xyz, k.c.xyz);
    } else if (op == kOpFilteredCosine) {
        r0.x = filteredClampedCosine(k.a.x, k.a.y);
    } else if (op == kOpMeanNormalLobe) {
        r0 = meanNormalLobe(k.a.xyz);
    } else if (op == kOpViewFootprint) {
        r0.x = viewFootprintWeight(k.a.x, k.b.xyz, k.a.y);
    } else if (op == kOpEnvironmentRoughness) {
        r0.x = environmentAggregateRoughness(k.a.x, k.a.y);
    } else if (op == kOpAggregateWidth) {
        r0.x = aggregateWidth(k.a.xyz, k.b.xyz);
    } else if (op == kOpPixelFootprint) {
        r0.x = pixelFootprint(k.a.x, k.b, k.c);
    } else if (op == kOpCurvature) {
        r0.x = curvatureRoughness(k.c.x, k.a.xyz, k.b.xyz, k.c.y, k.c.z);
    } else if (op == kOpToneMapAggregate) {
        r0.xyz = toneMapAggregate(k.a.xyz, k.b.xyz, k.c.xyz);
        r1.x = sggxSpikeRatio(k.d.x, k.d.y, k.d.z);
    } else if (op == kOpLight) {
        GpuLight light;
        light.positionRange = k.a;
        light.directionType = k.b;
        light.radiance = k.c;
        light.spot = k.d;
        vec3 L, E;
        bool reached = lightIncidence(light, k.e.xyz, L, E);
        r0.xyz = L;
        r1.xyz = E;
        r1.w = reached ? 1.0 : 0.0;
    } else if (op == kOpRangeWindow) {
        r0.x = rangeWindow(k.a.x, k.a.y);
    } else if (op == kOpToneMap) {
        r0.xyz = toneMapAces(k.a.xyz);
    } else if (op == kOpSrgbEncode) {
        r0.xyz = srgbEncode(k.a.xyz);
    } else if (op == kOpSrgbDecode) {
        r0.xyz = srgbDecode(k.a.xyz);
    } else if (op == kOpToksvig) {
        r0.x = toksvigLength(k.a.x, k.a.y, k.a.z, k.a.w);
    } else if (op == kOpFiltered) {
        r0.x = filteredAlpha(k.a.x, k.a.y);
    } else if (op == kOpQuantize) {
        r0.x = float(quantizeUnit(k.a.x, k.op.y));
        r0.y = float(quantizeSigned(k.a.x, k.op.y));
    } else if (op == kOpMean) {
        r0.x = meanUnit(k.op.y, k.op.z, k.op.w);
        r0.y = meanSigned(k.op.y, k.op.z, k.op.w);
    } else if (op == kOpMaterial) {
        GpuMaterial m;
        m.baseColorFactor = k.a;
        m.emissive = k.b;
        m.params = k.c;
        m.textures = ivec4(-1, -1, int(k.op.y), -1);
        MaterialSample s = evaluateMaterial(m, vec4(0.5, 0.5, 0.0, 0.0), vec4(1.0), k.d.xyz, k.e, k.op.z != 0u);
        r0 = vec4(s.normal, s.roughness);
        r1 = vec4(s.albedo, s.metallic);
    } else if (op == kOpDepth) {
        r0.x = viewDistanceFromDepth(k.a.x, k.a.y, k.a.z);
    } else if (op == kOpPlaneTolerance) {
        frame.extent = k.a;
        frame.projParams = k.b;
        r0.x = planeDepthTolerance(k.c.xy, k.c.z, k.d.xyz, k.c.w);
    }
    results[i].r0 = r0;
    results[i].r1 = r1;
}
