#pragma once
// Shared by the GPU tests: a lavapipe device with the Khronos validation layer
// and synchronisation validation on (a validation message fails the test), and
// small scenes built in code.

#include "engine/scene/scene.h"
#include "engine/vk/device.h"

#include <gtest/gtest.h>

#include <memory>

namespace agaa::test {

// Destroys the device, then fails the current test if the validation layer raised errors while
// it was destroyed (leaked objects are reported by vkDestroyDevice, after any check a test makes).
struct CheckedDeviceDeleter {
    void operator()(eng::vk::Device* device) const {
        std::shared_ptr<const std::atomic<uint32_t>> counter = device->validationErrorCounter();
        const uint32_t before = counter->load();
        delete device;
        EXPECT_EQ(counter->load(), before) << "validation errors raised while the device was destroyed";
    }
};
using ValidatedDevice = std::unique_ptr<eng::vk::Device, CheckedDeviceDeleter>;

// `options` may carry fault injection (DeviceOptions::failAllocation, loseDeviceAtSubmit).
inline ValidatedDevice makeValidatedDevice(eng::vk::DeviceOptions options = {}) {
    options.validation = true;
    options.synchronizationValidation = true;
    options.quiet = true;
    return ValidatedDevice(new eng::vk::Device(options));
}

// Fails the current test if the device saw any validation message, listing them.
inline void expectNoValidationErrors(const eng::vk::Device& device) {
    EXPECT_EQ(device.validationErrors(), 0u) << [&] {
        std::string all;
        for (const std::string& m : device.validationMessages())
            all += m + "\n";
        return all;
    }();
}

// A camera at the origin looking down -Z.
inline eng::scene::Camera originCamera(float yfov = 0.8f) {
    eng::scene::Camera c;
    c.view = glm::mat4(1.0f);
    c.yfov = yfov;
    c.znear = 0.05f;
    c.zfar = 100.0f;
    return c;
}

// An axis-aligned rectangle at view depth z (< 0), facing the camera, one material.
inline void addRectangle(eng::scene::Scene& s, glm::vec2 lo, glm::vec2 hi, float z, uint32_t material) {
    uint32_t base = uint32_t(s.vertices.size());
    glm::vec3 corners[4] = {{lo.x, lo.y, z}, {hi.x, lo.y, z}, {hi.x, hi.y, z}, {lo.x, hi.y, z}};
    for (const glm::vec3& p : corners) {
        eng::scene::Vertex v;
        v.position = p;
        v.normal = {0, 0, 1};
        s.vertices.push_back(v);
    }
    uint32_t first = uint32_t(s.indices.size());
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u})
        s.indices.push_back(base + i);
    s.draws.push_back({first, 6, material});
}

inline eng::scene::Scene emptyScene(const char* name) {
    eng::scene::Scene s;
    s.source = name;
    eng::scene::Material m;
    m.baseColorFactor = {0.8f, 0.8f, 0.8f, 1.0f};
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 1.0f;
    m.doubleSided = true;
    s.materials.push_back(m);
    eng::scene::Light sun;
    sun.type = eng::scene::LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(0.2f, -0.3f, -1.0f));
    sun.intensity = 2.0f;
    s.lights.push_back(sun);
    s.cameras.push_back(originCamera());
    s.bounds = {{-100, -100, -2}, {100, 100, 0}};
    return s;
}

} // namespace agaa::test
