// Geometry conversion: node transforms, winding, repairs (flat normals,
// degenerate triangles, zero normals), index and attribute types, cameras.

#include "engine/frame/frame_constants.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/scene_error.h"

#include "gltf_test_model.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace eng::scene {
namespace {

using test::TestModel;

constexpr float kEps = 1e-5f;

void expectNear(const glm::vec3& actual, const glm::vec3& expected, const char* what) {
    EXPECT_NEAR(actual.x, expected.x, kEps) << what;
    EXPECT_NEAR(actual.y, expected.y, kEps) << what;
    EXPECT_NEAR(actual.z, expected.z, kEps) << what;
}

glm::vec3 geometricNormal(const Scene& s, size_t triangle) {
    const glm::vec3 a = s.vertices[s.indices[triangle * 3]].position;
    const glm::vec3 b = s.vertices[s.indices[triangle * 3 + 1]].position;
    const glm::vec3 c = s.vertices[s.indices[triangle * 3 + 2]].position;
    return glm::normalize(glm::cross(b - a, c - a));
}

TEST(GltfLoader, MirroredChildNodeTransformsPositionsNormalsTangentsAndFlipsWinding) {
    TestModel m;
    const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int nrm = m.addVec3Accessor({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int tan = m.addFloatAccessor({1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1}, TINYGLTF_TYPE_VEC4);
    const int idx = m.addIndexAccessor({0, 1, 2});
    const int parent = m.addNode();
    m.model.nodes[static_cast<size_t>(parent)].translation = {1, 2, 3};
    const int child = m.addMeshNode({{"POSITION", pos}, {"NORMAL", nrm}, {"TANGENT", tan}}, idx, -1, parent);
    // 90 degrees about +Z: (x, y, z) -> (-y, x, z); scale (-2, 1, 1) mirrors.
    const double h = std::sqrt(0.5);
    m.model.nodes[static_cast<size_t>(child)].rotation = {0, 0, h, h};
    m.model.nodes[static_cast<size_t>(child)].scale = {-2, 1, 1};

    const Scene s = loadGltfModel(m.model, "mirror.gltf");
    ASSERT_EQ(s.triangleCount(), 1u) << "the mirrored triangle must survive";
    // Hand-computed: p' = T + R(S p).
    expectNear(s.vertices[s.indices[0]].position, {1, 2, 3}, "vertex 0 = T");
    // Winding flipped: the loader swaps the 2nd and 3rd index under a negative determinant.
    expectNear(s.vertices[s.indices[1]].position, {0, 2, 3},
               "2nd index must be the old 3rd vertex (winding flipped)");
    expectNear(s.vertices[s.indices[2]].position, {1, 0, 3},
               "3rd index must be the old 2nd vertex (winding flipped)");
    for (size_t i = 0; i < 3; ++i) {
        const Vertex& v = s.vertices[s.indices[i]];
        expectNear(v.normal, {0, 0, 1}, "normal by the inverse-transpose (R S^-1 n), renormalised");
        expectNear(glm::vec3(v.tangent), {0, -1, 0}, "tangent by the matrix, renormalised");
        EXPECT_EQ(v.tangent.w, -1.0f) << "a mirroring transform flips the bitangent sign";
    }
    EXPECT_GT(glm::dot(geometricNormal(s, 0), s.vertices[s.indices[0]].normal), 0.99f)
        << "after the flip, the front face (CCW) must agree with the shading normal";
}

TEST(GltfLoader, NodeMatrixIsColumnMajor) {
    TestModel m = test::makeTriangleModel();
    // Translation (5, 6, 7) in elements 12..14 of a column-major matrix.
    m.model.nodes[0].matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1};
    const Scene s = loadGltfModel(m.model, "matrix.gltf");
    ASSERT_EQ(s.triangleCount(), 1u);
    expectNear(s.bounds.min, {5, 6, 7}, "bounds.min = translated origin");
    expectNear(s.bounds.max, {6, 7, 7}, "bounds.max = translated (1, 1, 0)");
}

// glTF 2.0 section 3.12: a required extension the loader does not implement refuses the asset,
// naming it and the supported ones; an unsupported optional one is a warning.
TEST(GltfLoader, UnsupportedRequiredExtensionsAreRefusedByName) {
    for (const char* ext : {"KHR_draco_mesh_compression", "KHR_texture_basisu", "EXT_meshopt_compression"}) {
        TestModel m;
        const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        m.addMeshNode({{"POSITION", pos}}, m.addIndexAccessor({0, 1, 2}));
        m.model.extensionsUsed = {"KHR_lights_punctual", ext};
        m.model.extensionsRequired = {"KHR_lights_punctual", ext};
        try {
            loadGltfModel(m.model, "required.gltf");
            ADD_FAILURE() << ext << " is required and not supported: the asset must be refused";
        } catch (const SceneError& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("required.gltf: extensionsRequired[1]: '" + std::string(ext) +
                                "' is not supported"),
                      std::string::npos)
                << what;
            EXPECT_NE(what.find("supported: KHR_lights_punctual"), std::string::npos) << what;
        }
    }
    TestModel m;
    const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    m.addMeshNode({{"POSITION", pos}}, m.addIndexAccessor({0, 1, 2}));
    m.model.extensionsUsed = {"KHR_materials_emissive_strength", "EXT_texture_webp"};
    m.model.extensionsRequired = {"KHR_materials_emissive_strength"};
    const Scene s = loadGltfModel(m.model, "optional.gltf");
    ASSERT_EQ(s.stats.warnings.size(), 1u);
    EXPECT_NE(s.stats.warnings[0].find("extensionsUsed: 'EXT_texture_webp' is not supported"),
              std::string::npos)
        << s.stats.warnings[0];
}

// KHR_texture_transform (issue 16): offset, rotation and scale per texture slot reach the material
// and the GPU table as uv' = R(rotation) S(scale) uv + offset; a second UV set is a warning.
TEST(GltfLoader, TextureTransformReachesTheMaterialAndTheGpuTable) {
    TestModel m;
    const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    m.addMeshNode({{"POSITION", pos}}, m.addIndexAccessor({0, 1, 2}));
    m.model.extensionsUsed = {"KHR_texture_transform"};
    m.model.extensionsRequired = {"KHR_texture_transform"};
    tinygltf::Material mat;
    tinygltf::Value::Object transform;
    transform["offset"] =
        tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(-0.5), tinygltf::Value(0.25)});
    transform["scale"] = tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(2.0), tinygltf::Value(3.0)});
    transform["rotation"] = tinygltf::Value(1.5707963267948966);
    mat.pbrMetallicRoughness.baseColorTexture.extensions["KHR_texture_transform"] =
        tinygltf::Value(transform);
    mat.normalTexture.texCoord = 1;
    mat.emissiveTexture.texCoord = 2;
    m.model.materials.push_back(mat);
    m.model.meshes[0].primitives[0].material = 0;
    const Scene s = loadGltfModel(m.model, "transform.gltf");
    ASSERT_FALSE(s.materials.empty());
    const TextureTransform& t = s.materials[0].textureTransforms[0];
    EXPECT_EQ(t.offset, glm::vec2(-0.5f, 0.25f));
    EXPECT_EQ(t.scale, glm::vec2(2.0f, 3.0f));
    EXPECT_FLOAT_EQ(t.rotation, 1.5707963f);
    EXPECT_EQ(s.materials[0].textureTransforms[1].scale, glm::vec2(1.0f)) << "slots without it: identity";
    EXPECT_EQ(s.materials[0].textureTransforms[2].texCoord, 1u) << "the normal map reads TEXCOORD_1";
    bool warned = false;
    for (const std::string& w : s.stats.warnings)
        warned = warned || w.find("emissiveTexture: uses TEXCOORD_2") != std::string::npos;
    EXPECT_TRUE(warned) << "a third UV set is reported, naming the slot";
    // The GPU table: (1, 0) -> M (1, 0) + offset with M = R(90 deg) S(2, 3): (0, 2) + (-0.5, 0.25).
    const std::vector<shared::GpuMaterial> gpu = eng::frame::makeGpuMaterials(s);
    const glm::vec4 M = gpu[0].uvMatrix[0];
    const glm::vec2 uv = glm::mat2(glm::vec2(M.x, M.y), glm::vec2(M.z, M.w)) * glm::vec2(1, 0) +
                         glm::vec2(gpu[0].uvOffset[0].x, gpu[0].uvOffset[0].y);
    EXPECT_NEAR(uv.x, -0.5f, 1e-6f);
    EXPECT_NEAR(uv.y, 2.25f, 1e-6f);
    EXPECT_EQ(gpu[0].texCoords[2], 1);
    EXPECT_EQ(gpu[0].texCoords[0], 0);
}

// COLOR_0 (VEC3 and VEC4) and TEXCOORD_1 reach the vertices; out-of-range colours are clamped
// with a warning naming the accessor.
TEST(GltfLoader, VertexColoursAndTheSecondUvSetAreRead) {
    for (int type : {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}) {
        TestModel m;
        const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        const int uv1 = m.addFloatAccessor({0.25f, 0.5f, 1, 0, 0, 1}, TINYGLTF_TYPE_VEC2);
        const std::vector<float> colours3 = {1, 0, 0, 0, 1, 0, 0, 0, 2};
        const std::vector<float> colours4 = {1, 0, 0, 0.5f, 0, 1, 0, 1, 0, 0, 2, 1};
        const int col = m.addFloatAccessor(type == TINYGLTF_TYPE_VEC3 ? colours3 : colours4, type);
        m.addMeshNode({{"POSITION", pos}, {"TEXCOORD_1", uv1}, {"COLOR_0", col}},
                      m.addIndexAccessor({0, 1, 2}));
        const Scene s = loadGltfModel(m.model, "colours.gltf");
        ASSERT_EQ(s.vertices.size(), 3u);
        EXPECT_EQ(s.vertices[0].uv1, glm::vec2(0.25f, 0.5f));
        EXPECT_EQ(s.vertices[0].color, glm::vec4(1, 0, 0, type == TINYGLTF_TYPE_VEC3 ? 1.0f : 0.5f));
        EXPECT_EQ(s.vertices[2].color.b, 1.0f) << "2 is clamped to 1";
        bool warned = false;
        for (const std::string& w : s.stats.warnings)
            warned = warned || w.find("COLOR_0 values outside [0, 1]") != std::string::npos;
        EXPECT_TRUE(warned);
    }
}

// Sparse accessors (glTF 2.0 3.6.2.3): listed elements are replaced, the rest read from the
// bufferView; malformed sparse data is refused naming the field.
TEST(GltfLoader, SparseAccessorsSubstituteTheirElements) {
    auto model = [](std::vector<uint16_t> indices) {
        TestModel m;
        const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
        const std::vector<glm::vec3> values = {{5, 0, 0}, {0, 5, 0}};
        tinygltf::Accessor& a = m.model.accessors[size_t(pos)];
        a.sparse.isSparse = true;
        a.sparse.count = int(indices.size());
        a.sparse.indices.bufferView = m.addBufferView(indices.data(), indices.size() * 2);
        a.sparse.indices.byteOffset = 0;
        a.sparse.indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        a.sparse.values.bufferView = m.addBufferView(values.data(), values.size() * sizeof(glm::vec3));
        a.sparse.values.byteOffset = 0;
        m.addMeshNode({{"POSITION", pos}}, m.addIndexAccessor({0, 1, 2, 1, 3, 2}));
        return m;
    };
    const Scene s = loadGltfModel(model({1, 3}).model, "sparse.gltf");
    ASSERT_EQ(s.triangleCount(), 2u);
    std::vector<glm::vec3> seen;
    for (uint32_t i : s.indices)
        seen.push_back(s.vertices[i].position);
    expectNear(seen[0], {0, 0, 0}, "element 0 keeps its bufferView value");
    expectNear(seen[1], {5, 0, 0}, "element 1 is replaced by the first sparse value");
    expectNear(seen[2], {0, 1, 0}, "element 2 keeps its bufferView value");
    expectNear(seen[4], {0, 5, 0}, "element 3 is replaced by the second sparse value");
    for (const auto& [indices, what] : std::vector<std::pair<std::vector<uint16_t>, std::string>>{
             {{3, 1}, "does not increase"}, {{1, 9}, "is not below the count 4"}}) {
        try {
            loadGltfModel(model(indices).model, "bad_sparse.gltf");
            ADD_FAILURE() << what << ": malformed sparse indices must be refused";
        } catch (const SceneError& e) {
            EXPECT_NE(std::string(e.what()).find("accessors[0].sparse.indices[1]"), std::string::npos)
                << e.what();
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
        }
    }
}

TEST(GltfLoader, MissingNormalsBecomeFlatFaceNormals) {
    TestModel m;
    // A tent: two triangles sharing an edge at an angle; smooth sharing would blend them.
    const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0.5f, 1, 0}, {0.5f, 0.5f, 1}});
    const int idx = m.addIndexAccessor({0, 1, 3, 1, 2, 3});
    m.addMeshNode({{"POSITION", pos}}, idx);
    const Scene s = loadGltfModel(m.model, "flat.gltf");
    ASSERT_EQ(s.triangleCount(), 2u);
    EXPECT_EQ(s.stats.primitivesWithFlatNormals, 1u) << "the primitive without NORMAL must be counted";
    EXPECT_EQ(s.vertices.size(), 6u) << "shared vertices must be duplicated per triangle for flat shading";
    for (size_t t = 0; t < 2; ++t) {
        const glm::vec3 face = geometricNormal(s, t);
        for (size_t k = 0; k < 3; ++k) {
            expectNear(s.vertices[s.indices[t * 3 + k]].normal, face,
                       "vertex normal must equal its face normal");
        }
    }
}

TEST(GltfLoader, DegenerateTrianglesAreDroppedAndCounted) {
    TestModel m;
    const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}});
    // good, repeated index, collinear (zero area).
    const int idx = m.addIndexAccessor({0, 1, 2, 0, 0, 1, 0, 1, 3});
    const int nrm = m.addVec3Accessor({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    m.addMeshNode({{"POSITION", pos}, {"NORMAL", nrm}}, idx);
    const Scene s = loadGltfModel(m.model, "degenerate.gltf");
    EXPECT_EQ(s.triangleCount(), 1u) << "only the good triangle may remain";
    EXPECT_EQ(s.stats.degenerateTrianglesDropped, 2u)
        << "repeated-index and zero-area triangles must be counted";
    ASSERT_EQ(s.draws.size(), 1u);
    EXPECT_EQ(s.draws[0].indexCount, 3u) << "the draw must cover the surviving triangle only";
}

TEST(GltfLoader, ZeroLengthNormalIsReplacedByFaceNormalWithWarning) {
    TestModel m;
    const int pos = m.addVec3Accessor({{0, 0, 0}, {0, 0, -1}, {0, 1, 0}}); // face normal +X
    const int nrm = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}});
    const int idx = m.addIndexAccessor({0, 1, 2});
    m.addMeshNode({{"POSITION", pos}, {"NORMAL", nrm}}, idx);
    const Scene s = loadGltfModel(m.model, "zeronormal.gltf");
    ASSERT_EQ(s.triangleCount(), 1u);
    expectNear(s.vertices[0].normal, {1, 0, 0}, "zero normal must become the face normal");
    ASSERT_FALSE(s.stats.warnings.empty()) << "the repair must be reported";
    EXPECT_NE(s.stats.warnings[0].find("zeronormal.gltf"), std::string::npos) << s.stats.warnings[0];
    EXPECT_NE(s.stats.warnings[0].find("NORMAL"), std::string::npos) << s.stats.warnings[0];
}

TEST(GltfLoader, IndexComponentTypesAndNonIndexedAgree) {
    Scene reference;
    for (int type : {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, -1}) {
        TestModel m;
        const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
        const int idx = type < 0 ? -1 : m.addIndexAccessor({0, 1, 2}, type);
        m.addMeshNode({{"POSITION", pos}}, idx);
        const Scene s = loadGltfModel(m.model, "indices.gltf");
        ASSERT_EQ(s.triangleCount(), 1u) << "index component type " << type;
        expectNear(s.vertices[s.indices[2]].position, {0, 1, 0}, "third index must read the third vertex");
    }
}

TEST(GltfLoader, NormalizedUnsignedTexcoordsAreScaled) {
    TestModel m;
    const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int nrm = m.addVec3Accessor({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const uint16_t uvs[6] = {0, 0, 65535, 0, 0, 32768};
    tinygltf::Accessor acc;
    acc.bufferView = m.addBufferView(uvs, sizeof(uvs));
    acc.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    acc.normalized = true;
    acc.type = TINYGLTF_TYPE_VEC2;
    acc.count = 3;
    m.model.accessors.push_back(acc);
    const int uv = static_cast<int>(m.model.accessors.size() - 1);
    m.addMeshNode({{"POSITION", pos}, {"NORMAL", nrm}, {"TEXCOORD_0", uv}}, -1);
    const Scene s = loadGltfModel(m.model, "uv.gltf");
    ASSERT_EQ(s.vertices.size(), 3u);
    EXPECT_FLOAT_EQ(s.vertices[1].uv.x, 1.0f) << "normalized ushort 65535 must read as 1";
    EXPECT_NEAR(s.vertices[2].uv.y, 32768.0f / 65535.0f, 1e-6f) << "normalized ushort must divide by 65535";
    // Generated tangent follows +u = +X for this parametrisation.
    expectNear(glm::vec3(s.vertices[0].tangent), {1, 0, 0}, "tangent from UVs must follow +u");
}

TEST(GltfLoader, NonTrianglePrimitivesAreSkippedWithWarning) {
    TestModel m = test::makeTriangleModel();
    m.model.meshes[0].primitives.push_back(m.model.meshes[0].primitives[0]);
    m.model.meshes[0].primitives[1].mode = TINYGLTF_MODE_LINE;
    const Scene s = loadGltfModel(m.model, "lines.gltf");
    EXPECT_EQ(s.draws.size(), 1u) << "the LINES primitive must not become a draw";
    bool warned = false;
    for (const std::string& w : s.stats.warnings) {
        warned = warned || w.find("primitives[1].mode") != std::string::npos;
    }
    EXPECT_TRUE(warned) << "skipping a primitive must be reported with its field";
}

TEST(GltfLoader, PrimitiveWithoutMaterialGetsDefaultMaterial) {
    const TestModel m = test::makeTriangleModel();
    const Scene s = loadGltfModel(m.model, "nomaterial.gltf");
    ASSERT_EQ(s.materials.size(), 1u) << "materials must never be empty";
    ASSERT_EQ(s.draws.size(), 1u);
    EXPECT_EQ(s.draws[0].material, 0u) << "the draw must use the appended default material";
}

TEST(GltfLoader, DefaultCameraFramesBoundsWhenFileHasNone) {
    TestModel m = test::makeTriangleModel();
    m.model.nodes[0].translation = {10, 0, -4};
    m.model.nodes[0].scale = {3, 2, 1};
    const Scene s = loadGltfModel(m.model, "nocamera.gltf");
    ASSERT_EQ(s.cameras.size(), 1u) << "a default camera must be added";
    const Camera& c = s.cameras[0];
    const glm::vec3 centre = 0.5f * (s.bounds.min + s.bounds.max);
    const glm::vec3 inView = glm::vec3(c.view * glm::vec4(centre, 1.0f));
    EXPECT_NEAR(inView.x, 0.0f, 1e-4f) << "camera must look at the bounds centre";
    EXPECT_NEAR(inView.y, 0.0f, 1e-4f) << "camera must look at the bounds centre";
    EXPECT_LT(inView.z, 0.0f) << "the centre must be in front of the camera (-Z)";
    const float tanHalf = std::tan(0.5f * c.yfov);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? s.bounds.max.x : s.bounds.min.x,
                               (i & 2) ? s.bounds.max.y : s.bounds.min.y,
                               (i & 4) ? s.bounds.max.z : s.bounds.min.z);
        const glm::vec3 v = glm::vec3(c.view * glm::vec4(corner, 1.0f));
        EXPECT_LE(std::abs(v.x), -v.z * tanHalf + 1e-4f) << "corner " << i << " outside the 1:1 frustum";
        EXPECT_LE(std::abs(v.y), -v.z * tanHalf + 1e-4f) << "corner " << i << " outside the 1:1 frustum";
        EXPECT_GT(-v.z, c.znear) << "corner " << i << " in front of the near plane";
        EXPECT_LT(-v.z, c.zfar) << "corner " << i << " inside the far plane";
    }
}

TEST(GltfLoader, NodeCameraRemovesScaleAndDerivesFiniteFar) {
    TestModel m = test::makeTriangleModel();
    tinygltf::Camera cam;
    cam.type = "perspective";
    cam.perspective.yfov = 0.9;
    cam.perspective.znear = 0.1;
    cam.perspective.zfar = 0.0; // absent: infinite
    m.model.cameras.push_back(cam);
    const int node = m.addNode();
    m.model.nodes[static_cast<size_t>(node)].camera = 0;
    m.model.nodes[static_cast<size_t>(node)].translation = {0, 0, 5};
    m.model.nodes[static_cast<size_t>(node)].scale = {2, 2, 2};
    const Scene s = loadGltfModel(m.model, "camera.gltf");
    ASSERT_EQ(s.cameras.size(), 1u) << "the file's camera only, no default";
    const Camera& c = s.cameras[0];
    EXPECT_FLOAT_EQ(c.yfov, 0.9f);
    EXPECT_FLOAT_EQ(c.znear, 0.1f);
    const glm::vec3 origin = glm::vec3(c.view * glm::vec4(0, 0, 0, 1));
    expectNear(origin, {0, 0, -5}, "view must be the inverse of the unscaled node transform");
    EXPECT_TRUE(std::isfinite(c.zfar)) << "zfar must be finite";
    EXPECT_GT(c.zfar, 5.0f) << "derived zfar must reach past the geometry 5 m away";
}

} // namespace
} // namespace eng::scene
