#ifndef AGAA_RASTER_SURFACE_VISIBILITY_OUTPUT_GLSL
#define AGAA_RASTER_SURFACE_VISIBILITY_OUTPUT_GLSL
// For a drawer's fragment shaders (agaa/common/raster_pass.h): RasterOutput::SurfaceVisibility,
// SBAA's visibility prepass (Salvi and Vidimce 2012, section 3.1; agaa/sbaa/sbaa.h): per sample only
// what the surface selection needs, no material:
//   0 RG8_UNORM   the geometric normal (the interpolated vertex normal, no normal map; flipped on
//                 back faces as the material flips it), octahedral, view space, as v * 0.5 + 0.5:
//                 the orientation SBAA's merge compares; w the coverage alpha alpha-to-coverage reads
//   1 R32_SFLOAT  the scene-wide triangle number + 1 as an exact float (0 = nothing; integer MSAA
//                 colour is 1x only on lavapipe), the key the fill pass (RasterOutput::SurfaceFill)
//                 finds its surfaces by: number the triangles as that pass does
// Interpolate the normal as the fill pass does (centroid, or `sample` at sample rate), so both
// passes see one surface. Set 0: binding 0 the frame.
//     vec3 face = surfaceVisibilityFaceNormal(); // first: screen derivatives
//     writeSurfaceVisibility(usable ? normal : face, coverage, firstTriangle + gl_PrimitiveID);
#include "raster/frame.glsl"
#include "common/depth.glsl"
#include "common/face_normal.glsl"
#include "common/octahedral.glsl"

layout(location = 0) out vec4 outSurfaceNormal;
layout(location = 1) out float outSurfacePrimitive;

// The fragment's triangle's plane normal, view space, facing the viewer: the stand-in where a
// vertex normal is degenerate (zero-length, as a mesh without normals can give). From the
// fragment's depth at its unshifted pixel position (layer l is drawn shifted by
// frame.layerOffsets[l] pixels, common/scene_vertex.glsl), by screen derivatives: call it in
// uniform control flow, before any discard.
vec3 surfaceVisibilityFaceNormal() {
    vec2 q = gl_FragCoord.xy - frame.layerOffsets[gl_Layer].xy;
    vec3 P = viewPositionFromDepth(q, gl_FragCoord.z, frame.extent, frame.depthParams, frame.projParams);
    return viewFaceNormal(P, normalize(-P));
}

// geometricNormal: unit, view space, facing the viewer's side. primitive: the scene-wide triangle
// number (the drawer's first triangle + gl_PrimitiveID).
void writeSurfaceVisibility(vec3 geometricNormal, float coverage, uint primitive) {
    outSurfaceNormal = vec4(encodeOctahedral(geometricNormal) * 0.5 + 0.5, 0.0, coverage);
    outSurfacePrimitive = float(primitive + 1u);
}
#endif
