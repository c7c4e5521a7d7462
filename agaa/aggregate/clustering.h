#pragma once
// CPU reference of AGAA's aggregate definition (Algorithm 1). It runs the very source the GPU
// kernel runs (shaders/glsl/shared/clustering.h, compiled here with -ffp-contract=off), on the
// per-sample depth and normal bytes read back from the GPU, so the metadata words must match
// the GPU's bit for bit.

#include "shared/agaa.h"
#include "shared/frame.h"

#include <array>
#include <cstdint>
#include <vector>

namespace agaa {

// One pixel's samples as the clustering kernel sees them.
struct PixelSamples {
    std::array<float, shared::kMaxSamples> depth{};   // reversed Z, 0 = sky
    std::array<uint8_t, shared::kMaxSamples> theta{}; // encoded face normal
    std::array<uint8_t, shared::kMaxSamples> phi{};
};

struct PixelClusters {
    uint32_t count = 0; // aggregates created (0: sky only)
    std::array<uint32_t, shared::kMaxSamples> ids{};
    std::array<uint32_t, 4> words{}; // packed metadata; metadataWords(n, c) of them are used
};

PixelClusters clusterPixel(uint32_t x, uint32_t y, const PixelSamples&, const shared::FrameConstants&,
                           const shared::AgaaConstants&);

// Whole image: samples are row-major pixels; returns metadata words (row-major, words per
// pixel from the constants) and counts.
struct ClusterImage {
    std::vector<uint32_t> metadata;
    std::vector<uint32_t> counts;
};
ClusterImage clusterImage(uint32_t width, uint32_t height, const std::vector<PixelSamples>&,
                          const shared::FrameConstants&, const shared::AgaaConstants&);

} // namespace agaa
