#include "engine/scene/default_lighting.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace eng::scene {
namespace {

constexpr float kSunElevation = 0.87266463f; // 50 degrees
constexpr float kSunAzimuth = 0.61086524f;   // 35 degrees right of the camera's back
constexpr float kSunIlluminance = 100000.0f; // lux: clear noon
const glm::vec3 kSunColour{1.0f, 0.96f, 0.9f};

} // namespace

LightingMode parseLightingMode(const std::string& name) {
    if (name == "auto") return LightingMode::Automatic;
    if (name == "scene") return LightingMode::Scene;
    if (name == "fill") return LightingMode::Fill;
    if (name == "default") return LightingMode::Default;
    if (name == "both") return LightingMode::Both;
    throw std::invalid_argument("--lights '" + name + "' is not one of auto, scene, fill, default, both");
}

double lightIlluminanceAt(const Scene& scene, const glm::vec3& point) {
    double illuminance = 0.0;
    for (const Light& l : scene.lights) {
        const double intensity = double(l.intensity) * std::max({l.color.r, l.color.g, l.color.b});
        if (l.type == LightType::Directional) {
            illuminance += intensity;
        } else {
            const glm::vec3 d = l.position - point;
            illuminance += intensity / std::max(double(glm::dot(d, d)), 1.0e-4); // kMinLightDistance2
        }
    }
    return illuminance;
}

glm::vec3 defaultSunDirection(const Scene& scene, uint32_t camera) {
    // The camera's axes in world space: view is world -> view, the camera looks down -Z.
    glm::mat4 world(1.0f);
    if (camera < scene.cameras.size()) world = glm::inverse(scene.cameras[camera].view);
    glm::vec3 back(world[2]), right(world[0]);
    back.y = 0.0f;
    right.y = 0.0f;
    // A camera looking straight up or down has no horizontal axis: fall back to world +Z / +X.
    if (glm::length(back) < 1e-3f) back = glm::vec3(0, 0, 1);
    if (glm::length(right) < 1e-3f) right = glm::vec3(1, 0, 0);
    const glm::vec3 horizontal = glm::normalize(std::cos(kSunAzimuth) * glm::normalize(back) +
                                                std::sin(kSunAzimuth) * glm::normalize(right));
    return glm::normalize(std::cos(kSunElevation) * horizontal + glm::vec3(0, std::sin(kSunElevation), 0));
}

void applyLighting(Scene& scene, LightingMode mode, std::optional<Environment> userEnvironment,
                   uint32_t camera) {
    const bool hasLights = !scene.lights.empty();
    if (mode == LightingMode::Automatic) {
        mode = hasLights ? LightingMode::Fill : LightingMode::Default;
        scene.lightingCause = hasLights ? "automatic: the scene has " + std::to_string(scene.lights.size()) +
                                              (scene.lights.size() == 1 ? " light" : " lights")
                                        : "automatic: the scene has no lights";
    } else {
        scene.lightingCause = "setting --lights";
    }
    scene.lightingMode = mode == LightingMode::Scene     ? "scene"
                         : mode == LightingMode::Fill    ? "fill"
                         : mode == LightingMode::Default ? "default"
                                                         : "both";
    if (userEnvironment) {
        scene.environment = std::move(*userEnvironment);
        scene.lightingCause += "; environment " + scene.environment.source;
    }
    if (mode == LightingMode::Scene) return;
    if (mode == LightingMode::Fill) {
        if (!scene.environment.empty()) return;
        const double key = lightIlluminanceAt(scene, (scene.bounds.min + scene.bounds.max) * 0.5f);
        SkySettings fill;
        fill.sunDirection = defaultSunDirection(scene, camera);
        fill.sunIlluminance = 0.0f;
        fill.skyIlluminance = float(key * kFillRatio);
        if (fill.skyIlluminance > 0.0f) scene.environment = proceduralSky(fill);
        scene.environment.source =
            "fill sky at 1/4 of the lights' " + std::to_string(int64_t(std::llround(key))) + " lux";
        return;
    }
    if (mode == LightingMode::Default) scene.lights.clear();
    if (!scene.environment.empty()) return; // the user's map carries its own sun
    Light sun;
    sun.name = "default sun";
    sun.type = LightType::Directional;
    sun.color = kSunColour;
    sun.intensity = kSunIlluminance;
    const glm::vec3 towards = defaultSunDirection(scene, camera);
    sun.direction = -towards;
    sun.castsShadows = true;
    // The scene's own lights keep the shadow maps they had; the sun comes first so it gets one.
    scene.lights.insert(scene.lights.begin(), sun);
    SkySettings sky;
    sky.sunDirection = towards;
    sky.sunIlluminance = kSunIlluminance;
    scene.environment = proceduralSky(sky);
}

} // namespace eng::scene
