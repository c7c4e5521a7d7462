#pragma once
// The metadata and AG-buffer layouts as DESIGN.md (section 4.2, figure 5) and shared/agaa.h
// document them, written apart from shared/clustering.h and shared/ag_buffer.h, so tests can
// decode the GPU's words independently of the kernels' own code.

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace agaa::test::layout {

// ---- Metadata (DESIGN 4.2, figure 5), decoded without shared/clustering.h ----------------------
// b = ceil(log2 c) bits per sample, and 1 at c = 1 (the layer bit: 1 when the sample is off the
// aggregate's layer); sample s's id in bits [s b, s b + b) of the pixel's 32-bit words.
inline uint32_t bitsPerSample(uint32_t c) {
    uint32_t b = 0;
    while ((1u << b) < c)
        ++b;
    return std::max(b, 1u);
}
inline uint32_t wordsPerPixel(uint32_t n, uint32_t c) {
    return (n * bitsPerSample(c) + 31) / 32;
}
inline uint32_t decodeId(const uint32_t* pixelWords, uint32_t s, uint32_t c) {
    const uint32_t b = bitsPerSample(c);
    if (b == 0) return 0;
    const uint32_t bit = s * b;
    return (pixelWords[bit / 32] >> (bit % 32)) & ((1u << b) - 1u);
}
// Bits past n b in the pixel's last word: nothing else shares the words, so they must be 0.
inline bool paddingIsZero(const uint32_t* pixelWords, uint32_t n, uint32_t c) {
    const uint32_t used = n * bitsPerSample(c), words = wordsPerPixel(n, c);
    if (words == 0 || used % 32 == 0) return true;
    return (pixelWords[words - 1] >> (used % 32)) == 0;
}

// ---- The AG-buffer (shared/agaa.h's documented layout and scales) in double ---------------------
// Each field sums, over the samples routed to the aggregate, round(u scale) with u in [0, 1]: the
// Toksvig vector's components offset-binary (x + 1) / 2, the SGGX matrix's diagonal as it is and
// its off-diagonal + 1/2, albedo, metallic and the material's GGX alpha as they are.
struct Field {
    uint32_t word, shift, bits;
    double scale;
};

struct Layout {
    bool sggx;
    Field normal[6]; // Toksvig x, y, z; or SGGX xx, yy, zz, xy, xz, yz
    Field albedo[3], metallic, alpha, count;
    uint32_t normalFields;
};

// The per-sample scales of shared/agaa.h: Toksvig x min(floor((2^26 - 1) / n), 2^23 - 1), y and z
// min(floor((2^32 - 1) / n), 2^23 - 1), 16-bit albedo and metallic fields at 2^11 - 1; SGGX 16-bit
// fields at floor((2^16 - 1) / n), metallic 10 bits at floor((2^10 - 1) / n); alpha 2^26 - 1.
inline Layout agBufferLayout(bool sggx, uint32_t n) {
    Layout l{};
    l.sggx = sggx;
    l.alpha = {5, 0, 32, double((1u << 26) - 1)};
    if (sggx) {
        const double s16 = std::floor(65535.0 / n);
        const Field f[6] = {{0, 0, 16, s16},  {0, 16, 16, s16}, {1, 0, 16, s16},
                            {1, 16, 16, s16}, {2, 0, 16, s16},  {2, 16, 16, s16}};
        std::copy(f, f + 6, l.normal);
        l.normalFields = 6;
        l.albedo[0] = {3, 0, 16, s16};
        l.albedo[1] = {3, 16, 16, s16};
        l.albedo[2] = {4, 0, 16, s16};
        l.metallic = {4, 16, 10, std::floor(1023.0 / n)};
        l.count = {4, 26, 6, 1.0};
    } else {
        const double sx = std::min(std::floor(67108863.0 / n), 8388607.0);
        const double syz = std::min(std::floor(4294967295.0 / n), 8388607.0);
        l.normal[0] = {0, 0, 26, sx};
        l.normal[1] = {1, 0, 32, syz};
        l.normal[2] = {2, 0, 32, syz};
        l.normalFields = 3;
        l.albedo[0] = {3, 0, 16, 2047.0};
        l.albedo[1] = {3, 16, 16, 2047.0};
        l.albedo[2] = {4, 0, 16, 2047.0};
        l.metallic = {4, 16, 16, 2047.0};
        l.count = {0, 26, 6, 1.0};
    }
    return l;
}

inline uint32_t fieldValue(const uint32_t* words, const Field& f) {
    const uint32_t v = words[f.word] >> f.shift;
    return f.bits == 32 ? v : v & ((1u << f.bits) - 1u);
}

} // namespace agaa::test::layout
