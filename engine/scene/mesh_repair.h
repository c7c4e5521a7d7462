#pragma once
// Repairs applied to one primitive after it is in world space: degenerate
// triangles, missing or broken normals, missing tangents. The renderer relies on
// unit normals and a valid tangent frame for every vertex (a NaN there becomes a
// NaN pixel), so every path ends in finite unit vectors.

#include "engine/scene/scene.h"

#include <cstdint>
#include <vector>

namespace eng::scene {

// Triangles whose area is below this fraction of the squared diagonal of the
// primitive's bounds count as degenerate (they rasterise to nothing and give
// undefined face normals).
inline constexpr float kDegenerateRelativeArea = 1e-12f;

// Removes triangles with a repeated index or (near) zero area; returns how many.
uint32_t dropDegenerateTriangles(const std::vector<Vertex>& vertices, std::vector<uint32_t>& indices);

// Gives every triangle its own three vertices carrying the face normal (used when
// the primitive has no NORMAL attribute: sharing vertices would smooth the facets).
void makeFlatNormals(std::vector<Vertex>& vertices, std::vector<uint32_t>& indices);

// Replaces zero-length or non-finite normals by the area-weighted normal of the
// triangles around the vertex (the face normal for a lone triangle); renormalises
// the rest. Returns how many were replaced.
uint32_t repairNormals(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices);

// Tangents from the UV parametrisation (Lengyel's method), orthogonalised against
// the normal; vertices without usable UV derivatives get an arbitrary orthonormal
// tangent. w = +-1 is the bitangent sign.
void generateTangents(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices, bool hasUvs);

// Makes given tangents orthonormal to the normal; returns how many had to be
// replaced because they were zero, non-finite or parallel to the normal.
uint32_t repairTangents(std::vector<Vertex>& vertices);

// Any unit vector perpendicular to n (n must be unit length).
glm::vec3 anyPerpendicular(const glm::vec3& n);

} // namespace eng::scene
