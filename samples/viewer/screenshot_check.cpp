#include "samples/viewer/screenshot_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_set>

namespace agaa::viewer {

namespace {
constexpr uint32_t kEnough = 1024;
constexpr uint32_t kMinColours = 16;
constexpr double kMinStdDev = 2.0;
} // namespace

std::string BlankCheck::describe() const {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%s (%u%s distinct colours, luma std dev %.1f)",
                  blank ? "BLANK" : "not blank", distinctColours, distinctColours >= kEnough ? "+" : "",
                  lumaStdDev);
    return buffer;
}

BlankCheck checkNotBlank(const eng::io::ImageU8& image, uint32_t firstColumn, uint32_t rows) {
    BlankCheck check;
    std::unordered_set<uint32_t> colours;
    double sum = 0.0, sumSq = 0.0;
    uint64_t count = 0;
    for (uint32_t y = 0; y < std::min(rows, image.height); ++y)
        for (uint32_t x = firstColumn; x < image.width; ++x) {
            const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
            if (colours.size() < kEnough)
                colours.insert(uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16);
            const double luma = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            sum += luma;
            sumSq += luma * luma;
            ++count;
        }
    check.distinctColours = uint32_t(colours.size());
    if (count > 0) {
        const double mean = sum / double(count);
        check.lumaStdDev = std::sqrt(std::max(0.0, sumSq / double(count) - mean * mean));
    }
    check.blank = check.distinctColours < kMinColours || check.lumaStdDev < kMinStdDev;
    return check;
}

} // namespace agaa::viewer
