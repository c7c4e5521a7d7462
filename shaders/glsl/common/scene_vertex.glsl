#ifndef AGAA_SCENE_VERTEX_GLSL
#define AGAA_SCENE_VERTEX_GLSL
// The one vertex transform every scene raster pass uses. Passes that depth-test
// EQUAL against an earlier pass must produce bit-identical positions: same code,
// same inputs, `invariant gl_Position` (../shared/LAVAPIPE.md, "Traps").
//
// Sample-rate emulation (paper section 4.4): instance l of each draw goes to
// layer l, shifted by frame.layerOffsets[l] pixels in clip space, so layer l's
// hardware samples land on the emulated positions q - offset.
#extension GL_ARB_shader_viewport_layer_array : require

invariant gl_Position;

// Camera-relative (FrameConstants::viewProjRelative): the world position minus the eye first.
vec4 sceneClipPosition(vec3 worldPosition, uint layer, FrameConstants frame) {
    vec4 clip = frame.viewProjRelative * vec4(worldPosition - frame.eye.xyz, 1.0);
    clip.xy += frame.layerOffsets[layer].xy * 2.0 * frame.extent.zw * clip.w;
#ifdef AGAA_TEST_PERTURB_SCENE
    clip.x += 0.0625 * 2.0 * frame.extent.z * clip.w; // tools/perturb-test.sh: every vertex 1/16 pixel right
#endif
    return clip;
}

// The view-space position of a world position, camera-relative as sceneClipPosition.
vec3 sceneViewPosition(vec3 worldPosition, FrameConstants frame) {
    return mat3(frame.view) * (worldPosition - frame.eye.xyz);
}
#endif
