#pragma once
// Per-frame constants every pass reads: camera (reversed-Z projection), the
// sample pattern, lights in view space, sky and exposure.

#include "engine/frame/sample_pattern.h"
#include "engine/scene/scene.h"
#include "shared/frame.h"

#include <optional>
#include <vector>

namespace eng::frame {

struct ViewSettings {
    uint32_t width = 256;
    uint32_t height = 256;
    uint32_t camera = 0; // index into Scene::cameras
    glm::vec3 skyRadiance{0.35f, 0.5f, 0.8f};
    float exposure = 1.0f;
    // Replaces the scene camera's view matrix (camera paths, the viewer's orbit camera);
    // the camera's fov and clip planes still apply.
    std::optional<glm::mat4> viewOverride;
    // A host's own camera (view, yfov, znear, zfar) instead of Scene::cameras[camera]; checked
    // (0 < yfov < pi, 0 < znear < zfar). viewOverride, when set, still replaces its view.
    std::optional<scene::Camera> cameraOverride;
};

// The scene camera's view rotated about the world Y axis through `pivot` by `degrees`
// (a short orbit for temporal-stability measurements).
glm::mat4 orbitView(const glm::mat4& view, const glm::vec3& pivot, float degrees);

// Reversed Z, finite far: depth 1 at znear, 0 at zfar (see common/depth.glsl), Y flipped for Vulkan.
glm::mat4 reversedZPerspective(float yfov, float aspect, float znear, float zfar);

shared::FrameConstants makeFrameConstants(const scene::Scene&, const ViewSettings&, const SamplePattern&);
std::vector<shared::GpuLight> makeGpuLights(const scene::Scene&, const glm::mat4& view);
std::vector<shared::GpuMaterial> makeGpuMaterials(const scene::Scene&);

} // namespace eng::frame
