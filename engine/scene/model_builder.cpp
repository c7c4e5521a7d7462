#include "engine/scene/model_builder.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cstring>
#include <limits>

namespace eng::scene {

namespace {

// glTF rotation (x, y, z, w) of a frame whose -Z axis points along forward.
std::vector<double> rotationLookingAlong(const glm::vec3& forward) {
    const glm::vec3 f = glm::normalize(forward);
    const glm::vec3 upHint =
        std::abs(f.y) > 0.999f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    const glm::vec3 right = glm::normalize(glm::cross(f, upHint));
    const glm::vec3 up = glm::cross(right, f);
    const glm::quat q = glm::quat_cast(glm::mat3(right, up, -f));
    return {q.x, q.y, q.z, q.w};
}

std::vector<double> toDoubles(const glm::vec3& v) {
    return {v.x, v.y, v.z};
}

} // namespace

ModelBuilder::ModelBuilder(const std::string& generator) {
    m_model.asset.version = "2.0";
    m_model.asset.generator = generator;
    m_model.buffers.emplace_back();
    m_scene.name = generator;
}

size_t ModelBuilder::appendBytes(const void* data, size_t size) {
    std::vector<unsigned char>& bytes = m_model.buffers[0].data;
    // 4-byte alignment: glTF requires accessor offsets aligned to the component size.
    bytes.resize((bytes.size() + 3) & ~size_t(3), 0);
    const size_t offset = bytes.size();
    bytes.resize(offset + size);
    std::memcpy(bytes.data() + offset, data, size);
    return offset;
}

int ModelBuilder::addBufferView(size_t offset, size_t length, int target) {
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = offset;
    view.byteLength = length;
    view.target = target;
    m_model.bufferViews.push_back(view);
    return static_cast<int>(m_model.bufferViews.size() - 1);
}

int ModelBuilder::addAccessor(int bufferView, int componentType, int type, size_t count,
                              std::vector<double> min, std::vector<double> max) {
    tinygltf::Accessor accessor;
    accessor.bufferView = bufferView;
    accessor.componentType = componentType;
    accessor.type = type;
    accessor.count = count;
    accessor.minValues = std::move(min);
    accessor.maxValues = std::move(max);
    m_model.accessors.push_back(accessor);
    return static_cast<int>(m_model.accessors.size() - 1);
}

int ModelBuilder::addNode(tinygltf::Node node) {
    m_model.nodes.push_back(std::move(node));
    const int index = static_cast<int>(m_model.nodes.size() - 1);
    m_scene.nodes.push_back(index);
    return index;
}

int ModelBuilder::addMaterial(const MaterialDesc& desc) {
    tinygltf::Material m;
    m.name = desc.name;
    m.pbrMetallicRoughness.baseColorFactor = {desc.baseColor.r, desc.baseColor.g, desc.baseColor.b,
                                              desc.baseColor.a};
    m.pbrMetallicRoughness.metallicFactor = desc.metallic;
    m.pbrMetallicRoughness.roughnessFactor = desc.roughness;
    m.pbrMetallicRoughness.baseColorTexture.index = desc.baseColorTexture;
    m.emissiveFactor = toDoubles(desc.emissive);
    if (desc.emissiveStrength != 1.0f) {
        tinygltf::Value::Object ext;
        ext["emissiveStrength"] = tinygltf::Value(static_cast<double>(desc.emissiveStrength));
        m.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(ext);
        if (std::find(m_model.extensionsUsed.begin(), m_model.extensionsUsed.end(),
                      "KHR_materials_emissive_strength") == m_model.extensionsUsed.end()) {
            m_model.extensionsUsed.push_back("KHR_materials_emissive_strength");
        }
    }
    switch (desc.alphaMode) {
    case AlphaMode::Opaque:
        m.alphaMode = "OPAQUE";
        break;
    case AlphaMode::Mask:
        m.alphaMode = "MASK";
        break;
    case AlphaMode::Blend:
        m.alphaMode = "BLEND";
        break;
    }
    m.alphaCutoff = desc.alphaCutoff;
    m.doubleSided = desc.doubleSided;
    m_model.materials.push_back(m);
    return static_cast<int>(m_model.materials.size() - 1);
}

int ModelBuilder::addPngTexture(const std::vector<uint8_t>& png, const std::string& name) {
    const size_t offset = appendBytes(png.data(), png.size());
    tinygltf::Image image;
    image.name = name;
    image.mimeType = "image/png";
    image.bufferView = addBufferView(offset, png.size(), 0);
    m_model.images.push_back(image);

    tinygltf::Sampler sampler;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.wrapS = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
    m_model.samplers.push_back(sampler);

    tinygltf::Texture texture;
    texture.name = name;
    texture.source = static_cast<int>(m_model.images.size() - 1);
    texture.sampler = static_cast<int>(m_model.samplers.size() - 1);
    m_model.textures.push_back(texture);
    return static_cast<int>(m_model.textures.size() - 1);
}

void ModelBuilder::addMesh(const std::string& name, const MeshData& mesh, int material) {
    if (mesh.empty()) {
        return;
    }
    const size_t n = mesh.positions.size();
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
    const int posView = addBufferView(appendBytes(mesh.positions.data(), n * sizeof(glm::vec3)),
                                      n * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    const int nrmView = addBufferView(appendBytes(mesh.normals.data(), n * sizeof(glm::vec3)),
                                      n * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
    const int uvView = addBufferView(appendBytes(mesh.uvs.data(), n * sizeof(glm::vec2)),
                                     n * sizeof(glm::vec2), TINYGLTF_TARGET_ARRAY_BUFFER);
    const size_t indexBytes = mesh.indices.size() * sizeof(uint32_t);
    const int idxView = addBufferView(appendBytes(mesh.indices.data(), indexBytes), indexBytes,
                                      TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);

    tinygltf::Primitive prim;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    prim.material = material;
    // glTF requires min/max on POSITION.
    prim.attributes["POSITION"] =
        addAccessor(posView, kFloat, TINYGLTF_TYPE_VEC3, n, toDoubles(lo), toDoubles(hi));
    prim.attributes["NORMAL"] = addAccessor(nrmView, kFloat, TINYGLTF_TYPE_VEC3, n);
    prim.attributes["TEXCOORD_0"] = addAccessor(uvView, kFloat, TINYGLTF_TYPE_VEC2, n);
    prim.indices =
        addAccessor(idxView, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, mesh.indices.size());

    tinygltf::Mesh gltfMesh;
    gltfMesh.name = name;
    gltfMesh.primitives.push_back(prim);
    m_model.meshes.push_back(gltfMesh);

    tinygltf::Node node;
    node.name = name;
    node.mesh = static_cast<int>(m_model.meshes.size() - 1);
    addNode(std::move(node));
}

void ModelBuilder::addDirectionalLight(const std::string& name, const glm::vec3& direction,
                                       const glm::vec3& color, float intensityLux, bool castsShadows) {
    tinygltf::Light light;
    light.name = name;
    light.type = "directional";
    light.color = toDoubles(color);
    light.intensity = intensityLux;
    tinygltf::Value::Object extras;
    extras["castsShadows"] = tinygltf::Value(castsShadows);
    light.extras = tinygltf::Value(extras);
    m_model.lights.push_back(light);

    tinygltf::Node node;
    node.name = name;
    node.rotation = rotationLookingAlong(direction);
    tinygltf::Value::Object ext;
    ext["light"] = tinygltf::Value(static_cast<int>(m_model.lights.size() - 1));
    node.extensions["KHR_lights_punctual"] = tinygltf::Value(ext);
    addNode(std::move(node));
}

void ModelBuilder::addPointLight(const std::string& name, const glm::vec3& position, const glm::vec3& color,
                                 float intensityCandela, float range) {
    tinygltf::Light light;
    light.name = name;
    light.type = "point";
    light.color = toDoubles(color);
    light.intensity = intensityCandela;
    light.range = range;
    tinygltf::Value::Object extras;
    extras["castsShadows"] = tinygltf::Value(false);
    light.extras = tinygltf::Value(extras);
    m_model.lights.push_back(light);

    tinygltf::Node node;
    node.name = name;
    node.translation = toDoubles(position);
    tinygltf::Value::Object ext;
    ext["light"] = tinygltf::Value(static_cast<int>(m_model.lights.size() - 1));
    node.extensions["KHR_lights_punctual"] = tinygltf::Value(ext);
    addNode(std::move(node));
}

void ModelBuilder::addCamera(const Camera& camera, float aspectRatio) {
    tinygltf::Camera cam;
    cam.name = camera.name;
    cam.type = "perspective";
    cam.perspective.yfov = camera.yfov;
    cam.perspective.znear = camera.znear;
    cam.perspective.zfar = camera.zfar;
    cam.perspective.aspectRatio = aspectRatio;
    m_model.cameras.push_back(cam);

    const glm::mat4 world = glm::inverse(camera.view);
    const glm::quat q = glm::quat_cast(glm::mat3(world));
    tinygltf::Node node;
    node.name = camera.name;
    node.camera = static_cast<int>(m_model.cameras.size() - 1);
    node.translation = toDoubles(glm::vec3(world[3]));
    node.rotation = {q.x, q.y, q.z, q.w};
    addNode(std::move(node));
}

tinygltf::Model ModelBuilder::finish() {
    if (!m_model.lights.empty() && std::find(m_model.extensionsUsed.begin(), m_model.extensionsUsed.end(),
                                             "KHR_lights_punctual") == m_model.extensionsUsed.end()) {
        m_model.extensionsUsed.push_back("KHR_lights_punctual");
    }
    m_model.buffers[0].data.resize((m_model.buffers[0].data.size() + 3) & ~size_t(3), 0);
    m_model.scenes = {m_scene};
    m_model.defaultScene = 0;
    return std::move(m_model);
}

} // namespace eng::scene
