#include "image_error.h"

#include "engine/io/flip.h"
#include "engine/io/io_error.h"
#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace agaa::bench {

eng::io::ImageF srgbEncoded(const eng::io::ImageF& linearDisplay) {
    return eng::io::srgbEncoded(linearDisplay);
}

ErrorMetrics compareImages(const eng::io::ImageF& image, const eng::io::ImageF& truth) {
    ErrorMetrics m;
    m.rmse = eng::io::rmse(image, truth);
    m.psnr = eng::io::psnr(image, truth);
    m.ssim = eng::io::ssim(image, truth);
    m.p99 = eng::io::percentileAbsError(image, truth, 99.0);
    m.flip = eng::io::flipMean(truth, image);
    return m;
}

std::vector<double> pixelErrors(const eng::io::ImageF& a, const eng::io::ImageF& b) {
    if (a.width != b.width || a.height != b.height || !eng::io::isConsistent(a) || !eng::io::isConsistent(b))
        throw eng::io::IoError("pixelErrors: images differ in size or are inconsistent");
    std::vector<double> e(eng::io::pixelCount(a));
    for (size_t p = 0; p < e.size(); ++p) {
        double m = 0.0;
        for (size_t c = 0; c < 3; ++c)
            m = std::max(m, std::abs(double(a.rgba[p * 4 + c]) - b.rgba[p * 4 + c]));
        e[p] = m;
    }
    return e;
}

Window worstWindow(const std::vector<double>& score, uint32_t width, uint32_t height, uint32_t size,
                   const std::optional<Window>& exclude) {
    if (score.size() != size_t(width) * height || width == 0 || height == 0)
        throw std::invalid_argument("worstWindow: score does not hold width*height values");
    const uint32_t ww = std::clamp(size, 1u, width), wh = std::clamp(size, 1u, height);
    // Summed-area table with a zero border: window sums in O(1).
    std::vector<double> sat(size_t(width + 1) * (height + 1), 0.0);
    auto at = [&](uint32_t x, uint32_t y) -> double& { return sat[size_t(y) * (width + 1) + x]; };
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            at(x + 1, y + 1) = score[size_t(y) * width + x] + at(x, y + 1) + at(x + 1, y) - at(x, y);
    auto overlaps = [&](uint32_t x, uint32_t y) {
        if (!exclude) return false;
        return x < exclude->x + exclude->width && exclude->x < x + ww && y < exclude->y + exclude->height &&
               exclude->y < y + wh;
    };
    Window best;
    best.width = ww;
    best.height = wh;
    double bestSum = -1.0;
    // A quarter-window stride keeps the search cheap at 1280x720 and still lands on every feature.
    const uint32_t stride = std::max(1u, std::min(ww, wh) / 4);
    for (uint32_t y = 0; y + wh <= height; y += stride) {
        for (uint32_t x = 0; x + ww <= width; x += stride) {
            if (overlaps(x, y)) continue;
            double sum = at(x + ww, y + wh) - at(x, y + wh) - at(x + ww, y) + at(x, y);
            if (sum > bestSum) {
                bestSum = sum;
                best.x = x;
                best.y = y;
            }
        }
    }
    best.meanError = bestSum < 0.0 ? 0.0 : bestSum / (double(ww) * wh);
    return best;
}

std::vector<double> temporalErrorChange(const std::vector<eng::io::ImageF>& frames,
                                        const std::vector<eng::io::ImageF>& truths) {
    if (frames.size() != truths.size() || frames.size() < 2)
        throw std::invalid_argument(
            "temporalErrorChange: needs as many truths as frames, and at least 2 frames");
    std::vector<double> steps;
    for (size_t t = 1; t < frames.size(); ++t) {
        const eng::io::ImageF *a0 = &frames[t - 1], *b0 = &truths[t - 1], *a1 = &frames[t], *b1 = &truths[t];
        for (const eng::io::ImageF* img : {a0, b0, a1, b1})
            if (img->width != a0->width || img->height != a0->height || !eng::io::isConsistent(*img))
                throw eng::io::IoError("temporalErrorChange: path images differ in size");
        double sum = 0.0;
        const size_t pixels = eng::io::pixelCount(*a0);
        for (size_t p = 0; p < pixels; ++p)
            for (size_t c = 0; c < 3; ++c) {
                const size_t i = p * 4 + c;
                const double e0 = double(a0->rgba[i]) - b0->rgba[i], e1 = double(a1->rgba[i]) - b1->rgba[i];
                sum += std::abs(e1 - e0);
            }
        steps.push_back(sum / (3.0 * double(pixels)));
    }
    return steps;
}

} // namespace agaa::bench
