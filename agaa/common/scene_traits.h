#pragma once
// What a technique reads from the content it renders, besides the geometry its raster passes draw
// (agaa/common/raster_pass.h) and the per-frame buffers (FrameInputs): the scene's features, which
// pick the shader variants and AGAA's plan once, at construction; the lights and bounds the shadow
// maps are fitted to; the triangle count (SBAA's primitive ids are exact below 2^24); and the text
// the variants report. A host fills one for its own content; sceneTraits() derives it from ours.

#include "engine/scene/scene_features.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace eng::frame {
class GpuScene;
}

namespace agaa {

// The content types a host fills, under the module's names (engine/scene/scene.h and
// scene_features.h say what each field means).
using Light = eng::scene::Light;
using LightType = eng::scene::LightType;
using Camera = eng::scene::Camera;
using Bounds = eng::scene::Bounds;
using SceneFeatures = eng::scene::SceneFeatures;
using eng::scene::kGlossyMetallic;
using eng::scene::kGlossyRoughness;
using eng::scene::kMaxShadowedLights;
using eng::scene::kNearMirrorRoughness;

struct SceneTraits {
    std::string source; // names the content in messages, e.g. a file or "host:<name>"
    // Derived from the content, never forced: EffectSettings::forceAll forces them
    // (effectiveFeatures, agaa/common/effects.h). shadowedLights index `lights`.
    eng::scene::SceneFeatures features;
    uint32_t materials = 0; // materials the content holds (the forced benchmark alpha-tests each)
    uint64_t triangles = 0;
    eng::scene::Bounds bounds; // world space, what the shadow maps cover
    // The lights, in the order of FrameInputs::lights (shared::GpuLight[]); the shadow pass fits a
    // map to each of features.shadowedLights and the variants name them.
    std::vector<eng::scene::Light> lights;
    // The cameras eng::frame::ViewSettings::camera picks (FrameInputWriter); camera 0's view is the
    // one the shadow fit uses when a frame gives no FrameConstants (FrameInputs::constants). A host
    // that passes its own camera (ViewSettings::cameraOverride) may leave them empty.
    std::vector<eng::scene::Camera> cameras;
    std::string lightingMode = "scene", lightingCause = "the scene's own lights";
    std::string environmentSource; // reported when features.environment
};

// Our scene's traits: its derived features, materials, triangles, bounds, lights and cameras.
SceneTraits sceneTraits(const eng::scene::Scene& scene);

// What a technique is created for: the content's traits and, when the content is ours, its
// GpuScene, which then draws every raster pass the host's drawer (FrameInputs::geometry) does not
// (agaa::SceneDrawer) and binds its environment where the host gives none
// (FrameInputs::environment). A host with its own geometry gives its traits alone. Converts from a
// GpuScene, so a technique is created from our scene as before.
struct TechniqueContent {
    TechniqueContent(SceneTraits traits, const eng::frame::GpuScene* scene = nullptr)
        : traits(std::move(traits)), scene(scene) {}
    TechniqueContent(const eng::frame::GpuScene& scene); // NOLINT(google-explicit-constructor)

    SceneTraits traits;
    const eng::frame::GpuScene* scene = nullptr;
};

} // namespace agaa
