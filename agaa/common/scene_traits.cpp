#include "agaa/common/scene_traits.h"

#include "engine/frame/gpu_scene.h"

namespace agaa {

SceneTraits sceneTraits(const eng::scene::Scene& scene) {
    SceneTraits t;
    t.source = scene.source;
    t.features = eng::scene::deriveSceneFeatures(scene);
    t.materials = uint32_t(scene.materials.size());
    t.triangles = scene.triangleCount();
    t.bounds = scene.bounds;
    t.lights = scene.lights;
    t.cameras = scene.cameras;
    t.lightingMode = scene.lightingMode;
    t.lightingCause = scene.lightingCause;
    t.environmentSource = scene.environment.source;
    return t;
}

TechniqueContent::TechniqueContent(const eng::frame::GpuScene& scene)
    : traits(sceneTraits(scene.scene())), scene(&scene) {}

} // namespace agaa
