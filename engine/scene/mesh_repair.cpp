#include "engine/scene/mesh_repair.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eng::scene {

namespace {

bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Below this squared length a direction is treated as zero (it would normalise to garbage).
constexpr float kMinSquaredLength = 1e-24f;

glm::vec3 triangleCross(const std::vector<Vertex>& v, uint32_t a, uint32_t b, uint32_t c) {
    return glm::cross(v[b].position - v[a].position, v[c].position - v[a].position);
}

} // namespace

glm::vec3 anyPerpendicular(const glm::vec3& n) {
    // Cross with the axis least aligned with n: never near-parallel.
    const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    return glm::normalize(glm::cross(a, n));
}

uint32_t dropDegenerateTriangles(const std::vector<Vertex>& vertices, std::vector<uint32_t>& indices) {
    if (indices.empty()) {
        return 0;
    }
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(-std::numeric_limits<float>::max());
    for (uint32_t i : indices) {
        lo = glm::min(lo, vertices[i].position);
        hi = glm::max(hi, vertices[i].position);
    }
    const glm::vec3 diagonal = hi - lo;
    const double squaredDiagonal = glm::dot(diagonal, diagonal);
    const double minArea = static_cast<double>(kDegenerateRelativeArea) * squaredDiagonal;

    uint32_t dropped = 0;
    size_t out = 0;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        // Double precision: thin hair triangles are legitimately tiny and must
        // not be lost to float cancellation in the cross product.
        const glm::dvec3 pa(vertices[a].position), pb(vertices[b].position), pc(vertices[c].position);
        const double area = 0.5 * glm::length(glm::cross(pb - pa, pc - pa));
        if (a == b || b == c || a == c || !(area >= minArea) || area == 0.0) {
            ++dropped;
            continue;
        }
        indices[out++] = a;
        indices[out++] = b;
        indices[out++] = c;
    }
    indices.resize(out);
    return dropped;
}

void makeFlatNormals(std::vector<Vertex>& vertices, std::vector<uint32_t>& indices) {
    std::vector<Vertex> flat;
    flat.reserve(indices.size());
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        glm::vec3 n = triangleCross(vertices, indices[t], indices[t + 1], indices[t + 2]);
        const float len2 = glm::dot(n, n);
        // Degenerate triangles are dropped before this runs; the guard keeps a
        // caller that skipped that step from producing NaN.
        n = (len2 > kMinSquaredLength && std::isfinite(len2)) ? n / std::sqrt(len2)
                                                              : glm::vec3(0.0f, 0.0f, 1.0f);
        for (int k = 0; k < 3; ++k) {
            Vertex v = vertices[indices[t + static_cast<size_t>(k)]];
            v.normal = n;
            flat.push_back(v);
        }
    }
    vertices = std::move(flat);
    for (size_t i = 0; i < indices.size(); ++i) {
        indices[i] = static_cast<uint32_t>(i);
    }
}

uint32_t repairNormals(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices) {
    std::vector<bool> bad(vertices.size(), false);
    uint32_t badCount = 0;
    for (size_t i = 0; i < vertices.size(); ++i) {
        const glm::vec3 n = vertices[i].normal;
        const float len2 = glm::dot(n, n);
        if (!isFinite(n) || !(len2 > kMinSquaredLength) || !std::isfinite(len2)) {
            bad[i] = true;
            ++badCount;
        } else {
            vertices[i].normal = n / std::sqrt(len2);
        }
    }
    if (badCount == 0) {
        return 0;
    }
    std::vector<glm::vec3> accumulated(vertices.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        // Unnormalised cross product = area weighting.
        const glm::vec3 n = triangleCross(vertices, indices[t], indices[t + 1], indices[t + 2]);
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = indices[t + static_cast<size_t>(k)];
            if (bad[v]) {
                accumulated[v] += n;
            }
        }
    }
    for (size_t i = 0; i < vertices.size(); ++i) {
        if (!bad[i]) {
            continue;
        }
        const glm::vec3 n = accumulated[i];
        const float len2 = glm::dot(n, n);
        vertices[i].normal = (len2 > kMinSquaredLength && std::isfinite(len2)) ? n / std::sqrt(len2)
                                                                               : glm::vec3(0.0f, 0.0f, 1.0f);
    }
    return badCount;
}

void generateTangents(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices, bool hasUvs) {
    std::vector<glm::vec3> tan(vertices.size(), glm::vec3(0.0f));
    std::vector<glm::vec3> bitan(vertices.size(), glm::vec3(0.0f));
    if (hasUvs) {
        for (size_t t = 0; t + 2 < indices.size(); t += 3) {
            const uint32_t i0 = indices[t], i1 = indices[t + 1], i2 = indices[t + 2];
            const glm::vec3 e1 = vertices[i1].position - vertices[i0].position;
            const glm::vec3 e2 = vertices[i2].position - vertices[i0].position;
            const glm::vec2 d1 = vertices[i1].uv - vertices[i0].uv;
            const glm::vec2 d2 = vertices[i2].uv - vertices[i0].uv;
            const float det = d1.x * d2.y - d2.x * d1.y;
            // A triangle with collinear UVs defines no tangent direction; skip it.
            if (!(std::abs(det) > 1e-20f) || !std::isfinite(det)) {
                continue;
            }
            const float r = 1.0f / det;
            const glm::vec3 s = (e1 * d2.y - e2 * d1.y) * r;
            const glm::vec3 u = (e2 * d1.x - e1 * d2.x) * r;
            if (!isFinite(s) || !isFinite(u)) {
                continue;
            }
            for (uint32_t v : {i0, i1, i2}) {
                tan[v] += s;
                bitan[v] += u;
            }
        }
    }
    for (size_t i = 0; i < vertices.size(); ++i) {
        const glm::vec3 n = vertices[i].normal;
        glm::vec3 t = tan[i] - n * glm::dot(n, tan[i]);
        const float len2 = glm::dot(t, t);
        if (!(len2 > kMinSquaredLength) || !std::isfinite(len2)) {
            vertices[i].tangent = glm::vec4(anyPerpendicular(n), 1.0f);
            continue;
        }
        t /= std::sqrt(len2);
        const float w = glm::dot(glm::cross(n, t), bitan[i]) < 0.0f ? -1.0f : 1.0f;
        vertices[i].tangent = glm::vec4(t, w);
    }
}

uint32_t repairTangents(std::vector<Vertex>& vertices) {
    uint32_t replaced = 0;
    for (Vertex& v : vertices) {
        const glm::vec3 n = v.normal;
        glm::vec3 t = glm::vec3(v.tangent);
        t -= n * glm::dot(n, t);
        const float len2 = glm::dot(t, t);
        const float w = v.tangent.w < 0.0f ? -1.0f : 1.0f;
        if (!isFinite(t) || !(len2 > kMinSquaredLength) || !std::isfinite(len2)) {
            v.tangent = glm::vec4(anyPerpendicular(n), w);
            ++replaced;
        } else {
            v.tangent = glm::vec4(t / std::sqrt(len2), w);
        }
    }
    return replaced;
}

} // namespace eng::scene
