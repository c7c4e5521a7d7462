// The scripted run's blank check (screenshot_check.h) on images whose answer is known, so the
// viewer.screenshots test cannot pass on a cleared or single-colour frame.

#include "samples/viewer/screenshot_check.h"

#include <gtest/gtest.h>

namespace {

using agaa::viewer::checkNotBlank;

eng::io::ImageU8 gradient(uint32_t w, uint32_t h) {
    eng::io::ImageU8 image = eng::io::makeImageU8(w, h);
    for (uint32_t y = 0; y < h; ++y)
        for (uint32_t x = 0; x < w; ++x) {
            uint8_t* p = &image.rgba[(size_t(y) * w + x) * 4];
            p[0] = uint8_t(x * 255 / (w - 1));
            p[1] = uint8_t(y * 255 / (h - 1));
            p[2] = uint8_t((x * 7 + y * 13) % 256);
        }
    return image;
}

TEST(ViewerBlankCheck, ClearedFrameIsBlank) {
    // A frame nothing was drawn into: one colour everywhere.
    EXPECT_TRUE(checkNotBlank(eng::io::makeImageU8(64, 32, {0, 0, 0, 255}), 0, 32).blank);
    EXPECT_TRUE(checkNotBlank(eng::io::makeImageU8(64, 32, {90, 128, 200, 255}), 0, 32).blank);
}

TEST(ViewerBlankCheck, RenderedContentIsNotBlank) {
    const auto check = checkNotBlank(gradient(64, 32), 0, 32);
    EXPECT_FALSE(check.blank) << check.describe();
}

TEST(ViewerBlankCheck, OnlyTheSceneRegionCounts) {
    // Content (the UI) left of firstColumn and below `rows` must not make a cleared scene pass.
    eng::io::ImageU8 image = gradient(64, 32);
    for (uint32_t y = 0; y < 16; ++y)
        for (uint32_t x = 20; x < 64; ++x)
            for (int c = 0; c < 3; ++c)
                image.rgba[(size_t(y) * 64 + x) * 4 + c] = 10;
    EXPECT_TRUE(checkNotBlank(image, 20, 16).blank);
    EXPECT_FALSE(checkNotBlank(image, 0, 32).blank);
}

TEST(ViewerBlankCheck, FewColoursAreBlank) {
    // Two flat halves (a frame cleared to two colours) are not a rendered scene.
    eng::io::ImageU8 image = eng::io::makeImageU8(64, 32, {0, 0, 0, 255});
    for (size_t i = 0; i < image.rgba.size() / 2; i += 4)
        image.rgba[i] = image.rgba[i + 1] = image.rgba[i + 2] = 255;
    EXPECT_TRUE(checkNotBlank(image, 0, 32).blank);
}

} // namespace
