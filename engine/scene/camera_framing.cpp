#include "engine/scene/camera_framing.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace eng::scene {

namespace {

// An empty scene still needs a usable camera: treat it as a 1 m box at the origin.
constexpr float kMinRadius = 1e-3f;

glm::vec3 centreOf(const Bounds& b) {
    return 0.5f * (b.min + b.max);
}

float radiusOf(const Bounds& b) {
    return std::max(0.5f * glm::length(b.max - b.min), kMinRadius);
}

} // namespace

glm::mat4 lookAtView(const glm::vec3& eye, const glm::vec3& target) {
    glm::vec3 dir = target - eye;
    if (glm::dot(dir, dir) < 1e-20f) {
        dir = glm::vec3(0.0f, 0.0f, -1.0f);
    }
    dir = glm::normalize(dir);
    const glm::vec3 up = std::abs(dir.y) > 0.999f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::lookAtRH(eye, eye + dir, up);
}

float farPlaneFor(const Bounds& bounds, const glm::vec3& eye, float znear) {
    float farthest = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                               (i & 4) ? bounds.max.z : bounds.min.z);
        farthest = std::max(farthest, glm::length(corner - eye));
    }
    // 1.5x headroom so geometry at the far corner is not clipped by depth precision.
    return std::max(farthest * 1.5f, znear * 10.0f);
}

Camera frameBoundingSphere(const Bounds& bounds, float yfov) {
    const glm::vec3 centre = centreOf(bounds);
    const float radius = radiusOf(bounds);
    const float distance = radius / std::sin(0.5f * yfov);
    const glm::vec3 fromCentre = glm::normalize(glm::vec3(0.0f, 0.25f, 1.0f));
    const glm::vec3 eye = centre + fromCentre * distance;

    Camera camera;
    camera.name = "default";
    camera.yfov = yfov;
    camera.view = lookAtView(eye, centre);
    // The sphere starts at distance - radius; half of that keeps depth precision
    // without clipping, and never closer than 1/1000 of the distance.
    camera.znear = std::max(0.5f * (distance - radius), 1e-3f * distance);
    camera.zfar = std::max((distance + radius) * 1.5f, camera.znear * 10.0f);
    return camera;
}

Camera frameBox(const Bounds& bounds, const glm::vec3& viewDir, float yfov, float margin) {
    const glm::vec3 centre = centreOf(bounds);
    const glm::vec3 forward = glm::normalize(viewDir);
    // Orientation only: the basis does not depend on the distance we solve for.
    const glm::mat4 basis = lookAtView(glm::vec3(0.0f), forward);
    const float tanHalf = std::tan(0.5f * yfov);

    // A corner at view-space (x, y, z) relative to the centre is inside the square
    // frustum when max(|x|, |y|) <= (distance - depthTowardCamera) * tan(yfov/2).
    float distance = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? bounds.max.x : bounds.min.x, (i & 2) ? bounds.max.y : bounds.min.y,
                               (i & 4) ? bounds.max.z : bounds.min.z);
        const glm::vec3 v = glm::vec3(basis * glm::vec4(corner - centre, 0.0f));
        const float extent = std::max(std::abs(v.x), std::abs(v.y)) * margin;
        distance = std::max(distance, v.z + extent / tanHalf);
    }
    distance = std::max(distance, radiusOf(bounds) * 0.5f);
    const glm::vec3 eye = centre - forward * distance;

    Camera camera;
    camera.name = "framing";
    camera.yfov = yfov;
    camera.view = lookAtView(eye, centre);
    const float nearest = distance - radiusOf(bounds);
    camera.znear = std::max(0.5f * nearest, 1e-3f * distance);
    camera.zfar = farPlaneFor(bounds, eye, camera.znear);
    return camera;
}

Camera framePoints(const std::vector<glm::vec3>& points, const glm::vec3& viewDir, float yfov, float margin) {
    Bounds bounds;
    if (points.empty()) {
        return frameBox(bounds, viewDir, yfov, margin);
    }
    bounds.min = bounds.max = points[0];
    for (const glm::vec3& p : points) {
        bounds.min = glm::min(bounds.min, p);
        bounds.max = glm::max(bounds.max, p);
    }
    const glm::vec3 forward = glm::normalize(viewDir);
    const glm::mat4 basis = lookAtView(glm::vec3(0.0f), forward);
    const glm::mat3 toWorld = glm::transpose(glm::mat3(basis));
    const float tanHalf = std::tan(0.5f * yfov);

    // Solve the distance for a target, then move the target to the middle of the
    // projected extent and solve again; two rounds settle to well under 1%.
    glm::vec3 target = centreOf(bounds);
    float distance = 0.0f;
    for (int round = 0; round < 3; ++round) {
        distance = 0.0f;
        for (const glm::vec3& p : points) {
            const glm::vec3 v = glm::vec3(basis * glm::vec4(p - target, 0.0f));
            distance = std::max(distance, v.z + std::max(std::abs(v.x), std::abs(v.y)) * margin / tanHalf);
        }
        glm::vec2 lo(1e30f), hi(-1e30f);
        for (const glm::vec3& p : points) {
            const glm::vec3 v = glm::vec3(basis * glm::vec4(p - target, 0.0f));
            const glm::vec2 ndc = glm::vec2(v) / ((distance - v.z) * tanHalf);
            lo = glm::min(lo, ndc);
            hi = glm::max(hi, ndc);
        }
        const glm::vec2 mid = 0.5f * (lo + hi);
        // Shift in the plane through the target, at the target's depth.
        target += toWorld * glm::vec3(mid * distance * tanHalf, 0.0f);
    }
    const glm::vec3 eye = target - forward * distance;
    Camera camera;
    camera.name = "framing";
    camera.yfov = yfov;
    camera.view = lookAtView(eye, target);
    float nearest = distance;
    for (const glm::vec3& p : points) {
        nearest = std::min(nearest, -(camera.view * glm::vec4(p, 1.0f)).z);
    }
    camera.znear = std::max(0.5f * nearest, 1e-3f * distance);
    camera.zfar = farPlaneFor(bounds, eye, camera.znear);
    return camera;
}

} // namespace eng::scene
