// Stored reference images (issue 17): every method on every built-in, hard and real scene at the
// settings users run (golden_cases.cpp), rendered on lavapipe with validation on and compared
// with the golden metric (golden_compare.h). On a failure the rendered image (EXR and PNG) and an
// error heatmap are written to AGAA_GOLDEN_FAILURE_DIR, next to CTest's log, and their paths
// printed.
//
// AGAA_GOLDEN_WRITE=DIR (tools/update-goldens.sh): render every case into DIR instead of
// comparing, and print for each whether it differs from the stored golden and by how much.
// AGAA_GOLDEN_ONLY=FILE (tools/perturb-test.sh): render only the goldens FILE names, one stem
// (scene/case, as printed) a line: a later perturbation runs only what no earlier one failed.

#include "golden_cases.h"
#include "golden_compare.h"

#include "engine/io/exr.h"
#include "engine/io/metrics.h"
#include "engine/io/png.h"
#include "engine/io/tone_map.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/scene_error.h"
#include "gpu_test_support.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

using agaa::golden::GoldenCase;
using agaa::golden::GoldenScene;
using agaa::golden::SceneSource;

// The goldens are rendered by llvmpipe's JIT pinned to SSE4.1 (Mesa reads the override once, when
// the first Vulkan instance loads the driver). The JIT fuses multiply-adds on a CPU with FMA and
// not on one without, which moves FXAA's edge decisions and the spiky scenes' AGAA images past the
// thresholds (30 of 108 goldens, docs/cross-cpu.md); pinned, every x86-64 CPU renders the same
// bits. A caller's own GALLIUM_OVERRIDE_CPU_CAPS wins.
const bool kJitPinned = setenv("GALLIUM_OVERRIDE_CPU_CAPS", "sse4.1", /*overwrite=*/0) == 0;

const fs::path kGoldenDir = AGAA_GOLDEN_DIR;
const fs::path kFailureDir = AGAA_GOLDEN_FAILURE_DIR;
const fs::path kSharedScenes = AGAA_SHARED_SCENES_DIR;

// A real asset renders as a user gets it without flags: lighting auto (the default sun and sky,
// or a fill sky next to its own lights; engine/scene/default_lighting.h), exposure metered.
eng::scene::Scene loadScene(const GoldenScene& s) {
    if (s.source == SceneSource::Gltf) {
        eng::scene::Scene scene = eng::scene::loadGltf(kSharedScenes / s.asset);
        eng::scene::applyLighting(scene, eng::scene::LightingMode::Automatic);
        return scene;
    }
    return eng::scene::loadTestScene(s.name);
}

void writeImages(const fs::path& stem, const eng::io::ImageF& display) {
    fs::create_directories(stem.parent_path());
    eng::io::writeExr(stem.string() + ".exr", display); // half floats: what the metric reads
    eng::io::writePng(stem.string() + ".png", eng::io::quantizeToU8(eng::io::srgbEncoded(display)));
}

// What rendered the failing image: goldens are compared on whatever CPU runs the suite, and
// llvmpipe's JIT code follows the CPU's vector extensions (docs/cross-cpu.md).
std::string machine(const eng::vk::Device& device) {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, model = "unknown CPU", extensions;
    while (std::getline(cpuinfo, line)) {
        const std::string value = line.substr(line.find(':') == std::string::npos ? 0 : line.find(':') + 1);
        if (line.rfind("model name", 0) == 0 && model == "unknown CPU")
            model = value.substr(value.find_first_not_of(' '));
        if (line.rfind("flags", 0) != 0 || !extensions.empty()) continue;
        std::istringstream flags(value);
        for (std::string f; flags >> f;)
            if (f == "sse4_2" || f == "avx" || f == "avx2" || f == "fma" || f == "avx512f")
                extensions += " " + f;
    }
    auto env = [](const char* name) {
        const char* v = std::getenv(name);
        return std::string(name) + "=" + (v ? v : "unset");
    };
    return model + " (" + (extensions.empty() ? " none" : extensions) + " ); " + device.caps().deviceName +
           "; " + env("GALLIUM_OVERRIDE_CPU_CAPS") + " " + env("LP_NATIVE_VECTOR_WIDTH") + " " +
           env("LP_NUM_THREADS");
}

std::string describe(const agaa::golden::GoldenError& e) {
    const agaa::golden::GoldenThresholds t;
    char line[240];
    std::snprintf(
        line, sizeof line,
        "display RMSE %.3g, p%.0f %.3g, max %.3g, %.2f %% of pixels over %.2g %% relative, %zu pixels differ",
        e.rmse, t.percentile, e.percentileError, e.maxError, 100.0 * e.shareOverRelative,
        100.0 * t.relativeBound, e.differingPixels);
    return line + std::string(e.goldenBlack ? ", golden black" : "");
}

// The stems AGAA_GOLDEN_ONLY names, or nothing when it is unset (every golden runs). Throws
// naming the file when it cannot be read.
std::optional<std::set<std::string>> onlyStems() {
    const char* file = std::getenv("AGAA_GOLDEN_ONLY");
    if (!file) return std::nullopt;
    std::ifstream in(file);
    if (!in) throw std::runtime_error(std::string("AGAA_GOLDEN_ONLY: cannot read '") + file + "'");
    std::set<std::string> stems;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) stems.insert(line);
    return stems;
}

class Golden : public ::testing::TestWithParam<GoldenScene> {};

TEST_P(Golden, MatchesStoredImages) {
    const GoldenScene& goldenScene = GetParam();
    if (goldenScene.source == SceneSource::Gltf && !fs::exists(kSharedScenes / goldenScene.asset))
        GTEST_SKIP() << (kSharedScenes / goldenScene.asset) << " is missing (AGAA_SHARED_SCENES_DIR)";
    const char* writeDir = std::getenv("AGAA_GOLDEN_WRITE");
    const std::optional<std::set<std::string>> only = onlyStems();
    std::vector<GoldenCase> cases;
    for (const GoldenCase& c : agaa::golden::goldenCases(goldenScene))
        if (!only || only->count(c.stem(goldenScene))) cases.push_back(c);
    if (cases.empty()) GTEST_SKIP() << "not rendered: AGAA_GOLDEN_ONLY names none of its goldens";
    const eng::scene::Scene scene = loadScene(goldenScene);
    auto device = agaa::test::makeValidatedDevice();
    agaa::FrameRenderer renderer(*device, scene);
    for (const GoldenCase& c : cases) {
        const std::string stem = c.stem(goldenScene);
        const auto start = std::chrono::steady_clock::now();
        agaa::RenderRequest request = c.request(goldenScene.size);
        request.autoExposure = !scene.exposure.has_value();
        const agaa::RenderResult result = renderer.render(request);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        const fs::path goldenDir = goldenScene.imagesDir.empty() ? kGoldenDir : goldenScene.imagesDir;
        const fs::path golden = goldenDir / (stem + ".exr");
        const bool haveGolden = fs::exists(golden);
        if (writeDir) {
            // Update mode: the new image goes to writeDir; the script decides what to copy.
            writeImages(fs::path(writeDir) / stem, agaa::golden::roundedToHalf(result.display));
            if (!haveGolden) {
                std::printf("[ golden ] %s: new\n", stem.c_str());
                continue;
            }
            const agaa::golden::GoldenError e =
                agaa::golden::compareToGolden(result.display, eng::io::readExr(golden));
            std::printf("[ golden ] %s: %s%s\n", stem.c_str(),
                        e.differingPixels == 0 ? "unchanged"
                                               : (e.passed() ? "changed (within threshold), " : "changed, "),
                        e.differingPixels == 0 ? "" : describe(e).c_str());
            continue;
        }
        if (!haveGolden) {
            ADD_FAILURE() << golden << " is missing: run tools/update-goldens.sh";
            continue;
        }
        const agaa::golden::GoldenError e =
            agaa::golden::compareToGolden(result.display, eng::io::readExr(golden));
        std::printf("[ golden ] %s: %s (%.0f ms) %s\n", stem.c_str(), describe(e).c_str(), ms,
                    e.passed() ? "PASS" : "FAIL");
        if (e.passed()) continue;
        const fs::path out = kFailureDir / stem;
        writeImages(fs::path(out.string() + ".actual"), result.display);
        const eng::io::ImageF heat =
            eng::io::errorHeatmap(eng::io::srgbEncoded(agaa::golden::roundedToHalf(result.display)),
                                  eng::io::srgbEncoded(eng::io::readExr(golden)), 20.0f);
        eng::io::writePng(out.string() + ".heatmap.png", eng::io::quantizeToU8(heat));
        ADD_FAILURE() << stem << " differs from its golden: " << describe(e) << " (thresholds: RMSE "
                      << agaa::golden::GoldenThresholds{}.rmse << ", p99 "
                      << agaa::golden::GoldenThresholds{}.percentileError << ", "
                      << 100.0 * agaa::golden::GoldenThresholds{}.relativeShare << " % of pixels over "
                      << 100.0 * agaa::golden::GoldenThresholds{}.relativeBound
                      << " % relative)\n  golden:  " << (goldenDir / (stem + ".png")).string()
                      << "\n  actual:  " << out.string() << ".actual.png (.exr)\n  heatmap: " << out.string()
                      << ".heatmap.png (error x20: 0.05 is white)\n  machine: " << machine(*device);
    }
    agaa::test::expectNoValidationErrors(*device);
}

// A host's case file is read before any test runs: a bad one ends the binary with its message.
std::vector<GoldenScene> scenesOrExit() {
    try {
        return agaa::golden::goldenScenes();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "test_golden: %s\n", e.what());
        std::exit(2);
    }
}

INSTANTIATE_TEST_SUITE_P(Every, Golden, ::testing::ValuesIn(scenesOrExit()), [](const auto& info) {
    std::string s = info.param.name;
    for (char& ch : s)
        if (ch == '-') ch = '_';
    return s;
});

} // namespace
