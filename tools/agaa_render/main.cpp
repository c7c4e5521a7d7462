// agaa-render: the headless renderer. Renders one frame of a glTF scene (or a
// built-in procedural scene) with one anti-aliasing method and writes the
// linear EXR, the tone-mapped PNG, and optionally stats JSON and the graph.
//
// Exit codes: 0 success; 2 bad arguments or bad input; 3 the device lacks something required.

#include "agaa/method_settings.h"
#include "agaa/methods.h"
#include "engine/frame/exposure.h"
#include "engine/frame/sample_pattern.h"
#include "engine/io/exr.h"
#include "engine/io/io_error.h"
#include "engine/io/png.h"
#include "engine/io/tone_map.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/extra_lights.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/scene_error.h"
#include "engine/vk/check.h"
#include "engine/vk/device.h"
#include "tools/harness/converged_truth.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitMissingCapability = 3;

struct BadArgument : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Options {
    std::optional<std::string> sceneFile;
    std::string builtin = "default";
    agaa::RenderRequest request;
    std::string out = "out/frame";
    std::optional<std::string> stats, graph;
    bool validate = false, caps = false, help = false;
    bool noShadowCasters = false; // --shadow-casters none
    bool builtinGiven = false;
    std::string device;
    uint32_t frames = 1, warmup = 0;
    // --exposure: none = the scene's own (built-in scenes: 1), else auto; "auto"; or a value.
    std::optional<std::string> exposure;
    std::string lights = "auto";
    uint32_t extraLights = 0; // --extra-lights: generated point lights (engine/scene/extra_lights.h)
    std::optional<std::string> environment;
    uint32_t truth =
        0; // --truth K: the converged truth, K x K sub-pixel tiles at n = 32, instead of --method
    std::optional<std::string> truthCache;
};

// The synopsis (the README's, checked by cli.readme_synopsis) and the flags' help: the method
// settings come from their one declaration (agaa/method_settings.h).
std::string usage() {
    constexpr size_t kIndent = 19, kWidth = 100; // "usage: agaa-render "
    const std::string pad(kIndent, ' ');
    return "usage: agaa-render [--scene FILE | --builtin NAME] [--method NAME] [--width W] [--height H]\n" +
           pad + "[--camera I] [--exposure auto|E] [--ev100 V] [--out PREFIX] [--stats FILE.json]\n" + pad +
           "[--lights auto|scene|fill|default|both] [--extra-lights K]\n" + pad +
           "[--environment FILE.exr] [--shadow-casters scene|none] [--graph FILE.dot]\n" + pad +
           "[--frames K] [--warmup K] [--truth K] [--truth-cache DIR] [--validate]\n" + pad +
           "[--device NAME] [--caps] [--help]\n" + agaa::methodOptionsSynopsis(kIndent, kWidth) +
           "\n"
           "\n"
           "  --scene FILE      glTF 2.0 scene (.gltf or .glb)\n"
           "  --builtin NAME    procedural scene (default: 'default')\n"
           "  --method NAME     anti-aliasing method (default: reference)\n"
           "  --width/--height  image size in pixels, 1..8192 (default 256x256)\n"
           "  --camera I        scene camera index (default 0)\n"
           "  --exposure auto|E  linear exposure E (1e-6..1e6), or auto: metered from the log-average "
           "luminance\n"
           "                    of a no-AA frame's covered pixels (EV100 = log2(L S / K), S = 100, K = "
           "12.5);\n"
           "                    default: the scene's own (built-in scenes: 1), else auto\n"
           "  --ev100 V         a physical camera's exposure value at ISO 100, -20..30 (sunny 16: 15):\n"
           "                    exposure = 1 / (1.2 * 2^V)\n"
           "  --lights auto|scene|fill|default|both  scene: the file's lights only; fill: them and a sky at\n"
           "                    1/4 of their illuminance; default: a 100 klux sun with shadows and a "
           "procedural\n"
           "                    sky instead; both: all of them; auto (default): fill when the scene has "
           "lights,\n"
           "                    else default\n"
           "  --extra-lights K  K generated point lights, 0..1000 (default 0): a Halton (2, 3, 5) sequence "
           "in\n"
           "                    the bounds grown by a tenth of their diagonal, each lighting its "
           "neighbourhood\n"
           "                    (half the mean spacing) like the key light; no shadows\n"
           "  --environment FILE.exr  equirectangular (2:1) environment lighting every method (diffuse SH +\n"
           "                    pre-filtered specular) and shown as the sky; replaces the default sky and "
           "its sun\n"
           "  --shadow-casters scene|none  none: the scene's lights cast no shadows (a scene without "
           "shadows)\n"
           "  --truth K         the converged ground truth instead of --method: the reference at n = 32 "
           "with\n"
           "                    materials shaded per sample, at K times the width and height in K^2 tiles,\n"
           "                    each K x K block averaged (32 K^2 samples a pixel), K in 1..16; prints its\n"
           "                    own error estimate (its two checkerboard halves' display RMSE / 2)\n"
           "  --truth-cache DIR  keep truths in DIR, keyed by scene, view, lights, exposure and binary\n"
           "  --out PREFIX      writes PREFIX.exr (linear HDR) and PREFIX.png (tone-mapped sRGB)\n"
           "  --stats FILE      per-pass GPU times, storage, shading events, validation errors as JSON\n"
           "  --graph FILE      compiled render graph as Graphviz DOT (and FILE.json)\n"
           "  --frames K        timed frames, per-pass times are medians (default 1); --warmup K untimed "
           "first\n"
           "  --validate        Khronos validation layer on (also AGAA_VALIDATE=1)\n"
           "  --device NAME     pick the Vulkan device whose name contains NAME\n"
           "  --caps            print the device's capabilities and exit\n"
           "\n"
           "method settings (each names the methods that read it):\n" +
           agaa::methodOptionsHelp(kWidth);
}

uint32_t parseUint(const std::string& flag, const std::string& value, uint32_t lo, uint32_t hi) {
    uint32_t v = 0;
    auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec != std::errc() || ptr != value.data() + value.size() || v < lo || v > hi)
        throw BadArgument(flag + " '" + value + "' is not an integer in " + std::to_string(lo) + ".." +
                          std::to_string(hi));
    return v;
}

float parseFloat(const std::string& flag, const std::string& value, float lo, float hi) {
    try {
        size_t used = 0;
        float v = std::stof(value, &used);
        if (used == value.size() && v >= lo && v <= hi) return v;
    } catch (const std::exception&) {
    }
    throw BadArgument(flag + " '" + value + "' is not a number in [" + std::to_string(lo) + ", " +
                      std::to_string(hi) + "]");
}

Options parse(int argc, char** argv) {
    Options o;
    auto& r = o.request;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw BadArgument(a + " needs a value");
            return argv[++i];
        };
        const agaa::MethodOption* option =
            a.rfind("--", 0) == 0 ? agaa::findMethodOption(a.substr(2)) : nullptr;
        if (option) {
            const std::string v = value();
            try {
                agaa::setMethodOption(r.settings, *option, v);
            } catch (const std::invalid_argument& e) {
                throw BadArgument(e.what());
            }
        } else if (a == "--help" || a == "-h")
            o.help = true;
        else if (a == "--scene")
            o.sceneFile = value();
        else if (a == "--builtin") {
            o.builtin = value();
            o.builtinGiven = true;
        } else if (a == "--method")
            r.method = value();
        else if (a == "--shadow-casters") {
            std::string v = value();
            if (v != "scene" && v != "none")
                throw BadArgument("--shadow-casters '" + v + "' is not one of: scene, none");
            o.noShadowCasters = v == "none";
        } else if (a == "--width")
            r.view.width = parseUint(a, value(), 1, 8192);
        else if (a == "--height")
            r.view.height = parseUint(a, value(), 1, 8192);
        else if (a == "--camera")
            r.view.camera = parseUint(a, value(), 0, 1u << 20);
        else if (a == "--exposure") {
            o.exposure = value();
            if (*o.exposure != "auto") r.view.exposure = parseFloat(a, *o.exposure, 1e-6f, 1e6f);
        } else if (a == "--ev100") {
            // A physical camera's exposure value at ISO 100 (engine/frame/exposure.h).
            o.exposure = "ev100";
            r.view.exposure = eng::frame::exposureFromEv100(parseFloat(a, value(), -20.0f, 30.0f));
        } else if (a == "--lights") {
            o.lights = value();
            eng::scene::parseLightingMode(o.lights); // refuses anything else, naming the values
        } else if (a == "--extra-lights")
            o.extraLights = parseUint(a, value(), 0, eng::scene::kMaxExtraLights);
        else if (a == "--environment")
            o.environment = value();
        else if (a == "--out")
            o.out = value();
        else if (a == "--stats")
            o.stats = value();
        else if (a == "--graph")
            o.graph = value();
        else if (a == "--frames")
            o.frames = parseUint(a, value(), 1, 1000);
        else if (a == "--warmup")
            o.warmup = parseUint(a, value(), 0, 1000);
        else if (a == "--truth")
            o.truth = parseUint(a, value(), 1, agaa::kMaxTruthSupersampling);
        else if (a == "--truth-cache")
            o.truthCache = value();
        else if (a == "--validate")
            o.validate = true;
        else if (a == "--device")
            o.device = value();
        else if (a == "--caps")
            o.caps = true;
        else
            throw BadArgument("unknown argument '" + a + "' (see --help)");
    }
    if (!agaa::isKnownMethod(r.method))
        throw BadArgument("--method '" + r.method + "' is unknown (known: " + agaa::knownMethodNames() + ")");
    if (!r.settings.debug.empty()) {
        std::string allowed;
        bool known = false;
        for (const auto& m : agaa::knownMethods())
            if (m.name == r.method)
                for (const auto& v : m.debugViews) {
                    allowed += (allowed.empty() ? "" : ", ") + v;
                    known |= v == r.settings.debug;
                }
        if (!known)
            throw BadArgument("--debug '" + r.settings.debug + "' is not a debug view of --method " +
                              r.method + " (allowed: " + (allowed.empty() ? std::string("none") : allowed) +
                              ")");
    }
    if (o.sceneFile && o.builtinGiven)
        throw BadArgument("--scene and --builtin both name a scene; give one of them");
    r.timedFrames = o.frames;
    r.warmupFrames = o.warmup;
    return o;
}

// Creates the folder an output goes to, before anything renders; a parent that is a file (or
// cannot be created) is the user's input, refused with the flag and the path.
void prepareOutputFolder(const std::string& flag, const std::filesystem::path& path) {
    if (!path.has_parent_path()) return;
    const std::filesystem::path parent = path.parent_path();
    std::error_code ec;
    std::filesystem::create_directories(parent, ec);
    if (ec || !std::filesystem::is_directory(parent))
        throw BadArgument(flag + " '" + path.string() + "': cannot use '" + parent.string() +
                          "' as its folder (" + (ec ? ec.message() : std::string("not a directory")) + ")");
}

void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream f(path); // its folder: prepareOutputFolder, before rendering
    if (!f) throw eng::io::IoError("cannot write " + path.string());
    f << text;
}

nlohmann::json statsJson(const Options& o, const agaa::RenderResult& r, const eng::vk::Device& device) {
    nlohmann::json j;
    j["method"] = o.request.method;
    j["scene"] = o.sceneFile ? *o.sceneFile : "builtin:" + o.builtin;
    j["samples"] = r.samples;
    j["aggregates"] = o.request.settings.aggregates;
    j["width"] = o.request.view.width;
    j["height"] = o.request.view.height;
    j["device"] = device.caps().deviceName;
    j["extra_lights"] = o.extraLights;
    if (o.request.method == "sbaa" || o.request.method == "streaming")
        j["surfaces"] = o.request.settings.surfaces  ? o.request.settings.surfaces
                        : o.request.method == "sbaa" ? 4u
                                                     : 3u;
    if (r.lostCoverageFraction)
        j["lost_coverage"] = {{"fraction_of_samples", *r.lostCoverageFraction},
                              {"pixels", r.pixelsWithLostCoverage}};
    if (r.perSampleShading)
        j["shading_rate"] = {{"per_sample_pixels", r.perSampleShading->pixels},
                             {"per_sample_samples", r.perSampleShading->samples},
                             {"per_sample_events", r.perSampleShading->events}};
    j["frames_timed"] = o.frames;
    j["frames_warmup"] = o.warmup;
    j["passes"] = nlohmann::json::array();
    for (size_t i = 0; i < r.passes.size(); ++i)
        j["passes"].push_back({{"name", r.passes[i].name},
                               {"gpu_ms", r.passes[i].gpuMs},
                               {"gpu_ms_samples", r.passSamples[i]}});
    j["passes_culled"] = r.culledPasses;
    j["frame_gpu_ms"] = r.frameGpuMs;
    j["bytes_per_pixel"] = r.bytesPerPixel;
    j["storage_bytes"] = r.storageBytes;
    j["bytes_per_pixel_split"] = r.bytesPerPixelSplit;
    j["transient_bytes_per_pixel"] = r.transientBytesPerPixel;
    j["transient_bytes_requested"] = r.transientBytesRequested;
    j["transient_bytes_allocated"] = r.transientBytesAllocated;
    j["aliasing_saved_bytes"] = r.aliasingSavedBytes;
    j["shading_events_per_pixel"] = {
        {"mean", r.shadingEventsMean}, {"max", r.shadingEventsMax}, {"histogram", r.shadingEventsHistogram}};
    // AGAA lights each aggregate once: its shading events are its aggregates.
    if (o.request.method == "agaa") j["aggregates_per_pixel_histogram"] = r.shadingEventsHistogram;
    // Scene-driven effects (agaa/common/effects.h): the features and each variant with its cause.
    j["features"] = r.features;
    j["exposure"] = r.exposure;
    if (r.meteredEv100) j["ev100"] = *r.meteredEv100;
    j["effects"] = o.request.settings.effects.forceAll ? "all" : "scene";
    // Every method setting the method reads, in agaa-render's words (agaa/method_settings.h).
    j["settings"] = nlohmann::json::object();
    for (const agaa::MethodOption& option : agaa::methodOptions())
        if (agaa::methodReadsOption(option, o.request.method))
            j["settings"][option.name] = option.get(o.request.settings);
    j["variants"] = nlohmann::json::array();
    for (const agaa::VariantChoice& v : r.variants)
        j["variants"].push_back({{"effect", v.effect}, {"variant", v.variant}, {"cause", v.cause}});
    j["passes_run"] = nlohmann::json::array();
    for (const auto& p : r.passes)
        j["passes_run"].push_back(p.name);
    j["validation_errors"] = device.validationErrors();
    j["validation_enabled"] = device.validationEnabled();
    return j;
}

int renderTruth(const Options& o, agaa::FrameRenderer& renderer, const agaa::RenderRequest& request,
                eng::vk::Device& device) {
    agaa::TruthSettings settings;
    settings.supersampling = o.truth;
    std::optional<agaa::TruthCache> cache;
    if (o.truthCache) cache.emplace(*o.truthCache);
    const agaa::ConvergedTruth t =
        agaa::renderConvergedTruth(renderer, request, settings, cache ? &*cache : nullptr);
    std::filesystem::path prefix(o.out);
    eng::io::writeExr(prefix.string() + ".exr", t.hdr);
    eng::io::writePng(prefix.string() + ".png", eng::io::quantizeToU8(eng::io::srgbEncoded(t.display)));
    std::cout << "wrote " << prefix.string() << ".exr and " << prefix.string()
              << ".png (converged truth: " << settings.supersampling << "x" << settings.supersampling
              << " tiles at n=" << settings.samples << ", "
              << settings.samples * settings.supersampling * settings.supersampling << " samples a pixel, "
              << request.view.width << "x" << request.view.height << ", exposure " << t.exposure
              << (t.fromCache ? ", from the cache" : "") << ")\n"
              << "truth error estimate (display RMSE): " << t.errorEstimate << "; linear mean luminance "
              << t.meanLuminance << "\n";
    if (o.stats) {
        nlohmann::json j;
        j["method"] = "truth";
        j["supersampling"] = settings.supersampling;
        j["samples"] = settings.samples;
        j["width"] = request.view.width;
        j["height"] = request.view.height;
        j["exposure"] = t.exposure;
        j["error_estimate"] =
            std::isfinite(t.errorEstimate) ? nlohmann::json(t.errorEstimate) : nlohmann::json();
        j["mean_luminance"] = t.meanLuminance;
        j["from_cache"] = t.fromCache;
        j["key"] = t.key;
        j["validation_errors"] = device.validationErrors();
        writeText(*o.stats, j.dump(2) + "\n");
        std::cout << "wrote " << *o.stats << "\n";
    }
    if (device.validationErrors() > 0) {
        std::cerr << "agaa-render: " << device.validationErrors() << " validation error(s)\n";
        return 1;
    }
    return 0;
}

int renderWith(const Options& o, eng::vk::Device& device) {
    if (o.caps) {
        std::cout << device.caps().describe();
        return 0;
    }
    eng::scene::Scene scene =
        o.sceneFile ? eng::scene::loadGltf(*o.sceneFile) : eng::scene::loadTestScene(o.builtin);
    for (const std::string& w : scene.stats.warnings)
        std::cerr << "warning: " << w << "\n";
    if (o.noShadowCasters)
        for (eng::scene::Light& light : scene.lights)
            light.castsShadows = false;
    if (o.request.view.camera >= scene.cameras.size())
        throw BadArgument("--camera " + std::to_string(o.request.view.camera) +
                          " is out of range (the scene has " + std::to_string(scene.cameras.size()) +
                          " camera(s))");
    std::optional<eng::scene::Environment> environment;
    if (o.environment) {
        const eng::io::ImageF map = eng::io::readExr(*o.environment);
        environment = eng::scene::environmentFromEquirect(*o.environment, map.width, map.height, map.rgba);
    }
    eng::scene::applyLighting(scene, eng::scene::parseLightingMode(o.lights), std::move(environment),
                              o.request.view.camera);
    eng::scene::addExtraLights(scene, o.extraLights); // after the sun, so it can be the key light

    agaa::RenderRequest request = o.request;
    // Physical exposure: the scene's own when it gives one and --exposure does not, else metered.
    request.autoExposure = o.exposure ? *o.exposure == "auto" : !scene.exposure.has_value();
    if (!o.exposure && scene.exposure) request.view.exposure = *scene.exposure;
    agaa::FrameRenderer renderer(device, scene);
    if (o.truth > 0) return renderTruth(o, renderer, request, device);
    agaa::RenderResult r = renderer.render(request);
    if (!eng::io::allFinite(r.hdr) || !eng::io::allFinite(r.display)) {
        std::cerr << "agaa-render: internal error: the frame contains NaN or Inf; nothing written\n";
        return 1;
    }
    std::filesystem::path prefix(o.out);
    eng::io::writeExr(prefix.string() + ".exr", r.hdr);
    eng::io::writePng(prefix.string() + ".png", eng::io::quantizeToU8(eng::io::srgbEncoded(r.display)));
    std::cout << "wrote " << prefix.string() << ".exr and " << prefix.string() << ".png (" << o.request.method
              << ", n=" << r.samples << ", " << o.request.view.width << "x" << o.request.view.height << ", "
              << scene.triangleCount() << " triangles, frame " << r.frameGpuMs << " ms on "
              << device.caps().deviceName << ")\n";
    if (o.stats) {
        writeText(*o.stats, statsJson(o, r, device).dump(2) + "\n");
        std::cout << "wrote " << *o.stats << "\n";
    }
    if (o.graph) {
        // The variants and their causes ride along: DOT comments, and keys of the JSON dump.
        std::string dot = "// scene features: " + r.features + "\n";
        for (const agaa::VariantChoice& v : r.variants)
            dot += "// variant " + v.effect + ": " + v.variant + " (" + v.cause + ")\n";
        writeText(*o.graph, dot + r.graphDot);
        nlohmann::json graphJson = nlohmann::json::parse(r.graphJson);
        graphJson["features"] = r.features;
        graphJson["variants"] = nlohmann::json::array();
        for (const agaa::VariantChoice& v : r.variants)
            graphJson["variants"].push_back(
                {{"effect", v.effect}, {"variant", v.variant}, {"cause", v.cause}});
        writeText(*o.graph + ".json", graphJson.dump(2) + "\n");
        std::cout << "wrote " << *o.graph << " and " << *o.graph << ".json\n";
    }
    if (device.validationErrors() > 0) {
        std::cerr << "agaa-render: " << device.validationErrors() << " validation error(s)\n";
        return 1;
    }
    return 0;
}

// Every validation message counts, up to and including the device's destruction (where leaked
// objects are reported).
int run(const Options& o) {
    eng::vk::DeviceOptions deviceOptions;
    deviceOptions.validation = o.validate;
    deviceOptions.deviceName = o.device;
    auto device = std::make_unique<eng::vk::Device>(deviceOptions);
    std::shared_ptr<const std::atomic<uint32_t>> errors = device->validationErrorCounter();
    int rc = renderWith(o, *device);
    const uint32_t before = errors->load();
    device.reset();
    if (errors->load() > before) {
        std::cerr << "agaa-render: " << errors->load() - before
                  << " validation error(s) while the device was destroyed\n";
        return 1;
    }
    return rc;
}

} // namespace

int main(int argc, char** argv) {
    try {
        Options o = parse(argc, argv);
        if (o.help) {
            std::cout << usage() << "\nmethods:\n";
            for (const auto& m : agaa::knownMethods())
                std::cout << "  " << m.name << ": " << m.summary << "\n";
            std::cout << "built-in scenes:";
            for (const auto& k : eng::scene::sceneKinds())
                std::cout << " " << k;
            std::cout << "\n";
            return 0;
        }
        if (!o.caps) {
            prepareOutputFolder("--out", o.out);
            if (o.stats) prepareOutputFolder("--stats", *o.stats);
            if (o.graph) prepareOutputFolder("--graph", *o.graph);
        }
        return run(o);
    } catch (const BadArgument& e) {
        std::cerr << "agaa-render: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const eng::scene::SceneError& e) {
        std::cerr << "agaa-render: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::invalid_argument& e) {
        std::cerr << "agaa-render: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const eng::io::IoError& e) {
        std::cerr << "agaa-render: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const eng::vk::MissingCapability& e) {
        std::cerr << "agaa-render: the device lacks a required capability: " << e.what() << "\n";
        return kExitMissingCapability;
    } catch (const eng::vk::OutOfMemory& e) {
        std::cerr << "agaa-render: out of memory: " << e.what() << "\n";
        return 1;
    } catch (const eng::vk::DeviceLost& e) {
        std::cerr << "agaa-render: the device was lost: " << e.what() << "\n";
        return 1;
    } catch (const std::filesystem::filesystem_error& e) {
        std::cerr << "agaa-render: cannot write '" << e.path1().string() << "': " << e.code().message()
                  << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        // Nothing a user types should get here; if it does, say so rather than abort.
        std::cerr << "agaa-render: internal error: " << e.what() << "\n";
        return 1;
    }
}
