// Refusals: every malformed file must end in a SceneError whose message names
// the file and the field, and no mutation of a valid model may crash the loader.

#include "engine/scene/gltf_loader.h"
#include "engine/scene/prng.h"

#include "gltf_test_model.h"
#include "loader_test_support.h"

#include <gtest/gtest.h>

#include <limits>

namespace eng::scene {
namespace {

using test::TestModel;

using test::loadError;

void expectNames(const std::string& message, const std::filesystem::path& file, const std::string& field) {
    EXPECT_NE(message.find(file.string()), std::string::npos) << "message must name the file: " << message;
    EXPECT_NE(message.find(field), std::string::npos) << "message must name '" << field << "': " << message;
}

using MalformedFiles = test::TempDirTest;

TEST_F(MalformedFiles, AccessorBufferViewOutOfRange) {
    TestModel m = test::makeTriangleModel();
    m.model.accessors[0].bufferView = 7; // POSITION
    const auto path = m_dir / "badview.gltf";
    test::writeModel(m.model, path);
    expectNames(loadError(path), path, "accessors[0].bufferView");
}

TEST_F(MalformedFiles, AccessorByteRangePastBuffer) {
    TestModel m = test::makeTriangleModel();
    m.model.accessors[0].count = 1000; // the bufferView holds 3 vec3
    const auto path = m_dir / "pastend.glb";
    test::writeModel(m.model, path);
    expectNames(loadError(path), path, "accessors[0].count");
}

TEST_F(MalformedFiles, WrongAccessorTypeForAttribute) {
    TestModel m = test::makeTriangleModel();
    m.model.accessors[1].type = TINYGLTF_TYPE_VEC2; // NORMAL must be VEC3
    const auto path = m_dir / "wrongtype.gltf";
    test::writeModel(m.model, path);
    expectNames(loadError(path), path, "accessors[1].type");
}

TEST_F(MalformedFiles, IndexOutOfRange) {
    TestModel m;
    const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int idx = m.addIndexAccessor({0, 1, 5});
    m.addMeshNode({{"POSITION", pos}}, idx);
    const auto path = m_dir / "badindex.gltf";
    test::writeModel(m.model, path);
    const std::string message = loadError(path);
    expectNames(message, path, "accessors[1].count");
    EXPECT_NE(message.find("vertex 5"), std::string::npos) << "message must say which index: " << message;
}

TEST_F(MalformedFiles, NanPosition) {
    TestModel m;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const int pos = m.addVec3Accessor({{0, 0, 0}, {1, nan, 0}, {0, 1, 0}});
    m.addMeshNode({{"POSITION", pos}}, -1);
    const auto path = m_dir / "nan.glb";
    test::writeModel(m.model, path);
    const std::string message = loadError(path);
    expectNames(message, path, "accessors[0]");
    EXPECT_NE(message.find("not finite"), std::string::npos) << message;
}

TEST_F(MalformedFiles, MissingBufferFile) {
    const auto path = m_dir / "missingbuffer.gltf";
    test::writeFile(path, R"({"asset":{"version":"2.0"},
        "buffers":[{"uri":"missing.bin","byteLength":36}],
        "bufferViews":[{"buffer":0,"byteLength":36}],
        "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],
        "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
        "nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})");
    const std::string message = loadError(path);
    expectNames(message, path, "missing.bin");
}

TEST_F(MalformedFiles, TruncatedGlb) {
    const TestModel m = test::makeTriangleModel();
    const auto full = m_dir / "full.glb";
    test::writeModel(m.model, full);
    const std::string bytes = test::readFile(full);
    ASSERT_GT(bytes.size(), 40u) << "test setup: the .glb must have a header and chunks";
    const auto path = m_dir / "truncated.glb";
    test::writeFile(path, bytes.substr(0, bytes.size() / 2));
    const std::string message = loadError(path);
    EXPECT_NE(message.find(path.string()), std::string::npos) << "message must name the file: " << message;
    EXPECT_GT(message.size(), path.string().size() + 4)
        << "message must carry tinygltf's reason: " << message;
}

TEST_F(MalformedFiles, InvalidJson) {
    const auto path = m_dir / "broken.gltf";
    test::writeFile(path, R"({"asset": {"version": "2.0"}, "nodes": [ {"mesh": 0,, )");
    const std::string message = loadError(path);
    EXPECT_NE(message.find(path.string()), std::string::npos) << "message must name the file: " << message;
    EXPECT_NE(message.find("parse error"), std::string::npos)
        << "message must carry the JSON parse error: " << message;
}

TEST_F(MalformedFiles, UnreadableFile) {
    const auto path = m_dir / "does_not_exist.gltf";
    expectNames(loadError(path), path, "cannot open");
}

TEST_F(MalformedFiles, TextureIndexOutOfRange) {
    TestModel m = test::makeTriangleModel();
    tinygltf::Material mat;
    mat.pbrMetallicRoughness.baseColorTexture.index = 4;
    m.model.materials.push_back(mat);
    m.model.meshes[0].primitives[0].material = 0;
    const auto path = m_dir / "badtexture.gltf";
    test::writeModel(m.model, path);
    expectNames(loadError(path), path, "materials[0].pbrMetallicRoughness.baseColorTexture.index");
}

// Random index corruption of an in-memory model: every outcome must be a load or
// a SceneError, never a crash or another exception type.
TEST(MalformedModels, RandomIndexCorruptionNeverCrashes) {
    Prng rng(42);
    int refused = 0;
    for (int iteration = 0; iteration < 400; ++iteration) {
        TestModel m = test::makeTriangleModel();
        tinygltf::Material mat;
        mat.pbrMetallicRoughness.baseColorTexture.index = -1;
        m.model.materials.push_back(mat);
        m.model.meshes[0].primitives[0].material = 0;
        const int value = static_cast<int>(rng.below(12)) - 3;
        switch (rng.below(10)) {
        case 0:
            m.model.accessors[rng.below(3)].bufferView = value;
            break;
        case 1:
            m.model.bufferViews[rng.below(3)].buffer = value;
            break;
        case 2:
            m.model.bufferViews[rng.below(3)].byteOffset = rng.below(64);
            break;
        case 3:
            m.model.bufferViews[rng.below(3)].byteStride = rng.below(16);
            break;
        case 4:
            m.model.accessors[rng.below(3)].componentType = 5120 + value;
            break;
        case 5:
            m.model.meshes[0].primitives[0].indices = value;
            break;
        case 6:
            m.model.meshes[0].primitives[0].material = value;
            break;
        case 7:
            m.model.nodes[0].mesh = value;
            break;
        case 8:
            m.model.scenes[0].nodes[0] = value;
            break;
        default:
            m.model.materials[0].pbrMetallicRoughness.baseColorTexture.index = value;
            break;
        }
        try {
            const Scene s = loadGltfModel(m.model, "fuzz.gltf");
            for (uint32_t i : s.indices) {
                ASSERT_LT(i, s.vertices.size()) << "iteration " << iteration << ": index past the vertices";
            }
        } catch (const SceneError& e) {
            ++refused;
            EXPECT_NE(std::string(e.what()).find("fuzz.gltf"), std::string::npos) << e.what();
        }
    }
    EXPECT_GT(refused, 0) << "the corruptions must trigger at least some refusals";
}

} // namespace
} // namespace eng::scene
