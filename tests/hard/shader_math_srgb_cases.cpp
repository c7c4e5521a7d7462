// The shader-math edge cases of the sRGB transfer function (common/srgb.glsl): the encode the
// G-buffer's albedo is stored through, and the decode of the accumulate path's kept albedo
// (shared/sample_material.h), each against the standard's piecewise curve in double
// (shader_math_cases.cpp holds the rest).

#include "shader_math_checks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace agaa::hard {

using namespace checks;

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kDenormal = 1.0e-40f;

// IEC 61966-2-1 encode, from the standard's piecewise definition.
double srgbEncode(double linear) {
    const double x = std::clamp(linear, 0.0, 1.0);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

// Its inverse, from the standard's piecewise definition.
double srgbDecode(double encoded) {
    const double x = std::clamp(encoded, 0.0, 1.0);
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
}

} // namespace

void addSrgbCases(std::vector<EdgeCase>& cases) {
    auto add = [&](std::string name, std::vector<std::string> guards, MathCase in,
                   std::function<std::string(const MathResult&)> check) {
        cases.push_back({std::move(name), std::move(guards), in, std::move(check)});
    };
    // ---- sRGB encode (common/srgb.glsl): the albedo target's store, once fixed-function ----
    // Within 1/100 of an 8-bit step of the exact curve, so the stored byte is the exact one except
    // within that distance of a rounding boundary; both sides of the toe's cutoff, and the clamp.
    constexpr double kSrgbTolerance = 0.01 / 255.0;
    std::vector<float> linears = {0.0f, kDenormal, 0.0031308f, 0.00313081f, -1.0f, 2.0f, kInf, -kInf};
    for (int i = 1; i <= 32; ++i)
        linears.push_back(std::pow(i / 32.0f, 2.2f));
    for (float x : linears)
        add("srgbEncode x=" + fmt(x), {}, op(kOpSrgbEncode, glm::vec4(x, x * 0.5f, x * 0.25f, 0)),
            [x](const MathResult& r) {
                const D3 want(srgbEncode(x), srgbEncode(x * 0.5), srgbEncode(x * 0.25));
                return near3("encode(x)", glm::vec3(r.r0), want, 0.0, kSrgbTolerance);
            });
    // ---- sRGB decode (common/srgb.glsl): the accumulate path's kept albedo, an 8-bit code ----
    // Every 8-bit code's value within float rounding of the exact curve (the sRGB view's decode of
    // the G-buffer is exact to a float too); both sides of the toe's cutoff, and the clamp.
    std::vector<float> codes = {0.04045f, 0.04046f, -1.0f, 2.0f, kInf, -kInf, kDenormal};
    for (int i = 0; i <= 255; i += 3)
        codes.push_back(float(i) / 255.0f);
    for (int i : {10, 11, 254, 255})
        codes.push_back(float(i) / 255.0f);
    for (float x : codes)
        add("srgbDecode x=" + fmt(x), {}, op(kOpSrgbDecode, glm::vec4(x, x * 0.5f, x * 0.25f, 0)),
            [x](const MathResult& r) {
                const D3 want(srgbDecode(x), srgbDecode(x * 0.5), srgbDecode(x * 0.25));
                return near3("decode(x)", glm::vec3(r.r0), want, 1e-5, 1e-7);
            });
}

} // namespace agaa::hard
