#include "engine/scene/procedural_mesh.h"

#include <algorithm>
#include <cmath>

namespace eng::scene {

namespace {

constexpr float kTwoPi = 6.28318530718f;
constexpr float kPi = 3.14159265359f;

uint32_t nextIndex(const MeshData& mesh) {
    return static_cast<uint32_t>(mesh.positions.size());
}

void pushVertex(MeshData& mesh, const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
    mesh.positions.push_back(p);
    mesh.normals.push_back(n);
    mesh.uvs.push_back(uv);
}

void pushTriangle(MeshData& mesh, uint32_t a, uint32_t b, uint32_t c) {
    mesh.indices.push_back(a);
    mesh.indices.push_back(b);
    mesh.indices.push_back(c);
}

glm::vec3 perpendicularTo(const glm::vec3& t) {
    const glm::vec3 a = std::abs(t.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    return glm::normalize(glm::cross(t, a));
}

// Flat disc closing a ring; facing `facing`.
void addCap(MeshData& mesh, const glm::vec3& centre, const glm::vec3& n, const glm::vec3& b, float radius,
            int sides, const glm::vec3& facing, bool reverse) {
    const uint32_t c = nextIndex(mesh);
    pushVertex(mesh, centre, facing, glm::vec2(0.5f));
    for (int j = 0; j < sides; ++j) {
        const float a = kTwoPi * static_cast<float>(j) / static_cast<float>(sides);
        const glm::vec3 dir = std::cos(a) * n + std::sin(a) * b;
        pushVertex(mesh, centre + radius * dir, facing,
                   glm::vec2(0.5f) + 0.5f * glm::vec2(std::cos(a), std::sin(a)));
    }
    for (int j = 0; j < sides; ++j) {
        const uint32_t v0 = c + 1 + static_cast<uint32_t>(j);
        const uint32_t v1 = c + 1 + static_cast<uint32_t>((j + 1) % sides);
        if (reverse) {
            pushTriangle(mesh, c, v1, v0);
        } else {
            pushTriangle(mesh, c, v0, v1);
        }
    }
}

} // namespace

void addSphere(MeshData& mesh, const glm::vec3& centre, float radius, int rings, int segments) {
    rings = std::max(rings, 2);
    segments = std::max(segments, 3);
    const uint32_t base = nextIndex(mesh);
    for (int i = 0; i <= rings; ++i) {
        const float v = static_cast<float>(i) / static_cast<float>(rings);
        const float theta = v * kPi; // from +Y (north pole) down
        for (int j = 0; j <= segments; ++j) {
            const float u = static_cast<float>(j) / static_cast<float>(segments);
            const float phi = u * kTwoPi;
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              -std::sin(theta) * std::sin(phi));
            pushVertex(mesh, centre + radius * n, n, glm::vec2(u, v));
        }
    }
    const auto at = [&](int i, int j) { return base + static_cast<uint32_t>(i * (segments + 1) + j); };
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < segments; ++j) {
            // Pole rows collapse to a point on one side: emit only the non-degenerate triangle.
            if (i != 0) {
                pushTriangle(mesh, at(i, j), at(i + 1, j), at(i, j + 1));
            }
            if (i != rings - 1) {
                pushTriangle(mesh, at(i, j + 1), at(i + 1, j), at(i + 1, j + 1));
            }
        }
    }
}

void addTube(MeshData& mesh, const std::vector<glm::vec3>& path, const std::vector<float>& radii,
             const TubeOptions& options) {
    const size_t count = std::min(path.size(), radii.size());
    if (count < 2) {
        return;
    }
    const int sides = std::max(options.sides, 3);
    const size_t rings = options.pointedTip ? count - 1 : count;

    std::vector<glm::vec3> tangents(count);
    for (size_t i = 0; i < count; ++i) {
        const glm::vec3 d = path[std::min(i + 1, count - 1)] - path[i == 0 ? 0 : i - 1];
        tangents[i] = glm::normalize(d);
    }
    // Parallel transport: rotate the previous normal onto the plane of the new
    // tangent, so the rings do not twist along a curved path.
    std::vector<glm::vec3> normals(count);
    normals[0] = perpendicularTo(tangents[0]);
    for (size_t i = 1; i < count; ++i) {
        glm::vec3 n = normals[i - 1] - tangents[i] * glm::dot(normals[i - 1], tangents[i]);
        const float len = glm::length(n);
        normals[i] = len > 1e-6f ? n / len : perpendicularTo(tangents[i]);
    }

    const uint32_t base = nextIndex(mesh);
    for (size_t i = 0; i < rings; ++i) {
        const glm::vec3 b = glm::cross(tangents[i], normals[i]);
        const float v = static_cast<float>(i) / static_cast<float>(count - 1);
        for (int j = 0; j <= sides; ++j) {
            const float a = kTwoPi * static_cast<float>(j % sides) / static_cast<float>(sides);
            const glm::vec3 dir = std::cos(a) * normals[i] + std::sin(a) * b;
            pushVertex(mesh, path[i] + radii[i] * dir, dir, glm::vec2(static_cast<float>(j) / sides, v));
        }
    }
    const auto at = [&](size_t i, int j) {
        return base + static_cast<uint32_t>(i * static_cast<size_t>(sides + 1) + j);
    };
    for (size_t i = 0; i + 1 < rings; ++i) {
        for (int j = 0; j < sides; ++j) {
            pushTriangle(mesh, at(i, j), at(i, j + 1), at(i + 1, j + 1));
            pushTriangle(mesh, at(i, j), at(i + 1, j + 1), at(i + 1, j));
        }
    }
    if (options.pointedTip) {
        const size_t last = rings - 1;
        const uint32_t tip = nextIndex(mesh);
        pushVertex(mesh, path[count - 1], tangents[count - 1], glm::vec2(0.5f, 1.0f));
        for (int j = 0; j < sides; ++j) {
            pushTriangle(mesh, at(last, j), at(last, j + 1), tip);
        }
    } else if (options.capEnd) {
        const size_t last = count - 1;
        addCap(mesh, path[last], normals[last], glm::cross(tangents[last], normals[last]), radii[last], sides,
               tangents[last], false);
    }
    if (options.capStart) {
        addCap(mesh, path[0], normals[0], glm::cross(tangents[0], normals[0]), radii[0], sides, -tangents[0],
               true);
    }
}

void addQuad(MeshData& mesh, const glm::vec3& corner, const glm::vec3& edgeU, const glm::vec3& edgeV,
             float uRepeat, float vRepeat) {
    const glm::vec3 n = glm::normalize(glm::cross(edgeU, edgeV));
    const uint32_t b = nextIndex(mesh);
    pushVertex(mesh, corner, n, glm::vec2(0.0f, 0.0f));
    pushVertex(mesh, corner + edgeU, n, glm::vec2(uRepeat, 0.0f));
    pushVertex(mesh, corner + edgeU + edgeV, n, glm::vec2(uRepeat, vRepeat));
    pushVertex(mesh, corner + edgeV, n, glm::vec2(0.0f, vRepeat));
    pushTriangle(mesh, b, b + 1, b + 2);
    pushTriangle(mesh, b, b + 2, b + 3);
}

void addLeafCard(MeshData& mesh, const glm::vec3& base, const glm::vec3& along, const glm::vec3& side,
                 float length, float width, float bend) {
    constexpr int kAcross = 2;
    constexpr int kAlong = 3;
    const glm::vec3 face = glm::normalize(glm::cross(side, along));
    const uint32_t b = nextIndex(mesh);
    for (int i = 0; i <= kAlong; ++i) {
        const float s = static_cast<float>(i) / kAlong;
        // Position along the card: a parabola bending toward the face normal.
        const glm::vec3 spine = base + along * (length * s) + face * (bend * s * s);
        const glm::vec3 dSpine = along * length + face * (2.0f * bend * s);
        const glm::vec3 n = glm::normalize(glm::cross(side, dSpine));
        for (int j = 0; j <= kAcross; ++j) {
            const float t = static_cast<float>(j) / kAcross;
            pushVertex(mesh, spine + side * (width * (t - 0.5f)), n, glm::vec2(t, s));
        }
    }
    const auto at = [&](int i, int j) { return b + static_cast<uint32_t>(i * (kAcross + 1) + j); };
    for (int i = 0; i < kAlong; ++i) {
        for (int j = 0; j < kAcross; ++j) {
            // side x along = face, so (j, i) -> (j+1, i) -> (j+1, i+1) is CCW seen from the face.
            pushTriangle(mesh, at(i, j), at(i, j + 1), at(i + 1, j + 1));
            pushTriangle(mesh, at(i, j), at(i + 1, j + 1), at(i + 1, j));
        }
    }
}

} // namespace eng::scene
