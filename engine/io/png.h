#pragma once

#include "engine/io/image.h"

#include <filesystem>

namespace eng::io {

// Writes 8-bit RGBA PNG. Throws IoError, naming the file, when the buffer does not hold
// width*height RGBA pixels, the image is empty, or the file cannot be written.
void writePng(const std::filesystem::path& file, const ImageU8& image);

// Reads any PNG (grey, grey+alpha, RGB, RGBA, palette; 16-bit is reduced to 8-bit) as 8-bit RGBA;
// a missing alpha reads as 255. Throws IoError, naming the file, when it is missing, is not a PNG,
// or is corrupt or truncated.
ImageU8 readPng(const std::filesystem::path& file);

} // namespace eng::io
