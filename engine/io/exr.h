#pragma once

#include "engine/io/image.h"

#include <filesystem>

namespace eng::io {

enum class ExrPixelType {
    Half,  // 16-bit float: half the size; ~3 significant digits; finite range +-65504.
    Float, // 32-bit float: bit-exact round trip of an ImageF.
};

struct ExrWriteOptions {
    ExrPixelType pixelType = ExrPixelType::Half;
};

// Largest finite half. Half channels are written with every value clamped to [-kHalfMax, kHalfMax]:
// without the clamp anything above 65519.99 would round to +Inf, and an Inf in a reference image
// poisons every metric computed from it. A clamped highlight still tone-maps to white.
inline constexpr float kHalfMax = 65504.0f;

// Writes linear HDR RGBA as a scanline EXR (R, G, B, A channels, ZIP compression, lossless).
// Throws IoError, naming the file, when: the buffer does not hold width*height RGBA pixels,
// the image is empty, any value is NaN or +-Inf (the renderer guarantees finite output; this is
// the last line of defence, so a bad frame is refused rather than written), or the file
// cannot be written.
void writeExr(const std::filesystem::path& file, const ImageF& image, const ExrWriteOptions& options = {});

// Reads the first part of an EXR (scanline or tiled; half, float or uint channels are converted to
// float). A missing A channel reads as 1; a missing R, G or B as 0, but a file with none of R, G, B
// is refused. Throws IoError, naming the file, when it is missing, unreadable, corrupt or truncated.
ImageF readExr(const std::filesystem::path& file);

} // namespace eng::io
