#include "result_io.h"

#include "engine/io/io_error.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace agaa::bench {

using nlohmann::json;

namespace {

double quantile(const std::vector<double>& sorted, double q) {
    // Linear interpolation between closest ranks.
    if (sorted.empty()) return 0.0;
    const double pos = q * double(sorted.size() - 1);
    const size_t lo = size_t(std::floor(pos)), hi = std::min(lo + 1, sorted.size() - 1);
    return sorted[lo] + (sorted[hi] - sorted[lo]) * (pos - double(lo));
}

json spreadJson(const Spread& s) {
    return {{"median", s.median}, {"min", s.min}, {"max", s.max},
            {"q1", s.q1},         {"q3", s.q3},   {"samples", s.samples}};
}

Spread spreadFromJson(const json& j) {
    return makeSpread(j.at("samples").get<std::vector<double>>());
}

// JSON has no infinity: an identical image's PSNR is written as null.
json numberOrNull(double v) {
    return std::isfinite(v) ? json(v) : json(nullptr);
}

json errorJson(const std::optional<ErrorMetrics>& e) {
    if (!e) return nullptr;
    json j = {
        {"rmse", e->rmse}, {"psnr_db", numberOrNull(e->psnr)}, {"ssim", e->ssim}, {"p99_abs_error", e->p99}};
    if (e->flip) j["flip"] = *e->flip;
    return j;
}

std::optional<ErrorMetrics> errorFromJson(const json& j) {
    if (j.is_null()) return std::nullopt;
    ErrorMetrics e;
    e.rmse = j.at("rmse").get<double>();
    e.psnr =
        j.at("psnr_db").is_null() ? std::numeric_limits<double>::infinity() : j.at("psnr_db").get<double>();
    e.ssim = j.at("ssim").get<double>();
    e.p99 = j.at("p99_abs_error").get<double>();
    if (j.contains("flip")) e.flip = j.at("flip").get<double>();
    return e;
}

std::string csvNumber(double v) {
    if (!std::isfinite(v)) return v > 0 ? "inf" : "";
    std::ostringstream s;
    s.precision(9);
    s << v;
    return s.str();
}

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s)
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

} // namespace

Spread makeSpread(std::vector<double> samples) {
    Spread s;
    s.samples = samples;
    std::sort(samples.begin(), samples.end());
    if (samples.empty()) return s;
    s.min = samples.front();
    s.max = samples.back();
    s.median = quantile(samples, 0.5);
    s.q1 = quantile(samples, 0.25);
    s.q3 = quantile(samples, 0.75);
    return s;
}

json toJson(const JobResult& r) {
    json j;
    j["schema"] = kJobSchema;
    j["id"] = r.job.id();
    j["scene"] = r.job.scene;
    j["method"] = r.job.method;
    j["samples"] = r.job.samples;
    j["aggregates"] = r.job.aggregates;
    j["surfaces"] = r.job.surfaces;
    j["tolerance"] = r.job.tolerance;
    j["specular_aa"] = r.job.specularAA;
    j["uses_samples"] = r.job.usesSamples;
    j["uses_aggregates"] = r.job.usesAggregates;
    j["plan_index"] = r.job.index;
    j["samples_rendered"] = r.samplesRendered;
    j["width"] = r.width;
    j["height"] = r.height;
    j["frames_timed"] = r.timedFrames;
    j["frames_warmup"] = r.warmupFrames;
    json passes = json::array();
    for (const PassTime& p : r.passes)
        passes.push_back({{"name", p.name}, {"gpu_ms", spreadJson(p.ms)}});
    j["timing"] = {{"device", r.device},
                   {"frame_gpu_ms", spreadJson(r.frameMs)},
                   {"frame_span_gpu_ms", r.frameSpanMs},
                   {"passes", passes},
                   {"wall_s", r.wallSeconds}};
    j["bytes_per_pixel"] = r.bytesPerPixel;
    j["storage_bytes"] = r.storageBytes;
    j["shading_events_per_pixel"] = {{"mean", r.shadingEventsMean},
                                     {"max", r.shadingEventsMax},
                                     {"worst_lane_mean", r.shadingEventsWorstLane}};
    j["passes_culled"] = r.culledPasses;
    j["validation"] = {{"enabled", r.validationEnabled}, {"errors", r.validationErrors}};
    j["error_vs_same_n_reference"] = errorJson(r.errorSameN);
    j["truth"] = {{"supersampling", r.truth.supersampling},
                  {"samples", r.truth.samples},
                  {"error_estimate",
                   std::isfinite(r.truth.errorEstimate) ? json(r.truth.errorEstimate) : json(nullptr)},
                  {"mean_luminance", r.truth.meanLuminance}};
    j["error_vs_truth"] = errorJson(r.errorTruth);
    j["mean_luminance"] = r.meanLuminance;
    if (r.temporal) {
        const TemporalStability& t = *r.temporal;
        j["temporal"] = {{"frames", t.frames},
                         {"path", t.path},
                         {"step_degrees", t.stepDegrees},
                         {"step_fraction", t.stepFraction},
                         {"width", t.width},
                         {"height", t.height},
                         {"mean_error_change", t.meanErrorChange},
                         {"per_step", t.perStep},
                         {"mean_path_error", t.meanPathError},
                         {"path_error", t.pathError},
                         {"ghosting_error", t.ghostingError},
                         {"mean_path_flip", t.meanPathFlip},
                         {"disoccluded_pixels", t.disoccludedPixels}};
    } else {
        j["temporal"] = nullptr;
    }
    j["images"] = {{"display", r.imageDisplay},
                   {"heatmap", r.imageHeatmap},
                   {"truth", r.imageTruth},
                   {"heatmap_scale", r.heatmapScale}};
    return j;
}

JobResult jobFromJson(const json& j) {
    try {
        if (j.at("schema").get<std::string>() != kJobSchema)
            throw std::runtime_error("schema is not " + std::string(kJobSchema));
        JobResult r;
        r.job.scene = j.at("scene").get<std::string>();
        r.job.method = j.at("method").get<std::string>();
        r.job.samples = j.at("samples").get<uint32_t>();
        r.job.aggregates = j.at("aggregates").get<uint32_t>();
        r.job.surfaces = j.value("surfaces", 0u);              // absent in results written before the S axis
        r.job.tolerance = j.value("tolerance", std::string()); // and before the tolerance axis
        r.job.specularAA = j.value("specular_aa", false);      // and before the specular-AA axis
        r.job.usesSamples = j.at("uses_samples").get<bool>();
        r.job.usesAggregates = j.at("uses_aggregates").get<bool>();
        r.job.index = j.at("plan_index").get<size_t>();
        if (j.at("id").get<std::string>() != r.job.id())
            throw std::runtime_error("id does not match its fields");
        r.samplesRendered = j.at("samples_rendered").get<uint32_t>();
        r.width = j.at("width").get<uint32_t>();
        r.height = j.at("height").get<uint32_t>();
        r.timedFrames = j.at("frames_timed").get<uint32_t>();
        r.warmupFrames = j.at("frames_warmup").get<uint32_t>();
        const json& t = j.at("timing");
        r.device = t.at("device").get<std::string>();
        r.frameMs = spreadFromJson(t.at("frame_gpu_ms"));
        r.frameSpanMs = t.at("frame_span_gpu_ms").get<double>();
        for (const json& p : t.at("passes"))
            r.passes.push_back({p.at("name").get<std::string>(), spreadFromJson(p.at("gpu_ms"))});
        r.wallSeconds = t.at("wall_s").get<double>();
        r.bytesPerPixel = j.at("bytes_per_pixel").get<double>();
        r.storageBytes = j.at("storage_bytes").get<std::map<std::string, uint64_t>>();
        r.shadingEventsMean = j.at("shading_events_per_pixel").at("mean").get<double>();
        r.shadingEventsMax = j.at("shading_events_per_pixel").at("max").get<uint32_t>();
        r.shadingEventsWorstLane = j.at("shading_events_per_pixel").value("worst_lane_mean", 0.0);
        r.culledPasses = j.at("passes_culled").get<std::vector<std::string>>();
        r.validationEnabled = j.at("validation").at("enabled").get<bool>();
        r.validationErrors = j.at("validation").at("errors").get<uint32_t>();
        r.errorSameN = errorFromJson(j.at("error_vs_same_n_reference"));
        const json& truth = j.at("truth");
        r.truth.supersampling = truth.at("supersampling").get<uint32_t>();
        r.truth.samples = truth.at("samples").get<uint32_t>();
        r.truth.errorEstimate = truth.at("error_estimate").is_null()
                                    ? std::numeric_limits<double>::infinity()
                                    : truth.at("error_estimate").get<double>();
        r.truth.meanLuminance = truth.at("mean_luminance").get<double>();
        r.errorTruth = errorFromJson(j.at("error_vs_truth"));
        r.meanLuminance = j.at("mean_luminance").get<double>();
        if (!j.at("temporal").is_null()) {
            const json& tj = j.at("temporal");
            TemporalStability ts;
            ts.frames = tj.at("frames").get<uint32_t>();
            ts.stepDegrees = tj.at("step_degrees").get<float>();
            ts.path = tj.value("path", std::string("orbit")); // the orbit was the only path before
            ts.stepFraction = tj.value("step_fraction", 0.0f);
            ts.width = tj.at("width").get<uint32_t>();
            ts.height = tj.at("height").get<uint32_t>();
            ts.meanErrorChange = tj.at("mean_error_change").get<double>();
            ts.perStep = tj.at("per_step").get<std::vector<double>>();
            ts.meanPathError = tj.value("mean_path_error", 0.0);
            ts.pathError = tj.value("path_error", std::vector<double>());
            ts.ghostingError = tj.value("ghosting_error", 0.0);
            ts.meanPathFlip = tj.value("mean_path_flip", 0.0);
            ts.disoccludedPixels = tj.value("disoccluded_pixels", uint64_t(0));
            r.temporal = ts;
        }
        const json& im = j.at("images");
        r.imageDisplay = im.at("display").get<std::string>();
        r.imageHeatmap = im.at("heatmap").get<std::string>();
        r.imageTruth = im.at("truth").get<std::string>();
        r.heatmapScale = im.at("heatmap_scale").get<float>();
        return r;
    } catch (const json::exception& e) {
        throw std::runtime_error(std::string("not a benchmark job result: ") + e.what());
    }
}

void writeTextFile(const std::filesystem::path& file, const std::string& text) {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    std::ofstream f(file, std::ios::binary);
    f << text;
    if (!f) throw eng::io::IoError("cannot write " + file.string());
}

void writeJobFile(const std::filesystem::path& outDir, const JobResult& r) {
    writeTextFile(outDir / "jobs" / (r.job.id() + ".json"), toJson(r).dump(2) + "\n");
}

JobResult readJobFile(const std::filesystem::path& file) {
    std::ifstream f(file);
    if (!f) throw eng::io::IoError("cannot read " + file.string());
    try {
        return jobFromJson(json::parse(f));
    } catch (const std::exception& e) {
        throw eng::io::IoError(file.string() + ": " + e.what());
    }
}

void writeResultsJson(const std::filesystem::path& file, const std::vector<JobResult>& results) {
    json jobs = json::array();
    for (const JobResult& r : results)
        jobs.push_back(toJson(r));
    json j = {{"schema", kResultsSchema},
              {"metrics_note",
               "error metrics are computed on the tone-mapped display image, sRGB-encoded, in [0,1]"},
              {"jobs", jobs}};
    writeTextFile(file, j.dump(2) + "\n");
}

void writeResultsCsv(const std::filesystem::path& file, const std::vector<JobResult>& results) {
    std::ostringstream s;
    s << "id,scene,method,samples,aggregates,samples_rendered,width,height,frames_timed,frame_ms_median,"
         "frame_ms_min,frame_ms_max,frame_ms_q1,frame_ms_q3,bytes_per_pixel,shading_events_mean,"
         "shading_events_max,rmse_same_n,psnr_same_n,ssim_same_n,p99_same_n,rmse_truth,psnr_truth,ssim_truth,"
         "p99_truth,truth_error_estimate,temporal_error_change,validation_errors,passes,surfaces,"
         "shading_events_worst_lane,mean_luminance,truth_mean_luminance,truth_supersampling,tolerance,"
         "specular_aa,path_rmse_truth,ghosting_rmse_truth,flip_truth,path_flip_truth\n";
    for (const JobResult& r : results) {
        auto err = [&](const std::optional<ErrorMetrics>& e) {
            if (!e) return std::string(",,,");
            return csvNumber(e->rmse) + "," + csvNumber(e->psnr) + "," + csvNumber(e->ssim) + "," +
                   csvNumber(e->p99);
        };
        std::string passes;
        for (const PassTime& p : r.passes)
            passes += (passes.empty() ? "" : ";") + p.name + "=" + csvNumber(p.ms.median);
        s << csvField(r.job.id()) << "," << csvField(r.job.scene) << "," << csvField(r.job.method) << ","
          << r.job.samples << "," << r.job.aggregates << "," << r.samplesRendered << "," << r.width << ","
          << r.height << "," << r.timedFrames << "," << csvNumber(r.frameMs.median) << ","
          << csvNumber(r.frameMs.min) << "," << csvNumber(r.frameMs.max) << "," << csvNumber(r.frameMs.q1)
          << "," << csvNumber(r.frameMs.q3) << "," << csvNumber(r.bytesPerPixel) << ","
          << csvNumber(r.shadingEventsMean) << "," << r.shadingEventsMax << "," << err(r.errorSameN) << ","
          << err(r.errorTruth) << "," << csvNumber(r.truth.errorEstimate) << ","
          << (r.temporal ? csvNumber(r.temporal->meanErrorChange) : "") << "," << r.validationErrors << ","
          << csvField(passes) << "," << r.job.surfaces << "," << csvNumber(r.shadingEventsWorstLane) << ","
          << csvNumber(r.meanLuminance) << "," << csvNumber(r.truth.meanLuminance) << ","
          << r.truth.supersampling << "," << csvField(r.job.tolerance) << "," << (r.job.specularAA ? 1 : 0)
          << "," << (r.temporal && !r.temporal->pathError.empty() ? csvNumber(r.temporal->meanPathError) : "")
          << "," << (r.temporal && r.temporal->disoccludedPixels ? csvNumber(r.temporal->ghostingError) : "")
          << "," << (r.errorTruth && r.errorTruth->flip ? csvNumber(*r.errorTruth->flip) : "") << ","
          << (r.temporal && !r.temporal->pathError.empty() ? csvNumber(r.temporal->meanPathFlip) : "")
          << "\n";
    }
    writeTextFile(file, s.str());
}

} // namespace agaa::bench
