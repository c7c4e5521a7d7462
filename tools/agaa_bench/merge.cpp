#include "merge.h"

#include "agaa/methods.h"
#include "engine/io/io_error.h"
#include "engine/scene/scenegen.h"

#include <algorithm>
#include <set>
#include <tuple>

namespace agaa::bench {

namespace fs = std::filesystem;

namespace {

size_t rankIn(const std::vector<std::string>& order, const std::string& name) {
    auto it = std::find(order.begin(), order.end(), name);
    return it == order.end() ? order.size() : size_t(it - order.begin());
}

std::vector<std::string> methodOrder() {
    std::vector<std::string> names;
    for (const MethodInfo& m : knownMethods())
        names.push_back(m.name);
    return names;
}

bool sameDirectory(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    return fs::exists(a) && fs::exists(b) && fs::equivalent(a, b, ec);
}

} // namespace

std::vector<JobResult> readJobDir(const fs::path& dir) {
    const fs::path jobs = dir / "jobs";
    if (!fs::is_directory(jobs))
        throw eng::io::IoError(dir.string() + " has no jobs/ folder (not an agaa-bench output directory)");
    std::vector<fs::path> files;
    for (const fs::directory_entry& e : fs::directory_iterator(jobs))
        if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::vector<JobResult> results;
    for (const fs::path& f : files)
        results.push_back(readJobFile(f));
    return results;
}

void importRunDir(const fs::path& dir, const fs::path& outDir) {
    if (sameDirectory(dir, outDir)) return;
    for (const char* sub : {"jobs", "images"}) {
        const fs::path from = dir / sub;
        if (!fs::is_directory(from)) continue;
        fs::create_directories(outDir / sub);
        for (const fs::directory_entry& e : fs::directory_iterator(from)) {
            if (!e.is_regular_file()) continue;
            std::error_code ec;
            fs::copy_file(e.path(), outDir / sub / e.path().filename(), fs::copy_options::overwrite_existing,
                          ec);
            if (ec)
                throw eng::io::IoError("cannot copy " + e.path().string() + " to " + outDir.string() + ": " +
                                       ec.message());
        }
    }
}

MergeOutcome mergeResults(std::vector<JobResult> results) {
    MergeOutcome out;
    std::set<std::string> seen;
    for (JobResult& r : results) {
        if (!seen.insert(r.job.id()).second) {
            out.warnings.push_back("duplicate job " + r.job.id() + ": the first one read is kept");
            continue;
        }
        out.results.push_back(std::move(r));
    }
    const std::vector<std::string> scenes = eng::scene::sceneKinds(), methods = methodOrder();
    std::sort(out.results.begin(), out.results.end(), [&](const JobResult& a, const JobResult& b) {
        auto key = [&](const JobResult& r) {
            const SceneVariant v = parseSceneVariant(r.job.scene);
            return std::make_tuple(rankIn(scenes, v.base), v.base, v.extraLights,
                                   rankIn(methods, r.job.method), r.job.method, r.job.samples,
                                   r.job.aggregates, r.job.surfaces, r.job.tolerance, r.job.specularAA);
        };
        return key(a) < key(b);
    });
    if (!out.results.empty()) {
        const JobResult& first = out.results.front();
        for (const JobResult& r : out.results) {
            if (r.width != first.width || r.height != first.height)
                out.warnings.push_back(r.job.id() + " is " + std::to_string(r.width) + "x" +
                                       std::to_string(r.height) + ", others " + std::to_string(first.width) +
                                       "x" + std::to_string(first.height) + ": their times do not compare");
            if (r.timedFrames != first.timedFrames || r.device != first.device)
                out.warnings.push_back(r.job.id() + " was timed on '" + r.device + "' over " +
                                       std::to_string(r.timedFrames) + " frames, others on '" + first.device +
                                       "' over " + std::to_string(first.timedFrames));
        }
    }
    return out;
}

} // namespace agaa::bench
