#include "engine/io/exr.h"

#include "engine/io/io_error.h"

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>
#include <system_error>

namespace eng::io {

namespace {

constexpr const char* kChannelNames[4] = {"R", "G", "B", "A"};

void checkWritable(const std::filesystem::path& file, const ImageF& image) {
    if (!isConsistent(image)) {
        throw IoError(file, "cannot write EXR: buffer holds " + std::to_string(image.rgba.size()) +
                                " floats, expected " + std::to_string(pixelCount(image) * 4) + " for " +
                                std::to_string(image.width) + "x" + std::to_string(image.height));
    }
    if (image.width == 0 || image.height == 0) {
        throw IoError(file, "cannot write EXR: image is empty (" + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ")");
    }
    if (const size_t bad = countNonFinite(image); bad > 0) {
        const auto first =
            std::find_if(image.rgba.begin(), image.rgba.end(), [](float v) { return !std::isfinite(v); });
        const size_t index = size_t(first - image.rgba.begin()) / 4;
        throw IoError(file, "refusing to write EXR: " + std::to_string(bad) +
                                " NaN/Inf values, first at pixel (" + std::to_string(index % image.width) +
                                ", " + std::to_string(index / image.width) + ")");
    }
}

} // namespace

void writeExr(const std::filesystem::path& file, const ImageF& image, const ExrWriteOptions& options) {
    checkWritable(file, image);

    const bool half = options.pixelType == ExrPixelType::Half;
    const Imf::PixelType type = half ? Imf::HALF : Imf::FLOAT;

    std::vector<Imath::half> halfPixels;
    char* base = nullptr;
    size_t channelSize = sizeof(float);
    if (half) {
        halfPixels.resize(image.rgba.size());
        for (size_t i = 0; i < image.rgba.size(); ++i) {
            halfPixels[i] = Imath::half(std::clamp(image.rgba[i], -kHalfMax, kHalfMax));
        }
        base = reinterpret_cast<char*>(halfPixels.data());
        channelSize = sizeof(Imath::half);
    } else {
        // OutputFile only reads through the slice pointers.
        base = reinterpret_cast<char*>(const_cast<float*>(image.rgba.data()));
    }

    const size_t xStride = 4 * channelSize;
    const size_t yStride = xStride * image.width;
    try {
        Imf::Header header(int(image.width), int(image.height));
        header.compression() = Imf::ZIP_COMPRESSION;
        Imf::FrameBuffer frameBuffer;
        for (int c = 0; c < 4; ++c) {
            header.channels().insert(kChannelNames[c], Imf::Channel(type));
            frameBuffer.insert(kChannelNames[c], Imf::Slice(type, base + c * channelSize, xStride, yStride));
        }
        Imf::OutputFile out(file.c_str(), header);
        out.setFrameBuffer(frameBuffer);
        out.writePixels(int(image.height));
    } catch (const std::exception& e) {
        throw IoError(file, std::string("cannot write EXR: ") + e.what());
    }
}

ImageF readExr(const std::filesystem::path& file) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) {
        throw IoError(file, "cannot read EXR: no such file");
    }
    try {
        Imf::InputFile in(file.c_str());
        const Imath::Box2i window = in.header().dataWindow();
        const int64_t width = int64_t(window.max.x) - window.min.x + 1;
        const int64_t height = int64_t(window.max.y) - window.min.y + 1;
        if (width <= 0 || height <= 0 || uint64_t(width) * uint64_t(height) > kMaxImagePixels) {
            throw IoError(file, "cannot read EXR: unsupported data window " + std::to_string(width) + "x" +
                                    std::to_string(height));
        }

        const Imf::ChannelList& channels = in.header().channels();
        if (!channels.findChannel("R") && !channels.findChannel("G") && !channels.findChannel("B")) {
            throw IoError(file, "cannot read EXR: no R, G or B channel");
        }

        ImageF image = makeImage(uint32_t(width), uint32_t(height));
        char* base = reinterpret_cast<char*>(image.rgba.data());
        const size_t xStride = 4 * sizeof(float);
        const size_t yStride = xStride * size_t(width);
        Imf::FrameBuffer frameBuffer;
        for (int c = 0; c < 4; ++c) {
            const double fill = c == 3 ? 1.0 : 0.0;
            // Slice::Make shifts the base pointer so that the data window origin lands on pixel (0, 0).
            frameBuffer.insert(kChannelNames[c], Imf::Slice::Make(Imf::FLOAT, base + c * sizeof(float),
                                                                  window, xStride, yStride, 1, 1, fill));
        }
        in.setFrameBuffer(frameBuffer);
        in.readPixels(window.min.y, window.max.y);
        return image;
    } catch (const IoError&) {
        throw;
    } catch (const std::exception& e) {
        throw IoError(file, std::string("cannot read EXR: ") + e.what());
    }
}

} // namespace eng::io
