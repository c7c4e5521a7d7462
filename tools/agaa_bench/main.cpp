// agaa-bench: one command that renders every method and setting on every
// scene, measures what each costs (GPU time per pass, memory) and what it buys
// (error against two ground truths, temporal stability), and writes the
// per-job JSON, the merged results and a self-contained HTML report.
// See usage() in cli_options.cpp for flags and exit codes.

#include "cli_options.h"
#include "job_runner.h"
#include "merge.h"
#include "report_html.h"

#include "agaa/methods.h"
#include "engine/io/io_error.h"
#include "engine/scene/scene_error.h"
#include "engine/vk/check.h"
#include "engine/vk/device.h"

#include <chrono>
#include <cstdio>
#include <iostream>

namespace {

namespace fs = std::filesystem;
using namespace agaa::bench;

constexpr int kExitFailed = 1;
constexpr int kExitBadInput = 2;
constexpr int kExitMissingCapability = 3;

std::string clock(double seconds) {
    const long s = long(seconds + 0.5);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
    return buf;
}

void writeOutputs(const fs::path& out, std::vector<JobResult> results, const fs::path& chartJs,
                  const std::string& command) {
    MergeOutcome merged = mergeResults(std::move(results));
    for (const std::string& w : merged.warnings)
        std::cerr << "agaa-bench: warning: " << w << "\n";
    writeResultsJson(out / "results.json", merged.results);
    writeResultsCsv(out / "results.csv", merged.results);
    writeReport(out, merged.results, chartJs, {command, merged.warnings});
    std::cout << "wrote " << (out / "results.json").string() << ", " << (out / "results.csv").string()
              << " and " << (out / "report.html").string() << " (" << merged.results.size() << " jobs)\n";
}

int runMerge(const BenchOptions& o, const fs::path& chartJs) {
    std::vector<JobResult> all;
    for (const fs::path& dir : o.mergeDirs) {
        std::vector<JobResult> jobs = readJobDir(dir);
        std::cout << "merge: " << jobs.size() << " jobs from " << dir.string() << "\n";
        importRunDir(dir, o.out);
        for (JobResult& r : jobs)
            all.push_back(std::move(r));
    }
    writeOutputs(o.out, std::move(all), chartJs, o.command);
    return 0;
}

int runSweep(const BenchOptions& o, const fs::path& chartJs) {
    const std::vector<Job> plan = planSweep(o.sweep);
    std::vector<Job> jobs;
    for (const Job& j : plan)
        if (o.slice.contains(j.index)) jobs.push_back(j);
    std::cout << "agaa-bench: " << jobs.size() << " of " << plan.size() << " jobs (" << o.sweep.scenes.size()
              << " scenes, " << o.sweep.methods.size() << " methods), " << o.sweep.width << "x"
              << o.sweep.height << ", " << o.sweep.warmupFrames << "+" << o.sweep.timedFrames
              << " frames, temporal path " << o.sweep.temporalFrames << " frames -> " << o.out.string()
              << "\n";

    eng::vk::DeviceOptions deviceOptions;
    deviceOptions.validation = o.sweep.validate;
    eng::vk::Device device(deviceOptions);
    JobRunner runner(device, o.sweep, o.out);
    fs::create_directories(o.out / "jobs");

    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    uint32_t failed = 0, validationErrors = 0, missing = 0;
    for (size_t i = 0; i < jobs.size(); ++i) {
        const Job& job = jobs[i];
        const double before = elapsed();
        const std::string eta = i == 0 ? "?" : clock(before / double(i) * double(jobs.size() - i));
        std::printf("[%zu/%zu] %-40s elapsed %s, ETA %s ... ", i + 1, jobs.size(), job.id().c_str(),
                    clock(before).c_str(), eta.c_str());
        std::fflush(stdout);
        try {
            JobResult r = runner.run(job);
            writeJobFile(o.out, r);
            validationErrors += r.validationErrors;
            std::printf("frame %.2f ms, %.1f B/px, RMSE %.4f (%.1f s)\n", r.frameMs.median, r.bytesPerPixel,
                        r.errorTruth ? r.errorTruth->rmse : 0.0, elapsed() - before);
        } catch (const eng::vk::MissingCapability& e) {
            ++missing;
            std::printf("skipped: the device lacks %s\n", e.what());
        } catch (const std::exception& e) {
            ++failed;
            std::printf("FAILED: %s\n", e.what());
        }
        std::fflush(stdout);
    }
    validationErrors += runner.truthValidationErrors();
    std::cout << "agaa-bench: " << jobs.size() << " jobs in " << clock(elapsed()) << " (" << failed
              << " failed, " << missing << " skipped for missing capabilities)\n";

    // The results: every job of this plan that has a file in DIR/jobs, so slices run one after
    // another into the same DIR add up, and files from an unrelated earlier sweep stay out.
    std::vector<JobResult> results;
    for (const Job& j : plan) {
        const fs::path file = o.out / "jobs" / (j.id() + ".json");
        if (fs::exists(file)) results.push_back(readJobFile(file));
    }
    writeOutputs(o.out, std::move(results), chartJs, o.command);
    if (validationErrors > 0) {
        std::cerr << "agaa-bench: " << validationErrors << " validation error(s)\n";
        for (const std::string& m : device.validationMessages())
            std::cerr << "  " << m << "\n";
        return kExitFailed;
    }
    if (missing > 0 && missing == jobs.size()) return kExitMissingCapability;
    return failed > 0 ? kExitFailed : 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        const BenchOptions o = parseOptions(argc, argv);
        if (o.help) {
            std::cout << usage() << "\nmethods:\n";
            for (const agaa::MethodInfo& m : agaa::knownMethods())
                std::cout << "  " << m.name << ": " << m.summary << (m.usesSamples ? " [n]" : "")
                          << (m.usesAggregates ? " [c]" : "") << "\n";
            return 0;
        }
        const fs::path chartJs = findChartJs(); // before hours of rendering, not after
        return o.mergeDirs.empty() ? runSweep(o, chartJs) : runMerge(o, chartJs);
    } catch (const BadArgument& e) {
        std::cerr << "agaa-bench: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const eng::io::IoError& e) {
        std::cerr << "agaa-bench: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const eng::scene::SceneError& e) {
        std::cerr << "agaa-bench: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const std::invalid_argument& e) {
        std::cerr << "agaa-bench: " << e.what() << "\n";
        return kExitBadInput;
    } catch (const eng::vk::MissingCapability& e) {
        std::cerr << "agaa-bench: the device lacks a required capability: " << e.what() << "\n";
        return kExitMissingCapability;
    }
}
