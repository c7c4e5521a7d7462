#include "claims.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <functional>
#include <set>

namespace agaa::bench {

namespace {

const char* kAgaa = "agaa";
const char* kSimpleComplex = "simple-complex";
const char* kReference = "reference";
constexpr uint32_t kPaperAggregates = 2;

std::string lower(std::string s) {
    for (char& c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

const JobResult* find(const std::vector<JobResult>& results, const std::string& scene,
                      const std::string& method, uint32_t samples, std::optional<uint32_t> aggregates) {
    for (const JobResult& r : results) {
        if (r.job.scene != scene || r.job.method != method) continue;
        if (r.job.usesSamples && r.job.samples != samples) continue;
        if (aggregates && r.job.usesAggregates && r.job.aggregates != *aggregates) continue;
        return &r;
    }
    return nullptr;
}

std::string format(const char* fmt, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, fmt, v);
    return buf;
}

// Per scene: value(numerator job, denominator job); the row spans the scenes that have both.
using Measure = std::function<std::optional<double>(const JobResult& agaa, const JobResult& other)>;

ClaimRow compare(const std::vector<JobResult>& results, ClaimRow row, const std::string& other,
                 uint32_t samples, const Measure& measure, const char* fmt) {
    std::vector<std::string> scenes;
    for (const JobResult& r : results)
        if (std::find(scenes.begin(), scenes.end(), r.job.scene) == scenes.end())
            scenes.push_back(r.job.scene);
    std::vector<double> values;
    for (const std::string& scene : scenes) {
        const JobResult* a = find(results, scene, kAgaa, samples, kPaperAggregates);
        const JobResult* b = find(results, scene, other, samples, std::nullopt);
        if (!a || !b) continue;
        std::optional<double> v = measure(*a, *b);
        if (!v) continue;
        values.push_back(*v);
        row.perScene.push_back(scene + ": " + format(fmt, *v));
    }
    if (values.empty()) {
        row.measured = "not measured";
        row.missing = std::string(kAgaa) + " (n=" + std::to_string(samples) + ", c=2) and " + other +
                      " (n=" + std::to_string(samples) + ") on the same scene";
        return row;
    }
    const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
    row.measured = values.size() == 1 ? format(fmt, *lo)
                                      : format(fmt, *lo) + " .. " + format(fmt, *hi) + " over " +
                                            std::to_string(values.size()) + " scenes";
    return row;
}

std::optional<double> speedup(std::optional<double> slow, std::optional<double> fast) {
    if (!slow || !fast || *fast <= 0.0) return std::nullopt;
    return *slow / *fast;
}

} // namespace

std::optional<double> shadingPassMs(const JobResult& r) {
    double sum = 0.0;
    bool any = false;
    for (const PassTime& p : r.passes) {
        // The shading pass is the one that lights the samples or aggregates ("<method>.lighting");
        // shadow-map passes ("<method>.shadow") render depth and are not shading.
        const std::string n = lower(p.name);
        const std::string suffix = ".lighting";
        if (n.size() < suffix.size() || n.compare(n.size() - suffix.size(), suffix.size(), suffix) != 0)
            continue;
        sum += p.ms.median;
        any = true;
    }
    return any ? std::optional<double>(sum) : std::nullopt;
}

std::vector<ClaimRow> measureClaims(const std::vector<JobResult>& results) {
    const Measure shading = [](const JobResult& a, const JobResult& o) {
        return speedup(shadingPassMs(o), shadingPassMs(a));
    };
    const Measure frame = [](const JobResult& a, const JobResult& o) {
        return speedup(o.frameMs.median, a.frameMs.median);
    };
    const Measure memory = [](const JobResult& a, const JobResult& o) -> std::optional<double> {
        if (o.bytesPerPixel <= 0.0) return std::nullopt;
        return 100.0 * (a.bytesPerPixel / o.bytesPerPixel - 1.0);
    };
    const std::string paper = "quoted from the paper/talk (GTX 980, OpenGL, 1280x720): ";
    const std::string ue4 = "quoted from the UE4 talk notes: ";
    std::vector<ClaimRow> rows;
    rows.push_back(compare(
        results, {"AGAA (8x, c=2) shading pass vs Simple/Complex, speed-up", paper + "2.1x to 3.5x faster"},
        kSimpleComplex, 8, shading, "%.2fx"));
    rows.push_back(compare(
        results, {"AGAA (8x, c=2) whole frame vs Simple/Complex, speed-up", paper + "1.0x to 1.74x faster"},
        kSimpleComplex, 8, frame, "%.2fx"));
    rows.push_back(compare(
        results, {"AGAA (32x, c=2) shading pass vs Simple/Complex, speed-up", paper + "2.2x to 9.2x faster"},
        kSimpleComplex, 32, shading, "%.2fx"));
    rows.push_back(compare(
        results, {"AGAA (32x, c=2) whole frame vs Simple/Complex, speed-up", paper + "up to 2.53x faster"},
        kSimpleComplex, 32, frame, "%.2fx"));
    rows.push_back(
        compare(results,
                {"AGAA (8x, c=2) storage vs per-sample G-buffer (reference), bytes per pixel change",
                 paper + "about -37% (16 B per aggregate + 6 B per sample vs 16 B per sample)"},
                kReference, 8, memory, "%+.0f%%"));
    rows.push_back(
        compare(results,
                {"AGAA (16x, c=2) storage vs per-sample G-buffer (reference), bytes per pixel change",
                 paper + "about -50%"},
                kReference, 16, memory, "%+.0f%%"));
    rows.push_back(compare(
        results,
        {"AGAA (4x, c=2) lighting vs shading every sample (reference), speed-up", ue4 + "1.7x faster"},
        kReference, 4, shading, "%.2fx"));
    rows.push_back(compare(
        results,
        {"AGAA (8x, c=2) lighting vs shading every sample (reference), speed-up", ue4 + "2.6x faster"},
        kReference, 8, shading, "%.2fx"));
    return rows;
}

} // namespace agaa::bench
