#include "golden_cases.h"

#include "agaa/aggregate/agaa_constants.h"
#include "agaa/methods.h"
#include "engine/scene/scenegen.h"
#include "tools/scenes/adversarial_scenes.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace agaa::golden {

std::string GoldenCase::stem(const GoldenScene& scene) const {
    std::string s = scene.name + "/" + method + "-n" + std::to_string(samples);
    if (method.rfind("agaa", 0) == 0) s += "-c" + std::to_string(aggregates);
    if (tolerance && *tolerance != kToleranceNever) {
        char number[32];
        std::snprintf(number, sizeof number, "%g", double(*tolerance));
        s += "-tolerance-" + (*tolerance == kToleranceAuto ? std::string("auto") : std::string(number));
    }
    return s;
}

RenderRequest GoldenCase::request(uint32_t size) const {
    RenderRequest r;
    r.method = method;
    r.settings.samples = samples;
    r.settings.aggregates = aggregates;
    if (tolerance) r.settings.agaa.tolerance = *tolerance;
    r.view.width = r.view.height = size;
    return r;
}

void PrintTo(const GoldenScene& scene, std::ostream* os) {
    *os << scene.name;
}

std::vector<GoldenScene> hostGoldenScenes(const std::filesystem::path& caseFile,
                                          const std::filesystem::path& imagesDir) {
    std::ifstream in(caseFile);
    if (!in) throw std::runtime_error(caseFile.string() + ": cannot be read (AGAA_GOLDEN_HOST_CASES)");
    std::vector<GoldenScene> scenes;
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        const std::string where = caseFile.string() + ":" + std::to_string(number) + ": ";
        std::istringstream words(line.substr(0, line.find('#')));
        std::string kind;
        if (!(words >> kind)) continue;
        auto count = [&](const char* field, uint32_t lo, uint32_t hi, uint32_t fallback) {
            std::string text;
            if (!(words >> text)) return fallback;
            char* end = nullptr;
            const unsigned long v = std::strtoul(text.c_str(), &end, 10);
            if (*end != '\0' || v < lo || v > hi)
                throw std::runtime_error(where + field + " '" + text + "' is not a whole number in " +
                                         std::to_string(lo) + ".." + std::to_string(hi));
            return uint32_t(v);
        };
        if (kind == "scene") {
            GoldenScene s{"", SceneSource::Gltf, "", 64, {}, imagesDir};
            std::string file;
            if (!(words >> s.name >> file))
                throw std::runtime_error(where + "expected 'scene NAME FILE [SIZE]'");
            if (s.name.find_first_not_of(
                    "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != std::string::npos)
                throw std::runtime_error(where + "NAME '" + s.name +
                                         "' may hold only letters, digits, '_' and '-'");
            s.asset = (caseFile.parent_path() / file).lexically_normal().string();
            s.size = count("SIZE", 16, 256, 64);
            scenes.push_back(s);
        } else if (kind == "case") {
            if (scenes.empty()) throw std::runtime_error(where + "a 'case' line before any 'scene' line");
            GoldenCase c;
            if (!(words >> c.method))
                throw std::runtime_error(where + "expected 'case METHOD SAMPLES [AGGREGATES]'");
            if (!isKnownMethod(c.method))
                throw std::runtime_error(where + "METHOD '" + c.method +
                                         "' is not one of: " + knownMethodNames());
            c.samples = count("SAMPLES", 1, 32, 8);
            c.aggregates = count("AGGREGATES", 1, 4, 2);
            scenes.back().cases.push_back(c);
        } else {
            throw std::runtime_error(where + "'" + kind + "' is not 'scene' or 'case'");
        }
        std::string extra;
        if (words >> extra) throw std::runtime_error(where + "unexpected '" + extra + "'");
    }
    for (const GoldenScene& s : scenes)
        if (s.cases.empty())
            throw std::runtime_error(caseFile.string() + ": scene '" + s.name + "' has no case");
    if (scenes.empty()) throw std::runtime_error(caseFile.string() + ": no 'scene' line");
    return scenes;
}

std::vector<GoldenScene> goldenScenes() {
    if (const char* caseFile = std::getenv("AGAA_GOLDEN_HOST_CASES")) {
        const char* dir = std::getenv("AGAA_GOLDEN_HOST_DIR");
        const std::filesystem::path file(caseFile);
        return hostGoldenScenes(file, dir ? std::filesystem::path(dir) : file.parent_path() / "goldens");
    }
    std::vector<GoldenScene> scenes;
    for (const std::string& k : eng::scene::sceneKinds())
        scenes.push_back({k, SceneSource::Builtin, "", 64});
    for (const std::string& k : eng::scene::hardSceneKinds())
        scenes.push_back({k, SceneSource::Hard, "", 64});
    // The real scenes at 96x96: at 64 the ship's rigging and the chair are a handful of pixels.
    scenes.push_back({"gltf-cubes", SceneSource::Gltf, "Cubes/Cubes.glb", 96});
    scenes.push_back(
        {"gltf-mixed-lighting", SceneSource::Gltf, "MixedLightingExample/MixedLightingExample.gltf", 96});
    scenes.push_back(
        {"gltf-dutch-ship", SceneSource::Gltf, "dutch_ship_medium/dutch_ship_medium_1k.gltf", 96});
    return scenes;
}

std::vector<GoldenCase> goldenCases(const GoldenScene& scene) {
    if (!scene.cases.empty()) return scene.cases; // a host's
    // Every method at the default settings (n = 8, c = 2, S = 4 for SBAA and 3 for streaming; no-AA and FXAA
    // take one sample), AGAA as the paper has it (the shading rate at never), the samples path at
    // its default shading rate, and the accumulate path at the samples path's default tolerance (its
    // own default is never; docs/decisions/shading-rate-estimate.md, step 6). "agaa" is the
    // automatic path choice (samples at n <= 16).
    std::vector<GoldenCase> cases = {
        {"reference", 8, 1},
        {"noaa", 1, 1},
        {"fxaa", 1, 1},
        {"simple-complex", 8, 1},
        {"agaa-accumulate", 8, 2, kToleranceNever},
        {"agaa-samples", 8, 2, kToleranceNever},
        {"agaa-samples", 8, 2, kToleranceAuto},
        {"agaa-accumulate", 8, 2, kDefaultTolerance},
        {"sbaa", 8, 1},      // sbaa: S = 4 (default)
        {"streaming", 8, 1}, // streaming: S = 3 (default)
    };
    if (scene.source == SceneSource::Gltf) return cases;
    // c = 1 and 4 on both generation paths.
    for (const char* path : {"agaa-accumulate", "agaa-samples"})
        for (uint32_t c : {1u, 4u})
            cases.push_back({path, 8, c, kToleranceNever});
    if (scene.source == SceneSource::Hard) return cases;
    // The sample counts users run: native 4x and emulated 32x. ("agaa", the automatic choice, is
    // agaa-samples at n <= 16 and agaa-accumulate above: the same images, not stored twice.)
    for (uint32_t n : {4u, 32u}) {
        cases.push_back({"reference", n, 1});
        cases.push_back({"simple-complex", n, 1});
        cases.push_back({"agaa-accumulate", n, 2, kToleranceNever});
        cases.push_back({"agaa-samples", n, 2, kToleranceNever});
    }
    return cases;
}

} // namespace agaa::golden
