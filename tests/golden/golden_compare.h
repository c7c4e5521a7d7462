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
    // And at most 0.1 % of the pixels may change by more than 0.25 % relative (in linear light,
    // max over R, G, B). A change confined to a few highlights, or one in dark pixels, moves
    // neither the RMSE nor the p99: a 1 % BRDF change moves glints' highlights by at most 1.2e-3
    // and hard-grazing's dark floor by 2e-5 in display values, both under the two bounds above,
    // but every lit pixel of both by 1 % relative. The bound is 2.5 steps of a half float (a step is
    // at most 2^-10 relative); the floor is the smallest normal half, under which one step is a
    // constant 6e-8. A rerun, on any x86-64 CPU, changes no pixel at all (docs/cross-cpu.md).
    double relativeBound = 2.5e-3;
    double relativeFloor = 6.103515625e-5; // 2^-14
    double relativeShare = 1e-3;
};

struct GoldenError {
    double rmse = 0.0;
    double percentileError = 0.0;
    double maxError = 0.0;
    size_t differingPixels = 0;     // pixels with any R, G, B not bit-identical
    double shareOverRelative = 0.0; // of the pixels, those over GoldenThresholds::relativeBound
    bool goldenBlack = false;       // every R, G, B of the golden is 0: no change of shading can move it
    bool passed(const GoldenThresholds& t = {}) const {
        return rmse <= t.rmse && percentileError <= t.percentileError && shareOverRelative <= t.relativeShare;
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
