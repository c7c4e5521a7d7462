#pragma once

#include "engine/io/image.h"

namespace eng::io {

// Image-quality metrics for regression tests and reports. Inputs are display-encoded images in
// [0,1], normally toneMapped() output; the metrics do not tone map themselves. Everything is
// accumulated in double. Alpha is ignored.
//
// All of them throw IoError when the two images differ in size, a buffer does not match its size,
// an image is empty, or any value is NaN/Inf (a NaN metric would compare false against every
// threshold and could pass a `!(err > limit)` check silently).

// The checks above, for a metric of its own file (engine/io/flip.h); `metric` names it in the message.
void checkMetricInputs(const char* metric, const ImageF& a, const ImageF& b);

// sqrt(mean over all pixels and R, G, B of (a - b)^2).
double rmse(const ImageF& a, const ImageF& b);

// 10 log10(peak^2 / mse). Identical images give +infinity (std::numeric_limits<double>::infinity()),
// which compares greater than any threshold. peak must be > 0.
double psnr(const ImageF& a, const ImageF& b, double peak = 1.0);

// Mean SSIM (Wang, Bovik, Sheikh, Simoncelli 2004) on luma Y = 0.2126 R + 0.7152 G + 0.0722 B
// (Rec. 709 weights applied to the given values as they are). Local statistics use an 11x11
// Gaussian window, sigma 1.5, weights normalised to sum 1, at every position where the window lies
// fully inside the image; K1 = 0.01, K2 = 0.03, L = 1. An image narrower or shorter than 11 pixels is
// treated as one window with uniform weights. Identical images give exactly 1.
double ssim(const ImageF& a, const ImageF& b);

// Per-pixel error e = max over R, G, B of |a - b|, then the p-th percentile of e by nearest rank:
// the smallest e such that at least p% of the pixels are <= e, i.e. sorted[ceil(p/100 * N) - 1]
// (p = 0 gives the minimum, p = 100 the maximum). p in [0, 100].
double percentileAbsError(const ImageF& a, const ImageF& b, double p);

// The share of pixels (0 to 1) whose relative error max over R, G, B of
// |a - b| / max(|a|, |b|, floor) is greater than bound >= 0; floor > 0 keeps black pixels finite.
// Unlike an absolute error it weighs a dark pixel's change like a bright one's.
double shareAboveRelativeError(const ImageF& a, const ImageF& b, double bound, double floor);

// Per-pixel error (the e of percentileAbsError) times scale, clamped to [0,1], on a colour ramp:
// 0 black -> 0.25 blue -> 0.5 red -> 0.75 yellow -> 1 white, linear between stops; alpha 1.
// The result is already display-encoded: save it with quantizeToU8 + writePng, not toneMapToSrgb8.
// scale must be finite and > 0 (scale = 10 shows an error of 0.1 as white).
ImageF errorHeatmap(const ImageF& a, const ImageF& b, float scale);

} // namespace eng::io
