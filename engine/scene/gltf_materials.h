#pragma once
// glTF materials and their textures -> Scene::materials and Scene::textures.
// Textures are decoded to RGBA8 and tagged sRGB (base colour, emissive) or
// linear (metal-roughness, normal); a glTF texture used both ways becomes two.

#include "engine/scene/scene.h"

#include <tiny_gltf.h>

#include <string>

namespace eng::scene {

// Appends one Material per glTF material (same order, so glTF material i is
// Scene::materials[i]) and every texture they reference. Throws SceneError on a
// texture or image index out of range or an image without usable pixels.
void convertMaterials(const tinygltf::Model& model, const std::string& source, Scene& scene);

// Converts decoded pixels of any channel count (1-4) and depth (8, 16 bit, 32-bit
// float) to RGBA8. Grey expands to RGB; missing alpha is opaque.
std::vector<uint8_t> toRgba8(const tinygltf::Image& image, const std::string& source,
                             const std::string& field);

// The tinygltf image callback: decodes any image stb_image reads straight to RGBA8.
// Images stored in a bufferView are left for convertMaterials, which validates
// the byte range first.
bool decodeImageRgba8(tinygltf::Image* image, const int imageIndex, std::string* err, std::string* warn,
                      int reqWidth, int reqHeight, const unsigned char* bytes, int size, void* userData);

} // namespace eng::scene
