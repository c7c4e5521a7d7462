#pragma once
// The curvature roughness's subject (agaa/common/effects.h CurvatureRoughness): a lone glossy
// sphere or a flat square, roughness 0.2, lit by a point light, seen from `distance` metres.
// The square has no curvature (the option must leave it bit for bit); the sphere's curvature per
// pixel grows with its distance.

#include "engine/scene/camera_framing.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/model_builder.h"

#include <glm/glm.hpp>

namespace agaa::test {

inline eng::scene::Scene curvatureScene(bool sphere, float distance) {
    eng::scene::ModelBuilder b("test.curvature");
    eng::scene::MaterialDesc m;
    m.name = "glossy";
    m.baseColor = glm::vec4(0.6f, 0.6f, 0.6f, 1.0f);
    m.roughness = 0.2f;
    const int material = b.addMaterial(m);
    eng::scene::MeshData mesh;
    if (sphere)
        eng::scene::addSphere(mesh, {0.0f, 0.0f, 0.0f}, 0.5f, 24, 48);
    else
        eng::scene::addQuad(mesh, {-50.0f, -50.0f, 0.0f}, {100.0f, 0.0f, 0.0f}, {0.0f, 100.0f, 0.0f});
    b.addMesh("subject", mesh, material);
    b.addPointLight("light", {1.0f, 2.0f, distance}, {1.0f, 1.0f, 1.0f}, 50.0f, 0.0f);
    eng::scene::Camera camera;
    camera.name = "camera";
    camera.yfov = 0.8f;
    camera.view = eng::scene::lookAtView({0.0f, 0.0f, distance}, {0.0f, 0.0f, 0.0f});
    camera.znear = 0.05f;
    camera.zfar = 200.0f;
    b.addCamera(camera, 1.0f);
    return eng::scene::loadGltfModel(b.finish(), "test.curvature");
}

} // namespace agaa::test
