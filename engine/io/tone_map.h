#pragma once

#include "engine/io/image.h"

namespace eng::io {

// The display transform shared by the CPU (reports, metrics, PNG export) and the GLSL viewer.
// Both sides must implement exactly this, per colour channel, in 32-bit float:
//
//   toneMapAces(x):                         exposure is fixed at 1.0, so x is the linear value as is
//     if x is NaN          -> NaN           (propagated so that a bad pixel stays visible downstream)
//     if x <= 0            -> 0             (negative radiance is not physical; the rational curve
//                                            would climb back towards 1 for large negative x)
//     if x >= 8            -> 1             (the curve is >= 1 for x >= 7.2417 anyway; this keeps
//                                            huge and +Inf inputs from evaluating Inf/Inf = NaN)
//     else clamp((x * (2.51 x + 0.03)) / (x * (2.43 x + 0.59) + 0.14), 0, 1)
//                                           (Narkowicz 2015, "ACES Filmic Tone Mapping Curve";
//                                            the denominator has no real root, so it never is 0)
//
//   linearToSrgb(v):                        IEC 61966-2-1 sRGB OETF, exact piecewise form
//     v = clamp(v, 0, 1)                    (NaN propagated)
//     v <= 0.0031308 -> 12.92 v
//     else           -> 1.055 v^(1/2.4) - 0.055
//
//   display(c) = linearToSrgb(toneMapAces(c)) for R, G, B; alpha is set to 1 (opaque).
//   8-bit:       round(255 * display(c)), halves away from zero; alpha 255.
float toneMapAces(float x);
float linearToSrgb(float v);

// The display-encoded image as floats in [0,1]: the representation every metric in metrics.h is
// computed on. NaN in the input stays NaN (the metrics then refuse the image).
ImageF toneMapped(const ImageF& hdr);
// sRGB-encodes an already tone-mapped display image (linear values in [0, 1]; alpha kept).
// The renderers' `display` targets are resolved in linear space (DESIGN section 6); this is
// what goes to PNG files and what the error metrics compare.
ImageF srgbEncoded(const ImageF& display);

// toneMapped() quantised to 8 bits (see quantizeToU8), ready for writePng.
// Throws IoError if the image holds NaN or its buffer does not match its size.
ImageU8 toneMapToSrgb8(const ImageF& hdr);

} // namespace eng::io
