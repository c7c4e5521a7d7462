#include "engine/scene/scene_subjects.h"

#include "engine/scene/leaf_texture.h"

#include <algorithm>
#include <cmath>

namespace eng::scene {

namespace {

constexpr float kPi = 3.14159265359f;
constexpr float kTwoPi = 6.28318530718f;

glm::vec3 randomUnitVector(Prng& rng) {
    const float z = rng.range(-1.0f, 1.0f);
    const float phi = rng.range(0.0f, kTwoPi);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    return {r * std::cos(phi), z, r * std::sin(phi)};
}

glm::vec3 perpendicular(const glm::vec3& n) {
    const glm::vec3 a = std::abs(n.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    return glm::normalize(glm::cross(n, a));
}

// Leaf card oriented along `along`, its face turned toward `faceHint` (usually
// the camera side) so the alpha silhouette reads instead of showing edge-on.
void addOrientedLeaf(MeshData& mesh, const glm::vec3& base, const glm::vec3& along, const glm::vec3& faceHint,
                     float length, float width, float bend) {
    const glm::vec3 a = glm::normalize(along);
    glm::vec3 side = glm::cross(a, faceHint);
    if (glm::dot(side, side) < 1e-8f) {
        side = perpendicular(a);
    }
    addLeafCard(mesh, base, a, glm::normalize(side), length, width, bend);
}

MaterialDesc plainMaterial(const std::string& name, const glm::vec3& color, float metallic, float roughness) {
    MaterialDesc m;
    m.name = name;
    m.baseColor = glm::vec4(color, 1.0f);
    m.metallic = metallic;
    m.roughness = roughness;
    return m;
}

} // namespace

SubjectSink::SubjectSink(ModelBuilder& builder, Prng& rng, float density)
    : m_builder(builder), m_rng(rng), m_density(density) {}

int SubjectSink::scaled(int count) const {
    return std::max(1, static_cast<int>(std::lround(static_cast<float>(count) * m_density)));
}

int SubjectSink::material(const MaterialDesc& desc) {
    if (const auto it = m_materials.find(desc.name); it != m_materials.end()) {
        return it->second;
    }
    const int index = m_builder.addMaterial(desc);
    m_materials[desc.name] = index;
    return index;
}

int SubjectSink::leafMaterial() {
    if (m_leafTexture < 0) {
        m_leafTexture = m_builder.addPngTexture(encodePng(makeLeafImage(128)), "leaf");
    }
    MaterialDesc leaf;
    leaf.name = "leaf";
    leaf.baseColorTexture = m_leafTexture;
    leaf.roughness = 0.55f;
    leaf.alphaMode = AlphaMode::Mask;
    leaf.alphaCutoff = 0.5f;
    leaf.doubleSided = true;
    return material(leaf);
}

void SubjectSink::addSubject(const std::string& name, const MeshData& mesh, int material) {
    if (mesh.empty()) {
        return;
    }
    for (const glm::vec3& p : mesh.positions) {
        if (!m_hasSubject) {
            m_subject.min = m_subject.max = p;
            m_hasSubject = true;
        }
        m_subject.min = glm::min(m_subject.min, p);
        m_subject.max = glm::max(m_subject.max, p);
    }
    m_points.insert(m_points.end(), mesh.positions.begin(), mesh.positions.end());
    m_builder.addMesh(name, mesh, material);
}

void SubjectSink::addBackdrop(const std::string& name, const MeshData& mesh, int material) {
    m_builder.addMesh(name, mesh, material);
}

void addFurball(SubjectSink& sink, const glm::vec3& centre, float radius, float strandScale) {
    Prng& rng = sink.rng();
    MeshData skin;
    addSphere(skin, centre, radius, 48, 96);
    sink.addSubject("furball.skin", skin,
                    sink.material(plainMaterial("fur.skin", {0.35f, 0.22f, 0.12f}, 0.0f, 0.7f)));

    // 9000 strands x 21 triangles ~ 190k triangles at density 1: tens of
    // triangles per pixel at 720p, within lavapipe's budget.
    constexpr int kSegments = 4; // rings at s = 0, 1/4, 2/4, 3/4; the tip is a point
    const int strands = sink.scaled(static_cast<int>(std::lround(9000.0f * strandScale)));
    MeshData hair;
    hair.positions.reserve(static_cast<size_t>(strands) * 13);
    hair.indices.reserve(static_cast<size_t>(strands) * 21 * 3);
    std::vector<glm::vec3> path(kSegments + 1);
    std::vector<float> radii(kSegments + 1);
    TubeOptions tube;
    tube.sides = 3; // a triangular prism: round enough at 1-2 mm, a third of the triangles of a hexagon
    tube.pointedTip = true;
    for (int s = 0; s < strands; ++s) {
        const glm::vec3 n = randomUnitVector(rng);
        // Rooted just under the skin so no gap shows at grazing angles.
        const glm::vec3 root = centre + n * (radius * 0.99f);
        const float length = rng.range(0.05f, 0.15f);
        const float rootRadius = 0.5f * rng.range(0.001f, 0.002f);
        const glm::vec3 t = perpendicular(n);
        const float a = rng.range(0.0f, kTwoPi);
        const glm::vec3 bendDir = std::cos(a) * t + std::sin(a) * glm::cross(n, t);
        const float curl = rng.range(0.15f, 0.45f);
        const glm::vec3 sag = glm::vec3(0.0f, -0.25f, 0.0f);
        for (int k = 0; k <= kSegments; ++k) {
            const float u = static_cast<float>(k) / kSegments;
            path[static_cast<size_t>(k)] =
                root + n * (length * u) + (bendDir * curl + sag) * (length * u * u);
            radii[static_cast<size_t>(k)] = rootRadius * (1.0f - 0.6f * u);
        }
        addTube(hair, path, radii, tube);
    }
    sink.addSubject("furball.hair", hair,
                    sink.material(plainMaterial("fur.hair", {0.55f, 0.36f, 0.2f}, 0.0f, 0.35f)));
}

void addSpikeBall(SubjectSink& sink, const glm::vec3& centre, float radius, int count) {
    Prng& rng = sink.rng();
    const int gold = sink.material(plainMaterial("spikes.gold", {1.0f, 0.78f, 0.34f}, 1.0f, 0.02f));
    const int spikes = sink.scaled(count);
    TubeOptions tube;
    tube.sides = 6;
    tube.capEnd = true;
    MeshData mesh;
    constexpr float kGoldenAngle = 2.39996323f; // pi (3 - sqrt 5)
    for (int i = 0; i < spikes; ++i) {
        // Fibonacci lattice: even area per direction; a small jitter breaks its spirals.
        const float z = 1.0f - 2.0f * (static_cast<float>(i) + rng.range(0.25f, 0.75f)) / spikes;
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = kGoldenAngle * static_cast<float>(i) + rng.range(-0.05f, 0.05f);
        const glm::vec3 dir(r * std::cos(phi), z, r * std::sin(phi));
        addTube(mesh, {centre + dir * (0.3f * radius), centre + dir * radius}, {0.0025f, 0.0025f}, tube);
    }
    sink.addSubject("spikes", mesh, gold);
}

void addMetalLattice(SubjectSink& sink, const glm::vec3& centre, const glm::vec2& size) {
    Prng& rng = sink.rng();
    const int steel = sink.material(plainMaterial("metal.steel", {0.91f, 0.92f, 0.92f}, 1.0f, 0.18f));
    const int brass = sink.material(plainMaterial("metal.brass", {0.95f, 0.78f, 0.45f}, 1.0f, 0.28f));
    MeshData meshes[2];
    constexpr int kLayers = 3;
    constexpr float kLayerSpacing = 0.08f;
    constexpr int kLengthSegments = 32;
    const int columns = sink.scaled(16);
    const int rows = sink.scaled(12);
    TubeOptions tube;
    tube.sides = 10;
    tube.capStart = true;
    tube.capEnd = true;

    auto addBar = [&](const glm::vec3& from, const glm::vec3& to, const glm::vec3& bendAxis, float z) {
        const bool bent = rng.uniform() < 0.35f;
        const float amplitude = bent ? rng.range(0.02f, 0.05f) : 0.0f;
        const float radius = rng.range(0.003f, 0.005f);
        std::vector<glm::vec3> path(kLengthSegments + 1);
        std::vector<float> radii(kLengthSegments + 1, radius);
        for (int k = 0; k <= kLengthSegments; ++k) {
            const float u = static_cast<float>(k) / kLengthSegments;
            glm::vec3 p = glm::mix(from, to, u) + bendAxis * (amplitude * std::sin(kPi * u));
            p.z += z;
            path[static_cast<size_t>(k)] = p;
        }
        addTube(meshes[rng.below(2)], path, radii, tube);
    };
    for (int layer = 0; layer < kLayers; ++layer) {
        const float z = centre.z + (static_cast<float>(layer) - 1.0f) * kLayerSpacing;
        // Offset the middle layer by half a cell so the layers interleave on screen.
        const float shift = layer == 1 ? 0.5f : 0.0f;
        for (int i = 0; i < columns; ++i) {
            const float x =
                centre.x - 0.5f * size.x + (static_cast<float>(i) + 0.25f + shift * 0.5f) * size.x / columns;
            addBar({x, centre.y - 0.5f * size.y, 0.0f}, {x, centre.y + 0.5f * size.y, 0.0f},
                   {0.0f, 0.0f, 1.0f}, z);
        }
        for (int j = 0; j < rows; ++j) {
            const float y =
                centre.y - 0.5f * size.y + (static_cast<float>(j) + 0.25f + shift * 0.5f) * size.y / rows;
            addBar({centre.x - 0.5f * size.x, y, 0.0f}, {centre.x + 0.5f * size.x, y, 0.0f},
                   {0.0f, 0.3f, 1.0f}, z);
        }
    }
    sink.addSubject("metal.steel", meshes[0], steel);
    sink.addSubject("metal.brass", meshes[1], brass);
}

void addChainLink(SubjectSink& sink, const glm::vec3& centre, const glm::vec2& size, float mesh) {
    const int steel = sink.material(plainMaterial("chainlink.steel", {0.86f, 0.87f, 0.88f}, 1.0f, 0.15f));
    constexpr float kRadius = 0.004f;
    // The weave's half height: the two families' axes are 2 x kWeave apart at a crossing, which
    // leaves 2 mm between the wires' surfaces.
    constexpr float kWeave = 1.25f * kRadius;
    const float spacing = mesh / sink.density(); // denser fence, more wires
    // Path points per crossing: 6 at density 1, fewer above it so that the triangle count grows
    // as the density (wires x crossings per wire x points per crossing), not as its square.
    const int segmentsPerCrossing = std::clamp(static_cast<int>(std::lround(6.0f / sink.density())), 2, 6);
    TubeOptions tube;
    tube.sides = 8;
    tube.capStart = true;
    tube.capEnd = true;
    MeshData wires;
    const glm::vec2 half = 0.5f * size;
    const float r2 = 0.70710678f; // 1 / sqrt(2)
    // Family f runs along direction d = (1, s) / sqrt 2 (s = +1 or -1); a wire is the line
    // a = dot(p, n) = i * spacing with n = (-s, 1) / sqrt 2, and its crossings with the other family
    // fall every `spacing` along it, where z alternates sign with the crossing's parity.
    for (int family = 0; family < 2; ++family) {
        const float s = family == 0 ? 1.0f : -1.0f;
        const glm::vec2 d(r2, s * r2), n(-s * r2, r2);
        const float aMax = (half.x + half.y) * r2;
        const int wiresPerSide = static_cast<int>(std::floor(aMax / spacing));
        for (int i = -wiresPerSide; i <= wiresPerSide; ++i) {
            const float a = static_cast<float>(i) * spacing;
            // The wire's stretch inside the rectangle |x| <= half.x, |y| <= half.y, as t along d.
            float t0 = -1e9f, t1 = 1e9f;
            for (int axis = 0; axis < 2; ++axis) {
                const float origin = a * n[axis];
                const float lo = (-half[axis] - origin) / d[axis], hi = (half[axis] - origin) / d[axis];
                t0 = std::max(t0, std::min(lo, hi));
                t1 = std::min(t1, std::max(lo, hi));
            }
            if (t1 - t0 < spacing) continue;
            const int segments = std::max(
                2,
                static_cast<int>(std::ceil((t1 - t0) / spacing * static_cast<float>(segmentsPerCrossing))));
            std::vector<glm::vec3> path(static_cast<size_t>(segments) + 1);
            for (int k = 0; k <= segments; ++k) {
                const float t = t0 + (t1 - t0) * static_cast<float>(k) / static_cast<float>(segments);
                const glm::vec2 p = a * n + t * d;
                // The other family's index at p is dot(p, n') / spacing with n' = (s, 1) / sqrt 2;
                // family 1 is the mirror image so the wires meet over/under.
                const float other = (s * p.x + p.y) * r2 / spacing;
                const float phase = kPi * (other + static_cast<float>(i));
                const float z = (family == 0 ? 1.0f : -1.0f) * kWeave * std::cos(phase);
                path[static_cast<size_t>(k)] = centre + glm::vec3(p.x, p.y, z);
            }
            addTube(wires, path, std::vector<float>(path.size(), kRadius), tube);
        }
    }
    sink.addSubject("chainlink.wires", wires, steel);
}

void addFoliage(SubjectSink& sink, const glm::vec3& base, float width, float height) {
    Prng& rng = sink.rng();
    const int bark = sink.material(plainMaterial("bark", {0.28f, 0.19f, 0.11f}, 0.0f, 0.9f));
    const int leafMaterial = sink.leafMaterial();
    MeshData wood;
    MeshData leaves;
    constexpr int kBranches = 7;
    constexpr int kBranchPoints = 9;
    constexpr int kTwigsPerBranch = 18;
    const int leavesPerTwig = sink.scaled(9);
    TubeOptions branchTube;
    branchTube.sides = 8;
    branchTube.capEnd = true;
    TubeOptions twigTube;
    twigTube.sides = 6;
    twigTube.capEnd = true;

    for (int b = 0; b < kBranches; ++b) {
        const float x0 = base.x + width * ((static_cast<float>(b) + 0.5f) / kBranches - 0.5f) * 0.7f;
        const glm::vec3 lean(rng.range(-0.25f, 0.25f), 1.0f, rng.range(-0.15f, 0.15f));
        const float branchHeight = height * rng.range(0.7f, 1.0f);
        std::vector<glm::vec3> path(kBranchPoints);
        std::vector<float> radii(kBranchPoints);
        glm::vec3 wander(0.0f);
        for (int k = 0; k < kBranchPoints; ++k) {
            const float u = static_cast<float>(k) / (kBranchPoints - 1);
            wander += glm::vec3(rng.range(-0.02f, 0.02f), 0.0f, rng.range(-0.015f, 0.015f));
            path[static_cast<size_t>(k)] = glm::vec3(x0, base.y, base.z) + lean * (branchHeight * u) + wander;
            radii[static_cast<size_t>(k)] = glm::mix(0.012f, 0.004f, u);
        }
        addTube(wood, path, radii, branchTube);

        for (int t = 0; t < kTwigsPerBranch; ++t) {
            const float u = 0.25f + 0.7f * (static_cast<float>(t) + rng.uniform()) / kTwigsPerBranch;
            const float fk = u * (kBranchPoints - 1);
            const auto k = static_cast<size_t>(std::min(fk, static_cast<float>(kBranchPoints - 2)));
            const glm::vec3 start = glm::mix(path[k], path[k + 1], fk - static_cast<float>(k));
            const float sideSign = (t % 2 == 0) ? 1.0f : -1.0f;
            const glm::vec3 dir = glm::normalize(
                glm::vec3(sideSign * rng.range(0.6f, 1.0f), rng.range(0.3f, 0.8f), rng.range(-0.5f, 0.5f)));
            const float twigLength = rng.range(0.12f, 0.25f);
            std::vector<glm::vec3> twig(4);
            std::vector<float> twigRadii(4);
            for (int q = 0; q < 4; ++q) {
                const float s = static_cast<float>(q) / 3.0f;
                twig[static_cast<size_t>(q)] =
                    start + dir * (twigLength * s) + glm::vec3(0.0f, -0.03f * s * s, 0.0f);
                twigRadii[static_cast<size_t>(q)] = glm::mix(0.0035f, 0.0015f, s);
            }
            addTube(wood, twig, twigRadii, twigTube);

            for (int l = 0; l < leavesPerTwig; ++l) {
                const float s = (static_cast<float>(l) + 1.0f) / static_cast<float>(leavesPerTwig);
                const glm::vec3 at = start + dir * (twigLength * s) + glm::vec3(0.0f, -0.03f * s * s, 0.0f);
                const float leafSide = (l % 2 == 0) ? 1.0f : -1.0f;
                const glm::vec3 outward =
                    glm::normalize(glm::cross(dir, glm::vec3(0.0f, 0.0f, 1.0f)) * leafSide + dir * 0.6f +
                                   randomUnitVector(rng) * 0.3f);
                const glm::vec3 faceHint =
                    glm::normalize(glm::vec3(rng.range(-0.5f, 0.5f), rng.range(0.0f, 0.6f), 1.0f));
                const float length = rng.range(0.06f, 0.1f);
                addOrientedLeaf(leaves, at, outward, faceHint, length, length * 0.65f,
                                rng.range(-0.01f, 0.015f));
            }
        }
    }
    sink.addSubject("foliage.wood", wood, bark);
    sink.addSubject("foliage.leaves", leaves, leafMaterial);
}

void addBamboo(SubjectSink& sink, const glm::vec3& centre, const glm::vec2& area, float height) {
    Prng& rng = sink.rng();
    const int stalkMaterial =
        sink.material(plainMaterial("bamboo.stalk", {0.48f, 0.56f, 0.22f}, 0.0f, 0.45f));
    const int leafMaterial = sink.leafMaterial();
    MeshData stalks;
    MeshData leaves;
    const int count = sink.scaled(36);
    const int leavesPerNode = sink.scaled(3);
    TubeOptions tube;
    tube.sides = 12;
    tube.capEnd = true;
    constexpr float kNodeHalfWidth = 0.012f;

    for (int s = 0; s < count; ++s) {
        const glm::vec3 root(centre.x + rng.range(-0.5f, 0.5f) * area.x, centre.y,
                             centre.z + rng.range(-0.5f, 0.5f) * area.y);
        const float radius = rng.range(0.012f, 0.022f);
        const float stalkHeight = height * rng.range(0.75f, 1.0f);
        const glm::vec3 lean(rng.range(-0.04f, 0.04f), 0.0f, rng.range(-0.04f, 0.04f));
        const float internode = rng.range(0.28f, 0.36f);
        auto at = [&](float y) { return root + glm::vec3(0.0f, y, 0.0f) + lean * (y + 0.3f * y * y); };

        std::vector<glm::vec3> path;
        std::vector<float> radii;
        std::vector<float> nodes;
        path.push_back(at(0.0f));
        radii.push_back(radius);
        for (float y = internode; y < stalkHeight - 2.0f * kNodeHalfWidth; y += internode) {
            // A node is a short bulge: thin - thick - thin rings 12 mm apart.
            const float mid = y - 0.5f * internode;
            path.push_back(at(mid));
            radii.push_back(radius * 0.97f);
            path.push_back(at(y - kNodeHalfWidth));
            radii.push_back(radius);
            path.push_back(at(y));
            radii.push_back(radius * 1.15f);
            path.push_back(at(y + kNodeHalfWidth));
            radii.push_back(radius);
            nodes.push_back(y);
        }
        path.push_back(at(stalkHeight));
        radii.push_back(radius * 0.9f);
        addTube(stalks, path, radii, tube);

        for (float y : nodes) {
            if (y < 0.4f * stalkHeight) {
                continue;
            }
            for (int l = 0; l < leavesPerNode; ++l) {
                const float a = rng.range(0.0f, kTwoPi);
                const glm::vec3 out(std::cos(a), rng.range(-0.35f, 0.25f), std::sin(a));
                const glm::vec3 base = at(y) + glm::normalize(glm::vec3(out.x, 0.0f, out.z)) * radius;
                const float length = rng.range(0.15f, 0.24f);
                const glm::vec3 faceHint =
                    glm::normalize(glm::vec3(rng.range(-0.4f, 0.4f), rng.range(0.3f, 0.9f), 1.0f));
                addOrientedLeaf(leaves, base, out, faceHint, length, length * 0.22f, -rng.range(0.0f, 0.03f));
            }
        }
    }
    sink.addSubject("bamboo.stalks", stalks, stalkMaterial);
    sink.addSubject("bamboo.leaves", leaves, leafMaterial);
}

void addRailing(SubjectSink& sink, const glm::vec3& baseCentre, float width, float height) {
    const int paint = sink.material(plainMaterial("railing.paint", {0.06f, 0.07f, 0.08f}, 0.8f, 0.35f));
    MeshData mesh;
    // 4 cm spacing at density 1: a 6 mm bar is ~1 pixel wide at 720p framing.
    const int bars = std::max(2, static_cast<int>(std::lround(width / 0.04f * sink.density())));
    const float bottomRail = baseCentre.y + 0.08f;
    const float top = baseCentre.y + height;
    TubeOptions bar;
    bar.sides = 8;
    for (int i = 0; i < bars; ++i) {
        const float x = baseCentre.x - 0.5f * width + width * (static_cast<float>(i) + 0.5f) / bars;
        addTube(mesh, {{x, bottomRail, baseCentre.z}, {x, top, baseCentre.z}}, {0.006f, 0.006f}, bar);
    }
    TubeOptions rail;
    rail.sides = 12;
    rail.capStart = true;
    rail.capEnd = true;
    const float x0 = baseCentre.x - 0.5f * width - 0.03f;
    const float x1 = baseCentre.x + 0.5f * width + 0.03f;
    addTube(mesh, {{x0, top, baseCentre.z}, {x1, top, baseCentre.z}}, {0.018f, 0.018f}, rail);
    addTube(mesh, {{x0, bottomRail, baseCentre.z}, {x1, bottomRail, baseCentre.z}}, {0.012f, 0.012f}, rail);
    for (float x : {x0, x1}) {
        addTube(mesh, {{x, baseCentre.y, baseCentre.z}, {x, top + 0.03f, baseCentre.z}}, {0.02f, 0.02f},
                rail);
    }
    sink.addSubject("railing", mesh, paint);
}

void addFloor(SubjectSink& sink, float y, float halfSize, const glm::vec3& color) {
    MeshData mesh;
    addQuad(mesh, {-halfSize, y, halfSize}, {2.0f * halfSize, 0.0f, 0.0f}, {0.0f, 0.0f, -2.0f * halfSize});
    sink.addBackdrop("floor", mesh, sink.material(plainMaterial("floor", color, 0.0f, 0.8f)));
}

void addWall(SubjectSink& sink, float z, float halfWidth, float bottom, float top, const glm::vec3& color) {
    MeshData mesh;
    addQuad(mesh, {-halfWidth, bottom, z}, {2.0f * halfWidth, 0.0f, 0.0f}, {0.0f, top - bottom, 0.0f});
    sink.addBackdrop("wall", mesh, sink.material(plainMaterial("wall", color, 0.0f, 0.95f)));
}

} // namespace eng::scene
