#pragma once
// glTF 2.0 (.gltf and .glb) -> Scene. Everything a file can get wrong is either
// repaired with a warning in Scene::stats or refused with a SceneError naming the
// file and the field; nothing in a file can crash the loader or reach the
// renderer as NaN.

#include "engine/scene/scene.h"
#include "engine/scene/scene_error.h"

#include <tiny_gltf.h>

#include <filesystem>
#include <string>
#include <vector>

namespace eng::scene {

// Loads a .gltf (external or data-URI buffers and images) or a .glb file.
Scene loadGltf(const std::filesystem::path& path);

// The same conversion from a model already in memory; sourceName prefixes every
// message and becomes Scene::source.
Scene loadGltfModel(const tinygltf::Model& model, const std::string& sourceName);

// Keeps at most keepPerKind warnings of each kind (the same text with its numbers masked) and
// adds one line per kind with the count of those left out; lines are bounded in length.
void summariseWarnings(std::vector<std::string>& warnings, size_t keepPerKind = 5);

} // namespace eng::scene
