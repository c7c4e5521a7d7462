#include "gltf_test_model.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <fstream>
#include <sstream>

#include <unistd.h>

namespace eng::scene::test {

TestModel::TestModel() {
    model.asset.version = "2.0";
    model.buffers.emplace_back();
    model.scenes.emplace_back();
    model.defaultScene = 0;
}

int TestModel::addBufferView(const void* data, size_t size) {
    auto& bytes = model.buffers[0].data;
    bytes.resize((bytes.size() + 3) & ~size_t(3), 0);
    const size_t offset = bytes.size();
    bytes.resize(offset + size);
    std::memcpy(bytes.data() + offset, data, size);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = size;
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size() - 1);
}

int TestModel::addFloatAccessor(const std::vector<float>& values, int type) {
    const int components = type == TINYGLTF_TYPE_SCALAR ? 1
                           : type == TINYGLTF_TYPE_VEC2 ? 2
                           : type == TINYGLTF_TYPE_VEC3 ? 3
                                                        : 4;
    tinygltf::Accessor accessor;
    accessor.bufferView = addBufferView(values.data(), values.size() * sizeof(float));
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.type = type;
    accessor.count = values.size() / static_cast<size_t>(components);
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
}

int TestModel::addVec3Accessor(const std::vector<glm::vec3>& values) {
    std::vector<float> flat;
    for (const glm::vec3& v : values) {
        flat.insert(flat.end(), {v.x, v.y, v.z});
    }
    return addFloatAccessor(flat, TINYGLTF_TYPE_VEC3);
}

int TestModel::addIndexAccessor(const std::vector<uint32_t>& indices, int componentType) {
    std::vector<uint8_t> bytes;
    for (uint32_t i : indices) {
        if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
            bytes.push_back(static_cast<uint8_t>(i));
        } else if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
            const auto v = static_cast<uint16_t>(i);
            bytes.insert(bytes.end(), reinterpret_cast<const uint8_t*>(&v),
                         reinterpret_cast<const uint8_t*>(&v) + 2);
        } else {
            bytes.insert(bytes.end(), reinterpret_cast<const uint8_t*>(&i),
                         reinterpret_cast<const uint8_t*>(&i) + 4);
        }
    }
    tinygltf::Accessor accessor;
    accessor.bufferView = addBufferView(bytes.data(), bytes.size());
    accessor.componentType = componentType;
    accessor.type = TINYGLTF_TYPE_SCALAR;
    accessor.count = indices.size();
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size() - 1);
}

int TestModel::addNode(int parent) {
    model.nodes.emplace_back();
    const int index = static_cast<int>(model.nodes.size() - 1);
    if (parent >= 0) {
        model.nodes[static_cast<size_t>(parent)].children.push_back(index);
    } else {
        model.scenes[0].nodes.push_back(index);
    }
    return index;
}

int TestModel::addMeshNode(const std::map<std::string, int>& attributes, int indices, int material,
                           int parent) {
    tinygltf::Primitive prim;
    prim.attributes = attributes;
    prim.indices = indices;
    prim.material = material;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);
    const int node = addNode(parent);
    model.nodes[static_cast<size_t>(node)].mesh = static_cast<int>(model.meshes.size() - 1);
    return node;
}

TestModel makeTriangleModel() {
    TestModel m;
    const int pos = m.addVec3Accessor({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int nrm = m.addVec3Accessor({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int idx = m.addIndexAccessor({0, 1, 2});
    m.addMeshNode({{"POSITION", pos}, {"NORMAL", nrm}}, idx);
    return m;
}

std::filesystem::path makeTempDir(const std::string& testName) {
    static std::atomic<int> counter{0};
    const auto dir =
        std::filesystem::temp_directory_path() /
        ("eng_scene_test_" + testName + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

void writeFile(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    ASSERT_TRUE(out.good()) << "test setup: cannot write " << path;
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void writeModel(const tinygltf::Model& model, const std::filesystem::path& path) {
    tinygltf::TinyGLTF writer;
    const bool binary = path.extension() == ".glb";
    ASSERT_TRUE(writer.WriteGltfSceneToFile(&model, path.string(), true, true, !binary, binary))
        << "test setup: tinygltf could not write " << path;
}

} // namespace eng::scene::test
