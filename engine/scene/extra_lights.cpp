#include "engine/scene/extra_lights.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace eng::scene {

double radicalInverse(uint32_t index, uint32_t base) {
    double inverse = 1.0 / double(base), fraction = inverse, value = 0.0;
    for (; index > 0; index /= base, fraction *= inverse)
        value += double(index % base) * fraction;
    return value;
}

double keyLightIlluminance(const Scene& scene) {
    const glm::vec3 centre = 0.5f * (scene.bounds.min + scene.bounds.max);
    double key = 0.0;
    for (const Light& l : scene.lights) {
        const double intensity = double(l.intensity) * std::max({l.color.r, l.color.g, l.color.b});
        if (l.type == LightType::Directional) {
            key = std::max(key, intensity);
        } else {
            const glm::vec3 d = l.position - centre;
            key = std::max(key, intensity / std::max(double(glm::dot(d, d)), 1.0e-4)); // kMinLightDistance2
        }
    }
    return key;
}

void addExtraLights(Scene& scene, uint32_t count) {
    if (count > kMaxExtraLights)
        throw std::invalid_argument("--extra-lights '" + std::to_string(count) +
                                    "' is not an integer in 0.." + std::to_string(kMaxExtraLights));
    if (count == 0) return;
    const double key = keyLightIlluminance(scene);
    const double illuminance = key > 0.0 ? key : 1.0;
    const glm::dvec3 lo(scene.bounds.min), hi(scene.bounds.max);
    const double margin = double(kExtraLightMargin) * glm::length(hi - lo);
    const glm::dvec3 boxLo = lo - margin, extent = (hi - lo) + 2.0 * margin;
    // A scene whose bounds are a point still gets a box: 1 m on each side.
    const glm::dvec3 size = glm::max(extent, glm::dvec3(margin > 0.0 ? 0.0 : 1.0));
    const double volume = std::max(size.x * size.y * size.z, 1.0e-12);
    const double radius = 0.5 * std::cbrt(volume / double(count));
    for (uint32_t i = 0; i < count; ++i) {
        const glm::dvec3 u(radicalInverse(i + 1, 2), radicalInverse(i + 1, 3), radicalInverse(i + 1, 5));
        Light light;
        light.name = "extra." + std::to_string(i);
        light.type = LightType::Point;
        light.color = glm::vec3(1.0f);
        light.intensity = float(illuminance * radius * radius);
        light.position = glm::vec3(boxLo + u * size);
        light.range = float(4.0 * radius);
        light.castsShadows = false;
        scene.lights.push_back(light);
    }
}

} // namespace eng::scene
