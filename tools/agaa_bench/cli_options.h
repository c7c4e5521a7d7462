#pragma once
// agaa-bench's command line: flags, their allowed values, and the defaults of
// the small sweep (fits in minutes on two CPU cores) and of --full (the
// paper's settings). Every refusal names the flag and what it allows.

#include "sweep_plan.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace agaa::bench {

struct BadArgument : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct BenchOptions {
    std::filesystem::path out;
    SweepSettings sweep;
    JobSlice slice;
    std::vector<std::filesystem::path> mergeDirs; // --merge: no rendering
    bool help = false;
    std::string command; // argv joined, for the report
};

// Throws BadArgument naming the flag and the allowed values.
BenchOptions parseOptions(int argc, char** argv);

std::string usage();

} // namespace agaa::bench
