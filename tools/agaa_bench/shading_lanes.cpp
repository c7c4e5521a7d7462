#include "shading_lanes.h"

#include <algorithm>

namespace agaa::bench {

double worstLaneEventsPerPixel(const std::vector<uint32_t>& events, uint32_t width, uint32_t height,
                               uint32_t lanes) {
    if (width == 0 || height == 0 || lanes == 0 || events.size() < size_t(width) * height) return 0.0;
    double sum = 0.0;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x0 = 0; x0 < width; x0 += lanes) {
            const uint32_t x1 = std::min(width, x0 + lanes);
            uint32_t worst = 0;
            for (uint32_t x = x0; x < x1; ++x)
                worst = std::max(worst, events[size_t(y) * width + x]);
            sum += double(worst) * double(x1 - x0); // every lane of the group waits for the worst
        }
    return sum / (double(width) * double(height));
}

} // namespace agaa::bench
