#pragma once
// Physical exposure (issue 16), as real engines set it (Lagarde and de Rousiers 2014, "Moving
// Frostbite to Physically Based Rendering", section 5.1): a camera's EV100 maps scene luminance
// to the tone mapper's input by exposure = 1 / (1.2 * 2^EV100) (the saturation-based sensitivity
// with lens and vignetting factor q = 0.65), and automatic exposure meters the frame's
// log-average luminance L_avg: EV100 = log2(L_avg * S / K), S = 100, K = 12.5 (the reflected-light
// meter's calibration). Both a 100 klux sun and a 1 lux lamp come out readable.

#include "engine/scene/scene.h"

#include <cstdint>
#include <span>

namespace eng::frame {

// Luminance floor of the log average (cd/m^2): a black pixel would make the log -infinity.
inline constexpr double kMinMeteredLuminance = 1.0e-4;

float exposureFromEv100(double ev100);
double ev100FromLuminance(double averageLuminance);

// The log-average (geometric mean) luminance of the pixels whose coverage says they show
// geometry (covered[i] > 0; all pixels when none does), of a linear RGBA image (4 floats per
// pixel) rendered at `exposure`, brought back to scene units.
double logAverageLuminance(std::span<const float> rgba, std::span<const uint32_t> covered, float exposure);

// An exposure that keeps the metering frame's radiance inside the tone mapper's input range
// before anything is measured: a diffuse white surface under the illuminance the scene's lights
// and environment give its bounds' centre maps to about 1. 1 for a scene with no light at all.
float meteringExposure(const scene::Scene& scene);

} // namespace eng::frame
