// A sweep split with --job 0/2 and 1/2 into two directories and merged with
// --merge must give the same results.json as the same sweep run at once,
// except for what varies run to run (everything under "timing").

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// 2 jobs (reference n=4 and noaa on the plane), 32x32, 1 frame, no temporal path: a few seconds.
// With the validation layer: a validation error makes agaa-bench exit 1 and fails the test.
const std::string kSweep = "--scenes plane --methods reference,noaa --samples 4 --size 32x32 --frames 1 "
                           "--warmup 0 --temporal 0 --validate";

int bench(const std::string& args, const fs::path& log) {
    const std::string cmd =
        std::string("\"") + AGAA_BENCH_EXE + "\" " + args + " > \"" + log.string() + "\" 2>&1";
    return std::system(cmd.c_str());
}

json readJson(const fs::path& file) {
    std::ifstream f(file);
    EXPECT_TRUE(f.good()) << "missing " << file;
    return f ? json::parse(f) : json();
}

json withoutTimings(json results) {
    for (json& job : results.at("jobs"))
        job.erase("timing");
    return results;
}

size_t jobFiles(const fs::path& dir) {
    size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir / "jobs"))
        n += e.path().extension() == ".json";
    return n;
}

TEST(BenchMerge, SplitSweepMergesToTheSingleRunsResults) {
    const fs::path root = fs::temp_directory_path() / ("agaa_bench_merge_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root);
    ASSERT_EQ(bench("--out \"" + (root / "single").string() + "\" " + kSweep, root / "single.log"), 0)
        << "single run failed, see " << root / "single.log";
    ASSERT_EQ(bench("--out \"" + (root / "a").string() + "\" --job 0/2 " + kSweep, root / "a.log"), 0);
    ASSERT_EQ(bench("--out \"" + (root / "b").string() + "\" --job 1/2 " + kSweep, root / "b.log"), 0);
    // Each slice rendered only its own job: the merge really has to combine them.
    EXPECT_EQ(jobFiles(root / "a"), 1u) << "--job 0/2 must run exactly one of the two jobs";
    EXPECT_EQ(jobFiles(root / "b"), 1u) << "--job 1/2 must run exactly the other job";
    ASSERT_EQ(bench("--out \"" + (root / "merged").string() + "\" --merge \"" + (root / "a").string() +
                        "\" \"" + (root / "b").string() + "\"",
                    root / "merged.log"),
              0);

    const json single = readJson(root / "single" / "results.json");
    const json merged = readJson(root / "merged" / "results.json");
    ASSERT_EQ(single.at("jobs").size(), 2u) << "the sweep plans reference n=4 and noaa on one scene";
    // Every measured number but the timings (errors, bytes, shading events, images) must agree
    // exactly: the renders are deterministic and the merge order is canonical.
    EXPECT_EQ(withoutTimings(merged), withoutTimings(single))
        << "merged:\n"
        << withoutTimings(merged).dump(1) << "\nsingle:\n"
        << withoutTimings(single).dump(1);
    // The merged directory is self-contained: the report and every image it names were copied.
    EXPECT_TRUE(fs::exists(root / "merged" / "report.html"));
    EXPECT_TRUE(fs::exists(root / "merged" / "results.csv"));
    for (const json& job : merged.at("jobs"))
        for (const char* key : {"display", "heatmap", "truth"})
            EXPECT_TRUE(fs::exists(root / "merged" / job.at("images").at(key).get<std::string>()))
                << job.at("id") << " names a " << key << " image the merge did not copy";
    if (!HasFailure()) fs::remove_all(root);
}

} // namespace
