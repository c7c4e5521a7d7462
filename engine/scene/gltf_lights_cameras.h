#pragma once
// KHR_lights_punctual lights and perspective cameras attached to glTF nodes,
// placed in world space by the node's world matrix.

#include "engine/scene/scene.h"

#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <string>

namespace eng::scene {

// Whether a light said anything about shadows (extras.castsShadows); the loader
// only applies the "first sun casts" default when none did.
struct LightRecord {
    Light light;
    bool saidCastsShadows = false;
};

// Reads nodes[nodeIndex].extensions.KHR_lights_punctual; returns false when the
// node has no light (or an unusable one, with a warning in scene.stats).
bool readNodeLight(const tinygltf::Model& model, const std::string& source, int nodeIndex,
                   const glm::mat4& world, Scene& scene, LightRecord& out);

// Applies the shadow default: if no light carried extras.castsShadows, the first
// directional light casts shadows.
void resolveShadowCasters(const std::vector<LightRecord>& records, Scene& scene);

// Reads the perspective camera of nodes[nodeIndex]; zfar may be 0 (= unknown)
// until finishCameras() sees the bounds. Returns false for no or unusable camera.
bool readNodeCamera(const tinygltf::Model& model, const std::string& source, int nodeIndex,
                    const glm::mat4& world, Scene& scene, Camera& out);

// Gives cameras without a finite far plane one derived from scene.bounds, and
// adds the default framing camera when there is none.
void finishCameras(Scene& scene);

} // namespace eng::scene
