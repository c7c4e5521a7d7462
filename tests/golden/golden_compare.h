#pragma once
// The golden metric: how far a rendered display image is from its stored reference, and the
// thresholds that decide pass or fail (tests/README.md, "Golden images").
//
// Both images are the technique's display resolve (tone-mapped per shading event, linear [0,1]),
// compared after the sRGB encoding people look at. The stored EXR holds half floats, so the
// rendered image is first rounded to half exactly as the file would hold it: a rerun on the same
// lavapipe then gives every metric exactly 0 (bit for bit), and the thresholds only have to
// separate "nothing changed" from "shading changed by 1 %".

#include "engine/io/image.h"

#include <cstddef>

namespace agaa::golden {

struct GoldenThresholds {
    // Display RMSE over every pixel and R, G, B. A 1 % change of the BRDF (tools/perturb-test.sh)
    // moves the lit goldens by 1.5e-4 (gltf-cubes, nearly black) to 5.5e-3, median 1.7e-3
    // (measured, tests/README.md); a rerun on lavapipe gives exactly 0 on all of them.
    double rmse = 1e-4;
    // And the 99th percentile of the per-pixel max-over-RGB absolute error: one 8-bit step. A
    // local change of more than 1 % of the pixels fails even when the RMSE stays small.
    double percentile = 99.0;
    double percentileError = 1.0 / 255.0;
};

struct GoldenError {
    double rmse = 0.0;
    double percentileError = 0.0;
    double maxError = 0.0;
    size_t differingPixels = 0; // pixels with any R, G, B not bit-identical
    bool passed(const GoldenThresholds& t = {}) const {
        return rmse <= t.rmse && percentileError <= t.percentileError;
    }
};

// Every value rounded to the nearest half float (ties to even), as writeExr(Half) stores it.
eng::io::ImageF roundedToHalf(const eng::io::ImageF& image);

// `actual` and `golden` are linear display images of one size (golden as read from its EXR,
// actual straight from the renderer: rounded to half here). Throws eng::io::IoError on a size
// mismatch or a NaN (eng/io/metrics.h).
GoldenError compareToGolden(const eng::io::ImageF& actual, const eng::io::ImageF& golden,
                            const GoldenThresholds& t = {});

} // namespace agaa::golden
