#pragma once
// The paper's and talks' headline figures (seeds/README.md, GTX 980, 1280x720)
// beside the same ratios measured in this run. A claim whose methods or
// settings the run lacks reads "not measured"; nothing is filled in from the
// quotes.

#include "result_io.h"

#include <optional>
#include <string>
#include <vector>

namespace agaa::bench {

struct ClaimRow {
    std::string claim;                 // what is compared, in the paper's words
    std::string quoted;                // the figure as quoted, with its source
    std::string measured;              // "2.4x (min over scenes) .. 3.1x (max)" or "not measured"
    std::vector<std::string> perScene; // "plane: 2.4x" for every scene that has both sides
    std::string missing;               // what the run lacks when not measured
};

// The shading pass of a job: the sum of the median times of its passes whose name contains
// "light" or "shad" (the tiled-deferred lighting / shading pass of each method); empty when none.
std::optional<double> shadingPassMs(const JobResult& r);

std::vector<ClaimRow> measureClaims(const std::vector<JobResult>& results);

} // namespace agaa::bench
