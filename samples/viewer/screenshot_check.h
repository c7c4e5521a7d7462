#pragma once
// What the scripted run checks in each presented image: that the scene part (right of the UI
// panel) is not blank. Pure logic over an RGBA8 image: no window, no device.

#include "engine/io/image.h"

#include <cstdint>
#include <string>

namespace agaa::viewer {

struct BlankCheck {
    bool blank = true;
    uint32_t distinctColours = 0; // in the checked region, counted up to kEnough
    double lumaStdDev = 0.0;      // 0..255
    std::string describe() const;
};

// Looks at columns [firstColumn, width) of rows [0, rows). Blank: fewer than 16 distinct colours or a luma
// standard deviation under 2 (of 255): a cleared, single-colour or sky-only frame. A rendered scene of the
// built-ins has hundreds of colours and a deviation of tens.
BlankCheck checkNotBlank(const eng::io::ImageU8& image, uint32_t firstColumn, uint32_t rows);

} // namespace agaa::viewer
