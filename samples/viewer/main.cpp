// agaa-viewer: the interactive sample viewer. Each frame renders the scene with the chosen method
// at the window's size (1:1 pixels) in one render graph that ends in the swapchain image: display
// blit (the sRGB encode), the Dear ImGui panel on top, present. Controls: see README.md.
//
// Exit codes: 0 ok; 1 validation errors, a blank scripted frame or an internal failure; 2 bad
// command line, scene or setting; 3 no window (GLFW cannot start: no display) or a missing device
// capability.

#include "agaa/method_settings.h"
#include "agaa/methods.h"
#include "engine/io/io_error.h"
#include "engine/io/png.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/scenegen.h"
#include "engine/vk/check.h"
#include "samples/viewer/controls.h"
#include "samples/viewer/screenshot_check.h"
#include "samples/viewer/swapchain.h"
#include "samples/viewer/timing_history.h"
#include "samples/viewer/ui_overlay.h"
#include "samples/viewer/ui_panel.h"
#include "samples/viewer/view_renderer.h"
#include "samples/viewer/window.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <tuple>

namespace {

using agaa::viewer::Controls;
using agaa::viewer::PresentResult;
using agaa::viewer::Swapchain;
using agaa::viewer::Window;

constexpr int kExitFailure = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitNoWindow = 3;
// The shading-event count needs a readback: once every this many frames, not every frame.
constexpr uint32_t kEventsEvery = 16;

constexpr const char* kUsage =
    R"(usage: agaa-viewer [--scene FILE.gltf|.glb | --builtin NAME] [--width W --height H]
                   [--method NAME] [--samples N] [--aggregates C] [--debug VIEW] [--SETTING VALUE...]
                   [--exposure-ev EV] [--split | --difference [--difference-gain G]]
                   [--frames N [--screenshot FILE.png]] [--script cycle-methods --screenshot-dir DIR]
                   [--pixel-size P] [--no-ui] [--validate] [--help]
  --width/--height  window size in pixels, 1..8192 (default 640x360); rendered 1:1
  --samples         4, 8, 16 or 32 (default 8); --aggregates 1..4 (default 2)
  --SETTING VALUE   any other method setting of agaa-render's (agaa-render --help), e.g.
                    --agaa-ndf sggx; the panel's "method settings" lists them all
  --exposure-ev     exposure in stops, -8..8 (default 0: exposure 1)
  --split           split view: right half the per-sample reference at the same n
  --difference      difference view: |method - reference at the same n| x gain (default 4, 1..64)
  --frames          render this many frames, then exit (0 = until closed); with --script: per method
  --screenshot      with --frames: save the last presented swapchain image (with the UI) as PNG
  --script          cycle-methods: render --frames N (default 3) frames with every method in turn,
                    then agaa split against and different from the reference; save each step's last presented image
                    as DIR/NN-METHOD.png, check the scene part of each is not blank and count
                    validation messages per step
  --pixel-size      1, 2 or 4: window pixels per rendered pixel, each way (default 1: 1:1); more
                    renders 4x or 16x fewer pixels, each shown as an exact block (no blur)
  --no-ui           no ImGui panel (for timing the rendering alone)
  --validate        Khronos validation (also AGAA_VALIDATE=1); exits 1 on any validation error
)";

struct BadArgument : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Options {
    std::optional<std::string> sceneFile;
    std::string builtin = "railings";
    uint32_t width = 640, height = 360;
    agaa::viewer::ViewerSettings settings;
    std::string method = "agaa", debug;
    std::optional<uint32_t> frames;
    std::optional<std::string> screenshot;
    std::optional<std::string> script, screenshotDir;
    bool ui = true;
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

float parseFloat(const std::string& flag, const std::string& text, float lo, float hi) {
    char* end = nullptr;
    const float v = std::strtof(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !(v >= lo && v <= hi)) {
        char range[64];
        std::snprintf(range, sizeof range, "%g..%g", double(lo), double(hi));
        throw BadArgument(flag + " '" + text + "' is not a number in " + range);
    }
    return v;
}

Options parse(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw BadArgument(a + " needs a value");
            return argv[++i];
        };
        const agaa::MethodOption* setting =
            a.rfind("--", 0) == 0 ? agaa::findMethodOption(a.substr(2)) : nullptr;
        if (setting && setting->name != "samples" && setting->name != "aggregates" &&
            setting->name != "debug") {
            try {
                agaa::setMethodOption(o.settings.methodSettings, *setting, value());
            } catch (const std::invalid_argument& e) {
                throw BadArgument(e.what());
            }
        } else if (a == "--scene")
            o.sceneFile = value();
        else if (a == "--builtin")
            o.builtin = value();
        else if (a == "--width")
            o.width = parseUint(a, value(), 1, 8192);
        else if (a == "--height")
            o.height = parseUint(a, value(), 1, 8192);
        else if (a == "--method")
            o.method = value();
        else if (a == "--samples")
            o.settings.samples = parseUint(a, value(), 1, 64);
        else if (a == "--aggregates")
            o.settings.aggregates = parseUint(a, value(), 1, 64);
        else if (a == "--debug")
            o.debug = value();
        else if (a == "--exposure-ev")
            o.settings.exposureEv =
                parseFloat(a, value(), agaa::viewer::kMinExposureEv, agaa::viewer::kMaxExposureEv);
        else if (a == "--split")
            o.settings.compare = agaa::viewer::Compare::Split;
        else if (a == "--difference")
            o.settings.compare = agaa::viewer::Compare::Difference;
        else if (a == "--difference-gain")
            o.settings.differenceGain = parseFloat(a, value(), 1.0f, agaa::viewer::kMaxDifferenceGain);
        else if (a == "--frames")
            o.frames = parseUint(a, value(), 0, 1000000);
        else if (a == "--screenshot")
            o.screenshot = value();
        else if (a == "--script") {
            o.script = value();
            if (*o.script != "cycle-methods")
                throw BadArgument("--script '" + *o.script + "' is unknown (allowed: cycle-methods)");
        } else if (a == "--screenshot-dir")
            o.screenshotDir = value();
        else if (a == "--scale")
            throw BadArgument("--scale is gone: the viewer renders 1:1 at the window size (set "
                              "--width/--height, or --pixel-size 2|4 for blocks)");
        else if (a == "--pixel-size")
            o.settings.pixelSize = parseUint(a, value(), 1, 4);
        else if (a == "--no-ui")
            o.ui = false;
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
        if (it == views.end()) {
            std::string allowed;
            for (const std::string& v : views)
                allowed += (allowed.empty() ? "" : ", ") + v;
            throw BadArgument("--debug '" + o.debug + "' is not a debug view of " + o.method +
                              " (allowed: " + (allowed.empty() ? "none" : allowed) + ")");
        }
        o.settings.debugView = size_t(it - views.begin()) + 1;
    }
    if (o.screenshot && o.frames.value_or(0) == 0)
        throw BadArgument("--screenshot needs --frames N (the frame to save)");
    if (o.script && !o.screenshotDir) throw BadArgument("--script needs --screenshot-dir DIR");
    if (o.screenshotDir && !o.script) throw BadArgument("--screenshot-dir needs --script cycle-methods");
    if (o.script && o.screenshot)
        throw BadArgument("--script saves into --screenshot-dir; drop --screenshot");
    if (o.script && o.frames.value_or(1) == 0) throw BadArgument("--frames with --script must be at least 1");
    try {
        agaa::viewer::validate(o.settings);
    } catch (const std::invalid_argument& e) {
        throw BadArgument(e.what());
    }
    return o;
}

std::string fixed2(double ms) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", ms);
    return buffer;
}

std::string passTimes(const eng::frame::FrameTiming& t) {
    std::string s;
    for (const auto& p : t.passes)
        s += (s.empty() ? "" : ", ") + p.name + " " + fixed2(p.gpuMs);
    return s;
}

std::string numbered(uint32_t n, const std::string& what) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "%02u-", n);
    return buffer + what + ".png";
}

// The scripted run: every method alone, then agaa split against the reference and agaa's
// difference from it at 2x2 pixel blocks (two techniques in one graph); which step is on screen
// and whether its frames are done.
struct Script {
    size_t step = 0;
    static size_t steps() { return agaa::knownMethods().size() + 2; }
    agaa::viewer::Compare compare() const {
        const size_t methods = agaa::knownMethods().size();
        return step < methods    ? agaa::viewer::Compare::Off
               : step == methods ? agaa::viewer::Compare::Split
                                 : agaa::viewer::Compare::Difference;
    }
    size_t method() const {
        if (compare() == agaa::viewer::Compare::Off) return step;
        const auto& methods = agaa::knownMethods();
        return size_t(
            std::find_if(methods.begin(), methods.end(), [](const auto& m) { return m.name == "agaa"; }) -
            methods.begin());
    }
    std::string name() const {
        return compare() == agaa::viewer::Compare::Off     ? agaa::knownMethods()[step].name
               : compare() == agaa::viewer::Compare::Split ? "agaa-split"
                                                           : "agaa-difference-2x2";
    }
    uint32_t framesThisMethod = 0;
    uint32_t framesPerMethod = 3;
    uint32_t validationAtStart = 0;
    bool refused = false; // the step's settings were refused: its screenshot shows another step's
    uint32_t failures = 0;
};

int run(const Options& o) {
    eng::scene::Scene scene =
        o.sceneFile ? eng::scene::loadGltf(*o.sceneFile) : eng::scene::loadTestScene(o.builtin);
    for (const std::string& w : scene.stats.warnings)
        std::cerr << "warning: " << w << "\n";

    Window window(o.width, o.height, "agaa-viewer: " + scene.source);
    eng::vk::DeviceOptions deviceOptions;
    deviceOptions.validation = o.validate;
    deviceOptions.instanceExtensions = window.requiredInstanceExtensions();
    deviceOptions.swapchain = true;
    eng::vk::Device device(deviceOptions);
    agaa::viewer::ViewerSettings initial = o.settings;
    std::optional<Script> script;
    if (o.script) {
        script = Script{};
        script->framesPerMethod = o.frames.value_or(3);
        initial.method = 0;
        initial.debugView = 0;
        std::filesystem::create_directories(*o.screenshotDir);
    }
    Controls controls(scene, initial);
    int status = 0;
    {
        // Destroyed before the device: every Vulkan object of the renderer, UI and swapchain.
        agaa::viewer::ViewRenderer renderer(device, scene);
        Swapchain swapchain(device, window.createSurface(device.instance()), window.framebufferSize());
        std::optional<agaa::viewer::UiOverlay> ui;
        if (o.ui) ui.emplace(device, window.handle(), swapchain);
        std::cout << "agaa-viewer: " << scene.source << " (" << scene.triangleCount() << " triangles) on "
                  << device.caps().deviceName << (device.validationEnabled() ? ", validation on" : "") << "\n"
                  << Controls::help() << "\n";

        using Clock = std::chrono::steady_clock;
        Clock::time_point lastReport = Clock::now();
        uint32_t framesSinceReport = 0, frames = 0;
        double fps = 0.0;
        bool rendered = false;
        agaa::viewer::TimingHistory history;
        std::optional<agaa::viewer::ViewFrame> last;
        std::optional<double> eventsPerPixel;
        std::string error;
        agaa::viewer::ViewerSettings previous = controls.settings();
        uint32_t sinceEvents = kEventsEvery;
        VkExtent2D renderedSize{0, 0}; // the transients in the renderer's pool are of this size
        while (!window.shouldClose() && !controls.quitRequested()) {
            window.pollEvents();
            if (window.minimised()) {
                window.waitEvents(); // nothing to draw into; sleep until restored
                continue;
            }
            agaa::viewer::InputEvents input = window.takeInput();
            if (ui && ui->wantsMouse()) input.dragX = input.dragY = input.scroll = 0.0;
            if (ui && ui->wantsKeyboard()) input.keys.clear();
            const std::string change = controls.apply(input);
            if (!change.empty()) std::cout << change << "\n";
            if (input.resized) swapchain.recreate(window.framebufferSize());
            if (ui) ui->swapchainRecreated(swapchain);
            const VkExtent2D renderTo{
                agaa::viewer::renderSize(swapchain.extent().width, controls.settings().pixelSize),
                agaa::viewer::renderSize(swapchain.extent().height, controls.settings().pixelSize)};
            if (renderTo.width != renderedSize.width || renderTo.height != renderedSize.height) {
                if (renderedSize.width != 0) renderer.sizeChanged();
                renderedSize = renderTo;
            }

            if (script && script->framesThisMethod == 0) {
                controls.settings().method = script->method();
                controls.settings().debugView = 0;
                controls.settings().compare = script->compare();
                // The last step also renders at 2x2 blocks: the block blit and a pool resize.
                controls.settings().pixelSize =
                    script->compare() == agaa::viewer::Compare::Difference ? 2 : 1;
                script->validationAtStart = device.validationErrors();
                script->refused = false;
            }
            const bool lastFrame = !script && o.frames && *o.frames > 0 && frames + 1 == *o.frames;
            const bool scriptShot = script && script->framesThisMethod + 1 == script->framesPerMethod;
            bool keyShot = controls.takeScreenshotRequest();

            std::optional<agaa::viewer::AcquiredImage> image = swapchain.acquire();
            if (!image) {
                swapchain.recreate(window.framebufferSize());
                continue;
            }
            const VkExtent2D size = swapchain.extent();
            if (ui) {
                ui->beginFrame();
                agaa::viewer::PanelStats stats;
                stats.width = size.width;
                stats.height = size.height;
                stats.renderWidth = agaa::viewer::renderSize(size.width, controls.settings().pixelSize);
                stats.renderHeight = agaa::viewer::renderSize(size.height, controls.settings().pixelSize);
                stats.fps = fps;
                stats.frame = last ? &*last : nullptr;
                stats.eventsPerPixel = eventsPerPixel;
                stats.error = error;
                const agaa::viewer::PanelActions actions = drawPanel(controls, history, stats);
                if (actions.reset) controls.reset();
                keyShot = keyShot || actions.screenshot;
                ui->endFrame();
            }
            const agaa::viewer::ViewerSettings& now = controls.settings();
            const bool settingsChanged =
                std::tie(now.method, now.samples, now.aggregates, now.debugView) !=
                    std::tie(previous.method, previous.samples, previous.aggregates, previous.debugView) ||
                agaa::methodSettingsKey(now.methodSettings) !=
                    agaa::methodSettingsKey(previous.methodSettings);
            previous = now;
            if (settingsChanged) error.clear(); // the refusal stays on screen until the next change

            agaa::viewer::ViewRequest request;
            request.compare = controls.settings().compare;
            request.splitFraction = controls.settings().splitFraction;
            request.differenceGain = controls.settings().differenceGain;
            request.pixelSize = controls.settings().pixelSize;
            request.readShadingEvents = settingsChanged || ++sinceEvents >= kEventsEvery;
            request.screenshot =
                ((lastFrame && o.screenshot) || scriptShot || keyShot) && swapchain.canReadBack();
            agaa::viewer::OverlayPass overlay;
            if (ui) overlay = [&](eng::rg::Graph& g, eng::rg::Texture t) { return ui->addPass(g, t); };
            agaa::viewer::ViewFrame frame;
            try {
                agaa::viewer::validate(controls.settings());
                request.render = controls.request(size.width, size.height);
                frame = renderer.render(request, *image, overlay);
                controls.accept();
            } catch (const std::exception& e) {
                // invalid_argument (a setting the method refuses) or MissingCapability: the image
                // is acquired and must be presented, so render it with the last settings that
                // rendered. The very first frame has none to go back to.
                if (!rendered) throw;
                error = e.what();
                if (script) script->refused = true;
                std::cerr << "agaa-viewer: " << error << "; back to the previous settings\n";
                controls.revert();
                previous = controls.settings();
                request.render = controls.request(size.width, size.height);
                request.compare = controls.settings().compare;
                request.pixelSize = controls.settings().pixelSize;
                frame = renderer.render(request, *image, overlay);
            }
            rendered = true;
            if (frame.shadingEventsPerPixel) {
                eventsPerPixel = frame.shadingEventsPerPixel;
                sinceEvents = 0;
            }
            const PresentResult presented = swapchain.present(image->index);
            if (presented != PresentResult::Presented && !window.minimised())
                swapchain.recreate(window.framebufferSize());
            history.add(frame.timing);
            ++frames;
            ++framesSinceReport;

            const double seconds = std::chrono::duration<double>(Clock::now() - lastReport).count();
            if (seconds >= 1.0 || lastFrame) {
                fps = framesSinceReport / seconds;
                const std::string what = controls.describe(frame.samples);
                window.setTitle("agaa-viewer | " + what + " | " + fixed2(fps) + " fps");
                std::cout << what << " " << size.width << "x" << size.height << ": GPU "
                          << fixed2(frame.timing.frameMs) << " ms (" << passTimes(frame.timing) << "), "
                          << fixed2(fps) << " fps\n"
                          << std::flush;
                lastReport = Clock::now();
                framesSinceReport = 0;
            }

            if (frame.screenshot) {
                std::string file =
                    lastFrame && o.screenshot ? *o.screenshot : "agaa-viewer-" + numbered(frames, "shot");
                if (scriptShot) {
                    file = (std::filesystem::path(*o.screenshotDir) /
                            numbered(uint32_t(script->step + 1), script->name()))
                               .string();
                }
                eng::io::writePng(file, *frame.screenshot);
                std::cout << "wrote " << file << " (" << frame.screenshot->width << "x"
                          << frame.screenshot->height << ", the presented swapchain image)\n";
                if (scriptShot) {
                    // The scene outside the UI's windows: the UI alone would never look blank.
                    const uint32_t h = frame.screenshot->height;
                    const uint32_t firstColumn = ui ? uint32_t(agaa::viewer::kPanelWidth) : 0u;
                    const uint32_t rows = ui ? h - std::min(h, uint32_t(agaa::viewer::kTimingHeight)) : h;
                    const agaa::viewer::BlankCheck check =
                        agaa::viewer::checkNotBlank(*frame.screenshot, firstColumn, rows);
                    const uint32_t messages = device.validationErrors() - script->validationAtStart;
                    const bool ok = !check.blank && messages == 0 && !script->refused &&
                                    presented != PresentResult::OutOfDate;
                    std::cout << "script: " << script->name() << ": " << check.describe() << ", " << messages
                              << " validation errors"
                              << (script->refused ? ", settings refused: " + error : std::string())
                              << (ok ? "" : " FAILED") << "\n";
                    if (!ok) ++script->failures;
                }
            } else if (scriptShot || (lastFrame && o.screenshot)) {
                std::cerr << "agaa-viewer: the surface does not allow reading the swapchain image back\n";
                status = kExitFailure;
            }
            last = std::move(frame);
            if (script && ++script->framesThisMethod == script->framesPerMethod) {
                script->framesThisMethod = 0;
                if (++script->step == Script::steps()) break;
            }
            if (lastFrame) break;
        }
        vkDeviceWaitIdle(device.device());
        if (script) {
            std::cout << "script: " << script->step << " of " << Script::steps()
                      << " steps (every method, then agaa split and difference), " << script->failures
                      << " failed\n";
            if (script->failures > 0 || script->step != Script::steps()) status = kExitFailure;
        }
    }
    std::cout << "validation errors: " << device.validationErrors()
              << (device.validationEnabled() ? "" : " (validation off; AGAA_VALIDATE=1 or --validate)")
              << "\n";
    if (device.validationErrors() > 0) return kExitFailure;
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
        return kExitFailure;
    }
}
