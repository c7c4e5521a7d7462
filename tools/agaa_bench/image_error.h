#pragma once
// The benchmark's error measures, all on the display image sRGB-encoded: the
// tone-mapped resolve (RenderResult::display, linear [0,1]) through the sRGB
// OETF per channel, the image a viewer sees. RMSE, PSNR, SSIM and the 99th
// percentile pixel error come from engine/io/metrics, the mean ꟻLIP from
// engine/io/flip (the paper's viewer, 67 pixels a degree); this file adds the
// encoding, the window of worst error (for the report's crops) and temporal
// stability along a camera path.

#include "engine/io/image.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace agaa::bench {

// linearToSrgb per colour channel; alpha kept.
eng::io::ImageF srgbEncoded(const eng::io::ImageF& linearDisplay);

struct ErrorMetrics {
    double rmse = 0.0;
    double psnr = 0.0; // dB; +infinity when the images are identical
    double ssim = 1.0;
    double p99 = 0.0;           // 99th percentile over pixels of max over R, G, B of |a - b|
    std::optional<double> flip; // mean LDR ꟻLIP; empty in results written before it was measured
};

// Both images sRGB-encoded, same size. Throws eng::io::IoError on a size mismatch or NaN.
ErrorMetrics compareImages(const eng::io::ImageF& image, const eng::io::ImageF& truth);

struct Window {
    uint32_t x = 0, y = 0, width = 0, height = 0;
    double meanError = 0.0;
};

// Per-pixel score (one value a pixel, row-major); the size x size window (clamped to the image)
// with the highest mean score. Ties go to the first in row-major order, so the choice is
// deterministic. Windows overlapping `exclude` are skipped when given (for a second crop).
Window worstWindow(const std::vector<double>& score, uint32_t width, uint32_t height, uint32_t size,
                   const std::optional<Window>& exclude = std::nullopt);

// Per-pixel error max over R, G, B of |a - b| (the measure of percentileAbsError), one a pixel.
std::vector<double> pixelErrors(const eng::io::ImageF& a, const eng::io::ImageF& b);

// Temporal stability along a camera path (DESIGN section 7): with e_t the signed per-channel
// error image frames[t] - truths[t], the mean over pixels and R, G, B of |e_t - e_{t-1}|, one value
// per step t = 1..T-1. Flicker that the truth does not have shows up here; a method that is
// wrong in the same way every frame scores 0. All images the same size; at least 2 frames.
std::vector<double> temporalErrorChange(const std::vector<eng::io::ImageF>& frames,
                                        const std::vector<eng::io::ImageF>& truths);

} // namespace agaa::bench
