#include "engine/scene/gltf_lights_cameras.h"

#include "engine/scene/camera_framing.h"
#include "engine/scene/scene_error.h"

#include <algorithm>
#include <cmath>

namespace eng::scene {

namespace {

constexpr float kHalfPi = 1.57079632679f;
constexpr float kPi = 3.14159265359f;

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
    const float len2 = glm::dot(v, v);
    return (len2 > 1e-24f && std::isfinite(len2)) ? v / std::sqrt(len2) : fallback;
}

bool finiteMatrix(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) {
                return false;
            }
        }
    }
    return true;
}

} // namespace

bool readNodeLight(const tinygltf::Model& model, const std::string& source, int nodeIndex,
                   const glm::mat4& world, Scene& scene, LightRecord& out) {
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(nodeIndex)];
    const auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end()) {
        return false;
    }
    const std::string field = "nodes[" + std::to_string(nodeIndex) + "].extensions.KHR_lights_punctual.light";
    if (!ext->second.IsObject() || !ext->second.Has("light") || !ext->second.Get("light").IsInt()) {
        scene.stats.warnings.push_back(source + ": " + field + ": missing or not an integer; light ignored");
        return false;
    }
    const int index = ext->second.Get("light").GetNumberAsInt();
    if (index < 0 || static_cast<size_t>(index) >= model.lights.size()) {
        throw SceneError(source + ": " + field + ": light " + std::to_string(index) + " out of range (" +
                         std::to_string(model.lights.size()) + " lights)");
    }
    const tinygltf::Light& in = model.lights[static_cast<size_t>(index)];
    const std::string lightField = "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "]";
    auto warn = [&](const std::string& what) {
        scene.stats.warnings.push_back(source + ": " + lightField + what);
    };

    Light& light = out.light;
    light.name = in.name.empty() ? lightField : in.name;
    if (in.type == "directional") {
        light.type = LightType::Directional;
    } else if (in.type == "point") {
        light.type = LightType::Point;
    } else if (in.type == "spot") {
        light.type = LightType::Spot;
    } else {
        warn(".type: '" + in.type + "' is not directional, point or spot; light ignored");
        return false;
    }
    if (in.color.size() == 3) {
        for (int c = 0; c < 3; ++c) {
            const double v = in.color[static_cast<size_t>(c)];
            light.color[c] = std::isfinite(v) ? std::max(static_cast<float>(v), 0.0f) : 1.0f;
        }
    } else if (!in.color.empty()) {
        warn(".color: needs 3 numbers; using white");
    }
    light.intensity = static_cast<float>(in.intensity);
    if (!std::isfinite(light.intensity) || light.intensity < 0.0f) {
        warn(".intensity: must be finite and >= 0; using 0");
        light.intensity = 0.0f;
    }
    light.range = static_cast<float>(in.range);
    if (light.type == LightType::Directional || !std::isfinite(light.range) || light.range < 0.0f) {
        light.range = 0.0f; // glTF: directional lights have no range; undefined = infinite
    }
    if (light.type == LightType::Spot) {
        float outer = static_cast<float>(in.spot.outerConeAngle);
        float inner = static_cast<float>(in.spot.innerConeAngle);
        // glTF: 0 <= inner < outer <= pi/2.
        if (!std::isfinite(outer) || outer <= 0.0f || outer > kHalfPi) {
            warn(".spot.outerConeAngle: outside (0, pi/2]; clamped");
            outer = std::isfinite(outer) ? std::clamp(outer, 1e-3f, kHalfPi) : kPi / 4.0f;
        }
        if (!std::isfinite(inner) || inner < 0.0f || inner >= outer) {
            warn(".spot.innerConeAngle: outside [0, outerConeAngle); clamped");
            inner = std::isfinite(inner) ? std::clamp(inner, 0.0f, outer * 0.999f) : 0.0f;
        }
        light.innerConeAngle = inner;
        light.outerConeAngle = outer;
    }
    if (!finiteMatrix(world)) {
        throw SceneError(source + ": nodes[" + std::to_string(nodeIndex) + "]: world matrix not finite");
    }
    light.position = glm::vec3(world[3]);
    // glTF lights shine down -Z of their node.
    light.direction =
        safeNormalize(glm::mat3(world) * glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 0.0f, -1.0f));

    out.saidCastsShadows = false;
    if (in.extras.IsObject() && in.extras.Has("castsShadows")) {
        const tinygltf::Value& v = in.extras.Get("castsShadows");
        if (v.IsBool()) {
            light.castsShadows = v.Get<bool>();
            out.saidCastsShadows = true;
        } else {
            warn(".extras.castsShadows: not a boolean; ignored");
        }
    }
    return true;
}

void resolveShadowCasters(const std::vector<LightRecord>& records, Scene& scene) {
    const bool anySaid =
        std::any_of(records.begin(), records.end(), [](const LightRecord& r) { return r.saidCastsShadows; });
    bool sunAssigned = false;
    for (const LightRecord& r : records) {
        Light light = r.light;
        if (!anySaid) {
            light.castsShadows = !sunAssigned && light.type == LightType::Directional;
            sunAssigned = sunAssigned || light.castsShadows;
        }
        scene.lights.push_back(light);
    }
}

bool readNodeCamera(const tinygltf::Model& model, const std::string& source, int nodeIndex,
                    const glm::mat4& world, Scene& scene, Camera& out) {
    const tinygltf::Node& node = model.nodes[static_cast<size_t>(nodeIndex)];
    if (node.camera < 0) {
        return false;
    }
    const std::string nodeField = "nodes[" + std::to_string(nodeIndex) + "].camera";
    if (static_cast<size_t>(node.camera) >= model.cameras.size()) {
        throw SceneError(source + ": " + nodeField + ": camera " + std::to_string(node.camera) +
                         " out of range (" + std::to_string(model.cameras.size()) + " cameras)");
    }
    const tinygltf::Camera& in = model.cameras[static_cast<size_t>(node.camera)];
    const std::string field = "cameras[" + std::to_string(node.camera) + "]";
    auto warn = [&](const std::string& what) {
        scene.stats.warnings.push_back(source + ": " + field + what);
    };
    if (in.type != "perspective") {
        warn(".type: '" + in.type + "' cameras are not supported (perspective only); camera ignored");
        return false;
    }
    const auto& p = in.perspective;
    out.name = in.name.empty() ? field : in.name;
    out.yfov = static_cast<float>(p.yfov);
    if (!std::isfinite(out.yfov) || out.yfov <= 0.0f || out.yfov >= kPi) {
        warn(".perspective.yfov: outside (0, pi); using 0.8");
        out.yfov = 0.8f;
    }
    out.znear = static_cast<float>(p.znear);
    if (!std::isfinite(out.znear) || out.znear <= 0.0f) {
        warn(".perspective.znear: must be > 0; using 0.05");
        out.znear = 0.05f;
    }
    const double zfar = p.zfar;
    // 0 marks "derive from the bounds" for finishCameras (glTF: absent = infinite).
    out.zfar = (std::isfinite(zfar) && zfar > out.znear && zfar < 3.0e38) ? static_cast<float>(zfar) : 0.0f;

    if (!finiteMatrix(world)) {
        throw SceneError(source + ": nodes[" + std::to_string(nodeIndex) + "]: world matrix not finite");
    }
    // Remove scale (and shear) so the view matrix is rigid: keep the viewing
    // axis -Z and make X, Y orthonormal around it.
    const glm::vec3 z = safeNormalize(glm::vec3(world[2]), glm::vec3(0.0f, 0.0f, 1.0f));
    glm::vec3 x = glm::cross(glm::vec3(world[1]), z);
    x = safeNormalize(x, std::abs(z.y) < 0.999f ? glm::normalize(glm::cross(glm::vec3(0, 1, 0), z))
                                                : glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::vec3 y = glm::cross(z, x);
    glm::mat4 rigid(1.0f);
    rigid[0] = glm::vec4(x, 0.0f);
    rigid[1] = glm::vec4(y, 0.0f);
    rigid[2] = glm::vec4(z, 0.0f);
    rigid[3] = glm::vec4(glm::vec3(world[3]), 1.0f);
    out.view = glm::inverse(rigid);
    return true;
}

void finishCameras(Scene& scene) {
    for (Camera& camera : scene.cameras) {
        if (camera.zfar <= 0.0f) {
            const glm::vec3 eye = glm::vec3(glm::inverse(camera.view)[3]);
            camera.zfar = farPlaneFor(scene.bounds, eye, camera.znear);
        }
    }
    if (scene.cameras.empty()) {
        scene.cameras.push_back(frameBoundingSphere(scene.bounds));
    }
}

} // namespace eng::scene
