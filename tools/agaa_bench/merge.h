#pragma once
// Merging job results: from the per-job JSON files of one output directory, or
// of several (sweeps split with --job I/N, possibly on different machines),
// into one list in a canonical order, so a split run merges to the same
// results.json as a single run.

#include "result_io.h"

#include <filesystem>
#include <string>
#include <vector>

namespace agaa::bench {

// Every DIR/jobs/*.json, parsed. Throws eng::io::IoError naming the file that does not parse,
// or naming DIR when it has no jobs/ folder.
std::vector<JobResult> readJobDir(const std::filesystem::path& dir);

// Copies DIR/jobs/*.json and DIR/images/* into outDir (nothing when they are the same directory).
void importRunDir(const std::filesystem::path& dir, const std::filesystem::path& outDir);

struct MergeOutcome {
    std::vector<JobResult> results;    // canonical order
    std::vector<std::string> warnings; // duplicates dropped, sizes or frame counts that differ
};

// Drops duplicate ids (the first wins, a warning names the id) and sorts: scenes in the order of
// eng::scene::sceneKinds() (others after, by name), methods in the order of agaa::knownMethods()
// (others after, by name), then n, then c.
MergeOutcome mergeResults(std::vector<JobResult> results);

} // namespace agaa::bench
