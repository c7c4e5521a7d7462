#pragma once
// report.html: one self-contained page (Chart.js inlined, images referenced
// relative to the output directory, no network) with, per scene, the
// accuracy-vs-time and accuracy-vs-memory charts and their Pareto fronts, the
// per-pass time breakdown, growth with n, image comparisons where the methods
// differ most; the quoted-vs-measured claims; and a table of every job.

#include "result_io.h"

#include <filesystem>
#include <string>
#include <vector>

namespace agaa::bench {

// Chart.js (Debian libjs-chart.js): $AGAA_CHARTJS if set, else the path CMake found, else the
// Debian location. Throws eng::io::IoError naming the path and the package when it is missing.
std::filesystem::path findChartJs();

struct ReportInfo {
    std::string command;               // how the run was started, shown on the page
    std::vector<std::string> warnings; // from the merge, shown on the page
};

// Writes outDir/report.html. The images the results name must lie under outDir.
void writeReport(const std::filesystem::path& outDir, const std::vector<JobResult>& results,
                 const std::filesystem::path& chartJs, const ReportInfo& info);

} // namespace agaa::bench
