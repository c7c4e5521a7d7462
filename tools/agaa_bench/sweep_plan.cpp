#include "sweep_plan.h"

#include "agaa/method_settings.h"
#include "agaa/methods.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <set>
#include <stdexcept>

namespace agaa::bench {

namespace {

const MethodInfo& methodInfo(const std::string& name) {
    for (const MethodInfo& m : knownMethods())
        if (m.name == name) return m;
    throw std::invalid_argument("--methods: '" + name + "' is unknown (known: " + knownMethodNames() + ")");
}

std::vector<uint32_t> sortedUnique(std::vector<uint32_t> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

bool parseUint(const std::string& s, uint32_t& out) {
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && ptr == s.data() + s.size() && !s.empty();
}

} // namespace

std::string jobId(const std::string& scene, const std::string& method, uint32_t samples, uint32_t aggregates,
                  uint32_t surfaces, const std::string& tolerance, bool specularAA) {
    return scene + "__" + method + "__n" + std::to_string(samples) + "__c" + std::to_string(aggregates) +
           (surfaces ? "__s" + std::to_string(surfaces) : "") + (tolerance.empty() ? "" : "__t" + tolerance) +
           (specularAA ? "__saa" : "");
}

std::string Job::id() const {
    return jobId(scene, method, samples, aggregates, surfaces, tolerance, specularAA);
}

std::string Job::label() const {
    return method + (tolerance.empty() ? "" : " T" + tolerance) + (specularAA ? " + specular AA" : "");
}

std::string sceneWithLights(const std::string& scene, uint32_t extraLights) {
    return extraLights == 0 ? scene : scene + "+l" + std::to_string(extraLights);
}

SceneVariant parseSceneVariant(const std::string& name) {
    const size_t plus = name.rfind("+l");
    uint32_t k = 0;
    if (plus == std::string::npos || plus == 0 || !parseUint(name.substr(plus + 2), k) || k == 0 ||
        name.substr(plus + 2) != std::to_string(k))
        return {name, 0};
    return {name.substr(0, plus), k};
}

std::vector<Job> planSweep(const SweepSettings& settings) {
    const std::vector<uint32_t> samples = sortedUnique(settings.samples);
    const std::vector<uint32_t> aggregates = sortedUnique(settings.aggregates);
    const std::vector<uint32_t> lightCounts =
        settings.extraLights.empty() ? std::vector<uint32_t>{0} : sortedUnique(settings.extraLights);
    std::vector<std::string> scenes;
    for (const std::string& base : settings.scenes)
        for (uint32_t k : lightCounts)
            scenes.push_back(sceneWithLights(base, k));
    std::vector<Job> jobs;
    std::set<std::string> seen;
    for (const std::string& scene : scenes) {
        for (const std::string& method : settings.methods) {
            const MethodInfo& info = methodInfo(method);
            const std::vector<uint32_t> ns =
                info.usesSamples ? samples : std::vector<uint32_t>{kSamplesWhenUnused};
            const std::vector<uint32_t> cs =
                info.usesAggregates ? aggregates : std::vector<uint32_t>{kAggregatesWhenUnused};
            std::vector<uint32_t> ss = {0};
            if (info.maxSurfaces) {
                ss.clear();
                for (uint32_t s : sortedUnique(settings.surfaces))
                    if (s >= 1 && s <= info.maxSurfaces) ss.push_back(s);
                if (settings.surfaces.empty()) ss.push_back(info.defaultSurfaces);
                if (ss.empty())
                    throw std::invalid_argument("--surfaces: none of the values is in " + method + "'s 1.." +
                                                std::to_string(info.maxSurfaces));
            }
            std::vector<std::string> ts = {""};
            if (!settings.tolerances.empty() &&
                methodReadsOption(*findMethodOption("agaa-tolerance"), method))
                ts = settings.tolerances;
            for (uint32_t n : ns) {
                for (uint32_t c : cs) {
                    for (uint32_t s : ss) {
                        for (const std::string& t : ts) {
                            for (const bool saa : settings.specularAA) {
                                Job job;
                                job.scene = scene;
                                job.method = method;
                                job.samples = n;
                                job.aggregates = c;
                                job.surfaces = s;
                                // "auto" is AGAA's default: the job the sweep has without the axis.
                                job.tolerance = t == "auto" ? "" : t;
                                job.specularAA = saa;
                                job.usesSamples = info.usesSamples;
                                job.usesAggregates = info.usesAggregates;
                                if (!seen.insert(job.id()).second) continue;
                                job.index = jobs.size();
                                jobs.push_back(job);
                            }
                        }
                    }
                }
            }
        }
    }
    return jobs;
}

JobSlice parseJobSlice(const std::string& text) {
    const size_t slash = text.find('/');
    JobSlice slice;
    if (slash != std::string::npos && parseUint(text.substr(0, slash), slice.index) &&
        parseUint(text.substr(slash + 1), slice.count) && slice.count >= 1 && slice.count <= 1024 &&
        slice.index < slice.count)
        return slice;
    throw std::invalid_argument("--job '" + text +
                                "' is not I/N with N in 1..1024 and 0 <= I < N (e.g. 0/2, 1/2)");
}

void temporalSize(const SweepSettings& settings, uint32_t& width, uint32_t& height) {
    width = settings.width;
    height = settings.height;
    if (width <= settings.temporalMaxWidth) return;
    const double scale = double(settings.temporalMaxWidth) / double(width);
    width = settings.temporalMaxWidth;
    height = std::max<uint32_t>(1, uint32_t(std::lround(double(settings.height) * scale)));
}

std::vector<std::string> defaultSweepScenes() {
    std::vector<std::string> scenes = {"plane", "railings", "foliage", "furball", "metal"};
    if (realScenePath("ship")) scenes.push_back("ship"); // Godot's AA demo scene: ropes 1-6 cm wide
    return scenes;
}

const std::vector<RealScene>& realScenes() {
    static const std::vector<RealScene> scenes = {{"ship", "dutch_ship_medium/dutch_ship_medium_1k.gltf"},
                                                  {"chair", "MixedLightingExample/MixedLightingExample.gltf"},
                                                  {"cubes", "Cubes/Cubes.glb"}};
    return scenes;
}

std::filesystem::path sharedScenesDir() {
    if (const char* env = std::getenv("AGAA_SHARED_SCENES")) return env;
#ifdef AGAA_SHARED_SCENES_DIR
    return AGAA_SHARED_SCENES_DIR;
#else
    return "../shared/scenes";
#endif
}

std::optional<std::filesystem::path> realScenePath(const std::string& name) {
    for (const RealScene& s : realScenes())
        if (s.name == name) {
            const std::filesystem::path file = sharedScenesDir() / s.file;
            std::error_code ec;
            if (std::filesystem::is_regular_file(file, ec)) return file;
        }
    return std::nullopt;
}

} // namespace agaa::bench
