#include "engine/io/metrics.h"

#include "engine/io/io_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace eng::io {

namespace {

// SSIM constants, Wang et al. 2004, section III-C.
constexpr int kSsimWindow = 11;
constexpr double kSsimSigma = 1.5;
constexpr double kSsimK1 = 0.01;
constexpr double kSsimK2 = 0.03;
constexpr double kSsimRange = 1.0; // L: dynamic range of display-encoded values
constexpr double kSsimC1 = (kSsimK1 * kSsimRange) * (kSsimK1 * kSsimRange);
constexpr double kSsimC2 = (kSsimK2 * kSsimRange) * (kSsimK2 * kSsimRange);

std::string sizeText(const ImageF& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

// max over R, G, B of |a - b| for every pixel.
std::vector<double> maxAbsErrors(const ImageF& a, const ImageF& b) {
    std::vector<double> errors(pixelCount(a));
    for (size_t i = 0; i < errors.size(); ++i) {
        double e = 0.0;
        for (size_t c = 0; c < 3; ++c) {
            e = std::max(e, std::abs(double(a.rgba[4 * i + c]) - double(b.rgba[4 * i + c])));
        }
        errors[i] = e;
    }
    return errors;
}

std::vector<double> luma(const ImageF& image) {
    std::vector<double> y(pixelCount(image));
    for (size_t i = 0; i < y.size(); ++i) {
        y[i] =
            0.2126 * image.rgba[4 * i + 0] + 0.7152 * image.rgba[4 * i + 1] + 0.0722 * image.rgba[4 * i + 2];
    }
    return y;
}

std::array<double, kSsimWindow> gaussianWeights() {
    std::array<double, kSsimWindow> w{};
    double sum = 0.0;
    for (int i = 0; i < kSsimWindow; ++i) {
        const double d = double(i - kSsimWindow / 2); // offset from the centre tap, -5 .. 5
        w[size_t(i)] = std::exp(-d * d / (2.0 * kSsimSigma * kSsimSigma));
        sum += w[size_t(i)];
    }
    // The 2D window is the outer product of this 1D kernel with itself, so it sums to 1 too.
    for (double& v : w)
        v /= sum;
    return w;
}

// Wang et al. 2004, eq. (13), from local means, variances and covariance.
double ssimFromMoments(double muX, double muY, double varX, double varY, double covXY) {
    return ((2.0 * muX * muY + kSsimC1) * (2.0 * covXY + kSsimC2)) /
           ((muX * muX + muY * muY + kSsimC1) * (varX + varY + kSsimC2));
}

// Images smaller than the window: one window with uniform weights over the whole image.
double ssimWholeImage(const std::vector<double>& x, const std::vector<double>& y) {
    const double n = double(x.size());
    double muX = 0.0, muY = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
        muX += x[i];
        muY += y[i];
    }
    muX /= n;
    muY /= n;
    double varX = 0.0, varY = 0.0, covXY = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
        varX += (x[i] - muX) * (x[i] - muX);
        varY += (y[i] - muY) * (y[i] - muY);
        covXY += (x[i] - muX) * (y[i] - muY);
    }
    return ssimFromMoments(muX, muY, varX / n, varY / n, covXY / n);
}

} // namespace

void checkMetricInputs(const char* metric, const ImageF& a, const ImageF& b) {
    if (a.width != b.width || a.height != b.height) {
        throw IoError(std::string(metric) + ": size mismatch, " + sizeText(a) + " vs " + sizeText(b));
    }
    if (!isConsistent(a) || !isConsistent(b)) {
        throw IoError(std::string(metric) + ": pixel buffer does not match the image size " + sizeText(a));
    }
    if (pixelCount(a) == 0) {
        throw IoError(std::string(metric) + ": images are empty");
    }
    const size_t badA = countNonFinite(a);
    const size_t badB = countNonFinite(b);
    if (badA + badB > 0) {
        throw IoError(std::string(metric) + ": non-finite values (" + std::to_string(badA) +
                      " in the first image, " + std::to_string(badB) + " in the second)");
    }
}

double rmse(const ImageF& a, const ImageF& b) {
    checkMetricInputs("rmse", a, b);
    double sum = 0.0;
    for (size_t i = 0; i < pixelCount(a); ++i) {
        for (size_t c = 0; c < 3; ++c) {
            const double d = double(a.rgba[4 * i + c]) - double(b.rgba[4 * i + c]);
            sum += d * d;
        }
    }
    return std::sqrt(sum / (3.0 * double(pixelCount(a))));
}

double psnr(const ImageF& a, const ImageF& b, double peak) {
    if (!(peak > 0.0) || !std::isfinite(peak)) {
        throw IoError("psnr: peak must be finite and > 0, got " + std::to_string(peak));
    }
    const double error = rmse(a, b);
    if (error == 0.0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(peak * peak / (error * error));
}

double ssim(const ImageF& a, const ImageF& b) {
    checkMetricInputs("ssim", a, b);
    const std::vector<double> x = luma(a);
    const std::vector<double> y = luma(b);
    const size_t width = a.width, height = a.height;
    if (width < size_t(kSsimWindow) || height < size_t(kSsimWindow)) return ssimWholeImage(x, y);

    // Separable filtering of the five moment images x, y, x^2, y^2, xy over valid positions only.
    // x^2 and xy go through identical arithmetic when x == y, which makes identical images exactly 1.
    const std::array<double, kSsimWindow> w = gaussianWeights();
    const size_t outW = width - kSsimWindow + 1;
    const size_t outH = height - kSsimWindow + 1;
    constexpr size_t kMoments = 5;
    std::vector<std::array<double, kMoments>> rows(outW * height);
    for (size_t py = 0; py < height; ++py) {
        for (size_t px = 0; px < outW; ++px) {
            std::array<double, kMoments> m{};
            for (size_t k = 0; k < size_t(kSsimWindow); ++k) {
                const double xv = x[py * width + px + k];
                const double yv = y[py * width + px + k];
                m[0] += w[k] * xv;
                m[1] += w[k] * yv;
                m[2] += w[k] * (xv * xv);
                m[3] += w[k] * (yv * yv);
                m[4] += w[k] * (xv * yv);
            }
            rows[py * outW + px] = m;
        }
    }

    double sum = 0.0;
    for (size_t py = 0; py < outH; ++py) {
        for (size_t px = 0; px < outW; ++px) {
            std::array<double, kMoments> m{};
            for (size_t k = 0; k < size_t(kSsimWindow); ++k) {
                const std::array<double, kMoments>& r = rows[(py + k) * outW + px];
                for (size_t j = 0; j < kMoments; ++j)
                    m[j] += w[k] * r[j];
            }
            const double muX = m[0], muY = m[1];
            sum += ssimFromMoments(muX, muY, m[2] - muX * muX, m[3] - muY * muY, m[4] - muX * muY);
        }
    }
    return sum / double(outW * outH);
}

double percentileAbsError(const ImageF& a, const ImageF& b, double p) {
    if (!(p >= 0.0 && p <= 100.0)) {
        throw IoError("percentileAbsError: p must be in [0, 100], got " + std::to_string(p));
    }
    checkMetricInputs("percentileAbsError", a, b);
    std::vector<double> errors = maxAbsErrors(a, b);
    const size_t n = errors.size();
    const size_t rank = std::clamp<size_t>(size_t(std::ceil(p * double(n) / 100.0)), 1, n);
    std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(rank - 1), errors.end());
    return errors[rank - 1];
}

double shareAboveRelativeError(const ImageF& a, const ImageF& b, double bound, double floor) {
    if (!(bound >= 0.0) || !std::isfinite(bound) || !(floor > 0.0) || !std::isfinite(floor)) {
        throw IoError(
            "shareAboveRelativeError: bound must be finite and >= 0 and floor finite and > 0, got " +
            std::to_string(bound) + " and " + std::to_string(floor));
    }
    checkMetricInputs("shareAboveRelativeError", a, b);
    size_t above = 0;
    for (size_t i = 0; i < pixelCount(a); ++i) {
        double e = 0.0;
        for (size_t c = 0; c < 3; ++c) {
            const double x = a.rgba[4 * i + c], y = b.rgba[4 * i + c];
            e = std::max(e, std::abs(x - y) / std::max({std::abs(x), std::abs(y), floor}));
        }
        above += e > bound ? 1 : 0;
    }
    return double(above) / double(pixelCount(a));
}

ImageF errorHeatmap(const ImageF& a, const ImageF& b, float scale) {
    if (!(scale > 0.0f) || !std::isfinite(scale)) {
        throw IoError("errorHeatmap: scale must be finite and > 0, got " + std::to_string(scale));
    }
    checkMetricInputs("errorHeatmap", a, b);
    constexpr std::array<std::array<float, 3>, 5> kRamp = {{
        {0.0f, 0.0f, 0.0f}, // no error
        {0.0f, 0.0f, 1.0f},
        {1.0f, 0.0f, 0.0f},
        {1.0f, 1.0f, 0.0f},
        {1.0f, 1.0f, 1.0f}, // error >= 1 / scale
    }};
    const std::vector<double> errors = maxAbsErrors(a, b);
    ImageF out = makeImage(a.width, a.height);
    for (size_t i = 0; i < errors.size(); ++i) {
        const float t = std::clamp(float(errors[i]) * scale, 0.0f, 1.0f) * float(kRamp.size() - 1);
        const size_t lo = std::min(size_t(t), kRamp.size() - 2);
        const float f = t - float(lo);
        for (size_t c = 0; c < 3; ++c) {
            out.rgba[4 * i + c] = kRamp[lo][c] + f * (kRamp[lo + 1][c] - kRamp[lo][c]);
        }
        out.rgba[4 * i + 3] = 1.0f;
    }
    return out;
}

} // namespace eng::io
