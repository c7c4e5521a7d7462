#include "engine/frame/frame_constants.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace eng::frame {

// Same floor as kMinSpotCosRange in shaders/glsl/common/epsilon.glsl.
constexpr float kMinSpotCosRange = 1.0e-4f;

glm::mat4 reversedZPerspective(float yfov, float aspect, float znear, float zfar) {
    float f = 1.0f / std::tan(yfov * 0.5f);
    glm::mat4 p(0.0f);
    p[0][0] = f / aspect;
    p[1][1] = -f;                     // Vulkan: +Y down in framebuffer space
    p[2][2] = znear / (zfar - znear); // z_clip = A z_v + B, w_clip = -z_v
    p[3][2] = znear * zfar / (zfar - znear);
    p[2][3] = -1.0f;
    return p;
}

glm::mat4 viewTileCrop(const ViewTile& tile, uint32_t width, uint32_t height) {
    if (tile.scale < 1 || tile.scale > kMaxViewTileScale)
        throw std::invalid_argument("view tile scale " + std::to_string(tile.scale) +
                                    " is out of range (1.." + std::to_string(kMaxViewTileScale) + ")");
    const uint64_t wholeWidth = uint64_t(tile.scale) * width, wholeHeight = uint64_t(tile.scale) * height;
    if (uint64_t(tile.origin.x) + width > wholeWidth || uint64_t(tile.origin.y) + height > wholeHeight)
        throw std::invalid_argument("view tile at (" + std::to_string(tile.origin.x) + ", " +
                                    std::to_string(tile.origin.y) + ") lies outside its " +
                                    std::to_string(wholeWidth) + "x" + std::to_string(wholeHeight) + " view");
    glm::mat4 crop(1.0f);
    if (tile.scale == 1) return crop;
    // Computed in double: the tile's centre in the whole view's NDC, pixel rows downwards as the
    // shaders' ndc = 2 p / extent - 1.
    const double s = tile.scale;
    const double cx = (2.0 * tile.origin.x + width) / double(wholeWidth) - 1.0;
    const double cy = (2.0 * tile.origin.y + height) / double(wholeHeight) - 1.0;
    crop[0][0] = float(s);
    crop[1][1] = float(s);
    crop[3][0] = float(-s * cx);
    crop[3][1] = float(-s * cy);
    return crop;
}

glm::mat4 orbitView(const glm::mat4& view, const glm::vec3& pivot, float degrees) {
    // world' = T(pivot) R T(-pivot) world; the camera sees the scene rotated the other way.
    glm::mat4 toPivot(1.0f), fromPivot(1.0f), rotate(1.0f);
    toPivot[3] = glm::vec4(-pivot, 1.0f);
    fromPivot[3] = glm::vec4(pivot, 1.0f);
    float a = glm::radians(degrees);
    rotate[0] = {std::cos(a), 0.0f, -std::sin(a), 0.0f};
    rotate[2] = {std::sin(a), 0.0f, std::cos(a), 0.0f};
    return view * fromPivot * rotate * toPivot;
}

glm::mat4 truckView(const glm::mat4& view, float metres) {
    glm::mat4 shift(1.0f); // view space: the camera moves +x, so the scene moves -x
    shift[3] = glm::vec4(-metres, 0.0f, 0.0f, 1.0f);
    return shift * view;
}

glm::dvec3 cameraEye(const glm::mat4& view) {
    const glm::dmat4 v = view;
    const glm::dmat3 rotation = glm::dmat3(v);
    return -(glm::transpose(rotation) * glm::dvec3(v[3]));
}

void setCameraRelative(shared::FrameConstants& c) {
    c.viewProjRelative = c.proj * glm::mat4(glm::mat3(c.view));
    c.eye = glm::vec4(glm::vec3(cameraEye(c.view)), 0.0f);
}

void requireCameraRelative(const shared::FrameConstants& c) {
    shared::FrameConstants expected = c;
    setCameraRelative(expected);
    // Relative to the larger of the two: a host may compute them in its own order of operations.
    constexpr float kCameraRelativeTolerance = 1.0e-4f;
    auto near = [](float a, float b) {
        return std::abs(a - b) <= kCameraRelativeTolerance * std::max({1.0f, std::abs(a), std::abs(b)});
    };
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            if (!near(c.viewProjRelative[col][row], expected.viewProjRelative[col][row]))
                throw std::invalid_argument(
                    "FrameConstants::viewProjRelative does not follow from view and proj: "
                    "call eng::frame::setCameraRelative after changing them");
    for (int i = 0; i < 3; ++i)
        if (!near(c.eye[i], expected.eye[i]))
            throw std::invalid_argument("FrameConstants::eye is not the camera position of view: call "
                                        "eng::frame::setCameraRelative after changing view");
}

shared::FrameConstants makeFrameConstants(const scene::Scene& scene, const ViewSettings& view,
                                          const SamplePattern& pattern) {
    return makeFrameConstants(scene.cameras, scene.lights.size(), view, pattern);
}

shared::FrameConstants makeFrameConstants(std::span<const scene::Camera> cameras, size_t lights,
                                          const ViewSettings& view, const SamplePattern& pattern) {
    if (!view.cameraOverride && view.camera >= cameras.size())
        throw std::invalid_argument("camera " + std::to_string(view.camera) +
                                    " does not exist (the scene has " + std::to_string(cameras.size()) + ")");
    if (const std::optional<scene::Camera>& host = view.cameraOverride) {
        // A host's camera is user input: refused here rather than turned into a NaN projection.
        if (!(host->yfov > 0.0f && host->yfov < 3.14159f))
            throw std::invalid_argument("camera yfov " + std::to_string(host->yfov) +
                                        " is out of range (0..pi radians)");
        if (!(host->znear > 0.0f && host->zfar > host->znear))
            throw std::invalid_argument("camera znear " + std::to_string(host->znear) + " / zfar " +
                                        std::to_string(host->zfar) + " are out of range (0 < znear < zfar)");
    }
    if (!(std::abs(view.jitter.x) <= 0.5f && std::abs(view.jitter.y) <= 0.5f))
        throw std::invalid_argument("view jitter (" + std::to_string(view.jitter.x) + ", " +
                                    std::to_string(view.jitter.y) +
                                    ") is out of range ([-0.5, 0.5] pixels each)");
    const scene::Camera& cam = view.cameraOverride ? *view.cameraOverride : cameras[view.camera];
    shared::FrameConstants c{};
    float aspect = float(view.width) / float(view.height);
    c.view = view.viewOverride ? *view.viewOverride : cam.view;
    c.proj = viewTileCrop(view.tile, view.width, view.height) *
             reversedZPerspective(cam.yfov, aspect, cam.znear, cam.zfar);
    c.viewProj = c.proj * c.view;
    setCameraRelative(c);
    // A layer's hardware samples land on q - offset (common/scene_vertex.glsl): a jitter j moves
    // them to q + j.
    for (uint32_t l = 0; l < pattern.layers; ++l)
        c.layerOffsets[l] = glm::vec4(pattern.layerOffsets[l] - view.jitter, 0, 0);
    for (uint32_t s = 0; s < pattern.samples; ++s)
        c.samplePositions[s] = glm::vec4(pattern.positions[s] + view.jitter, 0, 0);
    c.skyRadiance = glm::vec4(view.skyRadiance, 0.0f);
    c.extent = {float(view.width), float(view.height), 1.0f / float(view.width), 1.0f / float(view.height)};
    c.depthParams = {cam.znear, cam.zfar, view.exposure, 0.0f};
    // zw: 0 for a whole view; a tile's NDC offset, which common/depth.glsl adds back on the ray.
    c.projParams = {c.proj[0][0], c.proj[1][1], c.proj[2][0], c.proj[2][1]};
    c.viewTile = {float(view.tile.scale), 0.0f, 0.0f, 0.0f};
    c.counts = {pattern.samples, pattern.samplesPerLayer, pattern.layers,
                uint32_t(std::min<size_t>(lights, shared::kMaxLights))};
    return c;
}

std::vector<shared::GpuLight> makeGpuLights(const scene::Scene& scene, const glm::mat4& view) {
    return makeGpuLights(scene.lights, view);
}

std::vector<shared::GpuLight> makeGpuLights(std::span<const scene::Light> lights, const glm::mat4& view) {
    std::vector<shared::GpuLight> out;
    for (const scene::Light& l : lights) {
        shared::GpuLight g{};
        // As the vertices (common/scene_vertex.glsl): R (p - eye), here in double.
        const glm::vec3 p =
            glm::vec3(glm::dmat3(glm::dmat4(view)) * (glm::dvec3(l.position) - cameraEye(view)));
        glm::vec3 d = glm::vec3(view * glm::vec4(l.direction, 0.0f));
        float dl = glm::length(d);
        d = dl > 0.0f ? d / dl : glm::vec3(0, 0, -1);
        uint32_t type = l.type == scene::LightType::Directional ? shared::kLightDirectional
                        : l.type == scene::LightType::Point     ? shared::kLightPoint
                                                                : shared::kLightSpot;
        g.positionRange = {p, l.range};
        g.directionType = {d, float(type)};
        g.radiance = {l.color * l.intensity, 0.0f};
        float cosOuter = std::cos(l.outerConeAngle), cosInner = std::cos(l.innerConeAngle);
        g.spot = {cosOuter, 1.0f / std::max(cosInner - cosOuter, kMinSpotCosRange), 0.0f, 0.0f};
        out.push_back(g);
    }
    if (out.empty()) out.push_back(shared::GpuLight{}); // a zero-sized storage buffer is not allowed
    return out;
}

std::vector<shared::GpuMaterial> makeGpuMaterials(const scene::Scene& scene) {
    std::vector<shared::GpuMaterial> out;
    for (const scene::Material& m : scene.materials) {
        shared::GpuMaterial g{};
        g.baseColorFactor = m.baseColorFactor;
        g.emissive = {m.emissiveFactor * m.emissiveStrength, m.alphaCutoff};
        uint32_t mode = m.alphaMode == scene::AlphaMode::Opaque ? shared::kAlphaOpaque
                        : m.alphaMode == scene::AlphaMode::Mask ? shared::kAlphaMask
                                                                : shared::kAlphaBlend;
        g.params = {m.metallicFactor, m.roughnessFactor, m.normalScale, float(mode)};
        g.textures = {m.baseColorTexture, m.metallicRoughnessTexture, m.normalTexture, m.emissiveTexture};
        for (int slot = 0; slot < 4; ++slot) {
            const scene::TextureTransform& t = m.textureTransforms[slot];
            const float c = std::cos(t.rotation), s = std::sin(t.rotation);
            g.uvMatrix[slot] = {c * t.scale.x, s * t.scale.x, -s * t.scale.y, c * t.scale.y};
            g.uvOffset[slot / 2][(slot % 2) * 2] = t.offset.x;
            g.uvOffset[slot / 2][(slot % 2) * 2 + 1] = t.offset.y;
            g.texCoords[slot] = int32_t(t.texCoord);
        }
        out.push_back(g);
    }
    return out;
}

} // namespace eng::frame
