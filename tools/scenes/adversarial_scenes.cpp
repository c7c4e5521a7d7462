#include "tools/scenes/adversarial_scenes.h"

#include "engine/scene/camera_framing.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/model_builder.h"
#include "engine/scene/prng.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eng::scene {

namespace {

constexpr float kYfov = 0.7f; // radians, as the regular scenes
constexpr float kAspect =
    1.0f; // the suite renders square and 17x13 images; the renderer uses the image's aspect

using Builder = void (*)(ModelBuilder&, Prng&);

struct HardKind {
    const char* name;
    Builder build;
    // Lit as a user's glTF with lights is by default (eng::scene::LightingMode::Fill): its lights
    // and the fill sky. The other kinds carry their own lights only.
    bool fillSky = false;
};

MaterialDesc material(const std::string& name, glm::vec3 color, float metallic, float roughness) {
    MaterialDesc m;
    m.name = name;
    m.baseColor = glm::vec4(color, 1.0f);
    m.metallic = metallic;
    m.roughness = roughness;
    m.doubleSided = true;
    return m;
}

// The glTF "Lambert" the agreement tests need: metallic 0, roughness 1.
MaterialDesc lambert(const std::string& name, glm::vec3 color) {
    return material(name, color, 0.0f, 1.0f);
}

// One triangle with its own three vertices and the given vertex normals (not normalised here:
// the degenerate scene hands zero and NaN normals to the loader on purpose).
void addTriangle(MeshData& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 na, glm::vec3 nb,
                 glm::vec3 nc) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c});
    mesh.normals.insert(mesh.normals.end(), {na, nb, nc});
    mesh.uvs.insert(mesh.uvs.end(), {glm::vec2(0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(0.0f, 1.0f)});
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2});
}

void addFlatTriangle(MeshData& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    addTriangle(mesh, a, b, c, n, n, n);
}

void setCamera(ModelBuilder& b, glm::vec3 eye, glm::vec3 target, float znear, float zfar) {
    Camera camera;
    camera.name = "camera";
    camera.yfov = kYfov;
    camera.view = lookAtView(eye, target);
    camera.znear = znear;
    camera.zfar = zfar;
    b.addCamera(camera, kAspect);
}

// castsShadows off in the agreement scenes: the comparison is about aggregation, and filtered
// shadow lookups legitimately differ between per-sample and per-aggregate shading.
void sun(ModelBuilder& b, glm::vec3 travel, float lux = 3.0f, bool castsShadows = true) {
    b.addDirectionalLight("sun", glm::normalize(travel), {1.0f, 0.96f, 0.9f}, lux, castsShadows);
}

// A zigzag sheet in the plane z = 0 (ridges along y), `period` metres per ridge, `depth`
// metres deep: wall normals approach +-x as depth/period grows. flat: every face has its own
// vertices and exact face normals; otherwise the vertices are shared and carry alternating
// +-x normals, so the interpolated normal passes through zero in the middle of each face.
MeshData zigzag(float x0, float x1, float y0, float y1, float period, float depth, bool flat) {
    MeshData m;
    const int faces = static_cast<int>(std::lround((x1 - x0) / (0.5f * period)));
    auto ridgeZ = [&](int i) { return (i % 2 == 0) ? 0.0f : -depth; };
    for (int i = 0; i < faces; ++i) {
        const float xa = x0 + static_cast<float>(i) * 0.5f * period;
        const float xb = xa + 0.5f * period;
        const glm::vec3 a(xa, y0, ridgeZ(i)), b(xb, y0, ridgeZ(i + 1)), c(xb, y1, ridgeZ(i + 1)),
            d(xa, y1, ridgeZ(i));
        if (flat) {
            addFlatTriangle(m, a, b, c);
            addFlatTriangle(m, a, c, d);
        } else {
            const glm::vec3 na(i % 2 == 0 ? 1.0f : -1.0f, 0.0f, 0.0f);
            const glm::vec3 nb = -na;
            addTriangle(m, a, b, c, na, nb, nb);
            addTriangle(m, a, c, d, na, nb, na);
        }
    }
    return m;
}

void buildFlat(ModelBuilder& b, Prng&) {
    MeshData quad;
    addQuad(quad, {-2.0f, -2.0f, 0.0f}, {4.0f, 0.0f, 0.0f}, {0.0f, 4.0f, 0.0f});
    b.addMesh("flat", quad, b.addMaterial(lambert("flat.lambert", {0.8f, 0.8f, 0.8f})));
    sun(b, {0.3f, -0.4f, -1.0f}, 3.0f, false);
    for (int k = 0; k < 4; ++k) {
        const glm::vec3 p((k & 1) ? 0.5f : -0.5f, (k & 2) ? 0.5f : -0.5f, 0.6f);
        b.addPointLight("point." + std::to_string(k), p, {1.0f, 0.8f, 0.6f}, 0.5f, 3.0f);
    }
    setCamera(b, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 0.1f, 10.0f);
}

// Lambert V-grooves a tenth of a pixel wide (about 6 faces per pixel at 32x32), lit from the
// side so the two wall orientations differ: the agreement case (c = 2 distinct surfaces).
void buildVGroove(ModelBuilder& b, Prng&) {
    b.addMesh("vgroove", zigzag(-1.5f, 1.5f, -1.5f, 1.5f, 0.01f, 0.02f, true),
              b.addMaterial(lambert("vgroove.lambert", {0.7f, 0.7f, 0.7f})));
    sun(b, {-0.6f, -0.2f, -0.77f}, 3.0f, false);
    sun(b, {0.1f, 0.3f, -1.0f}, 0.5f, false);
    setCamera(b, {0.0f, 0.0f, 2.5f}, {0.0f, 0.0f, 0.0f}, 0.1f, 10.0f);
}

// Issue 35's mirror V-grooves: a plate of 400 grooves 1 cm wide and 5 mm deep (walls at 45
// degrees), chrome at roughness exactly 0, under a sun along the view axis and the fill sky. Each
// pixel holds several grooves whose two walls mirror opposite halves of the sky, which the
// aggregate's mean normal (straight back at the camera) does not see.
void buildMirrorVGroove(ModelBuilder& b, Prng&) {
    b.addMesh("mirror-vgroove", zigzag(-2.0f, 2.0f, -2.0f, 2.0f, 0.01f, 0.005f, true),
              b.addMaterial(material("mirror-vgroove.chrome", {0.95f, 0.95f, 0.95f}, 1.0f, 0.0f)));
    sun(b, {0.0f, 0.0f, -1.0f}, 3.0f, false);
    setCamera(b, {0.0f, 0.0f, 3.5f}, {0.0f, 0.0f, 0.0f}, 0.1f, 10.0f);
}

// Opposing normals in one pixel: steep V-grooves (walls at +-88 degrees) whose shared vertices
// carry +-x normals (interpolation crosses zero), and a sheet folded edge-on to the camera (its
// two wings face +y and -y inside one pixel row). With c = 1 the Toksvig vector cancels.
void buildFold(ModelBuilder& b, Prng&) {
    b.addMesh("fold.grooves", zigzag(-1.0f, 0.0f, -1.0f, 1.0f, 0.01f, 0.15f, false),
              b.addMaterial(material("fold.red", {0.8f, 0.1f, 0.1f}, 0.0f, 0.25f)));
    b.addMesh("fold.grooves.metal", zigzag(0.0f, 1.0f, -1.0f, 0.0f, 0.005f, 0.15f, true),
              b.addMaterial(material("fold.steel", {0.9f, 0.9f, 0.9f}, 1.0f, 0.05f)));
    // The folded sheet: wings 1 degree either side of the view direction, meeting at a crease.
    MeshData sheet;
    const float wing = 1.5f, spread = wing * std::tan(0.0175f);
    for (int k = 0; k < 8; ++k) {
        const float x0 = 0.05f + 0.11f * static_cast<float>(k), x1 = x0 + 0.08f, y = 0.4f;
        const glm::vec3 crease0(x0, y, 0.3f), crease1(x1, y, 0.3f);
        const glm::vec3 up0(x0, y + spread, 0.3f - wing), up1(x1, y + spread, 0.3f - wing);
        const glm::vec3 dn0(x0, y - spread, 0.3f - wing), dn1(x1, y - spread, 0.3f - wing);
        addFlatTriangle(sheet, crease0, up1, crease1);
        addFlatTriangle(sheet, crease0, up0, up1);
        addFlatTriangle(sheet, crease0, crease1, dn1);
        addFlatTriangle(sheet, crease0, dn1, dn0);
    }
    b.addMesh("fold.sheet", sheet, b.addMaterial(material("fold.sheet", {0.2f, 0.6f, 0.9f}, 0.0f, 0.4f)));
    sun(b, {0.2f, -0.3f, -1.0f});
    b.addPointLight("point", {0.3f, 0.2f, 0.8f}, {1.0f, 1.0f, 1.0f}, 0.8f, 0.0f);
    setCamera(b, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 0.1f, 10.0f);
}

// Roughness exactly 0 (metal and dielectric) and exactly 1, with the sun straight from the
// camera: H = N at the centre of the mirror, the GGX peak D = 1/(pi alpha_min^2).
void buildMirror(ModelBuilder& b, Prng&) {
    MeshData wall;
    addQuad(wall, {-2.0f, -2.0f, -0.5f}, {4.0f, 0.0f, 0.0f}, {0.0f, 4.0f, 0.0f});
    b.addMesh("mirror.wall", wall,
              b.addMaterial(material("mirror.chrome", {0.95f, 0.95f, 0.95f}, 1.0f, 0.0f)));
    MeshData s0, s1, s2;
    addSphere(s0, {-0.35f, 0.2f, 0.0f}, 0.2f, 16, 32);
    addSphere(s1, {0.35f, 0.2f, 0.0f}, 0.2f, 16, 32);
    addSphere(s2, {0.0f, -0.3f, 0.0f}, 0.2f, 16, 32);
    b.addMesh("mirror.metal0", s0, b.addMaterial(material("mirror.gold", {1.0f, 0.8f, 0.4f}, 1.0f, 0.0f)));
    b.addMesh("mirror.rough1", s1, b.addMaterial(material("mirror.rough", {0.6f, 0.6f, 0.6f}, 0.0f, 1.0f)));
    b.addMesh("mirror.glossy0", s2,
              b.addMaterial(material("mirror.plastic", {0.1f, 0.3f, 0.8f}, 0.0f, 0.0f)));
    sun(b, {0.0f, 0.0f, -1.0f}, 5.0f);
    b.addPointLight("point", {0.0f, 0.2f, 0.6f}, {1.0f, 1.0f, 1.0f}, 2.0f, 0.0f);
    setCamera(b, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 0.1f, 10.0f);
}

// Exactly coplanar overlapping quads of different colours, triangulated differently.
void buildZFight(ModelBuilder& b, Prng&) {
    MeshData red, green, blue;
    addQuad(red, {-1.0f, -1.0f, 0.0f}, {1.6f, 0.0f, 0.0f}, {0.0f, 2.0f, 0.0f});
    // Same plane, corner at the opposite side: the diagonal runs the other way.
    addQuad(green, {1.0f, 1.0f, 0.0f}, {-1.6f, 0.0f, 0.0f}, {0.0f, -2.0f, 0.0f});
    addQuad(blue, {0.0f, -0.9f, 0.0f}, {0.9f, 0.9f, 0.0f}, {-0.9f, 0.9f, 0.0f});
    b.addMesh("zfight.red", red, b.addMaterial(lambert("zfight.red", {0.9f, 0.1f, 0.1f})));
    b.addMesh("zfight.green", green, b.addMaterial(material("zfight.green", {0.1f, 0.9f, 0.1f}, 0.0f, 0.3f)));
    b.addMesh("zfight.blue", blue, b.addMaterial(material("zfight.blue", {0.1f, 0.1f, 0.9f}, 1.0f, 0.2f)));
    sun(b, {0.3f, -0.4f, -1.0f});
    b.addPointLight("point", {0.2f, 0.1f, 0.5f}, {1.0f, 1.0f, 1.0f}, 0.5f, 0.0f);
    setCamera(b, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 0.1f, 10.0f);
}

// 24000 random triangles of about 1.5 cm in a 0.4 m box, random vertex normals: about 90
// triangles per covered pixel at 32x32 (dense fur), over a floor.
void buildDense(ModelBuilder& b, Prng& rng) {
    MeshData fur;
    auto unit = [&]() {
        const float z = rng.range(-1.0f, 1.0f), phi = rng.range(0.0f, 6.2831853f);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        return glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
    };
    for (int i = 0; i < 24000; ++i) {
        const glm::vec3 c(rng.range(-0.2f, 0.2f), rng.range(-0.2f, 0.2f), rng.range(-0.2f, 0.2f));
        const glm::vec3 a = c + 0.008f * unit(), bb = c + 0.008f * unit(), cc = c + 0.008f * unit();
        const glm::vec3 n = glm::cross(bb - a, cc - a);
        if (glm::dot(n, n) < 1e-12f) continue; // keep the count honest: the loader would drop it
        addTriangle(fur, a, bb, cc, unit(), unit(), unit());
    }
    b.addMesh("dense.fur", fur, b.addMaterial(material("dense.hair", {0.55f, 0.36f, 0.2f}, 0.0f, 0.35f)));
    MeshData floor;
    addQuad(floor, {-2.0f, -2.0f, -0.6f}, {4.0f, 0.0f, 0.0f}, {0.0f, 4.0f, 0.0f});
    b.addMesh("dense.floor", floor, b.addMaterial(lambert("dense.floor", {0.3f, 0.3f, 0.3f})));
    sun(b, {-0.35f, -1.0f, -0.45f});
    b.addPointLight("point", {0.3f, 0.3f, 0.5f}, {1.0f, 0.9f, 0.8f}, 0.5f, 0.0f);
    setCamera(b, {0.0f, 0.0f, 1.2f}, {0.0f, 0.0f, 0.0f}, 0.05f, 10.0f);
}

// Degenerate triangles (repeated indices, collinear and coincident vertices) and zero-length,
// NaN and huge vertex normals: the loader drops the former and repairs the latter, with warnings.
void buildDegenerate(ModelBuilder& b, Prng&) {
    MeshData m;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const glm::vec3 zero(0.0f), bad(nan, 0.0f, 1.0f), huge(0.0f, 0.0f, 3.0e38f);
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
            const float x = -1.0f + 0.25f * static_cast<float>(i), y = -1.0f + 0.25f * static_cast<float>(j);
            const glm::vec3 p00(x, y, 0.0f), p10(x + 0.25f, y, 0.0f), p11(x + 0.25f, y + 0.25f, 0.0f),
                p01(x, y + 0.25f, 0.0f);
            const int k = i + j;
            const glm::vec3 n0 = (k % 3 == 0) ? zero : (k % 3 == 1 ? bad : huge), n1(0.0f, 0.0f, 1.0f);
            addTriangle(m, p00, p10, p11, n0, n1, n1);
            addTriangle(m, p00, p11, p01, n1, n1, n0);
            addTriangle(m, p00, p10, 0.5f * (p00 + p10), n1, n1, n1); // collinear
            addTriangle(m, p11, p11, p11, n1, n1, n1);                // a point
        }
    // Repeated indices into shared vertices.
    const auto base = static_cast<uint32_t>(m.positions.size());
    m.indices.insert(m.indices.end(), {0u, 0u, 1u, base - 1, base - 1, base - 2});
    b.addMesh("degenerate.grid", m,
              b.addMaterial(material("degenerate.paint", {0.8f, 0.5f, 0.2f}, 0.0f, 0.5f)));
    MeshData sphere;
    addSphere(sphere, {0.4f, 0.4f, 0.3f}, 0.25f, 12, 24);
    for (size_t i = 0; i < sphere.normals.size(); i += 5)
        sphere.normals[i] = zero;
    b.addMesh("degenerate.sphere", sphere,
              b.addMaterial(material("degenerate.sphere", {0.3f, 0.6f, 0.3f}, 0.0f, 0.3f)));
    sun(b, {0.3f, -0.4f, -1.0f});
    setCamera(b, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 0.1f, 10.0f);
}

// Millimetre detail 1e5 m from the origin (fp32 spacing there is 7.8 mm, so the loader sees
// collapsed triangles), seen through a camera with near 1e-4 m and far 1e7 m.
void buildFar(ModelBuilder& b, Prng& rng) {
    const glm::vec3 origin(1.0e5f, 0.0f, 0.0f);
    MeshData bumps, base;
    for (int j = 0; j < 30; ++j)
        for (int i = 0; i < 30; ++i) {
            const glm::vec3 c = origin + glm::vec3(0.003f * static_cast<float>(i - 15),
                                                   0.003f * static_cast<float>(j - 15), 0.0f);
            const float h = rng.range(0.0005f, 0.002f);
            const glm::vec3 apex = c + glm::vec3(0.0f, 0.0f, h);
            const glm::vec3 q[4] = {c + glm::vec3(-0.001f, -0.001f, 0.0f),
                                    c + glm::vec3(0.001f, -0.001f, 0.0f), c + glm::vec3(0.001f, 0.001f, 0.0f),
                                    c + glm::vec3(-0.001f, 0.001f, 0.0f)};
            for (int e = 0; e < 4; ++e) {
                const glm::vec3 a = q[e], bb = q[(e + 1) % 4];
                const glm::vec3 n = glm::cross(bb - a, apex - a);
                if (glm::dot(n, n) > 0.0f && std::isfinite(glm::dot(n, n)))
                    addFlatTriangle(bumps, a, bb, apex);
                else
                    addTriangle(bumps, a, bb, apex, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.0f},
                                {0.0f, 0.0f, 1.0f});
            }
        }
    addQuad(base, origin + glm::vec3(-0.1f, -0.1f, -0.0005f), {0.2f, 0.0f, 0.0f}, {0.0f, 0.2f, 0.0f});
    b.addMesh("far.bumps", bumps, b.addMaterial(material("far.bumps", {0.8f, 0.8f, 0.8f}, 0.0f, 0.3f)));
    b.addMesh("far.base", base, b.addMaterial(lambert("far.base", {0.3f, 0.4f, 0.5f})));
    sun(b, {0.3f, -0.4f, -1.0f});
    b.addPointLight("point", origin + glm::vec3(0.01f, 0.01f, 0.02f), {1.0f, 1.0f, 1.0f}, 0.01f, 0.0f);
    setCamera(b, origin + glm::vec3(0.0f, 0.0f, 0.15f), origin, 1.0e-4f, 1.0e7f);
}

// A glossy floor seen at about 0.3 degrees, lit by a sun 0.06 degrees above the horizon and a
// point light lying in the floor plane (N.L = 0 exactly).
void buildGrazing(ModelBuilder& b, Prng&) {
    MeshData floor;
    addQuad(floor, {-100.0f, 0.0f, 100.0f}, {200.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -200.0f});
    b.addMesh("grazing.floor", floor,
              b.addMaterial(material("grazing.floor", {0.7f, 0.7f, 0.7f}, 0.5f, 0.1f)));
    sun(b, {0.0f, -0.001f, -1.0f});
    b.addPointLight("point.inplane", {0.0f, 0.0f, -1.0f}, {1.0f, 1.0f, 1.0f}, 1.0f, 0.0f);
    setCamera(b, {0.0f, 0.01f, 2.0f}, {0.0f, 0.0f, -200.0f}, 0.001f, 500.0f);
}

// HDR emissive strands (strength 1e3 and 1e4, KHR_materials_emissive_strength) a few
// millimetres wide over a black backdrop, no lights.
void buildEmissive(ModelBuilder& b, Prng& rng) {
    MeshData back;
    addQuad(back, {-2.0f, -2.0f, -0.5f}, {4.0f, 0.0f, 0.0f}, {0.0f, 4.0f, 0.0f});
    b.addMesh("emissive.black", back, b.addMaterial(lambert("emissive.black", {0.0f, 0.0f, 0.0f})));
    MeshData strands[2];
    TubeOptions tube;
    tube.sides = 4;
    for (int s = 0; s < 40; ++s) {
        std::vector<glm::vec3> path;
        std::vector<float> radii;
        glm::vec3 p(rng.range(-0.5f, 0.5f), -0.5f, rng.range(-0.3f, 0.1f));
        const float sway = rng.range(-0.3f, 0.3f);
        for (int k = 0; k <= 8; ++k) {
            const float u = static_cast<float>(k) / 8.0f;
            path.push_back(p + glm::vec3(sway * u * u, u, 0.0f));
            radii.push_back(rng.range(0.0005f, 0.002f));
        }
        addTube(strands[s % 2], path, radii, tube);
    }
    MaterialDesc warm = material("emissive.1e3", {0.0f, 0.0f, 0.0f}, 0.0f, 1.0f);
    warm.emissive = {1.0f, 0.6f, 0.2f};
    warm.emissiveStrength = 1.0e3f;
    MaterialDesc cold = material("emissive.1e4", {0.0f, 0.0f, 0.0f}, 0.0f, 1.0f);
    cold.emissive = {0.2f, 0.5f, 1.0f};
    cold.emissiveStrength = 1.0e4f;
    b.addMesh("emissive.warm", strands[0], b.addMaterial(warm));
    b.addMesh("emissive.cold", strands[1], b.addMaterial(cold));
    setCamera(b, {0.0f, 0.0f, 1.2f}, {0.0f, 0.0f, 0.0f}, 0.05f, 10.0f);
}

// Point lights at distance 0: one at the centre of a closed sphere, one exactly on a vertex
// the camera sees, one exactly on a corner of the floor; a spot with inner = outer cone.
void buildLightInside(ModelBuilder& b, Prng&) {
    MeshData sphere, floor;
    addSphere(sphere, {0.0f, 0.0f, 0.0f}, 0.3f, 16, 32);
    addQuad(floor, {-1.0f, -0.3f, 1.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -2.0f});
    b.addMesh("inside.sphere", sphere,
              b.addMaterial(material("inside.sphere", {0.8f, 0.8f, 0.8f}, 0.0f, 0.4f)));
    b.addMesh("inside.floor", floor, b.addMaterial(lambert("inside.floor", {0.5f, 0.5f, 0.5f})));
    // The vertex of the sphere closest to the camera (+Z side).
    glm::vec3 front = sphere.positions[0];
    for (const glm::vec3& p : sphere.positions)
        if (p.z > front.z) front = p;
    b.addPointLight("point.centre", {0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}, 10.0f, 0.0f);
    b.addPointLight("point.onvertex", front, {1.0f, 0.5f, 0.5f}, 10.0f, 0.0f);
    b.addPointLight("point.oncorner", floor.positions[0], {0.5f, 0.5f, 1.0f}, 10.0f, 1.0f);
    setCamera(b, {0.0f, 0.2f, 1.5f}, {0.0f, 0.0f, 0.0f}, 0.05f, 10.0f);
}

void buildNoLights(ModelBuilder& b, Prng&) {
    MeshData sphere, wall;
    addSphere(sphere, {0.0f, 0.0f, 0.0f}, 0.4f, 16, 32);
    addQuad(wall, {-2.0f, -2.0f, -0.5f}, {4.0f, 0.0f, 0.0f}, {0.0f, 4.0f, 0.0f});
    b.addMesh("nolights.sphere", sphere,
              b.addMaterial(material("nolights.sphere", {0.9f, 0.9f, 0.9f}, 1.0f, 0.0f)));
    b.addMesh("nolights.wall", wall, b.addMaterial(lambert("nolights.wall", {0.8f, 0.8f, 0.8f})));
    setCamera(b, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 0.1f, 10.0f);
}

// 1000 point lights (the renderer holds up to shared::kMaxLights = 1024) in a 10x10x10 grid in
// front of a wall and a sphere, half with a range window and half unbounded.
void buildManyLights(ModelBuilder& b, Prng&) {
    MeshData sphere, wall;
    addSphere(sphere, {0.0f, 0.0f, 0.0f}, 0.3f, 16, 32);
    addQuad(wall, {-2.0f, -2.0f, -0.4f}, {4.0f, 0.0f, 0.0f}, {0.0f, 4.0f, 0.0f});
    b.addMesh("many.sphere", sphere, b.addMaterial(material("many.sphere", {0.9f, 0.8f, 0.7f}, 0.0f, 0.3f)));
    b.addMesh("many.wall", wall, b.addMaterial(lambert("many.wall", {0.7f, 0.7f, 0.7f})));
    for (int i = 0; i < 1000; ++i) {
        const glm::vec3 p(-0.9f + 0.2f * static_cast<float>(i % 10),
                          -0.9f + 0.2f * static_cast<float>((i / 10) % 10),
                          -0.35f + 0.1f * static_cast<float>(i / 100));
        const glm::vec3 color(0.3f + 0.7f * static_cast<float>(i % 7) / 6.0f, 0.5f,
                              1.0f - 0.1f * static_cast<float>(i % 5));
        b.addPointLight("point." + std::to_string(i), p, color, 0.002f, (i % 2) ? 0.5f : 0.0f);
    }
    setCamera(b, {0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 0.1f, 10.0f);
}

// The camera looks straight up; the only geometry is a floor below it: every sample is sky.
void buildSky(ModelBuilder& b, Prng&) {
    MeshData floor;
    addQuad(floor, {-5.0f, 0.0f, 5.0f}, {10.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -10.0f});
    b.addMesh("sky.floor", floor, b.addMaterial(lambert("sky.floor", {0.5f, 0.5f, 0.5f})));
    sun(b, {0.3f, -1.0f, -0.2f});
    setCamera(b, {0.0f, 1.0f, 0.0f}, {0.0f, 100.0f, 0.0f}, 0.1f, 10.0f);
}

constexpr HardKind kHardKinds[] = {
    {"hard-flat", buildFlat},
    {"hard-vgroove", buildVGroove},
    {"hard-fold", buildFold},
    {"hard-mirror", buildMirror},
    {"hard-zfight", buildZFight},
    {"hard-dense", buildDense},
    {"hard-degenerate", buildDegenerate},
    {"hard-far", buildFar},
    {"hard-grazing", buildGrazing},
    {"hard-emissive", buildEmissive},
    {"hard-light-inside", buildLightInside},
    {"hard-no-lights", buildNoLights},
    {"hard-many-lights", buildManyLights},
    {"hard-sky", buildSky},
    // Last: a kind's place in this table seeds its generator, so a new kind goes at the end.
    {"hard-mirror-vgroove", buildMirrorVGroove, true},
};

} // namespace

std::vector<std::string> hardSceneKinds() {
    std::vector<std::string> names;
    for (const HardKind& k : kHardKinds)
        names.emplace_back(k.name);
    return names;
}

bool isHardSceneKind(std::string_view kind) {
    return std::any_of(std::begin(kHardKinds), std::end(kHardKinds),
                       [&](const HardKind& k) { return kind == k.name; });
}

tinygltf::Model generateHardScene(std::string_view kind, const GenOptions& options) {
    for (const HardKind& k : kHardKinds) {
        if (kind != k.name) continue;
        Prng rng(static_cast<uint64_t>(options.seed) * 131 + static_cast<uint64_t>(&k - kHardKinds));
        ModelBuilder builder("agaa scenegen " + std::string(k.name));
        k.build(builder, rng);
        return builder.finish();
    }
    std::string known;
    for (const HardKind& k : kHardKinds)
        known += (known.empty() ? "" : ", ") + std::string(k.name);
    throw SceneError("builtin:" + std::string(kind) + ": unknown hard scene kind; known hard kinds are " +
                     known);
}

tinygltf::Model generateTestScene(std::string_view kind, const GenOptions& options) {
    return isHardSceneKind(kind) ? generateHardScene(kind, options) : generateScene(kind, options);
}

Scene loadTestScene(std::string_view name) {
    if (!isHardSceneKind(name)) return loadBuiltin(name);
    Scene scene = loadGltfModel(generateHardScene(name), "builtin:" + std::string(name));
    scene.exposure = 1.0f; // the generated lights are sized for it, as loadBuiltin's
    for (const HardKind& k : kHardKinds)
        if (name == k.name && k.fillSky) applyLighting(scene, LightingMode::Fill);
    return scene;
}

} // namespace eng::scene
