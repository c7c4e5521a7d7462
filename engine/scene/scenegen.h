#pragma once
// Procedural test scenes, built as ordinary glTF models so they exercise the same
// loader path as files and can be written out by tools/scenegen. Each scene:
// metres, +Y up, one shadow-casting sun, 16 coloured point lights around the
// subject, and one camera that frames the subject at 16:9 and at 1:1.
// Deterministic: the same kind, seed and density give the same bytes on every
// platform (own PRNG, no std distributions).

#include "engine/scene/scene.h"
#include "engine/scene/scene_error.h"

#include <tiny_gltf.h>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace eng::scene {

struct GenOptions {
    uint32_t seed = 1;
    float density = 1.0f; // scales strand, leaf and bar counts; (0, kMaxDensity]
};

inline constexpr float kMaxDensity = 8.0f;

// furball, metal, foliage, bamboo, railings, plane, default, spikes, glints, chainlink. The adversarial
// hard-* test scenes live outside the package (tools/scenes/adversarial_scenes.h: loadTestScene).
std::vector<std::string> sceneKinds();

// Throws SceneError for an unknown kind (listing the known ones) or a density
// outside (0, kMaxDensity].
tinygltf::Model generateScene(std::string_view kind, const GenOptions& options = {});

// loadGltfModel(generateScene(name), "builtin:" + name).
Scene loadBuiltin(std::string_view name);

} // namespace eng::scene
