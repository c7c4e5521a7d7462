#pragma once
// What a benchmark run measures: the sweep settings taken from the command line
// and the list of jobs they expand to (scene x method x the settings the method
// takes). A job's id names its JSON file, so sweeps split with --job I/N land in
// files that merge without clashes.

#include "agaa/method_settings.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace agaa::bench {

struct SweepSettings {
    std::vector<std::string> scenes;
    std::vector<std::string> methods;
    std::vector<uint32_t> samples;    // n, for methods that take it
    std::vector<uint32_t> aggregates; // c, for methods that take it
    // S, for methods that take it (SBAA, streaming), each kept to the method's range; empty: each
    // method's default.
    std::vector<uint32_t> surfaces;
    // AGAA's shading-rate tolerance (--tolerances; --agaa-tolerance's values, "auto", "never" or
    // T), for the methods that read it; empty: not an axis.
    std::vector<std::string> tolerances;
    // Geometric specular anti-aliasing (--specular-aa off,on; --curvature-roughness): every job once
    // per value; {false}: not an axis (the jobs take --curvature-roughness as given, if given).
    std::vector<bool> specularAA = {false};
    // The light-count axis (--extra-lights): every scene once per K, with K generated point lights.
    std::vector<uint32_t> extraLights = {0};
    uint32_t width = 160;
    uint32_t height = 90;
    uint32_t timedFrames = 3;
    uint32_t warmupFrames = 1;
    // The converged truth (tools/harness/converged_truth.h): the reference at n = 32 with sample-rate
    // shading, k x k sub-pixel tiles; cached in truthCache (default DIR/truth-cache).
    uint32_t truthSupersampling = 4;
    std::filesystem::path truthCache;
    uint32_t temporalFrames = 5; // camera path length for temporal stability; 0 = not measured
    // The path (--temporal-path): an orbit about the bounds' centre in temporalStepDegrees steps,
    // or a truck sideways across the scene (eng::frame::truckView) in steps of
    // temporalTruckFraction of the bounds' diagonal.
    enum class TemporalPath { Orbit, Truck } temporalPath = TemporalPath::Orbit;
    float temporalStepDegrees = 0.5f;
    float temporalTruckFraction = 0.01f;
    uint32_t temporalMaxWidth = 320; // the path renders at the sweep size scaled down to this width
    bool validate = false;
    // The method settings given as flags (agaa/method_settings.h, agaa-render's), by name, each
    // applied to every job whose method reads it (the same-n reference's included; the converged
    // truth is always the reference at n = 32 with sample-rate shading). n, c and S are the
    // plan's axes, not among them.
    agaa::MethodSettings methodSettings;
    std::vector<std::string> givenSettings;
};

// n and c of a method that does not take them: n is the single sample it renders, c is 0 (none).
inline constexpr uint32_t kSamplesWhenUnused = 1;
inline constexpr uint32_t kAggregatesWhenUnused = 0;

struct Job {
    size_t index = 0; // position in the full plan (before --job slicing)
    std::string scene;
    std::string method;
    uint32_t samples = kSamplesWhenUnused;
    uint32_t aggregates = kAggregatesWhenUnused;
    bool usesSamples = false;
    bool usesAggregates = false;
    uint32_t surfaces = 0;   // S of the methods that take it (SBAA, streaming); 0 = none
    std::string tolerance;   // AGAA's --agaa-tolerance on the tolerance axis; empty: its default (auto)
    bool specularAA = false; // --curvature-roughness on (the --specular-aa axis)

    // "<scene>__<method>__n<N>__c<C>", then "__s<S>" for methods that take S, "__t<T>" on the
    // tolerance axis, "__saa" with specular anti-aliasing
    std::string id() const;
    // The method's name with what the axes added: "fxaa + specular AA", "agaa T30".
    std::string label() const;
};

std::string jobId(const std::string& scene, const std::string& method, uint32_t samples, uint32_t aggregates,
                  uint32_t surfaces = 0, const std::string& tolerance = "", bool specularAA = false);

// The light-count axis: a scene with K generated point lights (engine/scene/extra_lights.h) is the
// scene variant "<scene>+l<K>" in job ids, results and the report; K = 0 is the scene itself, so
// sweeps without the axis keep their ids.
std::string sceneWithLights(const std::string& scene, uint32_t extraLights);
struct SceneVariant {
    std::string base;
    uint32_t extraLights = 0;
};
// "foliage+l16" -> {foliage, 16}; a name without a well-formed "+l<K>" suffix is a base scene.
SceneVariant parseSceneVariant(const std::string& name);

// Scenes in the given order, each once per extra-light count (ascending); per scene, methods in the given
// order; per method, n ascending then c ascending, then S ascending (methods that take S: the
// sweep's surfaces within the method's range, or its default). Methods that take neither n nor c
// get one job per scene. Duplicates are dropped. Throws std::invalid_argument for an unknown method
// or for surfaces none of which a method that takes S allows.
std::vector<Job> planSweep(const SweepSettings& settings);

// --job I/N: run only the jobs whose plan index i satisfies i % N == I.
struct JobSlice {
    uint32_t index = 0;
    uint32_t count = 1;
    bool contains(size_t jobIndex) const { return jobIndex % count == index; }
    bool isWhole() const { return count == 1; }
};

// Parses "I/N" with N in 1..1024 and I < N; throws std::invalid_argument naming --job otherwise.
JobSlice parseJobSlice(const std::string& text);

// The size the temporal path renders at: the sweep size scaled down to temporalMaxWidth (aspect kept).
void temporalSize(const SweepSettings& settings, uint32_t& width, uint32_t& height);

// The scenes the default sweep covers (thin geometry, fur, foliage, metal, and the flat control).
// The built-ins the default sweep runs, then the real scenes of sharedScenesDir() that exist.
std::vector<std::string> defaultSweepScenes();

// Real third-party scenes (../shared/scenes, never copied into the repository), by the short
// name a sweep, its results and its file names use. They render with the lighting and exposure a
// user gets by default: lighting auto (engine/scene/default_lighting.h), exposure metered.
struct RealScene {
    std::string name; // e.g. "ship"
    std::string file; // relative to sharedScenesDir()
};
const std::vector<RealScene>& realScenes();
// $AGAA_SHARED_SCENES, else the folder configured at build time (AGAA_SHARED_SCENES_DIR).
std::filesystem::path sharedScenesDir();
// The file of a real scene's name, or nullopt when `name` is not one (or its file is missing).
std::optional<std::filesystem::path> realScenePath(const std::string& name);

} // namespace agaa::bench
