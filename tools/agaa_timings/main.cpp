// agaa-timings: per-pass GPU times of several methods on the same scene, in one process and
// one run, with the ratios the paper reports (AGAA vs its peers): shading ratio, frame ratio,
// bytes-per-pixel ratio. Pipelines are warmed up first (lavapipe JIT-compiles on first
// use); every time is the median over the timed frames. A benchmark, not a test: it prints,
// it asserts nothing about speed.
//
//   agaa-timings [--scenes foliage,furball] [--size 640x360] [--frames 5] [--warmup 2] [--rounds R]
//                [--jobs reference:8,agaa:8:2,simple-complex:8] [--breakdown] [--validate] [--json FILE]
//                [--extra-lights K[,K...]] [--METHOD-SETTING VALUE...]
// --rounds R: the job list rendered R times in turn, and every ratio taken within each round, then
// its median over the rounds. A machine whose speed drifts between jobs (lavapipe on a shared CPU:
// one pass's median moved by up to 40 % between runs of one binary) then moves both jobs of a
// ratio alike; the per-job detail printed is the first round's.
// --extra-lights: each scene once per K, with K generated point lights added
// (engine/scene/extra_lights.h); results of K > 0 are keyed "<scene>+l<K>".
// A job is METHOD[:N[:C]][:SETTING=VALUE...] (sbaa:N:S, streaming:N:S: S surfaces), SETTING any
// method setting the method reads (agaa/method_settings.h, as agaa-render's flags name them),
// e.g. agaa:8:2:agaa-lighting=registers:agaa-routing=fragment. A method setting given as a flag
// (--sample-rate-shading on) applies to every job that reads it; a job's own settings win.
// Every method whose name starts with "agaa" (agaa, agaa-accumulate, agaa-samples) is an AGAA job.
// For every AGAA job it prints, next to the shading/frame ratios against each peer at the same n:
//   - shading ms per shading event per pixel against the peer's (against the reference's: what
//     one aggregate costs to light against one sample), AGAA's shading being its lighting pass and
//     the per-sample pass of the pixels its shading rate flags, whose events count too; and the
//     same against no-AA's (needs a noaa job);
//   - visibility + generation against the per-sample G-buffer pass of Simple/Complex (or of the
//     reference) at the same n: the cost of AGAA's two raster passes against the one they replace;
//   - with --breakdown, where each AGAA pass's time goes, from runs that each remove one part
//     (the part-removed builds of breakdown_builds.h): lighting = shading + the rest, and
//     shading = the shadow footprint's taps + lights and lobes;
//     generation = atomics and routing + material + raster/depth/stencil; visibility = face-normal
//     encoding + the rest. Differences of medians: read them as estimates, not exact sums.
// Exit codes: 0 done; 2 bad arguments; 3 the device lacks something required.

#include "agaa/method_settings.h"
#include "agaa/methods.h"
#include "engine/scene/extra_lights.h"
#include "engine/scene/scene_error.h"
#include "engine/vk/check.h"
#include "tools/agaa_timings/breakdown_builds.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Job {
    std::string method;
    uint32_t samples = 8, aggregates = 2;
    uint32_t surfaces = 0; // sbaa:N:S, streaming:N:S; 0 = the method's default (4, 3)
    std::vector<std::pair<std::string, std::string>> options; // SETTING=VALUE (agaa/method_settings.h)
    bool isAgaa() const { return method.rfind("agaa", 0) == 0; }
    std::string label() const {
        std::string l = method + " n=" + std::to_string(samples);
        if (method == "sbaa" || method == "streaming")
            return l + " S=" + std::to_string(surfaces ? surfaces : method == "sbaa" ? 4u : 3u);
        if (!isAgaa()) return l;
        l += " c=" + std::to_string(aggregates);
        for (const auto& [k, v] : options)
            l += " " + k + "=" + v;
        return l;
    }
};

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    for (std::string item; std::getline(ss, item, sep);)
        if (!item.empty()) out.push_back(item);
    return out;
}

uint32_t number(const std::string& flag, const std::string& v, uint32_t lo, uint32_t hi) {
    uint32_t x = 0;
    auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
    if (ec != std::errc() || p != v.data() + v.size() || x < lo || x > hi)
        throw std::invalid_argument(flag + " '" + v + "' is not an integer in " + std::to_string(lo) + ".." +
                                    std::to_string(hi));
    return x;
}

Job parseJob(const std::string& text) {
    auto parts = split(text, ':');
    if (parts.empty() || !agaa::isKnownMethod(parts[0]))
        throw std::invalid_argument("--jobs entry '" + text +
                                    "' is not METHOD[:N[:C]][:KEY=VALUE...] with METHOD one of " +
                                    agaa::knownMethodNames());
    Job j;
    j.method = parts[0];
    size_t i = 1;
    if (i < parts.size() && parts[i].find('=') == std::string::npos)
        j.samples = number("--jobs samples", parts[i++], 1, 32);
    if (i < parts.size() && parts[i].find('=') == std::string::npos) {
        if (j.method == "sbaa")
            j.surfaces = number("--jobs surfaces", parts[i++], 1, 6); // sbaa:N:S
        else if (j.method == "streaming")
            j.surfaces = number("--jobs surfaces", parts[i++], 1, 3); // streaming:N:S
        else
            j.aggregates = number("--jobs aggregates", parts[i++], 1, 4);
    }
    agaa::MethodSettings probe;
    for (; i < parts.size(); ++i) {
        const size_t eq = parts[i].find('=');
        const std::string key = parts[i].substr(0, eq);
        const agaa::MethodOption* option = eq == std::string::npos ? nullptr : agaa::findMethodOption(key);
        if (!option || !agaa::methodReadsOption(*option, j.method))
            throw std::invalid_argument("--jobs entry '" + text + "': '" + parts[i] +
                                        "' is not SETTING=VALUE with SETTING a method setting " + j.method +
                                        " reads (agaa-render --help, 'method settings')");
        agaa::setMethodOption(probe, *option, parts[i].substr(eq + 1)); // names the allowed values
        j.options.push_back({key, parts[i].substr(eq + 1)});
    }
    return j;
}

// The time of the pass named `name`, or 0 when the result has none.
double passMs(const agaa::RenderResult& r, const std::string& name) {
    for (const auto& p : r.passes)
        if (p.name == name) return p.gpuMs;
    return 0.0;
}

// The shading of a method: its lighting pass (the pass whose name ends in ".lighting") and the
// passes under it (AGAA's per-sample pass for the pixels its shading rate flags,
// "agaa.lighting.perSample"), whose shading events the events per pixel count too.
double shadingMs(const agaa::RenderResult& r) {
    double sum = 0.0;
    for (const auto& p : r.passes) {
        const size_t at = p.name.find(".lighting");
        if (at == std::string::npos) continue;
        const size_t end = at + 9;
        if (end == p.name.size() || p.name[end] == '.') sum += p.gpuMs;
    }
    return sum;
}

// Shading ms per shading event per pixel of `a` over `b`'s: what one event costs to light, the
// issue's per-event figure against the reference (one event a sample).
double perEventCost(const agaa::RenderResult& a, const agaa::RenderResult& b) {
    if (a.shadingEventsMean <= 0 || b.shadingEventsMean <= 0 || shadingMs(b) <= 0) return 0.0;
    return (shadingMs(a) / a.shadingEventsMean) / (shadingMs(b) / b.shadingEventsMean);
}

// The technique's frame: every pass but the tool's readbacks.
double frameMs(const agaa::RenderResult& r) {
    double sum = 0.0;
    for (const auto& p : r.passes)
        if (p.name.rfind("readback.", 0) != 0) sum += p.gpuMs;
    return sum;
}

// The ratios printed: every AGAA job against every peer at the same n.
bool isPeer(const Job& agaaJob, const Job& peer) {
    return agaaJob.isAgaa() && !peer.isAgaa() && peer.samples == agaaJob.samples;
}

// Rounds 2..R of --rounds: every job again, in the same order, so that a drift in the machine's
// speed falls on the jobs of a round alike; each ratio is taken within a round (the first is
// `first`, the run already printed) and its median over the rounds printed and kept in `ratios`.
template <typename Request>
void timeRounds(agaa::FrameRenderer& renderer, const std::vector<Job>& jobs, const Request& request,
                const std::map<std::string, agaa::RenderResult>& first, uint32_t rounds,
                nlohmann::json& ratios) {
    std::map<std::string, std::vector<double>> frame, shading, perEvent; // per "A vs B": one a round
    auto addRound = [&](const std::map<std::string, agaa::RenderResult>& results) {
        for (const Job& a : jobs)
            for (const Job& b : jobs) {
                if (!isPeer(a, b)) continue;
                const agaa::RenderResult &ra = results.at(a.label()), &rb = results.at(b.label());
                const std::string key = a.label() + " vs " + b.label();
                frame[key].push_back(frameMs(rb) / frameMs(ra));
                shading[key].push_back(shadingMs(ra) > 0 ? shadingMs(rb) / shadingMs(ra) : 0.0);
                perEvent[key].push_back(perEventCost(ra, rb));
            }
    };
    addRound(first);
    for (uint32_t round = 2; round <= rounds; ++round) {
        std::map<std::string, agaa::RenderResult> results;
        for (const Job& job : jobs)
            results[job.label()] = renderer.render(request(job));
        addRound(results);
    }
    for (const auto& [key, f] : frame) {
        const std::vector<double>&sh = shading[key], &pe = perEvent[key];
        const auto [fmin, fmax] = std::minmax_element(f.begin(), f.end());
        std::printf("  %s over %u rounds: frame %.2fx faster (median; %.2fx to %.2fx), shading %.2fx, "
                    "%.2fx the cost per shading event\n",
                    key.c_str(), rounds, agaa::median(f), *fmin, *fmax, agaa::median(sh), agaa::median(pe));
        ratios[key]["frame_speedup_rounds"] = f;
        ratios[key]["shading_speedup_rounds"] = sh;
        ratios[key]["per_event_cost_rounds"] = pe;
        ratios[key]["frame_speedup_median"] = agaa::median(f);
        ratios[key]["shading_speedup_median"] = agaa::median(sh);
        ratios[key]["per_event_cost_median"] = agaa::median(pe);
    }
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> scenes = {"foliage", "furball"};
    uint32_t width = 640, height = 360, frames = 5, warmup = 2, rounds = 1;
    std::vector<uint32_t> extraLights = {0};
    std::vector<Job> jobs = {{"reference", 8, 1}, {"agaa", 8, 2}};
    if (agaa::isKnownMethod("simple-complex")) jobs.push_back({"simple-complex", 8, 1});
    bool validate = false, breakdown = false;
    agaa::MethodSettings every; // the method settings given as flags: every job that reads them
    std::vector<const agaa::MethodOption*> given;
    std::string jsonPath;
    try {
        for (int i = 1; i < argc; ++i) {
            std::string a = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
                return argv[++i];
            };
            if (a == "--scenes")
                scenes = split(value(), ',');
            else if (a == "--size") {
                auto wh = split(value(), 'x');
                if (wh.size() != 2) throw std::invalid_argument("--size must be WxH, e.g. 1280x720");
                width = number("--size width", wh[0], 1, 8192);
                height = number("--size height", wh[1], 1, 8192);
            } else if (a == "--frames")
                frames = number(a, value(), 1, 1000);
            else if (a == "--warmup")
                warmup = number(a, value(), 0, 1000);
            else if (a == "--rounds")
                rounds = number(a, value(), 1, 100);
            else if (a == "--jobs") {
                jobs.clear();
                for (const auto& j : split(value(), ','))
                    jobs.push_back(parseJob(j));
            } else if (a == "--validate")
                validate = true;
            else if (a == "--breakdown")
                breakdown = true;
            else if (const agaa::MethodOption* option =
                         a.rfind("--", 0) == 0 ? agaa::findMethodOption(a.substr(2)) : nullptr) {
                const std::string v = value();
                if (option->name == "samples" || option->name == "aggregates" || option->name == "surfaces")
                    throw std::invalid_argument(a + " is a job's N, C or S: --jobs METHOD:N:C (sbaa:N:S)");
                agaa::setMethodOption(every, *option, v);
                given.push_back(option);
            } else if (a == "--extra-lights") {
                extraLights.clear();
                for (const auto& k : split(value(), ','))
                    extraLights.push_back(number(a, k, 0, eng::scene::kMaxExtraLights));
                if (extraLights.empty()) throw std::invalid_argument("--extra-lights needs at least one K");
            } else if (a == "--json")
                jsonPath = value();
            else if (a == "--help" || a == "-h") {
                std::printf(
                    "usage: agaa-timings [--scenes a,b] [--size WxH] [--frames K] [--warmup K] [--rounds R]\n"
                    "                    [--jobs METHOD[:N[:C]][:SETTING=VALUE...],...] [--breakdown] "
                    "[--validate]\n"
                    "                    [--json FILE] [--extra-lights K[,K...]] [--SETTING VALUE...]\n"
                    "--rounds R: the jobs rendered R times in turn (1..100, default 1); each ratio is also\n"
                    "taken within every round and its median over the rounds printed\n"
                    "SETTING: a method setting of agaa-render's, as a job's SETTING=VALUE or as a flag\n"
                    "for every job that reads it:\n%s\n"
                    "methods: %s; scenes: builtin kinds\n",
                    agaa::methodOptionsSynopsis(2, 100).c_str(), agaa::knownMethodNames().c_str());
                return 0;
            } else
                throw std::invalid_argument("unknown argument '" + a + "' (see --help)");
        }
        eng::vk::DeviceOptions options;
        options.validation = validate;
        eng::vk::Device device(options);
        nlohmann::json out;
        out["device"] = device.caps().deviceName;
        out["size"] = {width, height};
        out["frames"] = frames;
        out["warmup"] = warmup;
        out["rounds"] = rounds;
        std::printf("device: %s, %ux%u, median of %u frames after %u warm-up frames, %u round(s)\n",
                    device.caps().deviceName.c_str(), width, height, frames, warmup, rounds);
        for (const std::string& sceneName : scenes)
            for (uint32_t lights : extraLights) {
                const std::string name = lights == 0 ? sceneName : sceneName + "+l" + std::to_string(lights);
                eng::scene::Scene scene = eng::scene::loadTestScene(sceneName);
                eng::scene::addExtraLights(scene, lights);
                agaa::FrameRenderer renderer(device, scene);
                std::map<std::string, agaa::RenderResult> results;
                std::printf("\n== %s (%u triangles, %zu lights)\n", name.c_str(), scene.triangleCount(),
                            scene.lights.size());
                auto request = [&](const Job& job) {
                    agaa::RenderRequest r;
                    r.method = job.method;
                    for (const agaa::MethodOption* option : given)
                        if (agaa::methodReadsOption(*option, job.method))
                            option->set(r.settings, option->get(every));
                    r.settings.samples = job.samples;
                    r.settings.aggregates = job.aggregates;
                    r.settings.surfaces = job.surfaces;
                    for (const auto& [k, v] : job.options)
                        agaa::setMethodOption(r.settings, *agaa::findMethodOption(k), v);
                    r.view.width = width;
                    r.view.height = height;
                    r.warmupFrames = warmup;
                    r.timedFrames = frames;
                    return r;
                };
                for (const Job& job : jobs) {
                    agaa::RenderResult res = renderer.render(request(job));
                    std::printf("  %-26s frame %9.2f ms  bytes/px %7.1f  events/px %.2f (max %u)\n",
                                job.label().c_str(), frameMs(res), res.bytesPerPixel, res.shadingEventsMean,
                                res.shadingEventsMax);
                    nlohmann::json passes = nlohmann::json::object();
                    for (const auto& p : res.passes) {
                        if (p.name.rfind("readback.", 0) == 0) continue;
                        std::printf("      %-28s %9.2f ms\n", p.name.c_str(), p.gpuMs);
                        passes[p.name] = p.gpuMs;
                    }
                    nlohmann::json variants = nlohmann::json::object();
                    for (const auto& v : res.variants)
                        variants[v.effect] = v.variant;
                    out["scenes"][name][job.label()] = {{"frame_ms", frameMs(res)},
                                                        {"shading_ms", shadingMs(res)},
                                                        {"bytes_per_pixel", res.bytesPerPixel},
                                                        {"events_per_pixel", res.shadingEventsMean},
                                                        {"passes", passes},
                                                        {"variants", variants}};
                    if (res.lostCoverageFraction) {
                        std::printf("      lost coverage: %.4f of the samples, %llu pixels\n",
                                    *res.lostCoverageFraction,
                                    static_cast<unsigned long long>(res.pixelsWithLostCoverage));
                        out["scenes"][name][job.label()]["lost_coverage"] = *res.lostCoverageFraction;
                    }
                    if (breakdown && job.isAgaa()) {
                        namespace parts = agaa::timings;
                        auto without = [&](agaa::ProgramOverrides builds) {
                            agaa::RenderRequest r = request(job);
                            r.settings.agaa.programs = std::move(builds);
                            return renderer.render(r);
                        };
                        agaa::RenderResult noShading = without(parts::lightingWithoutShading());
                        agaa::RenderResult noShadowFilter = without(parts::lightingWithoutShadowFilter());
                        agaa::RenderResult noAtomics =
                            without(parts::generationWithoutAtomicsVisibilityWithoutNormals());
                        agaa::RenderResult empty = without(parts::generationEmpty());
                        // The lighting pass alone: the per-sample pass runs in both builds.
                        const double lighting = passMs(res, "agaa.lighting"),
                                     prologue = passMs(noShading, "agaa.lighting"),
                                     unshadowed = passMs(noShadowFilter, "agaa.lighting");
                        const double generation = passMs(res, "agaa.generation");
                        const double material = passMs(noAtomics, "agaa.generation");
                        const double raster = passMs(empty, "agaa.generation");
                        const double visibility = passMs(res, "agaa.visibility");
                        const double noNormals = passMs(noAtomics, "agaa.visibility");
                        std::printf(
                            "      breakdown: lighting %.2f = shading %.2f + the rest %.2f (sample walk, "
                            "normalisation, culling, resolve)\n",
                            lighting, lighting - prologue, prologue);
                        std::printf("      breakdown: shading %.2f = shadow-map taps %.2f (the footprint, "
                                    "--shadow-footprint) + lights and lobes %.2f\n",
                                    lighting - prologue, lighting - unshadowed, unshadowed - prologue);
                        std::printf(
                            "      breakdown: generation %.2f = atomics and routing %.2f + material %.2f + "
                            "raster, depth and stencil %.2f\n",
                            generation, generation - material, material - raster, raster);
                        std::printf(
                            "      breakdown: visibility %.2f = face-normal encoding %.2f + the rest %.2f\n",
                            visibility, visibility - noNormals, noNormals);
                        out["scenes"][name][job.label()]["breakdown_ms"] = {
                            {"lighting_shading", lighting - prologue},
                            {"lighting_rest", prologue},
                            {"lighting_shadow_taps", lighting - unshadowed},
                            {"generation_atomics", generation - material},
                            {"generation_material", material - raster},
                            {"generation_raster", raster},
                            {"visibility_normals", visibility - noNormals},
                            {"visibility_rest", noNormals}};
                    }
                    results[job.label()] = std::move(res);
                }
                // Ratios of every AGAA job against every peer at the same n.
                const agaa::RenderResult* noaa = nullptr;
                for (const Job& b : jobs)
                    if (b.method == "noaa") noaa = &results[b.label()];
                for (const Job& a : jobs) {
                    if (!a.isAgaa()) continue;
                    const auto& ra = results[a.label()];
                    nlohmann::json& ratios = out["scenes"][name]["ratios"];
                    if (const double perEvent = noaa ? perEventCost(ra, *noaa) : 0.0; perEvent > 0) {
                        std::printf("  %s: lighting ms per shading event %.2fx no-AA's (%.2f vs %.2f ms per "
                                    "event/px)\n",
                                    a.label().c_str(), perEvent, shadingMs(ra) / ra.shadingEventsMean,
                                    shadingMs(*noaa) / noaa->shadingEventsMean);
                        ratios[a.label() + " per event vs noaa"] = perEvent;
                    }
                    for (const Job& b : jobs) {
                        if (!isPeer(a, b)) continue;
                        const auto& rb = results[b.label()];
                        double shading = shadingMs(ra) > 0 ? shadingMs(rb) / shadingMs(ra) : 0.0;
                        double frame = frameMs(rb) / frameMs(ra);
                        double bytes = ra.bytesPerPixel / rb.bytesPerPixel;
                        double perEvent = perEventCost(ra, rb);
                        std::printf(
                            "  %s vs %s: shading %.2fx faster (%.2fx the cost per shading event), frame "
                            "%.2fx faster, bytes/px %.3fx\n",
                            a.label().c_str(), b.label().c_str(), shading, perEvent, frame, bytes);
                        nlohmann::json entry = {{"shading_speedup", shading},
                                                {"per_event_cost", perEvent},
                                                {"frame_speedup", frame},
                                                {"bytes_ratio", bytes}};
                        // The peer's raster passes: its G-buffer, and SBAA's second geometry pass.
                        double gbuffer = passMs(rb, b.method + ".gbuffer") + passMs(rb, b.method + ".fill");
                        if (gbuffer > 0) {
                            // Accumulate: prepass + accumulation kernel; samples: its one G-buffer pass.
                            double raster = passMs(ra, "agaa.visibility") + passMs(ra, "agaa.generation") +
                                            passMs(ra, "agaa.gbuffer");
                            std::printf("      AGAA raster passes %.2f ms = %.2fx %s's (%.2f ms)\n", raster,
                                        raster / gbuffer, b.method.c_str(), gbuffer);
                            entry["raster_ratio"] = raster / gbuffer;
                        }
                        ratios[a.label() + " vs " + b.label()] = entry;
                    }
                }
                if (rounds > 1)
                    timeRounds(renderer, jobs, request, results, rounds, out["scenes"][name]["ratios"]);
            }
        if (device.validationErrors()) {
            std::fprintf(stderr, "agaa-timings: %u validation error(s)\n", device.validationErrors());
            return 1;
        }
        if (!jsonPath.empty()) std::ofstream(jsonPath) << out.dump(2) << "\n";
    } catch (const eng::vk::MissingCapability& e) {
        std::fprintf(stderr, "agaa-timings: the device lacks a required capability: %s\n", e.what());
        return 3;
    } catch (const std::invalid_argument& e) {
        std::fprintf(stderr, "agaa-timings: %s\n", e.what());
        return 2;
    } catch (const eng::scene::SceneError& e) {
        std::fprintf(stderr, "agaa-timings: %s\n", e.what());
        return 2;
    }
    return 0;
}
