#include "engine/scene/scenegen.h"

#include "engine/scene/camera_framing.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/scene_subjects.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace eng::scene {

namespace {

constexpr float kYfov = 0.7f; // radians (40 degrees)
constexpr float kAspect16x9 = 16.0f / 9.0f;
constexpr int kPointLights = 16;

enum class Kind { Furball, Metal, Foliage, Bamboo, Railings, Plane, Default, Spikes, GoldPoints, ChainLink };

struct KindName {
    Kind kind;
    const char* name;
};

constexpr KindName kKinds[] = {
    {Kind::Furball, "furball"},     {Kind::Metal, "metal"},       {Kind::Foliage, "foliage"},
    {Kind::Bamboo, "bamboo"},       {Kind::Railings, "railings"}, {Kind::Plane, "plane"},
    {Kind::Default, "default"},     {Kind::Spikes, "spikes"},     {Kind::GoldPoints, "glints"},
    {Kind::ChainLink, "chainlink"},
};

std::string knownList() {
    std::string s;
    for (const KindName& k : kKinds) {
        s += (s.empty() ? "" : ", ") + std::string(k.name);
    }
    return s;
}

// Where lights may not go: behind a wall or under the floor.
struct Stage {
    float floorY = -1e30f;
    std::optional<float> wallZ;
    glm::vec3 viewDir{0.0f, -0.25f, -1.0f};
    std::optional<Camera> fixedCamera;
};

glm::vec3 hueToRgb(float hue, float saturation) {
    const glm::vec3 k(0.0f, 2.0f / 3.0f, 1.0f / 3.0f);
    glm::vec3 rgb;
    for (int c = 0; c < 3; ++c) {
        const float p = std::abs(std::fmod(hue + k[c], 1.0f) * 6.0f - 3.0f);
        rgb[c] = std::clamp(p - 1.0f, 0.0f, 1.0f);
    }
    return glm::mix(glm::vec3(1.0f), rgb, saturation);
}

// The glossy thin-metal case under point lights alone (issue 34): 8 white lights of 20 cd on a
// ring 2 m from the subject's centre, no sun, no floor; every highlight is a point light's.
constexpr int kGoldPointLights = 8;
constexpr float kGoldPointRadius = 2.0f;   // metres
constexpr float kGoldPointCandela = 20.0f; // about 5 lux at the ball

void addGoldPointLights(ModelBuilder& builder, const Bounds& subject) {
    const glm::vec3 centre = 0.5f * (subject.min + subject.max);
    for (int k = 0; k < kGoldPointLights; ++k) {
        const float a = 6.28318530718f * (static_cast<float>(k) + 0.5f) / kGoldPointLights;
        // Alternately above and below the equator, so the highlights are not all in one band.
        const glm::vec3 p =
            centre +
            kGoldPointRadius * glm::normalize(glm::vec3(std::cos(a), k % 2 ? -0.4f : 0.6f, std::sin(a)));
        builder.addPointLight("point." + std::to_string(k), p, {1.0f, 1.0f, 1.0f}, kGoldPointCandela, 0.0f);
    }
}

void addLights(ModelBuilder& builder, const Bounds& subject, const Stage& stage, Kind kind) {
    if (kind == Kind::GoldPoints) {
        addGoldPointLights(builder, subject);
        return;
    }
    builder.addDirectionalLight("sun", glm::normalize(glm::vec3(-0.35f, -1.0f, -0.45f)), {1.0f, 0.96f, 0.9f},
                                3.0f, true);
    const glm::vec3 centre = 0.5f * (subject.min + subject.max);
    const glm::vec3 extent = subject.max - subject.min;
    const float size = std::max({extent.x, extent.y, extent.z, 0.1f});
    // The spike ball: one shadowed sun and 8 point lights (issue 14's measurement).
    const int pointLights = kind == Kind::Spikes ? 8 : kPointLights;
    for (int k = 0; k < pointLights; ++k) {
        const float a = 6.28318530718f * (static_cast<float>(k) + 0.5f) / pointLights;
        glm::vec3 p;
        float radius = 0.0f;
        if (kind == Kind::Plane) {
            // A ring in front of the plane, between it and the camera.
            radius = 0.45f * size;
            p = centre + glm::vec3(radius * std::cos(a), radius * std::sin(a), 0.3f * size);
        } else {
            // A ring around the subject, alternating above and below its middle.
            radius = 0.75f * size;
            const float lift = (k % 2 == 0 ? 0.35f : -0.1f) * extent.y;
            p = centre + glm::vec3(radius * std::cos(a), lift, radius * std::sin(a));
            p.y = std::max(p.y, stage.floorY + 0.05f);
            if (stage.wallZ) {
                p.z = std::max(p.z, *stage.wallZ + 0.1f);
            }
        }
        const glm::vec3 color = hueToRgb(static_cast<float>(k) / pointLights, 0.6f);
        // ~0.6 lux at the ring radius; range 2.5x so the falloff window covers the subject.
        const float intensity = 0.6f * radius * radius;
        builder.addPointLight("point." + std::to_string(k), p, color, intensity, 2.5f * radius + 0.5f);
    }
}

Stage buildKind(Kind kind, SubjectSink& sink) {
    Stage stage;
    switch (kind) {
    case Kind::Furball:
        stage.floorY = 0.0f;
        addFloor(sink, 0.0f, 3.0f, {0.18f, 0.18f, 0.2f});
        addFurball(sink, {0.0f, 0.65f, 0.0f}, 0.5f);
        stage.viewDir = {0.0f, -0.3f, -1.0f};
        break;
    case Kind::Metal:
        stage.floorY = 0.0f;
        addFloor(sink, 0.0f, 3.0f, {0.05f, 0.05f, 0.06f});
        addMetalLattice(sink, {0.0f, 0.65f, 0.0f}, {1.6f, 1.0f});
        stage.viewDir = {0.15f, -0.2f, -1.0f};
        break;
    case Kind::Foliage:
        stage.floorY = 0.0f;
        stage.wallZ = -0.6f;
        addFloor(sink, 0.0f, 3.0f, {0.25f, 0.22f, 0.18f});
        addWall(sink, -0.6f, 3.0f, 0.0f, 3.0f, {0.72f, 0.7f, 0.64f});
        addFoliage(sink, {0.0f, 0.0f, 0.0f}, 1.2f, 1.3f);
        stage.viewDir = {0.0f, -0.15f, -1.0f};
        break;
    case Kind::Bamboo:
        stage.floorY = 0.0f;
        addFloor(sink, 0.0f, 4.0f, {0.3f, 0.26f, 0.18f});
        addBamboo(sink, {0.0f, 0.0f, 0.0f}, {2.0f, 1.0f}, 2.4f);
        stage.viewDir = {0.0f, -0.1f, -1.0f};
        break;
    case Kind::Railings:
        stage.floorY = 0.0f;
        stage.wallZ = -0.4f;
        addFloor(sink, 0.0f, 3.0f, {0.3f, 0.3f, 0.3f});
        addWall(sink, -0.4f, 3.0f, 0.0f, 2.5f, {0.85f, 0.82f, 0.75f});
        addRailing(sink, {0.0f, 0.0f, 0.0f}, 1.6f, 1.0f);
        stage.viewDir = {0.0f, -0.2f, -1.0f};
        break;
    case Kind::Plane: {
        // The invariance case: one Lambert-like quad at z = 0, overfilling the
        // view at 16:9 (and so at 1:1) from a camera 2 m away on +Z.
        constexpr float kDistance = 2.0f;
        const float halfHeight = kDistance * std::tan(0.5f * kYfov) * 1.3f;
        const float halfWidth = halfHeight * kAspect16x9;
        MeshData quad;
        addQuad(quad, {-halfWidth, -halfHeight, 0.0f}, {2.0f * halfWidth, 0.0f, 0.0f},
                {0.0f, 2.0f * halfHeight, 0.0f});
        MaterialDesc lambert;
        lambert.name = "plane.lambert";
        lambert.baseColor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
        lambert.metallic = 0.0f;
        lambert.roughness = 1.0f;
        sink.addSubject("plane", quad, sink.material(lambert));
        Camera camera;
        camera.name = "camera";
        camera.yfov = kYfov;
        camera.view = lookAtView({0.0f, 0.0f, kDistance}, {0.0f, 0.0f, 0.0f});
        camera.znear = 0.1f;
        camera.zfar = 10.0f;
        stage.fixedCamera = camera;
        stage.wallZ = 0.0f;
        break;
    }
    case Kind::Spikes:
        // Thin glossy metal where AGAA once looked worse than no AA (issue 14): 6000 gold spikes.
        stage.floorY = 0.0f;
        addFloor(sink, 0.0f, 3.0f, {0.1f, 0.1f, 0.11f});
        addSpikeBall(sink, {0.0f, 1.05f, 0.0f}, 1.0f, 6000);
        stage.viewDir = {0.0f, -0.2f, -1.0f};
        break;
    case Kind::GoldPoints:
        // The spike ball alone, in the dark: 6000 gold rods of 2.5 mm, roughness 0.02.
        addSpikeBall(sink, {0.0f, 0.0f, 0.0f}, 1.0f, 6000);
        stage.viewDir = {0.0f, -0.2f, -1.0f};
        break;
    case Kind::ChainLink:
        // Issue 49's thin glossy metal: a chain-link fence of 4 mm steel wires 35 cm before a
        // wall, under the sun and the 16 point lights.
        stage.floorY = 0.0f;
        stage.wallZ = -0.35f;
        addFloor(sink, 0.0f, 3.0f, {0.2f, 0.2f, 0.21f});
        addWall(sink, -0.35f, 3.0f, 0.0f, 2.5f, {0.3f, 0.29f, 0.27f});
        addChainLink(sink, {0.0f, 0.65f, 0.0f}, {2.0f, 1.1f}, 0.06f);
        stage.viewDir = {0.1f, -0.15f, -1.0f};
        break;
    case Kind::Default:
        // Railings in front, fur and foliage behind, all on one floor before a wall.
        stage.floorY = 0.0f;
        stage.wallZ = -1.2f;
        addFloor(sink, 0.0f, 4.0f, {0.22f, 0.21f, 0.2f});
        addWall(sink, -1.2f, 4.0f, 0.0f, 3.0f, {0.7f, 0.68f, 0.63f});
        addRailing(sink, {0.0f, 0.0f, 0.45f}, 1.8f, 0.8f);
        addFurball(sink, {-0.4f, 0.45f, -0.35f}, 0.35f, 0.6f);
        addFoliage(sink, {0.55f, 0.0f, -0.6f}, 0.7f, 1.1f);
        stage.viewDir = {0.0f, -0.2f, -1.0f};
        break;
    }
    return stage;
}

} // namespace

std::vector<std::string> sceneKinds() {
    std::vector<std::string> names;
    for (const KindName& k : kKinds) {
        names.emplace_back(k.name);
    }
    return names;
}

tinygltf::Model generateScene(std::string_view kindName, const GenOptions& options) {
    const KindName* found = nullptr;
    for (const KindName& k : kKinds) {
        if (kindName == k.name) {
            found = &k;
        }
    }
    if (found == nullptr) {
        throw SceneError("builtin:" + std::string(kindName) + ": unknown scene kind; known kinds are " +
                         knownList());
    }
    if (!std::isfinite(options.density) || options.density <= 0.0f || options.density > kMaxDensity) {
        throw SceneError("builtin:" + std::string(kindName) + ": density " + std::to_string(options.density) +
                         " outside (0, " + std::to_string(kMaxDensity) + "]");
    }
    // Mix the kind into the seed so "default" does not repeat the furball's strands.
    const auto kindIndex = static_cast<uint64_t>(found - kKinds);
    Prng rng(static_cast<uint64_t>(options.seed) * 16 + kindIndex);
    ModelBuilder builder("agaa scenegen " + std::string(found->name));
    SubjectSink sink(builder, rng, options.density);
    const Stage stage = buildKind(found->kind, sink);

    const Bounds subject = sink.subjectBounds();
    addLights(builder, subject, stage, found->kind);
    Camera camera;
    if (stage.fixedCamera) {
        camera = *stage.fixedCamera;
    } else {
        camera = framePoints(sink.subjectPoints(), stage.viewDir, kYfov, 1.05f);
        camera.name = "camera";
        // The floor and wall reach beyond the subject: keep them inside the far plane.
        camera.zfar = std::max(camera.zfar, 20.0f);
    }
    builder.addCamera(camera, kAspect16x9);
    return builder.finish();
}

Scene loadBuiltin(std::string_view name) {
    Scene scene = loadGltfModel(generateScene(name), "builtin:" + std::string(name));
    scene.exposure = 1.0f; // the generated lights are sized for it
    return scene;
}

} // namespace eng::scene
