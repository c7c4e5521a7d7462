#include "disocclusion.h"

#include "engine/io/io_error.h"
#include "engine/io/metrics.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace agaa::bench {

namespace {

// Whether the previous frame saw, at texel (x, y), the point at distance `expected` (0: the sky).
bool sawAt(const eng::io::ImageF& previousDistance, int x, int y, float expected) {
    const int w = int(previousDistance.width), h = int(previousDistance.height);
    if (x < 0 || y < 0 || x >= w || y >= h) return false;
    const float seen = previousDistance.rgba[(size_t(y) * w + x) * 4];
    if (expected == 0.0f) return seen == 0.0f;
    return std::abs(seen - expected) <= kDisocclusionDistanceTolerance * expected;
}

} // namespace

std::vector<uint8_t> disoccludedPixels(const eng::io::ImageF& motion,
                                       const eng::io::ImageF& previousDistance) {
    eng::io::checkMetricInputs("disoccludedPixels", motion, previousDistance);
    std::vector<uint8_t> mask(size_t(motion.width) * motion.height, 0);
    for (size_t i = 0; i < mask.size(); ++i) {
        const float* m = &motion.rgba[i * 4];
        if (m[2] != 1.0f) {
            mask[i] = 1; // outside the previous frame
            continue;
        }
        // The texel the position falls in and its eight neighbours.
        const int x = int(std::floor(m[0])), y = int(std::floor(m[1]));
        bool seen = false;
        for (int dy = -1; dy <= 1 && !seen; ++dy)
            for (int dx = -1; dx <= 1 && !seen; ++dx)
                seen = sawAt(previousDistance, x + dx, y + dy, m[3]);
        mask[i] = seen ? 0 : 1;
    }
    return mask;
}

MaskedError maskedError(const std::vector<eng::io::ImageF>& frames,
                        const std::vector<eng::io::ImageF>& truths,
                        const std::vector<std::vector<uint8_t>>& masks) {
    if (frames.size() != truths.size() || frames.size() != masks.size())
        throw eng::io::IoError("maskedError: " + std::to_string(frames.size()) + " frames, " +
                               std::to_string(truths.size()) + " truths and " + std::to_string(masks.size()) +
                               " masks");
    double sum = 0.0;
    MaskedError e;
    for (size_t f = 0; f < frames.size(); ++f) {
        eng::io::checkMetricInputs("maskedError", frames[f], truths[f]);
        if (masks[f].empty()) continue;
        if (masks[f].size() != size_t(frames[f].width) * frames[f].height)
            throw eng::io::IoError("maskedError: frame " + std::to_string(f) + "'s mask has " +
                                   std::to_string(masks[f].size()) + " pixels, the frame " +
                                   std::to_string(size_t(frames[f].width) * frames[f].height));
        for (size_t i = 0; i < masks[f].size(); ++i) {
            if (!masks[f][i]) continue;
            ++e.pixels;
            for (size_t c = 0; c < 3; ++c) {
                const double d = double(frames[f].rgba[i * 4 + c]) - double(truths[f].rgba[i * 4 + c]);
                sum += d * d;
            }
        }
    }
    e.rmse = e.pixels ? std::sqrt(sum / (3.0 * double(e.pixels))) : 0.0;
    return e;
}

} // namespace agaa::bench
