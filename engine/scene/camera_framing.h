#pragma once
// Cameras placed from bounds: the loader's default camera (frames the bounding
// sphere) and the procedural scenes' cameras (fill the frame with a box). Both
// look at the box centre; view matrices follow glTF (camera looks down -Z, +Y up).

#include "engine/scene/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace eng::scene {

// Default when a file has no camera: yfov 0.8 rad, looking at the centre from +Z
// and slightly above, far enough that the bounding sphere fits the vertical fov.
Camera frameBoundingSphere(const Bounds& bounds, float yfov = 0.8f);

// Places the camera on the ray centre - viewDir * distance so that every corner
// of the box projects inside a square frustum of yfov (so it also fits 16:9),
// with margin > 1 leaving a border. viewDir is the direction the camera looks.
Camera frameBox(const Bounds& bounds, const glm::vec3& viewDir, float yfov, float margin = 1.05f);

// Like frameBox but fits the points themselves (a sphere's box corners lie far
// outside its silhouette), and recentres so the points' projection is centred.
Camera framePoints(const std::vector<glm::vec3>& points, const glm::vec3& viewDir, float yfov,
                   float margin = 1.05f);

// A view matrix for an eye looking at target with +Y as up (falls back to +Z
// as up when looking straight down or up).
glm::mat4 lookAtView(const glm::vec3& eye, const glm::vec3& target);

// A far plane that contains the whole box seen from eye, with headroom.
float farPlaneFor(const Bounds& bounds, const glm::vec3& eye, float znear);

} // namespace eng::scene
