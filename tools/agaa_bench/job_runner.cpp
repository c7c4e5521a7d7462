#include "job_runner.h"

#include "disocclusion.h"
#include "shading_lanes.h"

#include "agaa/method_settings.h"

#include "engine/frame/frame_constants.h"
#include "engine/io/flip.h"
#include "engine/io/metrics.h"
#include "engine/io/png.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/extra_lights.h"
#include "engine/scene/gltf_loader.h"
#include "tools/scenes/adversarial_scenes.h"

#include <chrono>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace agaa::bench {

namespace {

// Error 0.25 (a quarter of the display range) shows as white in the heatmaps.
constexpr float kHeatmapScale = 4.0f;

const std::string kReference = "reference";

ErrorMetrics identical() {
    ErrorMetrics e;
    e.rmse = 0.0;
    e.psnr = std::numeric_limits<double>::infinity();
    e.ssim = 1.0;
    e.p99 = 0.0;
    e.flip = 0.0;
    return e;
}

void writeDisplayPng(const std::filesystem::path& file, const eng::io::ImageF& srgb) {
    std::filesystem::create_directories(file.parent_path());
    eng::io::writePng(file, eng::io::quantizeToU8(srgb));
}

} // namespace

JobRunner::JobRunner(eng::vk::Device& device, const SweepSettings& settings, std::filesystem::path outDir)
    : m_device(device), m_settings(settings), m_outDir(std::move(outDir)), m_truthCache(settings.truthCache) {
}

JobRunner::~JobRunner() {
    m_scene.renderer.reset(); // before the scene it points at
}

void JobRunner::selectScene(const std::string& name) {
    if (m_scene.name == name && m_scene.renderer) return;
    m_scene.renderer.reset();
    m_scene = SceneState{};
    m_scene.name = name;
    const SceneVariant variant = parseSceneVariant(name);
    if (const std::optional<std::filesystem::path> file = realScenePath(variant.base)) {
        m_scene.scene = std::make_unique<eng::scene::Scene>(eng::scene::loadGltf(*file));
        eng::scene::applyLighting(*m_scene.scene, eng::scene::LightingMode::Automatic);
    } else {
        m_scene.scene = std::make_unique<eng::scene::Scene>(eng::scene::loadTestScene(variant.base));
    }
    eng::scene::addExtraLights(*m_scene.scene, variant.extraLights);
    m_scene.renderer = std::make_unique<FrameRenderer>(m_device, *m_scene.scene);
}

namespace {

// The same-n reference and the truth's request: the reference with the sweep's given settings
// and no axis.
Job referenceJob(uint32_t samples) {
    Job j;
    j.method = kReference;
    j.samples = samples;
    return j;
}

} // namespace

RenderRequest JobRunner::request(const Job& job, uint32_t width, uint32_t height, uint32_t pathFrame) const {
    RenderRequest r;
    r.method = job.method;
    for (const std::string& name : m_settings.givenSettings) {
        const MethodOption& option = *findMethodOption(name);
        if (methodReadsOption(option, job.method))
            option.set(r.settings, option.get(m_settings.methodSettings));
    }
    r.settings.samples = job.samples;
    r.settings.surfaces = job.surfaces; // 0: the method's default
    if (!job.tolerance.empty())
        setMethodOption(r.settings, *findMethodOption("agaa-tolerance"), job.tolerance);
    if (job.specularAA) r.settings.effects.curvatureRoughness.enabled = true;
    if (job.aggregates != kAggregatesWhenUnused) r.settings.aggregates = job.aggregates;
    r.view.width = width;
    r.view.height = height;
    // A real scene gives no exposure: metered, the same for every method of the sweep.
    r.autoExposure = !m_scene.scene->exposure.has_value();
    if (pathFrame > 0) {
        const eng::scene::Scene& s = *m_scene.scene;
        const glm::mat4& view = s.cameras.at(r.view.camera).view;
        const float t = float(pathFrame);
        if (m_settings.temporalPath == SweepSettings::TemporalPath::Truck)
            r.view.viewOverride = eng::frame::truckView(view, t * m_settings.temporalTruckFraction *
                                                                  glm::length(s.bounds.max - s.bounds.min));
        else
            r.view.viewOverride = eng::frame::orbitView(view, 0.5f * (s.bounds.min + s.bounds.max),
                                                        t * m_settings.temporalStepDegrees);
    }
    return r;
}

RenderResult JobRunner::renderTruth(const RenderRequest& request) {
    const uint32_t before = m_device.validationErrors();
    RenderResult result = m_scene.renderer->render(request);
    m_truthValidationErrors += m_device.validationErrors() - before;
    return result;
}

ConvergedTruth JobRunner::renderConverged(const RenderRequest& request) {
    const uint32_t before = m_device.validationErrors();
    TruthSettings settings;
    settings.supersampling = m_settings.truthSupersampling;
    ConvergedTruth truth = renderConvergedTruth(*m_scene.renderer, request, settings, &m_truthCache);
    m_truthValidationErrors += m_device.validationErrors() - before;
    return truth;
}

const eng::io::ImageF& JobRunner::referenceAtSamples(uint32_t samples) {
    auto it = m_scene.referenceAtSamples.find(samples);
    if (it != m_scene.referenceAtSamples.end()) return it->second;
    RenderResult r = renderTruth(request(referenceJob(samples), m_settings.width, m_settings.height, 0));
    it = m_scene.referenceAtSamples.emplace(samples, srgbEncoded(r.display)).first;
    return it->second;
}

const ConvergedTruth& JobRunner::truth() {
    if (!m_scene.truth) {
        m_scene.truth = renderConverged(request(referenceJob(32), m_settings.width, m_settings.height, 0));
        m_scene.truthDisplay = srgbEncoded(m_scene.truth->display);
        const ConvergedTruth& t = *m_scene.truth;
        std::printf("\n  truth for %s: %ux%u tiles at n=%u, error estimate %.5f, mean %.4f%s\n  ",
                    m_scene.name.c_str(), t.settings.supersampling, t.settings.supersampling,
                    t.settings.samples, t.errorEstimate, t.meanLuminance, t.fromCache ? " (cached)" : "");
    }
    return *m_scene.truth;
}

const std::vector<eng::io::ImageF>& JobRunner::pathTruth() {
    if (m_scene.pathTruth.empty()) {
        uint32_t w = 0, h = 0;
        temporalSize(m_settings, w, h);
        for (uint32_t t = 0; t < m_settings.temporalFrames; ++t) {
            const ConvergedTruth truth = renderConverged(request(referenceJob(32), w, h, t));
            m_scene.pathTruth.push_back(srgbEncoded(truth.display));
        }
    }
    return m_scene.pathTruth;
}

const std::vector<std::vector<uint8_t>>& JobRunner::pathDisocclusion() {
    if (m_scene.pathDisocclusion.empty()) {
        uint32_t w = 0, h = 0;
        temporalSize(m_settings, w, h);
        // Temporal AA's motion view along the path, from its first frame (it keeps its history
        // between requests): each frame's reprojection into the one before, and its own distances.
        Job motion;
        motion.method = "taa";
        motion.samples = 1;
        eng::io::ImageF previousDistance;
        for (uint32_t t = 0; t < m_settings.temporalFrames; ++t) {
            RenderRequest r = request(motion, w, h, t);
            r.settings.debug = "motion";
            if (t == 0) m_scene.renderer->technique(r).resetHistory();
            RenderResult view = renderTruth(r);
            m_scene.pathDisocclusion.push_back(t == 0 ? std::vector<uint8_t>()
                                                      : disoccludedPixels(view.hdr, previousDistance));
            previousDistance = std::move(view.display);
        }
    }
    return m_scene.pathDisocclusion;
}

std::vector<eng::io::ImageF> JobRunner::renderPath(const Job& job) {
    uint32_t w = 0, h = 0;
    temporalSize(m_settings, w, h);
    std::vector<eng::io::ImageF> frames;
    for (uint32_t t = 0; t < m_settings.temporalFrames; ++t) {
        RenderResult r = m_scene.renderer->render(request(job, w, h, t));
        frames.push_back(srgbEncoded(r.display));
    }
    return frames;
}

JobResult JobRunner::run(const Job& job) {
    selectScene(job.scene);
    const auto start = std::chrono::steady_clock::now();
    const uint32_t validationBefore = m_device.validationErrors();

    RenderRequest req = request(job, m_settings.width, m_settings.height, 0);
    req.warmupFrames = m_settings.warmupFrames;
    req.timedFrames = m_settings.timedFrames;
    RenderResult rendered = m_scene.renderer->render(req);
    if (!eng::io::allFinite(rendered.hdr) || !eng::io::allFinite(rendered.display))
        throw std::runtime_error(job.id() + ": the frame contains NaN or Inf");
    std::vector<eng::io::ImageF> path;
    if (m_settings.temporalFrames >= 2) path = renderPath(job);
    uint32_t validationErrors = m_device.validationErrors() - validationBefore;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    JobResult r;
    r.job = job;
    r.samplesRendered = rendered.samples;
    r.width = m_settings.width;
    r.height = m_settings.height;
    r.timedFrames = m_settings.timedFrames;
    r.warmupFrames = m_settings.warmupFrames;
    r.device = m_device.caps().deviceName;
    r.wallSeconds = wall;
    // Frame time per timed frame = the sum of its pass times, so its spread is known;
    // the runner's first-start-to-last-end span is kept beside it.
    std::vector<double> frameSums(rendered.passSamples.empty() ? 0 : rendered.passSamples[0].size(), 0.0);
    for (size_t p = 0; p < rendered.passes.size(); ++p) {
        r.passes.push_back({rendered.passes[p].name, makeSpread(rendered.passSamples[p])});
        for (size_t t = 0; t < frameSums.size() && t < rendered.passSamples[p].size(); ++t)
            frameSums[t] += rendered.passSamples[p][t];
    }
    r.frameMs = makeSpread(frameSums);
    r.frameSpanMs = rendered.frameGpuMs;
    r.bytesPerPixel = rendered.bytesPerPixel;
    r.storageBytes = rendered.storageBytes;
    r.shadingEventsMean = rendered.shadingEventsMean;
    r.shadingEventsMax = rendered.shadingEventsMax;
    r.shadingEventsWorstLane =
        worstLaneEventsPerPixel(rendered.shadingEvents, m_settings.width, m_settings.height);
    r.culledPasses = rendered.culledPasses;
    r.validationEnabled = m_device.validationEnabled();
    r.validationErrors = validationErrors;
    const ConvergedTruth& converged = truth();
    r.truth.supersampling = converged.settings.supersampling;
    r.truth.samples = converged.settings.samples;
    r.truth.errorEstimate = converged.errorEstimate;
    r.truth.meanLuminance = converged.meanLuminance;
    r.meanLuminance = meanLuminance(rendered.hdr);

    const eng::io::ImageF display = srgbEncoded(rendered.display);
    if (job.method == kReference && !job.specularAA) {
        // The reference is itself the same-n measure: error 0 by definition. Keep its image for it.
        r.errorSameN = identical();
        m_scene.referenceAtSamples.emplace(job.samples, display);
    } else if (job.usesSamples) {
        r.errorSameN = compareImages(display, referenceAtSamples(job.samples));
    }
    const eng::io::ImageF& truthDisplay = m_scene.truthDisplay;
    r.errorTruth = compareImages(display, truthDisplay);
    if (!path.empty()) {
        TemporalStability t;
        t.frames = m_settings.temporalFrames;
        const bool truck = m_settings.temporalPath == SweepSettings::TemporalPath::Truck;
        t.path = truck ? "truck" : "orbit";
        t.stepDegrees = truck ? 0.0f : m_settings.temporalStepDegrees;
        t.stepFraction = truck ? m_settings.temporalTruckFraction : 0.0f;
        t.width = path[0].width;
        t.height = path[0].height;
        const std::vector<eng::io::ImageF>& truths = pathTruth();
        t.perStep = temporalErrorChange(path, truths);
        for (double v : t.perStep)
            t.meanErrorChange += v / double(t.perStep.size());
        for (size_t f = 0; f < path.size(); ++f) {
            t.pathError.push_back(eng::io::rmse(path[f], truths[f]));
            t.meanPathFlip += eng::io::flipMean(truths[f], path[f]) / double(path.size());
        }
        for (double v : t.pathError)
            t.meanPathError += v / double(t.pathError.size());
        const MaskedError ghosting = maskedError(path, truths, pathDisocclusion());
        t.ghostingError = ghosting.rmse;
        t.disoccludedPixels = ghosting.pixels;
        r.temporal = t;
    }

    // Images, relative to the output directory (the report references them as files).
    const std::string size = std::to_string(m_settings.width) + "x" + std::to_string(m_settings.height);
    r.imageTruth = "images/" + job.scene + "__truth_k" + std::to_string(converged.settings.supersampling) +
                   "_" + size + ".png";
    if (m_scene.truthImage.empty()) {
        writeDisplayPng(m_outDir / r.imageTruth, truthDisplay);
        m_scene.truthImage = r.imageTruth;
    }
    r.imageDisplay = "images/" + job.id() + "_" + size + ".png";
    r.imageHeatmap = "images/" + job.id() + "_" + size + "__error.png";
    r.heatmapScale = kHeatmapScale;
    writeDisplayPng(m_outDir / r.imageDisplay, display);
    writeDisplayPng(m_outDir / r.imageHeatmap, eng::io::errorHeatmap(display, truthDisplay, kHeatmapScale));
    return r;
}

} // namespace agaa::bench
