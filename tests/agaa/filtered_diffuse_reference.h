#pragma once
// AGAA's filtered Lambert in double, written from its definition and not from the shader
// (common/brdf.glsl filteredClampedCosine): the shader-math twin (tests/hard) and the lighting
// references (tests/agaa) use it. Also the integral it approximates, to bound the model's error.

#include <algorithm>
#include <array>
#include <cmath>

namespace agaa::test {

// AGAA's filtered Lambert (common/brdf.glsl filteredClampedCosine), from its definition rather
// than the shader's expansion: the clamped cosine's Legendre coefficients integrated numerically,
// P_l by the three-term recurrence, bands l = 1..6 attenuated by r^(l(l+1)/2) on the exact max(0, x).
inline double legendre(int l, double x) {
    double p0 = 1.0, p1 = x;
    if (l == 0) return p0;
    for (int k = 1; k < l; ++k) {
        const double p2 = ((2 * k + 1) * x * p1 - k * p0) / (k + 1);
        p0 = p1;
        p1 = p2;
    }
    return p1;
}
// (2l + 1) / 2 * integral_0^1 x P_l(x) dx by the midpoint rule, for l = 0..6, computed once.
inline const std::array<double, 7>& clampedCosineCoefficients() {
    static const std::array<double, 7> coefficients = [] {
        std::array<double, 7> a{};
        const int steps = 4096;
        for (int l = 0; l < 7; ++l) {
            double sum = 0.0;
            for (int i = 0; i < steps; ++i) {
                const double x = (i + 0.5) / steps;
                sum += x * legendre(l, x);
            }
            a[size_t(l)] = (2 * l + 1) / 2.0 * sum / steps;
        }
        return a;
    }();
    return coefficients;
}
inline double filteredCosine(double x, double r) {
    double v = std::max(x, 0.0);
    for (int l = 1; l <= 6; ++l)
        v += clampedCosineCoefficients()[size_t(l)] * (std::pow(r, l * (l + 1) / 2.0) - 1.0) * legendre(l, x);
    return std::max(v, 0.0);
}
// What the expansion approximates: E[max(0, N.L)] for N drawn from a von Mises-Fisher lobe around z
// whose mean length is r (kappa from coth(kappa) - 1/kappa = r by bisection), x = z.L, by
// quadrature over the polar angle's cosine t and the azimuth.
inline double vmfClampedCosine(double x, double r) {
    double kappa = 0.0;
    if (r > 0.0) {
        double lo = 1e-9, hi = 1e6;
        for (int i = 0; i < 200; ++i) {
            const double m = std::sqrt(lo * hi);
            (1.0 / std::tanh(m) - 1.0 / m < r ? lo : hi) = m;
        }
        kappa = lo;
    }
    const double sx = std::sqrt(std::max(1.0 - x * x, 0.0));
    const int nt = 400, nphi = 128;
    double sum = 0.0, weight = 0.0;
    for (int i = 0; i < nt; ++i) {
        const double t = -1.0 + (i + 0.5) * 2.0 / nt, st = std::sqrt(std::max(1.0 - t * t, 0.0));
        const double density = std::exp(kappa * (t - 1.0)); // vMF density in t, unnormalised
        double ring = 0.0;
        for (int j = 0; j < nphi; ++j)
            ring +=
                std::max(st * std::cos((j + 0.5) * 2.0 * 3.14159265358979323846 / nphi) * sx + t * x, 0.0);
        sum += density * ring / nphi;
        weight += density;
    }
    return sum / weight;
}
// The expansion's largest distance from the vMF integral over r in [0, 0.99], x in [-1, 1]
// (measured: 0.043, at x = 0, where the clamped cosine's kink needs the bands above 6).
inline constexpr double kFilteredCosineModelError = 0.045;

} // namespace agaa::test
