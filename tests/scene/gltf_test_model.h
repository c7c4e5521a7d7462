#pragma once
// Small glTF models built in code for the loader tests, with direct control over
// every accessor (so a test can make one field wrong), plus temp-dir helpers.

#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace eng::scene::test {

class TestModel {
  public:
    TestModel();

    // Raw bytes appended to buffer 0 (4-byte aligned) with their own bufferView.
    int addBufferView(const void* data, size_t size);
    int addFloatAccessor(const std::vector<float>& values, int type);
    int addVec3Accessor(const std::vector<glm::vec3>& values);
    // componentType: UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT.
    int addIndexAccessor(const std::vector<uint32_t>& indices,
                         int componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);

    // A mesh with one triangle primitive on a new node; returns the node index.
    // The node is a scene root unless parent >= 0.
    int addMeshNode(const std::map<std::string, int>& attributes, int indices, int material = -1,
                    int parent = -1);
    int addNode(int parent = -1);

    tinygltf::Model model;
};

// One triangle (0,0,0) (1,0,0) (0,1,0) facing +Z with normals; returns the model.
TestModel makeTriangleModel();

// A fresh empty directory under the system temp dir, unique per test.
std::filesystem::path makeTempDir(const std::string& testName);

void writeFile(const std::filesystem::path& path, const std::string& bytes);
std::string readFile(const std::filesystem::path& path);

// WriteGltfSceneToFile with embedded buffers (.gltf) or a binary chunk (.glb).
void writeModel(const tinygltf::Model& model, const std::filesystem::path& path);

} // namespace eng::scene::test
