#pragma once
// The request every truth test starts from: the default method settings at one size.

#include "tools/harness/frame_renderer.h"

namespace agaa::test {

inline RenderRequest truthView(uint32_t width, uint32_t height) {
    RenderRequest r;
    r.view.width = width;
    r.view.height = height;
    return r;
}

} // namespace agaa::test
