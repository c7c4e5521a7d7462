#pragma once
// Adversarial procedural scenes for the hard-case suite (tests/hard): each one drives a
// numerical guard of the renderer to its edge (opposing normals in one pixel, roughness 0
// and 1, z-fighting, dozens of triangles per pixel, degenerate input, geometry 1e5 m from
// the origin, grazing angles, 1e4 emissive strength, a light inside the geometry, no
// lights, 1000 lights, a frame of sky). They are ordinary glTF models built with
// ModelBuilder, named "hard-<case>", reachable through generateTestScene/loadTestScene and
// `scenegen --kind`, and kept out of sceneKinds() so the benchmark does not sweep them.
// tests/hard/README.md lists what each proves. Test content: a tools/tests library
// (agaa_test_scenes), not part of the installed package.

#include "engine/scene/scenegen.h"

#include <tiny_gltf.h>

#include <string>
#include <string_view>
#include <vector>

namespace eng::scene {

// hard-flat, hard-vgroove, hard-fold, hard-mirror, hard-zfight, hard-dense, hard-degenerate,
// hard-far, hard-grazing, hard-emissive, hard-light-inside, hard-no-lights, hard-many-lights, hard-sky.
std::vector<std::string> hardSceneKinds();
bool isHardSceneKind(std::string_view kind);

// Throws SceneError for a name that is not a hard kind. Deterministic in options.seed.
tinygltf::Model generateHardScene(std::string_view kind, const GenOptions& options = {});

// What the tools and tests name a scene by: a hard-* kind, else engine/scene's generateScene
// (whose SceneError lists the built-in kinds).
tinygltf::Model generateTestScene(std::string_view kind, const GenOptions& options = {});
// loadBuiltin for the hard-* kinds as well.
Scene loadTestScene(std::string_view name);

} // namespace eng::scene
