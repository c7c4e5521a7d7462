#include "engine/io/image.h"
#include "engine/io/io_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace eng::io {
namespace {

TEST(Image, MakeImageFillsEveryPixelWithTheGivenValue) {
    const ImageF image = makeImage(3, 2, {0.25f, 0.5f, 0.75f, 1.0f});
    EXPECT_EQ(image.width, 3u);
    EXPECT_EQ(image.height, 2u);
    ASSERT_EQ(image.rgba.size(), 3u * 2u * 4u) << "buffer must hold exactly width*height RGBA pixels";
    EXPECT_TRUE(isConsistent(image));
    for (uint32_t y = 0; y < 2; ++y) {
        for (uint32_t x = 0; x < 3; ++x) {
            const RgbaF p = pixel(image, x, y);
            EXPECT_EQ(p.r, 0.25f);
            EXPECT_EQ(p.g, 0.5f);
            EXPECT_EQ(p.b, 0.75f);
            EXPECT_EQ(p.a, 1.0f);
        }
    }
}

TEST(Image, DefaultFillIsOpaqueBlack) {
    const RgbaF p = pixel(makeImage(1, 1), 0, 0);
    EXPECT_EQ(p.r, 0.0f);
    EXPECT_EQ(p.a, 1.0f) << "a fresh image must be opaque so that it can be written as is";
}

TEST(Image, SetPixelUsesRowMajorTopRowFirstLayout) {
    ImageF image = makeImage(4, 3);
    setPixel(image, 2, 1, {1.0f, 2.0f, 3.0f, 4.0f});
    // Row 1, column 2 of a 4-wide image: pixel index 1*4+2 = 6, float index 24.
    EXPECT_EQ(image.rgba[24], 1.0f) << "layout must be row-major with 4 floats per pixel";
    EXPECT_EQ(image.rgba[27], 4.0f);
    EXPECT_EQ(pixel(image, 2, 1).b, 3.0f);
    EXPECT_EQ(pixel(image, 1, 2).r, 0.0f) << "(x, y) must not be transposed";

    ImageU8 bytes = makeImageU8(4, 3);
    setPixel(bytes, 3, 2, {10, 20, 30, 40});
    EXPECT_EQ(bytes.rgba[(2 * 4 + 3) * 4 + 1], 20);
    EXPECT_EQ(pixel(bytes, 3, 2).a, 40);
    EXPECT_EQ(pixel(bytes, 0, 0).a, 255) << "default 8-bit fill is opaque";
}

TEST(Image, CountNonFiniteCountsNanAndBothInfinities) {
    ImageF image = makeImage(4, 4);
    EXPECT_TRUE(allFinite(image));
    EXPECT_EQ(countNonFinite(image), 0u);
    image.rgba[0] = std::numeric_limits<float>::quiet_NaN();
    image.rgba[7] = std::numeric_limits<float>::infinity();
    image.rgba[63] = -std::numeric_limits<float>::infinity(); // last float: alpha of the last pixel
    image.rgba[10] = std::numeric_limits<float>::max();       // finite, must not be counted
    EXPECT_EQ(countNonFinite(image), 3u);
    EXPECT_FALSE(allFinite(image));
}

TEST(Image, QuantizeRoundsHalvesAwayFromZeroAndClamps) {
    ImageF image = makeImage(1, 1, {0.5f, -0.25f, 2.0f, 1.0f / 255.0f});
    const ImageU8 bytes = quantizeToU8(image);
    const RgbaU8 p = pixel(bytes, 0, 0);
    EXPECT_EQ(p.r, 128) << "255 * 0.5 = 127.5 must round up, as the documented rule says";
    EXPECT_EQ(p.g, 0) << "negative values clamp to 0";
    EXPECT_EQ(p.b, 255) << "values above 1 clamp to 255";
    EXPECT_EQ(p.a, 1);
}

TEST(Image, DequantizedIsTheByteOver255AndQuantizesBackExactly) {
    ImageU8 bytes = makeImageU8(256, 1);
    for (uint32_t x = 0; x < 256; ++x)
        setPixel(bytes, x, 0, {uint8_t(x), uint8_t(255 - x), 0, 255});
    const ImageF image = dequantized(bytes);
    EXPECT_FLOAT_EQ(image.rgba[4 * 51], 0.2f);
    EXPECT_EQ(image.rgba[4 * 255], 1.0f);
    EXPECT_EQ(quantizeToU8(image).rgba, bytes.rgba) << "every byte survives the round trip";
}

TEST(Image, QuantizeRefusesNan) {
    ImageF image = makeImage(2, 2);
    image.rgba[5] = std::nanf("");
    EXPECT_THROW(quantizeToU8(image), IoError) << "NaN has no 8-bit value and must not silently become black";
}

TEST(Image, MakeImageRefusesSizesAboveTheLimit) {
    EXPECT_THROW(makeImage(1u << 15, 1u << 15), IoError) << "2^30 pixels is above kMaxImagePixels";
}

} // namespace
} // namespace eng::io
