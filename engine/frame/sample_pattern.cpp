#include "engine/frame/sample_pattern.h"

#include <stdexcept>

namespace eng::frame {
namespace {

// y-offset rank of layer l: a permutation of 0..m-1 that avoids the diagonal
// (x and y offsets moving together would align samples along one line).
uint32_t yRank(uint32_t layer, uint32_t layers) {
    switch (layers) {
    case 2:
        return 1 - layer;
    case 4: {
        constexpr uint32_t perm[4] = {1, 3, 0, 2};
        return perm[layer];
    }
    case 8:
        return (3 * layer + 3) % 8; // 3 is coprime with 8: a permutation
    default:
        return layer;
    }
}

} // namespace

bool isSupportedSampleCount(uint32_t n) {
    return n == 1 || n == 4 || n == 8 || n == 16 || n == 32;
}

std::string supportedSampleCounts() {
    return "1, 4, 8, 16, 32";
}

SamplePattern makeSamplePattern(uint32_t n) {
    if (!isSupportedSampleCount(n))
        throw std::invalid_argument("samples = " + std::to_string(n) +
                                    " is not supported (allowed: " + supportedSampleCounts() + ")");
    SamplePattern p;
    p.samples = n;
    if (n == 1) {
        p.samplesPerLayer = 1;
        p.layers = 1;
        p.layerOffsets = {{0.0f, 0.0f}};
        p.positions = {{0.5f, 0.5f}};
        return p;
    }
    p.samplesPerLayer = 4;
    p.layers = n / 4;
    const uint32_t m = p.layers;
    const float step = 1.0f / float(8 * m);
    for (uint32_t l = 0; l < m; ++l) {
        // Odd multiples of step, centred on zero: -(m-1)..(m-1) step 2.
        float ox = m == 1 ? 0.0f : float(2 * int(l) - int(m - 1)) * step;
        float oy = m == 1 ? 0.0f : float(2 * int(yRank(l, m)) - int(m - 1)) * step;
        p.layerOffsets.push_back({ox, oy});
    }
    for (uint32_t l = 0; l < m; ++l)
        for (uint32_t s = 0; s < 4; ++s)
            p.positions.push_back(kStandard4x[s] - p.layerOffsets[l]);
    return p;
}

} // namespace eng::frame
