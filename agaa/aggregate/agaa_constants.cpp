#include "agaa/aggregate/agaa_constants.h"

#include "shared/clustering.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace agaa {

void validate(const AggregateSettings& s) {
    if (s.samples != 4 && s.samples != 8 && s.samples != 16 && s.samples != 32)
        throw std::invalid_argument("agaa: --samples " + std::to_string(s.samples) +
                                    " is not supported (allowed: 4, 8, 16, 32)");
    if (s.aggregates < 1 || s.aggregates > shared::kMaxAggregates)
        throw std::invalid_argument("agaa: --aggregates " + std::to_string(s.aggregates) +
                                    " is out of range (allowed: 1, 2, 3, 4)");
    if (!(s.characteristicLength > 0.0f) || !std::isfinite(s.characteristicLength))
        throw std::invalid_argument("agaa: characteristic length must be a positive number of metres");
    if (!(s.seedThreshold >= 0.0f) || !std::isfinite(s.seedThreshold))
        throw std::invalid_argument("agaa: seed threshold must be >= 0");
    if (std::isnan(s.tolerance) || std::isinf(s.tolerance))
        throw std::invalid_argument("agaa: --agaa-tolerance must be a finite number >= 0, or never");
    if (!(s.aliasLimit > 0.0f))
        throw std::invalid_argument("agaa: --agaa-alias-limit must be a number > 0, or none");
    if (s.debugView == AggregateDebugView::ShadingRate && s.tolerance < 0.0f && s.tolerance != kToleranceAuto)
        throw std::invalid_argument("agaa: --debug shading-rate shows the pixels --agaa-tolerance shades per "
                                    "sample; give a tolerance (a number >= 0)");
}

shared::AgaaConstants makeAgaaConstants(const AggregateSettings& s, const shared::FrameConstants& frame,
                                        bool hasEmissive) {
    shared::AgaaConstants c{};
    // Decoding tables in double, rounded once to float: both the GPU and the CPU reference read them.
    for (uint32_t q = 0; q < shared::kNormalAngleLevels; ++q) {
        double theta = double(q) * (std::numbers::pi / 2.0) / 255.0;
        double phi = (double(q) / 256.0) * 2.0 * std::numbers::pi - std::numbers::pi;
        c.cosSinTheta[q] = {float(std::cos(theta)), float(std::sin(theta)), 0.0f, 0.0f};
        c.cosSinPhi[q] = {float(std::cos(phi)), float(std::sin(phi)), 0.0f, 0.0f};
    }
    float znear = frame.depthParams.x, zfar = frame.depthParams.y;
    c.clustering = {1.0f / s.characteristicLength, s.seedThreshold, znear * zfar, zfar - znear};
    c.ndcParams = {2.0f / frame.extent.x, 2.0f / frame.extent.y, frame.projParams.x, frame.projParams.y};
    c.shape = {s.aggregates, shared::metadataBits(s.aggregates),
               shared::metadataWords(s.samples, s.aggregates), s.samples};
    // Toksvig with roughness injected as variance (agaa/aggregate/README.md): the reference
    // Blinn-Phong exponent of the smoothest representable surface.
    float smax = 2.0f / (kMinGgxAlpha * kMinGgxAlpha) - 2.0f;
    c.toksvig = {smax, kMinGgxAlpha, kMaxGgxAlpha, 0.0f};
    c.options = {uint32_t(s.debugView), uint32_t(s.position), hasEmissive ? 1u : 0u, uint32_t(s.ndf)};
    c.modes = {uint32_t(s.distance), uint32_t(s.routing), 0u, 0u};
    // The limit as the largest float when there is none (or at a tolerance of 0, which flags every
    // covered pixel): the shader's estimate < limit then always holds, with no infinity in a buffer.
    const bool limited = s.tolerance > 0.0f && std::isfinite(s.aliasLimit);
    c.shadingRate = {std::max(s.tolerance, 0.0f), limited ? s.aliasLimit : std::numeric_limits<float>::max(),
                     kAliasedSaturation, kMeanNormalGap};
    return c;
}

} // namespace agaa
