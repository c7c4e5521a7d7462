#pragma once
// Assembles a tinygltf::Model from procedural pieces: one buffer holding every
// attribute, index and embedded image, one node per mesh (already in world
// space), light nodes (KHR_lights_punctual) and a camera node. The result is a
// plain glTF model: it can be written to disk or converted with loadGltfModel.

#include "engine/scene/procedural_mesh.h"
#include "engine/scene/scene.h"

#include <tiny_gltf.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace eng::scene {

struct MaterialDesc {
    std::string name;
    glm::vec4 baseColor{1.0f};
    float metallic = 0.0f;
    float roughness = 0.5f;
    glm::vec3 emissive{0.0f};
    float emissiveStrength = 1.0f; // written as KHR_materials_emissive_strength when != 1
    int baseColorTexture = -1;     // glTF texture index from addPngTexture
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
};

class ModelBuilder {
  public:
    explicit ModelBuilder(const std::string& generator);

    int addMaterial(const MaterialDesc& desc);
    // Stores the PNG in the buffer (image with bufferView + mimeType), so both
    // .gltf and .glb output carry it, and an in-memory load can decode it.
    int addPngTexture(const std::vector<uint8_t>& png, const std::string& name);
    // A node with the mesh at identity transform; empty meshes are skipped.
    void addMesh(const std::string& name, const MeshData& mesh, int material);
    void addDirectionalLight(const std::string& name, const glm::vec3& direction, const glm::vec3& color,
                             float intensityLux, bool castsShadows);
    void addPointLight(const std::string& name, const glm::vec3& position, const glm::vec3& color,
                       float intensityCandela, float range);
    // A perspective camera node whose world matrix is inverse(camera.view).
    void addCamera(const Camera& camera, float aspectRatio);

    tinygltf::Model finish();

  private:
    size_t appendBytes(const void* data, size_t size);
    int addBufferView(size_t offset, size_t length, int target);
    int addAccessor(int bufferView, int componentType, int type, size_t count, std::vector<double> min = {},
                    std::vector<double> max = {});
    int addNode(tinygltf::Node node);

    tinygltf::Model m_model;
    tinygltf::Scene m_scene;
};

} // namespace eng::scene
