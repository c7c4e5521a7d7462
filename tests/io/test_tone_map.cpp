#include "engine/io/io_error.h"
#include "engine/io/tone_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace eng::io {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

TEST(ToneMapAces, BlackStaysBlack) {
    EXPECT_EQ(toneMapAces(0.0f), 0.0f) << "0 must map to exactly 0 (the curve has no offset)";
    EXPECT_EQ(toneMapAces(-1.0f), 0.0f) << "negative radiance maps to black, not up the rational curve";
    EXPECT_EQ(toneMapAces(-1e6f), 0.0f) << "without the guard, large negative x would map to 1";
    EXPECT_EQ(toneMapAces(-kInf), 0.0f);
}

TEST(ToneMapAces, MatchesHandComputedValues) {
    // x = 1:    1*(2.51+0.03) / (1*(2.43+0.59)+0.14) = 2.54 / 3.16 = 0.803797468...
    EXPECT_NEAR(toneMapAces(1.0f), 2.54 / 3.16, 1e-6);
    // x = 0.18: 0.18*0.4818 / (0.18*1.0274+0.14) = 0.086724 / 0.324932 = 0.266898920...
    EXPECT_NEAR(toneMapAces(0.18f), 0.086724 / 0.324932, 1e-6);
    // x = 7:    7*17.6 / (7*17.6+0.14) = 123.2 / 123.34 = 0.998864926... (still below the saturation point)
    EXPECT_NEAR(toneMapAces(7.0f), 123.2 / 123.34, 1e-6);
}

TEST(ToneMapAces, IsMonotonic) {
    float previous = toneMapAces(0.0f);
    for (int i = 1; i <= 20000; ++i) {
        const float x = float(i) * 0.001f; // 0.001 .. 20, across the saturation point at ~7.24
        const float y = toneMapAces(x);
        ASSERT_GE(y, previous) << "tone curve decreased at x = " << x;
        if (x < 5.0f) {
            ASSERT_GT(y, previous) << "tone curve flat below saturation at x = " << x;
        }
        previous = y;
    }
}

TEST(ToneMapAces, SaturatesToOne) {
    EXPECT_EQ(toneMapAces(8.0f), 1.0f);
    EXPECT_EQ(toneMapAces(1e6f), 1.0f);
    EXPECT_EQ(toneMapAces(std::numeric_limits<float>::max()), 1.0f)
        << "x*x overflows; must not give Inf/Inf = NaN";
    EXPECT_EQ(toneMapAces(kInf), 1.0f);
    EXPECT_LT(toneMapAces(7.0f), 1.0f) << "must not saturate early";
}

TEST(ToneMapAces, PropagatesNan) {
    EXPECT_TRUE(std::isnan(toneMapAces(std::nanf("")))) << "a NaN pixel must stay visible, not turn black";
}

TEST(LinearToSrgb, ExactPiecewiseBoundary) {
    constexpr float kBoundary = 0.0031308f;
    // IEC 61966-2-1: the linear segment includes the boundary (v <= 0.0031308).
    EXPECT_EQ(linearToSrgb(kBoundary), 12.92f * kBoundary);
    // The two segments meet (to ~1e-7): no visible step at the boundary.
    const float above = std::nextafter(kBoundary, 1.0f);
    const float below = std::nextafter(kBoundary, 0.0f);
    EXPECT_NEAR(linearToSrgb(above), linearToSrgb(kBoundary), 1e-6f);
    EXPECT_NEAR(linearToSrgb(above), 1.055f * std::pow(above, 1.0f / 2.4f) - 0.055f, 1e-7f)
        << "just above the boundary the power segment must be used";
    EXPECT_EQ(linearToSrgb(below), 12.92f * below)
        << "just below the boundary the linear segment must be used";
}

TEST(LinearToSrgb, KnownValues) {
    EXPECT_EQ(linearToSrgb(0.0f), 0.0f);
    EXPECT_NEAR(linearToSrgb(0.5f), 0.7353569830524495, 1e-6) << "1.055 * 0.5^(1/2.4) - 0.055";
    EXPECT_NEAR(linearToSrgb(0.001f), 0.01292, 1e-7) << "linear segment: 12.92 * 0.001";
    EXPECT_NEAR(linearToSrgb(0.18f), 0.4613561295004, 1e-6) << "middle grey";
    EXPECT_NEAR(linearToSrgb(1.0f), 1.0, 1e-6);
}

TEST(LinearToSrgb, ClampsToUnitRange) {
    EXPECT_EQ(linearToSrgb(-0.5f), 0.0f);
    EXPECT_EQ(linearToSrgb(4.0f), linearToSrgb(1.0f));
    EXPECT_TRUE(std::isnan(linearToSrgb(std::nanf(""))));
}

TEST(ToneMapToSrgb8, MapsBlackWhiteAndAKnownValue) {
    ImageF hdr = makeImage(3, 1);
    setPixel(hdr, 0, 0, {0.0f, 0.0f, 0.0f, 0.0f});
    setPixel(hdr, 1, 0, {100.0f, 1e9f, 8.0f, 0.5f});
    setPixel(hdr, 2, 0, {1.0f, 0.18f, -1.0f, 1.0f});
    const ImageU8 out = toneMapToSrgb8(hdr);
    ASSERT_EQ(out.width, 3u);
    ASSERT_EQ(out.height, 1u);
    EXPECT_EQ(pixel(out, 0, 0).r, 0);
    EXPECT_EQ(pixel(out, 0, 0).a, 255) << "alpha is always 255, whatever the input alpha";
    EXPECT_EQ(pixel(out, 1, 0).r, 255);
    EXPECT_EQ(pixel(out, 1, 0).g, 255);
    EXPECT_EQ(pixel(out, 1, 0).b, 255);
    EXPECT_EQ(pixel(out, 1, 0).a, 255);
    // x = 1: ACES 0.8037975 -> sRGB 0.9082305 -> 255 * 0.9082305 = 231.599 -> 232.
    EXPECT_EQ(pixel(out, 2, 0).r, 232);
    // x = 0.18: ACES 0.2668989 -> sRGB 0.5534576 -> 141.13 -> 141.
    EXPECT_EQ(pixel(out, 2, 0).g, 141);
    EXPECT_EQ(pixel(out, 2, 0).b, 0);
}

TEST(ToneMapToSrgb8, AgreesWithFloatToneMapped) {
    ImageF hdr = makeImage(64, 1);
    for (uint32_t x = 0; x < 64; ++x) {
        const float v = std::ldexp(1.0f, int(x) / 4 - 8) * (1.0f + float(x % 4) * 0.25f); // 2^-8 .. ~2^8
        setPixel(hdr, x, 0, {v, v * 0.5f, v * 2.0f, 1.0f});
    }
    const ImageF display = toneMapped(hdr);
    const ImageU8 bytes = toneMapToSrgb8(hdr);
    for (size_t i = 0; i < display.rgba.size(); ++i) {
        ASSERT_GE(display.rgba[i], 0.0f);
        ASSERT_LE(display.rgba[i], 1.0f) << "toneMapped output must be in [0,1]";
        ASSERT_EQ(bytes.rgba[i], uint8_t(std::lround(255.0f * display.rgba[i])))
            << "8-bit output must be the rounded float display image, index " << i;
    }
    EXPECT_EQ(pixel(display, 5, 0).a, 1.0f) << "toneMapped alpha is opaque";
}

TEST(ToneMapToSrgb8, RefusesNan) {
    ImageF hdr = makeImage(2, 2);
    hdr.rgba[4] = std::nanf("");
    EXPECT_THROW(toneMapToSrgb8(hdr), IoError) << "NaN must not be written as black";
    EXPECT_TRUE(std::isnan(toneMapped(hdr).rgba[4])) << "the float path keeps NaN so that metrics refuse it";
}

} // namespace
} // namespace eng::io
