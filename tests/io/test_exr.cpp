#include "engine/io/exr.h"
#include "engine/io/io_error.h"
#include "engine/io/png.h"

#include "io_test_support.h"

#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <string>

namespace eng::io {
namespace {

using test::expectIoErrorNaming;
using test::ScratchDir;

// 17x13: odd and non-square, so a swapped width/height or a wrong row stride scrambles pixels.
constexpr uint32_t kWidth = 17;
constexpr uint32_t kHeight = 13;

ImageF makeHdrPattern(uint32_t width, uint32_t height, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> radiance(0.0f, 1000.0f);
    ImageF image = makeImage(width, height);
    for (uint32_t y = 0; y < height; ++y) {
        for (uint32_t x = 0; x < width; ++x) {
            setPixel(image, x, y, {radiance(rng), radiance(rng) * 1e-3f, float(x) + 100.0f * float(y), 0.5f});
        }
    }
    return image;
}

TEST(Exr, FloatRoundTripIsBitExact) {
    ScratchDir dir;
    ImageF image = makeHdrPattern(kWidth, kHeight, 1);
    // Values half could not hold: above 65504, tiny, negative, 0.1 (inexact in half).
    setPixel(image, 0, 0, {1e30f, 1e-30f, -3.5f, 0.1f});
    setPixel(image, kWidth - 1, kHeight - 1, {70000.0f, std::numeric_limits<float>::max(), 0.1f, 2.0f});
    writeExr(dir / "float.exr", image, {ExrPixelType::Float});

    const ImageF back = readExr(dir / "float.exr");
    ASSERT_EQ(back.width, kWidth);
    ASSERT_EQ(back.height, kHeight);
    ASSERT_EQ(back.rgba.size(), image.rgba.size());
    EXPECT_EQ(std::memcmp(back.rgba.data(), image.rgba.data(), image.rgba.size() * sizeof(float)), 0)
        << "FLOAT channels must round-trip every bit, including values outside the half range";
}

TEST(Exr, HalfRoundTripIsWithinHalfPrecision) {
    ScratchDir dir;
    const ImageF image = makeHdrPattern(kWidth, kHeight, 2);
    writeExr(dir / "half.exr", image); // HALF is the default

    const ImageF back = readExr(dir / "half.exr");
    ASSERT_EQ(back.width, kWidth);
    ASSERT_EQ(back.height, kHeight);
    ASSERT_EQ(back.rgba.size(), image.rgba.size());
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        // Round to nearest half: relative error <= 2^-11 for normals, absolute <= 2^-25 for subnormals.
        const float v = image.rgba[i];
        const float tolerance = std::max(std::abs(v) * std::ldexp(1.0f, -11), std::ldexp(1.0f, -25));
        ASSERT_NEAR(back.rgba[i], v, tolerance) << "float index " << i << " (pixel " << i / 4 << ")";
    }
}

TEST(Exr, HalfIsTheDefaultAndFloatOptionTakesEffect) {
    ScratchDir dir;
    const ImageF image = makeImage(3, 5, {0.1f, 0.1f, 0.1f, 1.0f});
    writeExr(dir / "default.exr", image);
    writeExr(dir / "float.exr", image, {ExrPixelType::Float});
    // half(0.1) = 0.0999755859375: seeing it proves the channels really are 16-bit.
    EXPECT_EQ(readExr(dir / "default.exr").rgba[0], 0.0999755859375f) << "default must write HALF";
    EXPECT_EQ(readExr(dir / "float.exr").rgba[0], 0.1f) << "ExrPixelType::Float must write FLOAT";
}

TEST(Exr, HalfClampsToLargestFiniteHalfInsteadOfInf) {
    ScratchDir dir;
    ImageF image = makeImage(6, 1);
    setPixel(image, 0, 0,
             {65504.0f, 65000.0f, 65519.0f, 1.0f});          // at, below, just under the Inf rounding point
    setPixel(image, 1, 0, {65520.0f, 70000.0f, 1e9f, 1.0f}); // would all round to +Inf unclamped
    setPixel(image, 2, 0, {-65504.0f, -70000.0f, -std::numeric_limits<float>::max(), 1.0f});
    writeExr(dir / "range.exr", image);

    const ImageF back = readExr(dir / "range.exr");
    EXPECT_TRUE(allFinite(back)) << "half output must never contain Inf";
    EXPECT_EQ(pixel(back, 0, 0).r, 65504.0f) << "the largest finite half is representable exactly";
    EXPECT_NEAR(pixel(back, 0, 0).g, 65000.0f, 16.0f) << "half spacing near 65000 is 32";
    EXPECT_EQ(pixel(back, 0, 0).b, 65504.0f);
    EXPECT_EQ(pixel(back, 1, 0).r, 65504.0f) << "65520 rounds to Inf in half; must be clamped";
    EXPECT_EQ(pixel(back, 1, 0).g, 65504.0f);
    EXPECT_EQ(pixel(back, 1, 0).b, 65504.0f);
    EXPECT_EQ(pixel(back, 2, 0).r, -65504.0f);
    EXPECT_EQ(pixel(back, 2, 0).g, -65504.0f) << "clamping must be symmetric";
    EXPECT_EQ(pixel(back, 2, 0).b, -65504.0f);
}

TEST(Exr, AlphaIsPreserved) {
    ScratchDir dir;
    ImageF image = makeImage(2, 2, {1.0f, 1.0f, 1.0f, 0.25f});
    writeExr(dir / "alpha.exr", image);
    EXPECT_EQ(pixel(readExr(dir / "alpha.exr"), 1, 1).a, 0.25f) << "alpha must be written, not dropped to 1";
}

// Writes `channels` (FLOAT) with the given data window through OpenEXR directly, to produce files that
// writeExr never makes: missing channels, a data window not at the origin.
void writeRawExr(const std::filesystem::path& file, const std::vector<std::string>& channels,
                 const Imath::Box2i& window, float value) {
    const int width = window.max.x - window.min.x + 1;
    const int height = window.max.y - window.min.y + 1;
    Imf::Header header(Imath::Box2i({0, 0}, window.max), window);
    std::vector<std::vector<float>> planes(channels.size());
    Imf::FrameBuffer frameBuffer;
    for (size_t c = 0; c < channels.size(); ++c) {
        planes[c].assign(size_t(width) * size_t(height), value);
        planes[c][0] = value + 1.0f; // marks the top-left pixel of the data window
        header.channels().insert(channels[c], Imf::Channel(Imf::FLOAT));
        frameBuffer.insert(channels[c], Imf::Slice::Make(Imf::FLOAT, planes[c].data(), window));
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(frameBuffer);
    out.writePixels(height);
}

TEST(Exr, MissingAlphaReadsAsOpaque) {
    ScratchDir dir;
    const auto file = dir / "rgb.exr";
    writeRawExr(file, {"R", "G", "B"}, Imath::Box2i({0, 0}, {4, 2}), 0.5f);
    const ImageF image = readExr(file);
    ASSERT_EQ(image.width, 5u);
    ASSERT_EQ(image.height, 3u);
    EXPECT_EQ(pixel(image, 2, 1).r, 0.5f);
    EXPECT_EQ(pixel(image, 2, 1).a, 1.0f) << "an RGB-only EXR must read as opaque, not transparent";
}

TEST(Exr, DataWindowOffsetLandsAtPixelZero) {
    ScratchDir dir;
    const auto file = dir / "offset.exr";
    writeRawExr(file, {"R", "G", "B", "A"}, Imath::Box2i({10, 20}, {16, 22}), 0.25f);
    const ImageF image = readExr(file);
    ASSERT_EQ(image.width, 7u) << "width comes from the data window, not the display window";
    ASSERT_EQ(image.height, 3u);
    EXPECT_EQ(pixel(image, 0, 0).g, 1.25f) << "the data window's first pixel must be pixel (0, 0)";
    EXPECT_EQ(pixel(image, 6, 2).g, 0.25f);
}

TEST(Exr, FileWithoutColourChannelsIsRefused) {
    ScratchDir dir;
    const auto file = dir / "depth_only.exr";
    writeRawExr(file, {"Z"}, Imath::Box2i({0, 0}, {3, 3}), 1.0f);
    // Reading it as all-black would make a broken reference look like a valid dark image.
    expectIoErrorNaming(file, [&] { readExr(file); });
}

TEST(Exr, RefusesNanAndDoesNotCreateTheFile) {
    ScratchDir dir;
    ImageF image = makeImage(kWidth, kHeight);
    setPixel(image, 3, 2, {0.0f, std::numeric_limits<float>::quiet_NaN(), 0.0f, 1.0f});
    const auto file = dir / "nan.exr";
    expectIoErrorNaming(file, [&] { writeExr(file, image); });
    expectIoErrorNaming(file, [&] { writeExr(file, image, {ExrPixelType::Float}); });
    EXPECT_FALSE(std::filesystem::exists(file)) << "a refused image must leave no file behind";
}

TEST(Exr, RefusesInfinity) {
    ScratchDir dir;
    ImageF image = makeImage(2, 2);
    image.rgba[0] = std::numeric_limits<float>::infinity();
    const auto file = dir / "inf.exr";
    // Clamping +Inf to 65504 would hide a renderer bug; it is refused like NaN.
    expectIoErrorNaming(file, [&] { writeExr(file, image); });
}

TEST(Exr, RefusesBufferSizeMismatchAndEmptyImages) {
    ScratchDir dir;
    ImageF image = makeImage(4, 4);
    image.rgba.pop_back();
    const auto file = dir / "bad.exr";
    expectIoErrorNaming(file, [&] { writeExr(file, image); });
    expectIoErrorNaming(file, [&] { writeExr(file, ImageF{}); });
}

TEST(Exr, UnwritablePathThrowsNamingTheFile) {
    ScratchDir dir;
    const ImageF image = makeImage(2, 2);
    const auto missingDir = dir / "no_such_dir/out.exr";
    expectIoErrorNaming(missingDir, [&] { writeExr(missingDir, image); });
    const auto isDirectory = dir.path();
    expectIoErrorNaming(isDirectory, [&] { writeExr(isDirectory, image); });
}

TEST(Exr, MissingFileThrowsNamingTheFile) {
    ScratchDir dir;
    const auto file = dir / "does_not_exist.exr";
    expectIoErrorNaming(file, [&] { readExr(file); });
}

TEST(Exr, CorruptFileThrowsNamingTheFile) {
    ScratchDir dir;
    const auto file = dir / "garbage.exr";
    {
        std::ofstream out(file, std::ios::binary);
        std::mt19937 rng(7);
        for (int i = 0; i < 4096; ++i)
            out.put(char(rng()));
    }
    expectIoErrorNaming(file, [&] { readExr(file); });

    const auto empty = dir / "empty.exr";
    std::ofstream(empty, std::ios::binary).close();
    expectIoErrorNaming(empty, [&] { readExr(empty); });
}

TEST(Exr, TruncatedFileThrowsNamingTheFile) {
    ScratchDir dir;
    const auto file = dir / "truncated.exr";
    writeExr(file, makeHdrPattern(64, 64, 3), {ExrPixelType::Float});
    const auto fullSize = std::filesystem::file_size(file);

    // Cut inside the pixel data, then inside the header: both must be errors, never a crash or a silent
    // half-black image.
    std::filesystem::resize_file(file, fullSize / 2);
    expectIoErrorNaming(file, [&] { readExr(file); });
    std::filesystem::resize_file(file, 40);
    expectIoErrorNaming(file, [&] { readExr(file); });
}

TEST(Exr, PngFileIsRefused) {
    ScratchDir dir;
    const auto file = dir / "actually_a_png.exr";
    writePng(file, makeImageU8(4, 4));
    expectIoErrorNaming(file, [&] { readExr(file); });
}

} // namespace
} // namespace eng::io
