#ifndef AGAA_SCENE_MATERIALS_GLSL
#define AGAA_SCENE_MATERIALS_GLSL
// This project's scene as a client of the raster contract (agaa/common/raster_pass.h): its
// material table and textures live in the drawer's own set 1 (eng::frame::GpuScene::materialSet),
// never in set 0, which is the module's. A host's shaders declare their own materials instead.
// Needs shared/frame.h (GpuMaterial, kMaxSceneTextures).
layout(set = 1, binding = 0) uniform sampler2D textures[kMaxSceneTextures];
layout(set = 1, binding = 1, std430) readonly buffer Materials { GpuMaterial materials[]; };
#endif
