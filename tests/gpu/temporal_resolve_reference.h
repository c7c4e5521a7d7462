#pragma once
// Temporal AA's resolve on the CPU, in double, written from Karis 2014 and Salvi's variance clip
// as agaa/temporal/temporal_aa.h describes them (not from temporal/resolve.comp): for a still
// camera, where every pixel's history lies at its own centre.
//   box:    the 3x3 neighbourhood of the current frame (clamped to the edge) in YCoCg, mean mu and
//           standard deviation sigma per channel; half-extent gamma sigma
//   clip:   the history moved along the segment to mu until it is inside the box
//   blend:  alpha / (1 + Y(current)) and (1 - alpha) / (1 + Y(history)), normalised (Y: Rec. 709
//           luma), for HDR; alpha and 1 - alpha for the display, whose values are bounded

#include "engine/io/image.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace agaa::test {

inline eng::io::ImageF temporalResolveStill(const eng::io::ImageF& current, const eng::io::ImageF& history,
                                            double alpha, double gamma, bool fireflyWeights) {
    using V = std::array<double, 3>;
    const int w = int(current.width), h = int(current.height);
    const auto at = [&](const eng::io::ImageF& img, int x, int y) {
        const size_t i = (size_t(std::clamp(y, 0, h - 1)) * w + size_t(std::clamp(x, 0, w - 1))) * 4;
        return V{img.rgba[i], img.rgba[i + 1], img.rgba[i + 2]};
    };
    const auto ycocg = [](const V& c) {
        return V{0.25 * c[0] + 0.5 * c[1] + 0.25 * c[2], 0.5 * c[0] - 0.5 * c[2],
                 -0.25 * c[0] + 0.5 * c[1] - 0.25 * c[2]};
    };
    const auto rgb = [](const V& y) { return V{y[0] + y[1] - y[2], y[0] + y[2], y[0] - y[1] - y[2]}; };
    const auto luma = [](const V& c) {
        return 0.2126 * std::max(c[0], 0.0) + 0.7152 * std::max(c[1], 0.0) + 0.0722 * std::max(c[2], 0.0);
    };
    eng::io::ImageF out = current;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            V mean{}, square{};
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const V c = ycocg(at(current, x + dx, y + dy));
                    for (int k = 0; k < 3; ++k) {
                        mean[k] += c[k] / 9.0;
                        square[k] += c[k] * c[k] / 9.0;
                    }
                }
            V hist = ycocg(at(history, x, y));
            double reach = 0.0; // how far out of the box, in half-extents, along the worst axis
            for (int k = 0; k < 3; ++k) {
                const double half = gamma * std::sqrt(std::max(square[k] - mean[k] * mean[k], 0.0));
                reach = std::max(reach, std::abs(hist[k] - mean[k]) / std::max(half, 1e-6));
            }
            if (reach > 1.0)
                for (int k = 0; k < 3; ++k)
                    hist[k] = mean[k] + (hist[k] - mean[k]) / reach;
            const V c = at(current, x, y), hr = rgb(hist);
            const double wc = fireflyWeights ? alpha / (1.0 + luma(c)) : alpha;
            const double wh = fireflyWeights ? (1.0 - alpha) / (1.0 + luma(hr)) : 1.0 - alpha;
            const size_t i = (size_t(y) * w + size_t(x)) * 4;
            for (int k = 0; k < 3; ++k)
                out.rgba[i + k] = float((c[k] * wc + hr[k] * wh) / (wc + wh));
        }
    return out;
}

} // namespace agaa::test
