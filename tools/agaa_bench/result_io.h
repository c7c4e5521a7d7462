#pragma once
// One benchmark job's measurements as a plain struct, and its file forms: the
// per-job JSON (DIR/jobs/<id>.json, what split sweeps exchange), the merged
// results.json and results.csv. Everything that varies run to run on the same
// inputs (GPU times, wall time, device name) sits under "timing" in the JSON,
// so two runs can be compared by dropping that key.

#include "image_error.h"
#include "sweep_plan.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace agaa::bench {

// /2: errors against the converged truth (tools/harness/converged_truth.h) with its own error.
inline constexpr const char* kJobSchema = "agaa-bench-job/2";
inline constexpr const char* kResultsSchema = "agaa-bench-results/2";

// Median and spread over the timed frames (after warm-up), milliseconds.
struct Spread {
    double median = 0.0, min = 0.0, max = 0.0, q1 = 0.0, q3 = 0.0;
    std::vector<double> samples;
};
Spread makeSpread(std::vector<double> samples);

struct PassTime {
    std::string name;
    Spread ms;
};

struct TemporalStability {
    uint32_t frames = 0;
    float stepDegrees = 0.0f; // the orbit's step
    uint32_t width = 0, height = 0;
    double meanErrorChange = 0.0; // mean over steps (see temporalErrorChange)
    std::vector<double> perStep;
    // Display RMSE (sRGB) of each path frame against its own converged truth, and their mean: what
    // a user who moves sees (a temporal method's still frame has converged; its path frames carry
    // the history's lag). Empty in results written before it was measured.
    std::vector<double> pathError;
    double meanPathError = 0.0;
    // Ghosting (disocclusion.h): the display RMSE over the pixels each frame's predecessor did not
    // see, frames 1..T-1 pooled, and how many pixels that was (0: none were, or results written
    // before it was measured; the error is then not a figure).
    double ghostingError = 0.0;
    double meanPathFlip = 0.0; // the path frames' mean ꟻLIP against their truths (0 before it was measured)
    uint64_t disoccludedPixels = 0;
    std::string path = "orbit"; // SweepSettings::TemporalPath: "orbit" or "truck"
    float stepFraction = 0.0f;  // the truck's step, a fraction of the bounds' diagonal
};

// The converged truth a job's errors are measured against (tools/harness/converged_truth.h): the
// reference at n = samples with sample-rate shading, supersampled k x k.
struct TruthInfo {
    uint32_t supersampling = 4; // k
    uint32_t samples = 32;      // per sub-pixel
    // The truth's own display RMSE, estimated from its two halves; +infinity when unknown (k = 1).
    // An error difference between two methods below it is not a measured one.
    double errorEstimate = 0.0;
    double meanLuminance = 0.0; // its linear image mean (Rec. 709 luma)
};

struct JobResult {
    Job job;
    uint32_t samplesRendered = 0; // what the technique rasterised (1 for single-sample methods)
    uint32_t width = 0, height = 0;
    uint32_t timedFrames = 0, warmupFrames = 0;

    // Timing (under "timing" in the JSON): frame ms is the sum of the frame's pass times.
    std::string device;
    Spread frameMs;
    double frameSpanMs = 0.0; // median first-pass start to last-pass end, from the frame runner
    std::vector<PassTime> passes;
    double wallSeconds = 0.0; // this job's wall time on the host, truths excluded

    double bytesPerPixel = 0.0;
    std::map<std::string, uint64_t> storageBytes;
    double shadingEventsMean = 0.0;
    uint32_t shadingEventsMax = 0;
    // Figure 13's SIMD view: events per pixel when each 8-pixel lane group costs its worst pixel
    // (shading_lanes.h); 0 in results written before it was measured.
    double shadingEventsWorstLane = 0.0;
    std::vector<std::string> culledPasses;
    bool validationEnabled = false;
    uint32_t validationErrors = 0;

    // Against the reference at the same n (absent for methods that take no n); for the reference
    // itself 0 by definition, not rendered twice.
    std::optional<ErrorMetrics> errorSameN;
    TruthInfo truth;
    std::optional<ErrorMetrics> errorTruth; // against the converged truth, same size
    double meanLuminance = 0.0; // this frame's linear image mean (luma): energy against the truth's
    std::optional<TemporalStability> temporal;

    // Relative to the output directory.
    std::string imageDisplay, imageHeatmap, imageTruth;
    float heatmapScale = 4.0f;
};

nlohmann::json toJson(const JobResult& r);
// Throws std::runtime_error naming the field when the JSON is not a job result.
JobResult jobFromJson(const nlohmann::json& j);

void writeJobFile(const std::filesystem::path& outDir, const JobResult& r);
JobResult readJobFile(const std::filesystem::path& file);

// results.json: {"schema", "jobs": [...]} in the order given.
void writeResultsJson(const std::filesystem::path& file, const std::vector<JobResult>& results);
// results.csv: one row per job, flat columns, header first.
void writeResultsCsv(const std::filesystem::path& file, const std::vector<JobResult>& results);

// Writes text to a file, creating its directory; throws eng::io::IoError when it cannot.
void writeTextFile(const std::filesystem::path& file, const std::string& text);

} // namespace agaa::bench
