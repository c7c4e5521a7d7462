// agaa-viewer: the interactive sample viewer. Each frame renders the scene with FrameRenderer
// (the same path as agaa-render and the benchmark) at a fraction of the window size, sRGB-encodes
// the tone-mapped display image on the CPU and presents it through the swapchain. Controls and
// the live per-pass GPU times: see README.md.
//
// Exit codes: 0 ok; 1 validation errors or an internal failure; 2 bad command line, scene or
// setting; 3 no window (GLFW cannot start: no display) or a missing device capability.

#include "agaa/methods.h"
#include "engine/io/io_error.h"
#include "engine/io/png.h"
#include "engine/io/tone_map.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/scenegen.h"
#include "engine/vk/check.h"
#include "samples/viewer/controls.h"
#include "samples/viewer/swapchain.h"
#include "samples/viewer/window.h"
#include "tools/harness/frame_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

namespace {

using agaa::viewer::Controls;
using agaa::viewer::PresentResult;
using agaa::viewer::Swapchain;
using agaa::viewer::Window;

constexpr int kExitValidation = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitNoWindow = 3;

constexpr const char* kUsage =
    R"(usage: agaa-viewer [--scene FILE.gltf|.glb | --builtin NAME] [--width W --height H] [--scale S]
                   [--method NAME] [--samples N] [--aggregates C] [--debug VIEW]
                   [--frames N [--screenshot FILE.png]] [--validate] [--help]
  --width/--height  window size in pixels, 1..8192 (default 1280x720)
  --scale           render resolution as a fraction of the window, (0, 1] (default 0.5; lavapipe is slow)
  --samples         4, 8, 16 or 32 (default 8); --aggregates 1..4 (default 2)
  --frames          render this many frames, then exit (0 = until closed)
  --screenshot      with --frames: save the last presented swapchain image as PNG (key P saves
                    any frame as agaa-viewer-NNNNNN.png in the working directory)
  --validate        Khronos validation (also AGAA_VALIDATE=1); exits 1 on any validation error
)";

struct BadArgument : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Options {
    std::optional<std::string> sceneFile;
    std::string builtin = "railings";
    uint32_t width = 1280, height = 720;
    float scale = 0.5f;
    agaa::viewer::ViewerSettings settings;
    std::string method = "agaa", debug;
    uint32_t frames = 0;
    std::optional<std::string> screenshot;
    bool validate = false;
    bool help = false;
};

uint32_t parseUint(const std::string& flag, const std::string& text, uint32_t lo, uint32_t hi) {
    size_t used = 0;
    unsigned long v = 0;
    try {
        v = std::stoul(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || text.empty() || text[0] == '-' || v < lo || v > hi)
        throw BadArgument(flag + " '" + text + "' is not an integer in " + std::to_string(lo) + ".." +
                          std::to_string(hi));
    return uint32_t(v);
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw BadArgument(a + " needs a value");
            return argv[++i];
        };
        if (a == "--scene")
            o.sceneFile = value();
        else if (a == "--builtin")
            o.builtin = value();
        else if (a == "--width")
            o.width = parseUint(a, value(), 1, 8192);
        else if (a == "--height")
            o.height = parseUint(a, value(), 1, 8192);
        else if (a == "--scale") {
            const std::string text = value();
            char* end = nullptr;
            const float s = std::strtof(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !(s > 0.0f && s <= 1.0f))
                throw BadArgument("--scale '" + text + "' is not a number in (0, 1]");
            o.scale = s;
        } else if (a == "--method")
            o.method = value();
        else if (a == "--samples")
            o.settings.samples = parseUint(a, value(), 1, 64);
        else if (a == "--aggregates")
            o.settings.aggregates = parseUint(a, value(), 1, 64);
        else if (a == "--debug")
            o.debug = value();
        else if (a == "--frames")
            o.frames = parseUint(a, value(), 0, 1000000);
        else if (a == "--screenshot")
            o.screenshot = value();
        else if (a == "--validate")
            o.validate = true;
        else if (a == "--help" || a == "-h")
            o.help = true;
        else
            throw BadArgument("unknown option '" + a + "' (see --help)");
    }
    const auto& methods = agaa::knownMethods();
    o.settings.method = methods.size();
    for (size_t m = 0; m < methods.size(); ++m)
        if (methods[m].name == o.method) o.settings.method = m;
    if (o.settings.method == methods.size())
        throw BadArgument("--method '" + o.method + "' is unknown (known: " + agaa::knownMethodNames() + ")");
    if (!o.debug.empty()) {
        const auto& views = methods[o.settings.method].debugViews;
        auto it = std::find(views.begin(), views.end(), o.debug);
        if (it == views.end())
            throw BadArgument("--debug '" + o.debug + "' is not a debug view of " + o.method);
        o.settings.debugView = size_t(it - views.begin()) + 1;
    }
    if (o.screenshot && o.frames == 0) throw BadArgument("--screenshot needs --frames N (the frame to save)");
    agaa::viewer::validate(o.settings); // samples and aggregates within the cycles the keys walk
    return o;
}

// The display image is tone-mapped linear [0,1]: encode with the sRGB OETF the reports use.
// A non-finite pixel (never expected) shows black rather than throwing mid-session.
eng::io::ImageU8 encodeDisplay(const eng::io::ImageF& display, size_t& nonFinite) {
    eng::io::ImageU8 out = eng::io::makeImageU8(display.width, display.height);
    nonFinite = 0;
    for (size_t i = 0; i < display.rgba.size(); i += 4) {
        for (size_t c = 0; c < 3; ++c) {
            float v = display.rgba[i + c];
            if (!std::isfinite(v)) {
                ++nonFinite;
                v = 0.0f;
            }
            out.rgba[i + c] = uint8_t(std::lround(255.0f * eng::io::linearToSrgb(v)));
        }
        out.rgba[i + 3] = 255;
    }
    return out;
}

std::string fixed2(double ms) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", ms);
    return buffer;
}

std::string passTimes(const agaa::RenderResult& r) {
    std::string s;
    for (const auto& p : r.passes)
        s += (s.empty() ? "" : ", ") + p.name + " " + fixed2(p.gpuMs);
    return s;
}

std::string screenshotName(uint32_t frame) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "agaa-viewer-%06u.png", frame);
    return buffer;
}

std::string describeCamera(const agaa::viewer::OrbitCamera& camera) {
    return "camera yaw " + fixed2(camera.yawDegrees()) + " pitch " + fixed2(camera.pitchDegrees()) +
           " distance x" + fixed2(camera.distanceScale());
}

int run(const Options& o) {
    eng::scene::Scene scene =
        o.sceneFile ? eng::scene::loadGltf(*o.sceneFile) : eng::scene::loadBuiltin(o.builtin);
    for (const std::string& w : scene.stats.warnings)
        std::cerr << "warning: " << w << "\n";

    Window window(o.width, o.height, "agaa-viewer: " + scene.source);
    eng::vk::DeviceOptions deviceOptions;
    deviceOptions.validation = o.validate;
    deviceOptions.instanceExtensions = window.requiredInstanceExtensions();
    deviceOptions.swapchain = true;
    eng::vk::Device device(deviceOptions);
    Controls controls(scene, o.settings);
    int status = 0;
    {
        // Destroyed before the device: the renderer's and the swapchain's Vulkan objects.
        agaa::FrameRenderer renderer(device, scene);
        Swapchain swapchain(device, window.createSurface(device.instance()), window.framebufferSize());
        std::cout << "agaa-viewer: " << scene.source << " (" << scene.triangleCount() << " triangles) on "
                  << device.caps().deviceName << (device.validationEnabled() ? ", validation on" : "") << "\n"
                  << Controls::help() << "\n";

        using Clock = std::chrono::steady_clock;
        Clock::time_point lastReport = Clock::now();
        uint32_t framesSinceReport = 0, frames = 0;
        bool rendered = false;
        while (!window.shouldClose() && !controls.quitRequested()) {
            window.pollEvents();
            if (window.minimised()) {
                window.waitEvents(); // nothing to draw into; sleep until restored
                continue;
            }
            const agaa::viewer::InputEvents input = window.takeInput();
            const std::string change = controls.apply(input);
            if (!change.empty()) std::cout << change << "\n";
            if (input.resized) swapchain.recreate(window.framebufferSize());

            const VkExtent2D size = swapchain.extent();
            const uint32_t width = std::max(1u, uint32_t(std::lround(size.width * o.scale)));
            const uint32_t height = std::max(1u, uint32_t(std::lround(size.height * o.scale)));
            agaa::RenderResult result;
            try {
                result = renderer.render(controls.request(width, height));
                controls.accept();
            } catch (const std::exception& e) {
                // invalid_argument (a setting the method refuses) or MissingCapability: keep the
                // last settings that rendered. The very first frame has none to go back to.
                if (!rendered) throw;
                std::cerr << "agaa-viewer: " << e.what() << "; back to the previous settings\n";
                controls.revert();
                continue;
            }
            rendered = true;
            size_t nonFinite = 0;
            const eng::io::ImageU8 frame = encodeDisplay(result.display, nonFinite);
            if (nonFinite)
                std::cerr << "agaa-viewer: " << nonFinite << " non-finite display values shown black\n";

            const bool last = o.frames > 0 && frames + 1 == o.frames;
            const bool keyShot = controls.takeScreenshotRequest();
            eng::io::ImageU8 screenshot;
            eng::io::ImageU8* shot = (last && o.screenshot) || keyShot ? &screenshot : nullptr;
            PresentResult presented = swapchain.present(frame, shot);
            if (presented == PresentResult::OutOfDate && !window.minimised()) {
                swapchain.recreate(window.framebufferSize());
                presented = swapchain.present(frame, shot);
            }
            if (presented != PresentResult::Presented && !window.minimised())
                swapchain.recreate(window.framebufferSize());
            ++frames;
            ++framesSinceReport;

            const double seconds = std::chrono::duration<double>(Clock::now() - lastReport).count();
            if (seconds >= 1.0 || last) {
                const std::string what = controls.describe(result.samples);
                const double fps = framesSinceReport / seconds;
                window.setTitle("agaa-viewer | " + what + " | " + std::to_string(width) + "x" +
                                std::to_string(height) + " | GPU " + fixed2(result.frameGpuMs) + " ms | " +
                                fixed2(fps) + " fps");
                std::cout << what << " " << width << "x" << height << ": GPU " << fixed2(result.frameGpuMs)
                          << " ms (" << passTimes(result) << "), " << fixed2(fps) << " fps, "
                          << describeCamera(controls.camera()) << "\n"
                          << std::flush;
                lastReport = Clock::now();
                framesSinceReport = 0;
            }
            if (shot) {
                const std::string file = last && o.screenshot ? *o.screenshot : screenshotName(frames);
                if (presented != PresentResult::OutOfDate) {
                    eng::io::writePng(file, screenshot);
                    std::cout << "wrote " << file << " (" << screenshot.width << "x" << screenshot.height
                              << ", the presented swapchain image)\n";
                } else {
                    std::cerr << "agaa-viewer: frame " << frames << " was not presented; no screenshot\n";
                    if (last) status = 1;
                }
            }
            if (last) break;
        }
        vkDeviceWaitIdle(device.device());
    }
    std::cout << "validation errors: " << device.validationErrors()
              << (device.validationEnabled() ? "" : " (validation off; AGAA_VALIDATE=1 or --validate)")
              << "\n";
    if (device.validationErrors() > 0) return kExitValidation;
    return status;
}

} // namespace

int main(int argc, char** argv) {
    try {
        const Options o = parse(argc, argv);
        if (o.help) {
            std::cout << kUsage << "\n" << Controls::help() << "\nbuilt-in scenes:";
            for (const auto& k : eng::scene::sceneKinds())
                std::cout << " " << k;
            std::cout << "\n";
            return 0;
        }
        return run(o);
    } catch (const agaa::viewer::WindowError& e) {
        std::cerr << "agaa-viewer: " << e.what() << "\n";
        return kExitNoWindow;
    } catch (const eng::vk::MissingCapability& e) {
        std::cerr << "agaa-viewer: the device lacks a required capability: " << e.what() << "\n";
        return kExitNoWindow;
    } catch (const BadArgument& e) {
        std::cerr << "agaa-viewer: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const eng::scene::SceneError& e) {
        std::cerr << "agaa-viewer: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::invalid_argument& e) {
        std::cerr << "agaa-viewer: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const eng::io::IoError& e) {
        std::cerr << "agaa-viewer: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::exception& e) {
        std::cerr << "agaa-viewer: internal error: " << e.what() << "\n";
        return 1;
    }
}
