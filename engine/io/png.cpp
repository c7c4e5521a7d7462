#include "engine/io/png.h"

#include "engine/io/io_error.h"

#include <stb_image.h>
#include <stb_image_write.h>

#include <climits>
#include <cstring>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace eng::io {

namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::vector<unsigned char> readBytes(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
        throw IoError(file, "cannot read PNG: no such file");
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        throw IoError(file, "cannot read PNG: cannot open file");
    }
    std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) {
        throw IoError(file, "cannot read PNG: read error");
    }
    return bytes;
}

} // namespace

void writePng(const std::filesystem::path& file, const ImageU8& image) {
    if (!isConsistent(image)) {
        throw IoError(file, "cannot write PNG: buffer holds " + std::to_string(image.rgba.size()) +
                                " bytes, expected " + std::to_string(pixelCount(image) * 4) + " for " +
                                std::to_string(image.width) + "x" + std::to_string(image.height));
    }
    if (image.width == 0 || image.height == 0) {
        throw IoError(file, "cannot write PNG: image is empty (" + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ")");
    }
    // stb takes int sizes and an int row stride.
    if (image.width > uint32_t(INT_MAX / 4) || image.height > uint32_t(INT_MAX)) {
        throw IoError(file, "cannot write PNG: " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " is too large");
    }
    const int width = int(image.width);
    if (stbi_write_png(file.c_str(), width, int(image.height), 4, image.rgba.data(), width * 4) == 0) {
        // stb does not say why; the usual cause is a missing directory or no write permission.
        throw IoError(file, "cannot write PNG: cannot create or write the file");
    }
}

ImageU8 readPng(const std::filesystem::path& file) {
    const std::vector<unsigned char> bytes = readBytes(file);
    // Checked here because stb_image would happily decode a JPEG or BMP given a .png name.
    if (bytes.size() < sizeof(kPngSignature) ||
        std::memcmp(bytes.data(), kPngSignature, sizeof(kPngSignature)) != 0) {
        throw IoError(file, "cannot read PNG: not a PNG file (bad signature)");
    }
    if (bytes.size() > size_t(INT_MAX)) {
        throw IoError(file, "cannot read PNG: file is larger than 2 GiB");
    }

    int width = 0, height = 0, channelsInFile = 0;
    if (stbi_info_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channelsInFile) == 0) {
        throw IoError(file, std::string("cannot read PNG: ") + stbi_failure_reason());
    }
    if (width <= 0 || height <= 0 || uint64_t(width) * uint64_t(height) > kMaxImagePixels) {
        throw IoError(file, "cannot read PNG: unsupported size " + std::to_string(width) + "x" +
                                std::to_string(height));
    }

    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes.data(), int(bytes.size()), &width, &height, &channelsInFile, 4),
        stbi_image_free);
    if (!pixels) {
        throw IoError(file, std::string("cannot read PNG: ") + stbi_failure_reason());
    }

    ImageU8 image{uint32_t(width), uint32_t(height), {}};
    image.rgba.assign(pixels.get(), pixels.get() + pixelCount(image) * 4);
    return image;
}

} // namespace eng::io
