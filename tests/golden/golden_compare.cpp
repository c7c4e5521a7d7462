#include "golden_compare.h"

#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"

namespace agaa::golden {

eng::io::ImageF roundedToHalf(const eng::io::ImageF& image) {
    eng::io::ImageF out = image;
    for (float& v : out.rgba)
        v = float(static_cast<_Float16>(v)); // IEEE binary16, round to nearest even
    return out;
}

GoldenError compareToGolden(const eng::io::ImageF& actual, const eng::io::ImageF& golden,
                            const GoldenThresholds& t) {
    const eng::io::ImageF stored = roundedToHalf(actual);
    GoldenError e;
    e.goldenBlack = true;
    for (size_t p = 0; p < golden.rgba.size() / 4; ++p)
        for (int c = 0; c < 3; ++c)
            e.goldenBlack = e.goldenBlack && golden.rgba[p * 4 + c] == 0.0f;
    for (size_t p = 0; p < stored.rgba.size() / 4 && stored.rgba.size() == golden.rgba.size(); ++p)
        for (int c = 0; c < 3; ++c)
            if (stored.rgba[p * 4 + c] != golden.rgba[p * 4 + c]) {
                ++e.differingPixels;
                break;
            }
    e.shareOverRelative = eng::io::shareAboveRelativeError(stored, golden, t.relativeBound, t.relativeFloor);
    const eng::io::ImageF a = eng::io::srgbEncoded(stored), b = eng::io::srgbEncoded(golden);
    e.rmse = eng::io::rmse(a, b);
    e.percentileError = eng::io::percentileAbsError(a, b, t.percentile);
    e.maxError = eng::io::percentileAbsError(a, b, 100.0);
    return e;
}

} // namespace agaa::golden
