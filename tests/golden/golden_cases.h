#pragma once
// The stored reference images (tests/golden/images/): which scene, method and settings each one
// holds, and where its files live. One list, read by the golden test and by the update script
// (through the same test binary), so the two cannot disagree about what a golden is.

#include "tools/harness/frame_renderer.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace agaa::golden {

enum class SceneSource {
    Builtin, // eng::scene::loadBuiltin: the procedural scenes (sceneKinds())
    Hard,    // eng::scene::loadTestScene: the adversarial hard-* scenes (hardSceneKinds())
    Gltf,    // a real asset under ../shared/scenes (AGAA_SHARED_SCENES_DIR), or a host's file
};

struct GoldenCase {
    std::string method; // agaa/methods.h
    uint32_t samples = 8;
    uint32_t aggregates = 2;
    // AGAA's shading rate (MethodSettings::agaa.tolerance); none: the method's default, as a host's
    // cases have it. The built-in cases store AGAA as the paper has it (never), which the shading
    // rate must leave bit for bit, and the samples path's default once per scene.
    std::optional<float> tolerance;
    // "<scene>/<method>-n<N>[-c<C>][-tolerance-<T>]" without extension (.exr: the metric, .png: for
    // people); the tolerance is named unless it is never or the method's default.
    std::string stem(const struct GoldenScene& scene) const;
    RenderRequest request(uint32_t size) const;
};

struct GoldenScene {
    std::string name; // test name and folder under images/
    SceneSource source;
    std::string asset;  // Gltf: path relative to the shared scenes folder, or absolute (a host's)
    uint32_t size = 64; // square image, pixels
    // A host's scene (hostGoldenScenes): its own cases and the folder its goldens live in.
    std::vector<GoldenCase> cases;
    std::filesystem::path imagesDir; // empty: tests/golden/images
};

// gtest prints the scene's name for a parameter.
void PrintTo(const GoldenScene& scene, std::ostream* os);

// Every scene that has goldens: built-in, hard, real. With AGAA_GOLDEN_HOST_CASES=FILE set, only
// the host's scenes that FILE lists (hostGoldenScenes).
std::vector<GoldenScene> goldenScenes();

// A host's own goldens (tests/README.md, "A host's scenes"): a case file of lines
//   scene NAME FILE.gltf|FILE.glb [SIZE]     FILE relative to the case file; SIZE 16..256, default 64
//   case METHOD SAMPLES [AGGREGATES]         a case of the scene above (agaa-render's method names)
// ('#' starts a comment). The goldens live in imagesDir: AGAA_GOLDEN_HOST_DIR, or the case file's
// folder's goldens/. Throws std::runtime_error naming the file, line and field on a bad line.
std::vector<GoldenScene> hostGoldenScenes(const std::filesystem::path& caseFile,
                                          const std::filesystem::path& imagesDir);
// The cases of one scene: every method at n = 8 (c = 2) on every scene; on the built-in scenes
// also n = 4 and n = 32 and c = 1 and 4 on both AGAA paths; on the hard scenes c = 1 and 4.
std::vector<GoldenCase> goldenCases(const GoldenScene& scene);

} // namespace agaa::golden
