#pragma once
// ꟻLIP for LDR images (Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild, "ꟻLIP:
// A Difference Evaluator for Alternating Images", HPG 2020), written from the paper: the error a
// viewer sees flipping between two images at a given viewing distance, per pixel in [0, 1].
//
// Beside display RMSE because the two weigh errors differently: ꟻLIP discounts what the eye's
// contrast sensitivity filters out at the viewing distance (sub-pixel noise, a colour shift in
// fine detail) and charges edges and points that appear or vanish (a blurred edge, a lost glint),
// which is how temporal AA's blur and MSAA's aliasing differ.
//
// Per pixel:
//  1. colour: both images, sRGB -> linear -> YCxCz (the linearised CIELAB), each channel filtered
//     with its contrast sensitivity function (a sum of Gaussians, kernel in degrees of visual
//     angle); back to linear RGB clamped to [0, 1], then CIELAB with Hunt's adjustment
//     (a, b scaled by L / 100), the HyAB distance |dL| + |d(a, b)|, raised to qc = 0.7 and
//     compressed so that the largest distance (green against blue) is 1 and the share pc = 0.4
//     of it already maps to pt = 0.95.
//  2. features: on the relative luminance, edges (first derivative of a Gaussian of standard
//     deviation 0.5 * 0.082 degrees) and points (second derivative), each kernel scaled so that
//     its positive weights sum to 1 and its negative to -1; the feature error is
//     (max(|edge difference|, |point difference|) / sqrt(2))^qf, qf = 0.5.
//  3. ꟻLIP = colour error ^ (1 - feature error).
// Borders repeat the edge pixel. Everything in double.

#include "engine/io/image.h"

#include <numbers>
#include <vector>

namespace eng::io {

// The paper's default viewer: a 0.7 m wide 3840-pixel monitor seen from 0.7 m, 67.02 pixels per
// degree.
inline constexpr double kFlipDefaultPixelsPerDegree = 0.7 * (3840.0 / 0.7) * std::numbers::pi / 180.0;

// The per-pixel ꟻLIP error, row-major, each in [0, 1]. Both images are display-encoded sRGB
// (values outside [0, 1] are clamped first); alpha is ignored. Throws IoError on a size mismatch,
// an empty image, a non-finite value, or pixelsPerDegree not finite and > 0.
std::vector<double> flipErrorMap(const ImageF& reference, const ImageF& test,
                                 double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

// The mean of flipErrorMap: the figure the authors report for an image pair.
double flipMean(const ImageF& reference, const ImageF& test,
                double pixelsPerDegree = kFlipDefaultPixelsPerDegree);

} // namespace eng::io
