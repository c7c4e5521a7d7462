#include "engine/io/exr.h"
#include "engine/io/io_error.h"
#include "engine/io/png.h"

#include "io_test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <string>

namespace eng::io {
namespace {

using test::expectIoErrorNaming;
using test::ScratchDir;

ImageU8 makeNoise(uint32_t width, uint32_t height, uint32_t seed) {
    std::mt19937 rng(seed);
    ImageU8 image = makeImageU8(width, height);
    for (uint8_t& v : image.rgba)
        v = uint8_t(rng());
    return image;
}

TEST(Png, RoundTripIsExact) {
    ScratchDir dir;
    // 17x13 noise: odd, non-square, every byte value likely, alpha varying too.
    const ImageU8 image = makeNoise(17, 13, 11);
    writePng(dir / "noise.png", image);
    const ImageU8 back = readPng(dir / "noise.png");
    EXPECT_EQ(back.width, 17u);
    EXPECT_EQ(back.height, 13u);
    EXPECT_EQ(back.rgba, image.rgba) << "PNG is lossless: every byte, alpha included, must come back";
}

TEST(Png, TopRowIsFirst) {
    ScratchDir dir;
    ImageU8 image = makeImageU8(2, 3);
    setPixel(image, 0, 0, {255, 0, 0, 255});
    writePng(dir / "orientation.png", image);
    const ImageU8 back = readPng(dir / "orientation.png");
    EXPECT_EQ(pixel(back, 0, 0).r, 255) << "reader must not flip vertically";
    EXPECT_EQ(pixel(back, 0, 2).r, 0);
}

TEST(Png, RefusesBufferSizeMismatchAndEmptyImages) {
    ScratchDir dir;
    ImageU8 image = makeImageU8(4, 4);
    image.rgba.resize(image.rgba.size() + 4);
    const auto file = dir / "bad.png";
    expectIoErrorNaming(file, [&] { writePng(file, image); });
    expectIoErrorNaming(file, [&] { writePng(file, ImageU8{}); });
    EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(Png, UnwritablePathThrowsNamingTheFile) {
    ScratchDir dir;
    const auto file = dir / "no_such_dir/out.png";
    expectIoErrorNaming(file, [&] { writePng(file, makeImageU8(2, 2)); });
}

TEST(Png, MissingFileThrowsNamingTheFile) {
    ScratchDir dir;
    const auto file = dir / "does_not_exist.png";
    expectIoErrorNaming(file, [&] { readPng(file); });
}

TEST(Png, CorruptFileThrowsNamingTheFile) {
    ScratchDir dir;
    const auto noise = dir / "garbage.png";
    {
        std::ofstream out(noise, std::ios::binary);
        std::mt19937 rng(5);
        for (int i = 0; i < 1024; ++i)
            out.put(char(rng()));
    }
    expectIoErrorNaming(noise, [&] { readPng(noise); });

    // A valid signature followed by garbage gets past the signature check and must fail in the decoder.
    const auto badBody = dir / "bad_body.png";
    {
        std::ofstream out(badBody, std::ios::binary);
        out.write("\x89PNG\r\n\x1a\n", 8);
        std::mt19937 rng(6);
        for (int i = 0; i < 1024; ++i)
            out.put(char(rng()));
    }
    expectIoErrorNaming(badBody, [&] { readPng(badBody); });

    const auto empty = dir / "empty.png";
    std::ofstream(empty, std::ios::binary).close();
    expectIoErrorNaming(empty, [&] { readPng(empty); });
}

TEST(Png, TruncatedFileThrowsNamingTheFile) {
    ScratchDir dir;
    const auto file = dir / "truncated.png";
    writePng(file, makeNoise(64, 64, 12)); // noise barely compresses: the cut lands inside IDAT
    std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
    expectIoErrorNaming(file, [&] { readPng(file); });
    std::filesystem::resize_file(file, 20);
    expectIoErrorNaming(file, [&] { readPng(file); });
}

TEST(Png, BmpFileIsRefusedThoughStbCouldDecodeIt) {
    ScratchDir dir;
    const auto file = dir / "actually_a_bmp.png";
    {
        // A valid 1x1 24-bit BMP (BITMAPINFOHEADER): stb_image decodes this, so only the PNG signature
        // check stops readPng from returning a non-PNG as if it were one.
        // clang-format off
        const unsigned char bmp[58] = {
            'B', 'M', 58, 0, 0, 0, 0, 0, 0, 0, 54, 0, 0, 0,    // file header: size 58, pixels at 54
            40, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 24, 0,  // info header: 1x1, 1 plane, 24 bpp,
            0, 0, 0, 0, 4, 0, 0, 0, 0x13, 0x0b, 0, 0,          //   uncompressed, 4 bytes of pixels,
            0x13, 0x0b, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,          //   72 dpi, no palette
            0x30, 0x20, 0x10, 0,                                // one BGR pixel + row padding
        };
        // clang-format on
        std::ofstream out(file, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bmp), sizeof(bmp));
    }
    expectIoErrorNaming(file, [&] { readPng(file); });
}

TEST(Png, ExrFileIsRefused) {
    ScratchDir dir;
    const auto file = dir / "actually_an_exr.png";
    writeExr(file, makeImage(4, 4));
    expectIoErrorNaming(file, [&] { readPng(file); });
}

} // namespace
} // namespace eng::io
