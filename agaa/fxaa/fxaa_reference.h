#pragma once
// FXAA 3.11 quality (Lottes 2009): the quality presets' search steps (the one table the
// GPU pass specialises on) and the CPU twin of shaders/glsl/fxaa/fxaa.comp, which the
// GPU output is tested against (tests/gpu/test_peers.cpp).

#include "engine/io/image.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace agaa {

struct FxaaSettings {
    // Quality preset as in FXAA 3.11: 10..15 (medium dither), 20..29 (low dither), 39 (extreme).
    uint32_t preset = 39;
    float subpix = 0.75f;         // sub-pixel aliasing removal: 0 off .. 1 softest (FXAA 3.11 default 0.75)
    float edgeThreshold = 0.166f; // local contrast needed, relative to the local max luma (default 0.166)
    float edgeThresholdMin =
        0.0833f; // and at least this absolute luma, so darks are left alone (default 0.0833)
};

// The end-of-edge search steps of a preset, in pixels (FXAA 3.11 FXAA_QUALITY__P0..P11).
// Throws std::invalid_argument naming the allowed presets for any other value.
std::span<const float> fxaaPresetSteps(uint32_t preset);
std::string fxaaPresetNames(); // "10, 11, ..., 39" for messages
// Throws std::invalid_argument naming the setting and its range.
void checkFxaaSettings(const FxaaSettings& settings);

// Pixel luma as the pass computes it (sqrt of Rec. 601 luma of the tone-mapped colour).
float fxaaLuma(const eng::io::ImageF& image, int x, int y);

// FXAA of a tone-mapped image (linear [0,1] RGBA), alpha set to 1: the GPU pass's arithmetic in fp32.
// decisionMargins (optional, one per pixel): the smallest distance, in luma, between a value the
// pass compared and what it was compared with (step 1's contrast threshold, the orientation, the
// side, every end-of-edge test, the span's sign; step 1's alone where it leaves the pixel as is).
// A pixel may depart from this twin by more than fp32 rounding only where its
// margin is within rounding: a decision on its threshold (tests/gpu/test_peers_fxaa.cpp).
eng::io::ImageF fxaaReference(const eng::io::ImageF& display, const FxaaSettings& settings,
                              std::vector<float>* decisionMargins = nullptr);

// Whether the pixel passes the local contrast test (step 1), i.e. FXAA may change it.
bool fxaaIsEdgePixel(const eng::io::ImageF& display, int x, int y, const FxaaSettings& settings);

} // namespace agaa
