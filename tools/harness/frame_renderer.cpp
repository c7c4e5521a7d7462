#include "tools/harness/frame_renderer.h"

#include "agaa/method_settings.h"
#include "engine/frame/exposure.h"
#include "engine/frame/readback.h"
#include "engine/frame/sample_pattern.h"
#include "shared/frame.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace agaa {
namespace rg = eng::rg;
namespace vk = eng::vk;

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

namespace {

eng::io::ImageF readImage(const vk::Device& device, const vk::Buffer& buffer, uint32_t w, uint32_t h) {
    vk::invalidateBuffer(device, buffer);
    eng::io::ImageF img = eng::io::makeImage(w, h);
    std::memcpy(img.rgba.data(), buffer.mapped, size_t(w) * h * 16);
    return img;
}

} // namespace

FrameRenderer::FrameRenderer(vk::Device& device, const eng::scene::Scene& scene)
    : m_device(device), m_scene(scene), m_gpuScene(device, scene), m_runner(device) {
    if (scene.lights.size() > shared::kMaxLights)
        throw std::invalid_argument(scene.source + ": " + std::to_string(scene.lights.size()) +
                                    " lights; at most " + std::to_string(shared::kMaxLights) +
                                    " are supported");
    m_frameConstants =
        vk::createBuffer(device, sizeof(shared::FrameConstants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                         vk::MemoryUse::Upload, "frame.constants");
    size_t lightCount = std::max<size_t>(1, scene.lights.size());
    try {
        m_lights =
            vk::createBuffer(device, lightCount * sizeof(shared::GpuLight),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload, "frame.lights");
    } catch (...) {
        vk::destroyBuffer(device, m_frameConstants); // the members' own destructors release the rest
        throw;
    }
}

FrameRenderer::~FrameRenderer() {
    vkDeviceWaitIdle(m_device.device());
    m_techniques.clear();
    vk::destroyBuffer(m_device, m_frameConstants);
    vk::destroyBuffer(m_device, m_lights);
}

Technique& FrameRenderer::technique(const RenderRequest& r) {
    const std::string key = r.method + "/" + methodSettingsKey(r.settings);
    auto it = m_techniques.find(key);
    if (it == m_techniques.end())
        it = m_techniques.emplace(key, createTechnique(r.method, m_device, m_gpuScene, r.settings)).first;
    return *it->second;
}

float FrameRenderer::meteredExposure(const eng::frame::ViewSettings& view, double& ev100) {
    // Metered at most 128 pixels wide whatever the frame's size, so a sweep's supersampled truth
    // and its frames share one exposure; keyed by what the metering frame sees.
    const uint32_t meterWidth = std::min(view.width, 128u);
    const uint32_t meterHeight =
        std::max(1u, uint32_t(std::lround(double(view.height) * meterWidth / double(view.width))));
    std::string key =
        std::to_string(view.camera) + "/" + std::to_string(meterWidth) + "x" + std::to_string(meterHeight);
    if (view.viewOverride)
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                key += "/" + std::to_string((*view.viewOverride)[c][r]);
    auto it = m_meteredExposure.find(key);
    if (it == m_meteredExposure.end()) {
        RenderRequest meter;
        meter.method = "noaa";
        meter.view = view;
        meter.view.tile = {}; // a tile of the view is metered as the whole view
        meter.view.width = meterWidth;
        meter.view.height = meterHeight;
        meter.view.exposure = eng::frame::meteringExposure(m_scene);
        const RenderResult r = render(meter);
        const double luminance =
            eng::frame::logAverageLuminance(r.hdr.rgba, r.shadingEvents, meter.view.exposure);
        const double ev = eng::frame::ev100FromLuminance(luminance);
        it = m_meteredExposure.emplace(key, std::pair{eng::frame::exposureFromEv100(ev), ev}).first;
    }
    ev100 = it->second.second;
    return it->second.first;
}

float FrameRenderer::exposureFor(const RenderRequest& request) {
    if (!request.autoExposure) return request.view.exposure;
    double ev100 = 0.0;
    eng::frame::ViewSettings whole = request.view;
    whole.tile = {};
    return meteredExposure(whole, ev100);
}

RenderResult FrameRenderer::render(const RenderRequest& original) {
    if (original.autoExposure) {
        RenderRequest fixed = original;
        fixed.autoExposure = false;
        double ev100 = 0.0;
        fixed.view.exposure = meteredExposure(original.view, ev100);
        RenderResult r = render(fixed);
        r.meteredEv100 = ev100;
        r.variants.push_back({"exposure", "auto: EV100 " + std::to_string(ev100).substr(0, 5),
                              "log-average luminance of the no-AA frame's covered pixels"});
        return r;
    }
    const RenderRequest& request = original;
    const uint32_t w = request.view.width, h = request.view.height;
    // Only the reference reconstructs its rays through common/depth.glsl alone, which honours a
    // tile's off-axis projection; the converged truth is all that renders tiles.
    if (request.view.tile.scale != 1 && request.method != "reference")
        throw std::invalid_argument("a view tile is rendered by the reference method only, not '" +
                                    request.method + "'");
    if (w == 0 || h == 0 || w > 8192 || h > 8192)
        throw std::invalid_argument("image size " + std::to_string(w) + "x" + std::to_string(h) +
                                    " is out of range (1..8192 each)");
    Technique& tech = technique(request);
    const eng::frame::SamplePattern pattern = eng::frame::makeSamplePattern(tech.samples());
    eng::frame::ViewSettings view = request.view;
    shared::FrameConstants constants{};
    // The frame's constants and lights; a temporal method's with the jitter of its next frame.
    const auto writeInputs = [&] {
        if (tech.temporal()) view.jitter = tech.subpixelJitter(); // else the request's own
        constants = eng::frame::makeFrameConstants(m_scene, view, pattern);
        const std::vector<shared::GpuLight> lights = eng::frame::makeGpuLights(m_scene, constants.view);
        vk::writeBuffer(m_device, m_frameConstants, std::as_bytes(std::span(&constants, 1)));
        vk::writeBuffer(m_device, m_lights, std::as_bytes(std::span(lights)));
    };
    writeInputs();

    // Owned for this call only; released on every path out (a graph error throws mid-way).
    struct HostBuffers {
        vk::Device& device;
        vk::Buffer hdr, display, events, lost, perSample;
        ~HostBuffers() {
            vkDeviceWaitIdle(device.device());
            vk::destroyBuffer(device, hdr);
            vk::destroyBuffer(device, display);
            vk::destroyBuffer(device, events);
            if (lost.buffer) vk::destroyBuffer(device, lost);
            if (perSample.buffer) vk::destroyBuffer(device, perSample);
        }
    } host{m_device, {}, {}, {}, {}, {}};
    // One at a time into the owner: one that fails leaves the ones before it to ~HostBuffers.
    host.hdr =
        eng::frame::createReadbackBuffer(m_device, w, h, VK_FORMAT_R32G32B32A32_SFLOAT, "readback.hdr");
    host.display =
        eng::frame::createReadbackBuffer(m_device, w, h, VK_FORMAT_R32G32B32A32_SFLOAT, "readback.display");
    host.events = eng::frame::createReadbackBuffer(m_device, w, h, VK_FORMAT_R32_UINT, "readback.events");
    const vk::Buffer& hdrHost = host.hdr;
    const vk::Buffer& displayHost = host.display;
    const vk::Buffer& eventsHost = host.events;

    FrameTargets targets;
    // The frame's graph: the inputs, the technique's passes and the readbacks.
    const auto record = [&](rg::Graph& graph) {
        FrameInputs inputs;
        inputs.constants = &constants;
        inputs.width = w;
        inputs.height = h;
        // Host-written before submission (the submit makes them visible): no prior GPU use.
        inputs.frameConstants = graph.importBuffer(
            "frame.constants", {m_frameConstants.buffer, m_frameConstants.size}, std::nullopt, std::nullopt);
        inputs.lights =
            graph.importBuffer("frame.lights", {m_lights.buffer, m_lights.size}, std::nullopt, std::nullopt);
        targets = tech.addPasses(graph, inputs);
        if (request.extraPasses) request.extraPasses(graph, tech, inputs);
        eng::frame::addReadbackPass(graph, targets.hdr, hdrHost, "readback.hdr");
        eng::frame::addReadbackPass(graph, targets.display, displayHost, "readback.display");
        eng::frame::addReadbackPass(graph, targets.shadingEvents, eventsHost, "readback.events");
        if (targets.lostSamples.valid()) {
            if (!host.lost.buffer)
                host.lost =
                    eng::frame::createReadbackBuffer(m_device, w, h, VK_FORMAT_R32_UINT, "readback.lost");
            eng::frame::addReadbackPass(graph, targets.lostSamples, host.lost, "readback.lost");
        }
        if (targets.perSampleShaded.valid()) {
            if (!host.perSample.buffer)
                host.perSample = eng::frame::createReadbackBuffer(m_device, w, h, VK_FORMAT_R32_UINT,
                                                                  "readback.perSampleShaded");
            eng::frame::addReadbackPass(graph, targets.perSampleShaded, host.perSample,
                                        "readback.perSampleShaded");
        }
        graph.compile();
    };
    rg::Graph graph;
    record(graph);

    RenderResult result;
    result.samples = tech.samples();
    // A temporal method's frames each record anew, with their own jitter and the history the frame
    // before left (Technique::temporal); the others replay the one recording.
    const auto run = [&](uint32_t frame) {
        if (frame > 0 && tech.temporal()) {
            writeInputs();
            graph = rg::Graph();
            record(graph);
        }
        return m_runner.run(graph);
    };
    uint32_t frame = 0;
    for (uint32_t i = 0; i < request.warmupFrames; ++i)
        run(frame++);
    std::vector<eng::frame::FrameTiming> timings;
    for (uint32_t i = 0; i < std::max(1u, request.timedFrames); ++i)
        timings.push_back(run(frame++));

    for (size_t p = 0; p < timings[0].passes.size(); ++p) {
        std::vector<double> samples;
        for (const auto& t : timings)
            samples.push_back(t.passes[p].gpuMs);
        result.passes.push_back({timings[0].passes[p].name, median(samples)});
        result.passSamples.push_back(samples);
    }
    std::vector<double> frames;
    for (const auto& t : timings)
        frames.push_back(t.frameMs);
    result.frameGpuMs = median(frames);
    result.culledPasses = graph.culledPassNames();
    result.graphDot = graph.dumpDot();
    result.graphJson = graph.dumpJson();
    result.variants = tech.variants();
    result.exposure = request.view.exposure;
    result.features = eng::scene::describe(eng::scene::deriveSceneFeatures(m_scene), m_scene);

    uint64_t storage = 0;
    const double pixels = double(w) * h;
    for (const auto& [name, bytes] : m_runner.pool().bytesByName()) {
        if (tech.isStorage(name)) {
            result.storageBytes[name] = bytes;
            storage += bytes;
            result.bytesPerPixelSplit[tech.storageCategory(name)] += double(bytes) / pixels;
        } else if (name.rfind("readback.", 0) != 0) {
            result.transientBytesPerPixel += double(bytes) / pixels;
        }
    }
    result.bytesPerPixel = double(storage) / pixels;
    result.transientBytesRequested = m_runner.pool().requestedBytes();
    result.transientBytesAllocated = m_runner.pool().allocatedBytes();
    result.aliasingSavedBytes = result.transientBytesRequested - result.transientBytesAllocated;

    result.hdr = readImage(m_device, hdrHost, w, h);
    result.display = readImage(m_device, displayHost, w, h);
    vk::invalidateBuffer(m_device, eventsHost);
    result.shadingEvents.resize(size_t(w) * h);
    std::memcpy(result.shadingEvents.data(), eventsHost.mapped, result.shadingEvents.size() * 4);
    uint64_t sum = 0;
    for (uint32_t e : result.shadingEvents) {
        sum += e;
        result.shadingEventsMax = std::max(result.shadingEventsMax, e);
    }
    result.shadingEventsMean = double(sum) / double(result.shadingEvents.size());
    result.shadingEventsHistogram.assign(result.shadingEventsMax + 1, 0);
    for (uint32_t e : result.shadingEvents)
        result.shadingEventsHistogram[e] += 1;
    if (targets.lostSamples.valid()) {
        vk::invalidateBuffer(m_device, host.lost);
        std::vector<uint32_t> lost(size_t(w) * h);
        std::memcpy(lost.data(), host.lost.mapped, lost.size() * 4);
        uint64_t lostSum = 0;
        for (uint32_t l : lost) {
            lostSum += l;
            result.pixelsWithLostCoverage += l > 0 ? 1 : 0;
        }
        result.lostCoverageFraction = double(lostSum) / (pixels * double(tech.samples()));
    }
    if (targets.perSampleShaded.valid()) {
        vk::invalidateBuffer(m_device, host.perSample);
        std::vector<uint32_t> flags(size_t(w) * h);
        std::memcpy(flags.data(), host.perSample.mapped, flags.size() * 4);
        uint64_t flagged = 0, flaggedSamples = 0, flaggedEvents = 0;
        for (size_t p = 0; p < flags.size(); ++p)
            if (flags[p]) {
                ++flagged;
                flaggedSamples += uint64_t(std::popcount(flags[p]));
                flaggedEvents += result.shadingEvents[p];
            }
        result.perSampleShading = RenderResult::PerSampleShading{
            double(flagged) / pixels, double(flaggedSamples) / (pixels * double(tech.samples())),
            sum ? double(flaggedEvents) / double(sum) : 0.0};
        result.perSampleMembers = std::move(flags);
    }
    return result;
}

} // namespace agaa
