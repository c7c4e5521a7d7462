#pragma once
// Chooses where the report zooms in: per scene, the windows where the methods
// differ most against the high-rate truth, found from the images the jobs
// wrote (so a merged run, whose images were copied, chooses the same ones).

#include "image_error.h"
#include "result_io.h"

#include <filesystem>
#include <string>
#include <vector>

namespace agaa::bench {

struct SceneCrops {
    std::string scene;
    uint32_t width = 0, height = 0; // the full image
    std::vector<Window> windows;    // best first, not overlapping
    std::string note;               // why there are none, when there are none
};

// Per pixel, the spread over the scene's jobs of their error against the truth (max minus min of
// the per-pixel error, on the 8-bit sRGB images; the error itself when the scene has one job);
// then up to `count` windows of min(W, H)/4 pixels (8..128) with the highest mean.
std::vector<SceneCrops> chooseCrops(const std::filesystem::path& outDir,
                                    const std::vector<JobResult>& results, uint32_t count = 2);

} // namespace agaa::bench
