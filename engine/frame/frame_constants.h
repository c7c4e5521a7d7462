#pragma once
// Per-frame constants every pass reads: camera (reversed-Z projection), the
// sample pattern, lights in view space, sky and exposure.

#include "engine/frame/sample_pattern.h"
#include "engine/scene/scene.h"
#include "shared/frame.h"

#include <optional>
#include <span>
#include <vector>

namespace eng::frame {

// One tile of a view `scale` times larger in each axis: the frame shows the width x height pixels
// at pixel `origin` of the (scale width) x (scale height) image. The converged truth
// (tools/harness/converged_truth.h) renders its supersampled image tile by tile this way, so its
// memory is one frame's at any scale. scale 1 is the whole view.
struct ViewTile {
    uint32_t scale = 1;
    glm::uvec2 origin{0, 0};
};

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
    // Checked: 1 <= scale <= kMaxViewTileScale, and the tile inside the larger image.
    ViewTile tile;
    // The frame's sub-pixel offset in pixels, each component in [-0.5, 0.5] (checked): every sample
    // of the pattern moves by it (FrameConstants::samplePositions) and the geometry is drawn
    // shifted by its opposite (layerOffsets), so a temporal method's frames sample different
    // points of each pixel. The projection is not jittered: a reprojection reads it as it is.
    glm::vec2 jitter{0.0f, 0.0f};
};

inline constexpr uint32_t kMaxViewTileScale = 64;

// The clip-space crop that turns the whole view's projection into `tile`'s: x' = s x - s c w,
// with s = tile.scale and c the tile's centre in the whole view's NDC. Identity for scale 1.
glm::mat4 viewTileCrop(const ViewTile& tile, uint32_t width, uint32_t height);

// The scene camera's view rotated about the world Y axis through `pivot` by `degrees`
// (a short orbit for temporal-stability measurements).
glm::mat4 orbitView(const glm::mat4& view, const glm::vec3& pivot, float degrees);

// The view's camera moved `metres` along its own right axis, looking the same way (a truck across
// the scene: parallax and disocclusion for temporal measurements).
glm::mat4 truckView(const glm::mat4& view, float metres);

// Reversed Z, finite far: depth 1 at znear, 0 at zfar (see common/depth.glsl), Y flipped for Vulkan.
glm::mat4 reversedZPerspective(float yfov, float aspect, float znear, float zfar);

shared::FrameConstants makeFrameConstants(const scene::Scene&, const ViewSettings&, const SamplePattern&);
// The same from a host's cameras (ViewSettings::camera indexes them) and its number of lights.
shared::FrameConstants makeFrameConstants(std::span<const scene::Camera> cameras, size_t lights,
                                          const ViewSettings&, const SamplePattern&);
// The camera's world position for a rigid view matrix, -R^T t, in double (exact for the matrix as
// given: the fp32 view's own rounding stays, its cancellation does not grow).
glm::dvec3 cameraEye(const glm::mat4& view);
// Fills FrameConstants::viewProjRelative and eye from view and proj (makeFrameConstants does; a
// host that builds FrameConstants itself calls it after setting them).
void setCameraRelative(shared::FrameConstants&);
// Throws std::invalid_argument when viewProjRelative or eye do not follow from view and proj (a
// host that changed view or proj after makeFrameConstants without setCameraRelative): every
// scene raster pass reads them, and stale ones draw the scene from the wrong place.
void requireCameraRelative(const shared::FrameConstants&);
// The lights in view space, each position as R (p - eye) in double: camera-relative, as the vertices.
std::vector<shared::GpuLight> makeGpuLights(const scene::Scene&, const glm::mat4& view);
std::vector<shared::GpuLight> makeGpuLights(std::span<const scene::Light> lights, const glm::mat4& view);
std::vector<shared::GpuMaterial> makeGpuMaterials(const scene::Scene&);

} // namespace eng::frame
