#include "engine/io/flip.h"

#include "engine/io/io_error.h"
#include "engine/io/metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace eng::io {

namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;
using Plane = std::vector<double>; // one channel, row-major

// The paper's constants (section 4).
constexpr double kColourExponent = 0.7;        // qc
constexpr double kFeatureExponent = 0.5;       // qf
constexpr double kCompressedShare = 0.4;       // pc: this share of cmax ...
constexpr double kCompressedTarget = 0.95;     // pt: ... maps to this error
constexpr double kFeatureWidthDegrees = 0.082; // w: the feature detectors' Gaussian sd is w / 2
constexpr double kKernelReachSigmas = 3.0;     // every kernel reaches 3 standard deviations

// The contrast sensitivity functions, Johnson and Fairchild's sums of Gaussians in the spatial
// domain: a1 sqrt(pi / b1) exp(-pi^2 x^2 / b1) + a2 sqrt(pi / b2) exp(-pi^2 x^2 / b2), x in degrees.
struct Csf {
    double a1, b1, a2, b2;
};
constexpr Csf kAchromatic{1.0, 0.0047, 0.0, 0.0}; // one Gaussian: a2 = 0
constexpr Csf kRedGreen{1.0, 0.0053, 0.0, 0.0};
constexpr Csf kBlueYellow{34.1, 0.04, 13.5, 0.025};
constexpr double kWidestCsfScale = 0.04; // the largest b: all three kernels share its radius

// Linear sRGB (Rec. 709 primaries, D65) to CIE XYZ, IEC 61966-2-1.
constexpr Mat3 kRgbToXyz{{{0.4124564, 0.3575761, 0.1804375},
                          {0.2126729, 0.7151522, 0.0721750},
                          {0.0193339, 0.1191920, 0.9503041}}};

Vec3 multiply(const Mat3& m, const Vec3& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2],
            m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

Mat3 inverse(const Mat3& m) {
    const double c00 = m[1][1] * m[2][2] - m[1][2] * m[2][1];
    const double c01 = m[1][2] * m[2][0] - m[1][0] * m[2][2];
    const double c02 = m[1][0] * m[2][1] - m[1][1] * m[2][0];
    const double det = m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02;
    return {{{c00 / det, (m[0][2] * m[2][1] - m[0][1] * m[2][2]) / det,
              (m[0][1] * m[1][2] - m[0][2] * m[1][1]) / det},
             {c01 / det, (m[0][0] * m[2][2] - m[0][2] * m[2][0]) / det,
              (m[0][2] * m[1][0] - m[0][0] * m[1][2]) / det},
             {c02 / det, (m[0][1] * m[2][0] - m[0][0] * m[2][1]) / det,
              (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / det}}};
}

const Mat3& xyzToRgb() {
    static const Mat3 m = inverse(kRgbToXyz);
    return m;
}

// The reference white: linear RGB (1, 1, 1) in XYZ.
Vec3 whitePoint() {
    return multiply(kRgbToXyz, {1.0, 1.0, 1.0});
}

double srgbToLinear(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// YCxCz (Y' = 116 y - 16, Cx = 500 (x - y), Cz = 200 (y - z) on the white-normalised XYZ) and back.
Vec3 xyzToYcxcz(const Vec3& xyz) {
    const Vec3 w = whitePoint();
    const double x = xyz[0] / w[0], y = xyz[1] / w[1], z = xyz[2] / w[2];
    return {116.0 * y - 16.0, 500.0 * (x - y), 200.0 * (y - z)};
}

Vec3 ycxczToXyz(const Vec3& v) {
    const Vec3 w = whitePoint();
    const double y = (v[0] + 16.0) / 116.0;
    return {(y + v[1] / 500.0) * w[0], y * w[1], (y - v[2] / 200.0) * w[2]};
}

// CIELAB of a linear RGB colour, then Hunt's adjustment: chroma fades with lightness.
Vec3 huntAdjustedLab(const Vec3& linear) {
    const Vec3 xyz = multiply(kRgbToXyz, linear);
    const Vec3 w = whitePoint();
    constexpr double delta = 6.0 / 29.0;
    const auto f = [](double t) {
        return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
    };
    const double fx = f(xyz[0] / w[0]), fy = f(xyz[1] / w[1]), fz = f(xyz[2] / w[2]);
    const double L = 116.0 * fy - 16.0;
    return {L, 0.01 * L * 500.0 * (fx - fy), 0.01 * L * 200.0 * (fy - fz)};
}

double hyab(const Vec3& a, const Vec3& b) {
    return std::abs(a[0] - b[0]) + std::hypot(a[1] - b[1], a[2] - b[2]);
}

// Convolution with the separable kernel along x then y, borders repeating the edge pixel. Both
// kernels have odd length, centred.
Plane filtered(const Plane& in, size_t width, size_t height, const std::vector<double>& alongX,
               const std::vector<double>& alongY) {
    const int rx = int(alongX.size() / 2), ry = int(alongY.size() / 2);
    Plane rows(in.size()), out(in.size());
    for (size_t y = 0; y < height; ++y)
        for (size_t x = 0; x < width; ++x) {
            double sum = 0.0;
            for (int i = -rx; i <= rx; ++i)
                sum += alongX[size_t(i + rx)] *
                       in[y * width + size_t(std::clamp(int(x) + i, 0, int(width) - 1))];
            rows[y * width + x] = sum;
        }
    for (size_t y = 0; y < height; ++y)
        for (size_t x = 0; x < width; ++x) {
            double sum = 0.0;
            for (int i = -ry; i <= ry; ++i)
                sum += alongY[size_t(i + ry)] *
                       rows[size_t(std::clamp(int(y) + i, 0, int(height) - 1)) * width + x];
            out[y * width + x] = sum;
        }
    return out;
}

// One channel through its contrast sensitivity function: each Gaussian term is separable, and
// the 2D kernel (their weighted sum) is normalised to sum 1.
Plane csfFiltered(const Plane& in, size_t width, size_t height, const Csf& csf, double ppd) {
    const int radius = int(std::ceil(
        kKernelReachSigmas * std::sqrt(kWidestCsfScale / (2.0 * std::numbers::pi * std::numbers::pi)) * ppd));
    const auto gaussian = [&](double b, double& sum) {
        std::vector<double> g(size_t(2 * radius + 1));
        sum = 0.0;
        for (int i = -radius; i <= radius; ++i) {
            const double x = double(i) / ppd;
            g[size_t(i + radius)] = std::exp(-std::numbers::pi * std::numbers::pi * x * x / b);
            sum += g[size_t(i + radius)];
        }
        return g;
    };
    double sum1 = 0.0, sum2 = 0.0;
    const std::vector<double> g1 = gaussian(csf.b1, sum1);
    const double w1 = csf.a1 * std::sqrt(std::numbers::pi / csf.b1);
    Plane out = filtered(in, width, height, g1, g1);
    if (csf.a2 == 0.0) {
        for (double& v : out)
            v /= sum1 * sum1; // w1 cancels
        return out;
    }
    const std::vector<double> g2 = gaussian(csf.b2, sum2);
    const double w2 = csf.a2 * std::sqrt(std::numbers::pi / csf.b2);
    const Plane second = filtered(in, width, height, g2, g2);
    const double total = w1 * sum1 * sum1 + w2 * sum2 * sum2;
    for (size_t i = 0; i < out.size(); ++i)
        out[i] = (w1 * out[i] + w2 * second[i]) / total;
    return out;
}

// Edge and point magnitudes of the luminance: the detector along one axis times the normalised
// Gaussian along the other, both directions, their length.
struct Features {
    Plane edges, points;
};

Features features(const Plane& luminance, size_t width, size_t height, double ppd) {
    const double sigma = 0.5 * kFeatureWidthDegrees * ppd;
    const int radius = int(std::ceil(kKernelReachSigmas * sigma));
    const size_t n = size_t(2 * radius + 1);
    std::vector<double> gaussian(n), edge(n), point(n);
    double gaussianSum = 0.0, edgePositive = 0.0, pointPositive = 0.0, pointNegative = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        const double x = double(i);
        const double g = std::exp(-x * x / (2.0 * sigma * sigma));
        const size_t k = size_t(i + radius);
        gaussian[k] = g;
        edge[k] = -x * g;
        point[k] = (x * x / (sigma * sigma) - 1.0) * g;
        gaussianSum += g;
        if (edge[k] > 0.0) edgePositive += edge[k];
        (point[k] > 0.0 ? pointPositive : pointNegative) += std::abs(point[k]);
    }
    // The 2D kernel's positive weights sum to the 1D detector's times the Gaussian's sum, so
    // scaling each factor scales the product.
    for (size_t k = 0; k < n; ++k) {
        gaussian[k] /= gaussianSum;
        edge[k] /= edgePositive; // odd: its negative weights sum to -edgePositive too
        point[k] /= point[k] > 0.0 ? pointPositive : pointNegative;
    }
    const auto magnitude = [](const Plane& a, const Plane& b) {
        Plane m(a.size());
        for (size_t i = 0; i < a.size(); ++i)
            m[i] = std::hypot(a[i], b[i]);
        return m;
    };
    return {magnitude(filtered(luminance, width, height, edge, gaussian),
                      filtered(luminance, width, height, gaussian, edge)),
            magnitude(filtered(luminance, width, height, point, gaussian),
                      filtered(luminance, width, height, gaussian, point))};
}

// What the colour pipeline needs of one image: its Hunt-adjusted CIELAB after the contrast
// sensitivity filters, and its unfiltered relative luminance for the features.
struct Prepared {
    std::vector<Vec3> lab;
    Plane luminance;
};

Prepared prepare(const ImageF& image, double ppd) {
    const size_t width = image.width, height = image.height, count = width * height;
    std::array<Plane, 3> opponent{Plane(count), Plane(count), Plane(count)};
    Prepared p;
    p.luminance.resize(count);
    for (size_t i = 0; i < count; ++i) {
        const Vec3 linear{srgbToLinear(image.rgba[4 * i]), srgbToLinear(image.rgba[4 * i + 1]),
                          srgbToLinear(image.rgba[4 * i + 2])};
        const Vec3 v = xyzToYcxcz(multiply(kRgbToXyz, linear));
        for (size_t c = 0; c < 3; ++c)
            opponent[c][i] = v[c];
        p.luminance[i] = (v[0] + 16.0) / 116.0;
    }
    const Plane y = csfFiltered(opponent[0], width, height, kAchromatic, ppd);
    const Plane cx = csfFiltered(opponent[1], width, height, kRedGreen, ppd);
    const Plane cz = csfFiltered(opponent[2], width, height, kBlueYellow, ppd);
    p.lab.resize(count);
    for (size_t i = 0; i < count; ++i) {
        Vec3 linear = multiply(xyzToRgb(), ycxczToXyz({y[i], cx[i], cz[i]}));
        for (double& c : linear)
            c = std::clamp(c, 0.0, 1.0);
        p.lab[i] = huntAdjustedLab(linear);
    }
    return p;
}

} // namespace

std::vector<double> flipErrorMap(const ImageF& reference, const ImageF& test, double pixelsPerDegree) {
    checkMetricInputs("flip", reference, test);
    if (!(pixelsPerDegree > 0.0) || !std::isfinite(pixelsPerDegree))
        throw IoError("flip: pixels per degree must be finite and > 0, got " +
                      std::to_string(pixelsPerDegree));
    const size_t width = reference.width, height = reference.height;
    const Prepared r = prepare(reference, pixelsPerDegree), t = prepare(test, pixelsPerDegree);
    const Features fr = features(r.luminance, width, height, pixelsPerDegree);
    const Features ft = features(t.luminance, width, height, pixelsPerDegree);

    // The largest colour distance, green against blue, maps to 1.
    const double cmax =
        std::pow(hyab(huntAdjustedLab({0.0, 1.0, 0.0}), huntAdjustedLab({0.0, 0.0, 1.0})), kColourExponent);
    const double knee = kCompressedShare * cmax;
    std::vector<double> error(width * height);
    for (size_t i = 0; i < error.size(); ++i) {
        const double distance = std::pow(hyab(r.lab[i], t.lab[i]), kColourExponent);
        const double colour = distance < knee ? kCompressedTarget / knee * distance
                                              : kCompressedTarget + (distance - knee) / (cmax - knee) *
                                                                        (1.0 - kCompressedTarget);
        const double feature =
            std::pow(std::max(std::abs(fr.edges[i] - ft.edges[i]), std::abs(fr.points[i] - ft.points[i])) /
                         std::numbers::sqrt2,
                     kFeatureExponent);
        error[i] = std::pow(colour, 1.0 - feature);
    }
    return error;
}

double flipMean(const ImageF& reference, const ImageF& test, double pixelsPerDegree) {
    const std::vector<double> error = flipErrorMap(reference, test, pixelsPerDegree);
    double sum = 0.0;
    for (double e : error)
        sum += e;
    return sum / double(error.size());
}

} // namespace eng::io
