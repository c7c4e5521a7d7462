#pragma once
// A loaded scene, flattened for rendering: every mesh primitive is pre-transformed
// into world space and appended to one vertex and one index buffer; draws are
// index ranges with a material. Units are metres, glTF conventions (right-handed,
// +Y up). The renderer uploads these arrays as they are.

#include "engine/scene/environment.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace eng::scene {

// 72 bytes, matches the vertex input layout of every raster pass (engine/vk/pipeline.cpp).
struct Vertex {
    glm::vec3 position{0.0f};                  // world space
    glm::vec3 normal{0.0f, 0.0f, 1.0f};        // world space, unit length
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f}; // world space xyz, w = bitangent sign
    glm::vec2 uv{0.0f};                        // TEXCOORD_0
    glm::vec2 uv1{0.0f};                       // TEXCOORD_1 (0 without)
    glm::vec4 color{1.0f};                     // COLOR_0, linear RGBA (white without)
};
static_assert(sizeof(Vertex) == 72);

// Decoded texture, always RGBA8. srgb says how the renderer must interpret it
// (base colour and emissive are sRGB; metal-roughness and normal maps are linear).
struct Texture {
    std::string name;
    uint32_t width = 0;
    uint32_t height = 0;
    bool srgb = false;
    std::vector<uint8_t> rgba8; // width * height * 4
};

enum class AlphaMode { Opaque, Mask, Blend };

// KHR_texture_transform on one texture slot: uv' = T(offset) R(rotation) S(scale) uv, rotation in
// radians counter-clockwise in uv space (the extension's reference GLSL).
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;
    glm::vec2 scale{1.0f};
    uint32_t texCoord = 0; // the UV set the slot reads: TEXCOORD_0 or TEXCOORD_1
};

// glTF metallic-roughness material. Texture indices are into Scene::textures, -1 = none.
struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};
    float metallicFactor = 1.0f;
    float roughnessFactor = 1.0f;
    glm::vec3 emissiveFactor{0.0f};
    float emissiveStrength = 1.0f; // KHR_materials_emissive_strength
    float normalScale = 1.0f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    bool doubleSided = false;
    int32_t baseColorTexture = -1;
    int32_t metallicRoughnessTexture = -1;
    int32_t normalTexture = -1;
    int32_t emissiveTexture = -1;
    // Per slot: base colour, metal-roughness, normal, emissive (the order of GpuMaterial::textures).
    TextureTransform textureTransforms[4];
};

// One contiguous index range drawn with one material.
struct Draw {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    uint32_t material = 0;
};

enum class LightType { Directional, Point, Spot };

// KHR_lights_punctual, in world space. Intensity in glTF units: lux for
// directional, candela for point and spot.
struct Light {
    std::string name;
    LightType type = LightType::Point;
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f}; // unit, the direction light travels
    float range = 0.0f;                     // 0 = infinite (glTF: undefined range)
    float innerConeAngle = 0.0f;            // radians, spot only
    float outerConeAngle = 0.7853982f;      // radians, spot only
    bool castsShadows = false;              // extras.castsShadows, or the sun by default
};

// A perspective camera. view is world -> view space (looking down -Z).
struct Camera {
    std::string name;
    glm::mat4 view{1.0f};
    float yfov = 0.8f; // radians
    float znear = 0.05f;
    float zfar = 100.0f; // always finite: the loader derives one from the bounds if glTF gives none
};

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
};

struct LoadStats {
    uint32_t degenerateTrianglesDropped = 0;
    uint32_t primitivesWithFlatNormals = 0; // had no NORMAL attribute
    std::vector<std::string> warnings;      // repairs made, each naming the file and field
};

struct Scene {
    std::string source; // file path or "builtin:<name>"
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<Draw> draws;
    std::vector<Material> materials; // never empty: a default material is appended when needed
    std::vector<Texture> textures;
    std::vector<Light> lights;
    std::vector<Camera>
        cameras; // never empty: a default camera framing the bounds is added when the file has none
    Bounds bounds;
    LoadStats stats;
    // Distant lighting and the sky (engine/scene/environment.h); empty: uncovered samples show a
    // constant sky colour and nothing lights the scene but its lights.
    Environment environment;
    // Where the lights came from (engine/scene/default_lighting.h): "scene", "default" or "both",
    // and why, for the stats.
    std::string lightingMode = "scene";
    std::string lightingCause = "the scene's own lights";
    // The exposure the scene was authored for (the built-in scenes: 1, their lights are sized for
    // it); none, as for every glTF file: metered (engine/frame/exposure.h).
    std::optional<float> exposure;

    uint32_t triangleCount() const { return static_cast<uint32_t>(indices.size() / 3); }
};

} // namespace eng::scene
