#pragma once
// Indexed triangle geometry for the procedural scenes: spheres, tubes along a
// path (hair strands, bars, stalks, branches), quads and bent leaf cards. All
// triangles are counter-clockwise seen from the side their normals face, and
// none is degenerate (the loader would drop it and change the counts).

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace eng::scene {

struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; // unit length, one per position
    std::vector<glm::vec2> uvs;     // one per position
    std::vector<uint32_t> indices;

    size_t triangleCount() const { return indices.size() / 3; }
    bool empty() const { return indices.empty(); }
};

// UV sphere; rings >= 2 latitude bands, segments >= 3 around.
void addSphere(MeshData& mesh, const glm::vec3& centre, float radius, int rings, int segments);

struct TubeOptions {
    int sides = 8;           // >= 3
    bool capStart = false;   // flat disc closing the first ring
    bool capEnd = false;     // flat disc closing the last ring (ignored with pointedTip)
    bool pointedTip = false; // the last path point is a tip vertex, not a ring (hair)
};

// A generalised cylinder: one ring of `sides` vertices per path point with the
// matching radius, framed by parallel transport so it does not twist.
// path.size() == radii.size() >= 2.
void addTube(MeshData& mesh, const std::vector<glm::vec3>& path, const std::vector<float>& radii,
             const TubeOptions& options);

// A parallelogram corner, corner + edgeU, corner + edgeU + edgeV, corner + edgeV,
// facing cross(edgeU, edgeV); uv (0,0) at corner, (uRepeat, vRepeat) opposite.
void addQuad(MeshData& mesh, const glm::vec3& corner, const glm::vec3& edgeU, const glm::vec3& edgeV,
             float uRepeat = 1.0f, float vRepeat = 1.0f);

// A leaf card: a 2 x 3 grid from base along `along` (unit) for length, width
// across `side` (unit, perpendicular to along), bent by `bend` metres toward
// its face normal cross(side, along) at the tip. uv.x across, uv.y base to tip.
void addLeafCard(MeshData& mesh, const glm::vec3& base, const glm::vec3& along, const glm::vec3& side,
                 float length, float width, float bend);

} // namespace eng::scene
