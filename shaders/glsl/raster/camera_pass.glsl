#ifndef AGAA_RASTER_CAMERA_PASS_GLSL
#define AGAA_RASTER_CAMERA_PASS_GLSL
// For a drawer's vertex shaders (agaa/common/raster_pass.h): set 0 of the camera's raster passes
// (RasterOutput SampleGBuffer, SampleGBufferPrimitive, SurfaceVisibility), which the module pushes,
// and the vertex transform they share. Instance i of a draw renders into layer i, shifted by that
// layer's sample offset (the layered 4x emulation of 8, 16 and 32 samples):
//     gl_Position = cameraClipPosition(worldPosition); gl_Layer = int(gl_InstanceIndex);
// Positions are world space; the transform is camera-relative (FrameConstants::eye), so a world far
// from the origin keeps its precision. Passes that test EQUAL against another pass's depth need
// bit-identical positions: every drawer uses this function, `invariant gl_Position` included.
#include "raster/frame.glsl"
#include "common/scene_vertex.glsl"

vec4 cameraClipPosition(vec3 worldPosition) {
    return sceneClipPosition(worldPosition, uint(gl_InstanceIndex), frame);
}
// A world-space position into view space (camera-relative, as cameraClipPosition): AGAA's
// visibility prepass takes the face normal from its screen derivatives.
vec3 cameraViewPosition(vec3 worldPosition) {
    return sceneViewPosition(worldPosition, frame);
}
// A world-space direction (a normal) into view space, where the G-buffer stores it.
vec3 cameraViewDirection(vec3 worldDirection) {
    return mat3(frame.view) * worldDirection;
}
#endif
