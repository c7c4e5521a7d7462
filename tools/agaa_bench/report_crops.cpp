#include "report_crops.h"

#include "engine/io/io_error.h"
#include "engine/io/png.h"

#include <algorithm>
#include <limits>

namespace agaa::bench {

namespace {

eng::io::ImageF toFloat(const eng::io::ImageU8& u8) {
    eng::io::ImageF f;
    f.width = u8.width;
    f.height = u8.height;
    f.rgba.resize(u8.rgba.size());
    for (size_t i = 0; i < u8.rgba.size(); ++i)
        f.rgba[i] = float(u8.rgba[i]) / 255.0f;
    return f;
}

std::vector<std::string> scenesInOrder(const std::vector<JobResult>& results) {
    std::vector<std::string> scenes;
    for (const JobResult& r : results)
        if (std::find(scenes.begin(), scenes.end(), r.job.scene) == scenes.end())
            scenes.push_back(r.job.scene);
    return scenes;
}

SceneCrops cropsForScene(const std::filesystem::path& outDir, const std::vector<const JobResult*>& jobs,
                         uint32_t count) {
    SceneCrops crops;
    crops.scene = jobs.front()->job.scene;
    const eng::io::ImageF truth = toFloat(eng::io::readPng(outDir / jobs.front()->imageTruth));
    crops.width = truth.width;
    crops.height = truth.height;
    const size_t pixels = eng::io::pixelCount(truth);
    std::vector<double> lo(pixels, std::numeric_limits<double>::infinity()), hi(pixels, 0.0);
    for (const JobResult* r : jobs) {
        const eng::io::ImageF image = toFloat(eng::io::readPng(outDir / r->imageDisplay));
        const std::vector<double> e = pixelErrors(image, truth);
        for (size_t p = 0; p < pixels; ++p) {
            lo[p] = std::min(lo[p], e[p]);
            hi[p] = std::max(hi[p], e[p]);
        }
    }
    std::vector<double> score(pixels);
    for (size_t p = 0; p < pixels; ++p)
        score[p] = jobs.size() > 1 ? hi[p] - lo[p] : hi[p];
    const uint32_t size = std::clamp(std::min(truth.width, truth.height) / 4, 8u, 128u);
    std::optional<Window> previous;
    for (uint32_t i = 0; i < count; ++i) {
        Window w = worstWindow(score, truth.width, truth.height, size, previous);
        if (previous && w.meanError <= 0.0) break; // nothing left that differs
        crops.windows.push_back(w);
        previous = w;
    }
    return crops;
}

} // namespace

std::vector<SceneCrops> chooseCrops(const std::filesystem::path& outDir,
                                    const std::vector<JobResult>& results, uint32_t count) {
    std::vector<SceneCrops> all;
    for (const std::string& scene : scenesInOrder(results)) {
        std::vector<const JobResult*> jobs;
        for (const JobResult& r : results)
            if (r.job.scene == scene) jobs.push_back(&r);
        try {
            all.push_back(cropsForScene(outDir, jobs, count));
        } catch (const eng::io::IoError& e) {
            SceneCrops none;
            none.scene = scene;
            none.note = std::string("no image comparison: ") + e.what();
            all.push_back(none);
        }
    }
    return all;
}

} // namespace agaa::bench
