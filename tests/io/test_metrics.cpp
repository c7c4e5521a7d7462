#include "engine/io/io_error.h"
#include "engine/io/metrics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace eng::io {
namespace {

// All values below are dyadic fractions, exact in float, so the hand computations are exact too.

// a = [(0.25, 0.5, 0.75), (0, 0, 1)], b = [(0.25, 0.5, 0.25), (0.5, 0, 1)]
// differences 0, 0, 0.5 and 0.5, 0, 0 -> sum of squares 0.5 over 6 samples -> mse = 1/12
// rmse = sqrt(1/12) = 0.288675134594813; psnr = 10 log10(1 / (1/12)) = 10 log10 12 = 10.7918124604762
struct TinyPair {
    ImageF a = makeImage(2, 1);
    ImageF b = makeImage(2, 1);
    TinyPair() {
        setPixel(a, 0, 0, {0.25f, 0.5f, 0.75f, 1.0f});
        setPixel(a, 1, 0, {0.0f, 0.0f, 1.0f, 1.0f});
        setPixel(b, 0, 0, {0.25f, 0.5f, 0.25f, 0.0f}); // alpha differs: must be ignored
        setPixel(b, 1, 0, {0.5f, 0.0f, 1.0f, 0.5f});
    }
};

ImageF makeGrey(uint32_t width, uint32_t height, float value) {
    return makeImage(width, height, {value, value, value, 1.0f});
}

ImageF makeNoise(uint32_t width, uint32_t height, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    ImageF image = makeImage(width, height);
    for (size_t i = 0; i < image.rgba.size(); ++i)
        image.rgba[i] = (i % 4 == 3) ? 1.0f : unit(rng);
    return image;
}

TEST(Rmse, MatchesHandComputedValue) {
    const TinyPair p;
    EXPECT_NEAR(rmse(p.a, p.b), std::sqrt(1.0 / 12.0), 1e-15) << "RGB only, mean over all 6 samples";
    EXPECT_NEAR(rmse(p.b, p.a), std::sqrt(1.0 / 12.0), 1e-15) << "symmetric";
    EXPECT_EQ(rmse(p.a, p.a), 0.0);
}

TEST(Psnr, MatchesHandComputedValue) {
    const TinyPair p;
    EXPECT_NEAR(psnr(p.a, p.b), 10.0 * std::log10(12.0), 1e-12) << "10 log10(1 / mse), mse = 1/12";
    // peak 2: 10 log10(4 / (1/12)) = 10 log10 48
    EXPECT_NEAR(psnr(p.a, p.b, 2.0), 10.0 * std::log10(48.0), 1e-12) << "peak must enter squared";
}

TEST(Psnr, IdenticalImagesGiveInfinity) {
    const TinyPair p;
    const double value = psnr(p.a, p.a);
    EXPECT_TRUE(std::isinf(value) && value > 0.0) << "documented: zero error is +infinity, got " << value;
    EXPECT_THROW(psnr(p.a, p.b, 0.0), IoError) << "a zero peak is meaningless";
}

TEST(Metrics, SizeMismatchThrows) {
    const ImageF a = makeGrey(4, 3, 0.5f);
    const ImageF b = makeGrey(3, 4, 0.5f); // same pixel count, transposed
    EXPECT_THROW(rmse(a, b), IoError);
    EXPECT_THROW(psnr(a, b), IoError);
    EXPECT_THROW(ssim(a, b), IoError);
    EXPECT_THROW(percentileAbsError(a, b, 50.0), IoError);
    EXPECT_THROW(errorHeatmap(a, b, 1.0f), IoError);
}

TEST(Metrics, NonFiniteInputThrows) {
    const ImageF a = makeGrey(16, 16, 0.5f);
    ImageF b = a;
    b.rgba[17] = std::numeric_limits<float>::quiet_NaN();
    // A NaN metric compares false against any threshold and could pass a regression check.
    EXPECT_THROW(rmse(a, b), IoError);
    EXPECT_THROW(ssim(b, a), IoError);
    EXPECT_THROW(percentileAbsError(a, b, 50.0), IoError) << "sorting NaN is undefined behaviour";
}

TEST(Metrics, EmptyAndInconsistentImagesThrow) {
    EXPECT_THROW(rmse(ImageF{}, ImageF{}), IoError) << "no pixels: no mean to take";
    ImageF a = makeGrey(2, 2, 0.5f);
    ImageF b = a;
    b.rgba.pop_back();
    EXPECT_THROW(rmse(a, b), IoError) << "must not read past the shorter buffer";
}

TEST(Ssim, IdenticalImagesGiveExactlyOne) {
    const ImageF noise = makeNoise(37, 29, 3); // Gaussian-window path
    EXPECT_EQ(ssim(noise, noise), 1.0);
    const ImageF small = makeNoise(5, 4, 4); // whole-image path
    EXPECT_EQ(ssim(small, small), 1.0);
}

TEST(Ssim, ConstantVersusShiftedConstantMatchesFormula) {
    // Both constant: sigma_x = sigma_y = sigma_xy = 0, so the contrast/structure factor is C2/C2 = 1 and
    // SSIM = (2 mu_x mu_y + C1) / (mu_x^2 + mu_y^2 + C1), C1 = (0.01 * 1)^2 = 1e-4.
    // mu_x = 0.5, mu_y = 0.75: (0.75 + 1e-4) / (0.25 + 0.5625 + 1e-4) = 0.7501 / 0.8126 = 0.923086389367...
    const double expected = (2.0 * 0.5 * 0.75 + 1e-4) / (0.5 * 0.5 + 0.75 * 0.75 + 1e-4);
    // Luma of a grey pixel is the grey value (the Rec.709 weights sum to 1, up to rounding).
    EXPECT_NEAR(ssim(makeGrey(32, 20, 0.5f), makeGrey(32, 20, 0.75f)), expected, 1e-12)
        << "Gaussian-window path";
    EXPECT_NEAR(ssim(makeGrey(6, 6, 0.5f), makeGrey(6, 6, 0.75f)), expected, 1e-12) << "whole-image path";
    EXPECT_NEAR(ssim(makeGrey(40, 8, 0.5f), makeGrey(40, 8, 0.75f)), expected, 1e-12)
        << "only the height is below the window: still the whole-image path";
}

TEST(Ssim, TwoPixelImageMatchesHandComputedFormula) {
    // Whole-image window, uniform weights, population (1/N) statistics:
    // x = [0, 1]: mu_x = 0.5,  sigma_x^2 = 0.25
    // y = [0, 0.5]: mu_y = 0.25, sigma_y^2 = 0.0625, sigma_xy = ((-0.5)(-0.25) + (0.5)(0.25)) / 2 = 0.125
    // SSIM = (2*0.5*0.25 + C1)(2*0.125 + C2) / ((0.25 + 0.0625 + C1)(0.25 + 0.0625 + C2)), C2 = 9e-4
    //      = (0.2501 * 0.2509) / (0.3126 * 0.3134) = 0.640510697074...
    ImageF x = makeImage(2, 1);
    ImageF y = makeImage(2, 1);
    setPixel(x, 1, 0, {1.0f, 1.0f, 1.0f, 1.0f});
    setPixel(y, 1, 0, {0.5f, 0.5f, 0.5f, 1.0f});
    EXPECT_NEAR(ssim(x, y), (0.2501 * 0.2509) / (0.3126 * 0.3134), 1e-12);
}

TEST(Ssim, SingleWindowUsesGaussianWeights) {
    // 11x11 is exactly one window position. x is black with a single white centre pixel, y is black.
    // The 1D kernel is g(k) = exp(-k^2 / (2 * 1.5^2)) / S, S = sum over k = -5..5, so the centre weight of
    // the 2D window is wc = (1/S)^2. Then mu_x = wc, sigma_x^2 = wc - wc^2, mu_y = sigma_y^2 = sigma_xy = 0:
    // SSIM = C1 / (wc^2 + C1) * C2 / (wc - wc^2 + C2). A uniform 1/121 window would give 0.0588 instead of
    // 0.00026.
    double sum = 0.0;
    for (int k = -5; k <= 5; ++k)
        sum += std::exp(-double(k * k) / (2.0 * 1.5 * 1.5));
    const double wc = 1.0 / (sum * sum);
    const double expected = 1e-4 / (wc * wc + 1e-4) * 9e-4 / (wc - wc * wc + 9e-4);
    ImageF x = makeGrey(11, 11, 0.0f);
    setPixel(x, 5, 5, {1.0f, 1.0f, 1.0f, 1.0f});
    EXPECT_NEAR(ssim(x, makeGrey(11, 11, 0.0f)), expected, 1e-12) << "11x11 Gaussian window, sigma 1.5";
}

TEST(Ssim, UsesRec709LumaWeights) {
    // Pure red 1 vs black: luma 0.2126 vs 0, constant images -> (0 + C1) / (0.2126^2 + C1).
    const ImageF red = makeImage(3, 3, {1.0f, 0.0f, 0.0f, 1.0f});
    const ImageF black = makeGrey(3, 3, 0.0f);
    EXPECT_NEAR(ssim(red, black), 1e-4 / (0.2126 * 0.2126 + 1e-4), 1e-12);
}

TEST(Ssim, InvertedImageScoresLow) {
    const ImageF image = makeNoise(48, 40, 5);
    ImageF inverted = image;
    for (size_t i = 0; i < inverted.rgba.size(); ++i) {
        if (i % 4 != 3) inverted.rgba[i] = 1.0f - inverted.rgba[i];
    }
    const double value = ssim(image, inverted);
    EXPECT_LT(value, 0.5) << "anti-correlated structure must score low";
    EXPECT_GE(value, -1.0) << "SSIM is bounded below by -1";
}

TEST(Ssim, SmallNoiseScoresHighButBelowOne) {
    const ImageF image = makeNoise(48, 40, 6);
    ImageF noisy = image;
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> jitter(-0.01f, 0.01f);
    for (size_t i = 0; i < noisy.rgba.size(); ++i) {
        if (i % 4 != 3) noisy.rgba[i] += jitter(rng);
    }
    const double value = ssim(image, noisy);
    EXPECT_GT(value, 0.95) << "a 1% perturbation must barely move SSIM";
    EXPECT_LT(value, 1.0) << "but it must move it";
    EXPECT_NEAR(ssim(noisy, image), value, 1e-12) << "SSIM is symmetric";
}

TEST(PercentileAbsError, NearestRankOnAKnownDistribution) {
    // Errors {0.15, 0.20, 0.35, 0.40, 0.50} (the classic nearest-rank example, scaled by 1/100),
    // placed in different channels to exercise the per-pixel max over RGB.
    // Nearest rank = ceil(p/100 * 5): p5 -> 1 -> 0.15, p30 -> 2 -> 0.20, p40 -> 2 -> 0.20,
    // p50 -> 3 -> 0.35, p100 -> 5 -> 0.50, p0 -> clamped to rank 1 -> 0.15.
    const ImageF a = makeGrey(5, 1, 0.0f);
    ImageF b = makeGrey(5, 1, 0.0f);
    setPixel(b, 0, 0, {0.0f, 0.40f, 0.01f, 1.0f});
    setPixel(b, 1, 0, {0.50f, 0.0f, 0.0f, 1.0f});
    setPixel(b, 2, 0, {0.10f, 0.10f, 0.15f, 1.0f});
    setPixel(b, 3, 0, {0.0f, 0.0f, 0.35f, 1.0f});
    setPixel(b, 4, 0, {0.20f, 0.0f, 0.0f, 0.0f}); // alpha error 1 must be ignored
    EXPECT_EQ(percentileAbsError(a, b, 5.0), double(0.15f));
    EXPECT_EQ(percentileAbsError(a, b, 30.0), double(0.20f));
    EXPECT_EQ(percentileAbsError(a, b, 40.0), double(0.20f))
        << "ceil(2.0) = 2: exact ranks must not round up";
    EXPECT_EQ(percentileAbsError(a, b, 50.0), double(0.35f));
    EXPECT_EQ(percentileAbsError(a, b, 100.0), double(0.50f));
    EXPECT_EQ(percentileAbsError(a, b, 0.0), double(0.15f));
}

TEST(PercentileAbsError, UniformHundredValues) {
    // Errors k/128 for k = 1..100 in shuffled order: the p-th percentile (integer p) is p/128.
    const ImageF a = makeGrey(10, 10, 0.0f);
    ImageF b = makeGrey(10, 10, 0.0f);
    std::vector<int> ks(100);
    for (int k = 0; k < 100; ++k)
        ks[size_t(k)] = k + 1;
    std::shuffle(ks.begin(), ks.end(), std::mt19937(13));
    for (size_t i = 0; i < 100; ++i)
        b.rgba[4 * i + 1] = float(ks[i]) / 128.0f;
    EXPECT_EQ(percentileAbsError(a, b, 50.0), 50.0 / 128.0);
    EXPECT_EQ(percentileAbsError(a, b, 90.0), 90.0 / 128.0);
    EXPECT_EQ(percentileAbsError(a, b, 99.0), 99.0 / 128.0);
    EXPECT_EQ(percentileAbsError(a, b, 99.5), 100.0 / 128.0) << "ceil(99.5) = 100";
}

TEST(ShareAboveRelativeError, WeighsDarkAndBrightPixelsAlike) {
    // Relative errors (max over RGB): 1 % on a bright pixel, 1 % on a dark one, 0.1 % on a mid one,
    // an absolute 1e-7 on black (under the floor 1e-4: 1e-3 relative), and none.
    const ImageF a = makeGrey(5, 1, 0.0f);
    ImageF b = a, c = a;
    setPixel(b, 0, 0, {0.8f, 0.8f, 0.8f, 1.0f});
    setPixel(c, 0, 0, {0.8f, 0.808f, 0.8f, 1.0f});
    setPixel(b, 1, 0, {0.002f, 0.001f, 0.003f, 1.0f});
    setPixel(c, 1, 0, {0.002f, 0.001f, 0.00303f, 1.0f});
    setPixel(b, 2, 0, {0.5f, 0.5f, 0.5f, 1.0f});
    setPixel(c, 2, 0, {0.5005f, 0.5f, 0.5f, 0.0f}); // alpha must be ignored
    setPixel(c, 3, 0, {0.0f, 1e-7f, 0.0f, 1.0f});
    EXPECT_EQ(shareAboveRelativeError(b, c, 0.005, 1e-4), 2.0 / 5.0) << "the 1 % pixels, bright and dark";
    EXPECT_EQ(shareAboveRelativeError(c, b, 0.005, 1e-4), 2.0 / 5.0) << "symmetric";
    EXPECT_EQ(shareAboveRelativeError(b, c, 0.0005, 1e-4), 4.0 / 5.0)
        << "and the 0.1 % pixel and black's 1e-3";
    EXPECT_EQ(shareAboveRelativeError(b, c, 0.02, 1e-4), 0.0);
    EXPECT_EQ(shareAboveRelativeError(a, a, 0.0, 1e-4), 0.0) << "black against black: nothing over any bound";
    EXPECT_THROW(shareAboveRelativeError(b, c, -1e-9, 1e-4), IoError);
    EXPECT_THROW(shareAboveRelativeError(b, c, 0.01, 0.0), IoError) << "a zero floor divides 0 by 0";
    EXPECT_THROW(shareAboveRelativeError(b, c, std::nan(""), 1e-4), IoError);
    c.rgba[2] = std::numeric_limits<float>::quiet_NaN();
    EXPECT_THROW(shareAboveRelativeError(b, c, 0.01, 1e-4), IoError)
        << "a NaN pixel is neither over nor under";
}

TEST(PercentileAbsError, RefusesPOutsideZeroToHundred) {
    const ImageF a = makeGrey(2, 2, 0.0f);
    EXPECT_THROW(percentileAbsError(a, a, -1.0), IoError);
    EXPECT_THROW(percentileAbsError(a, a, 100.5), IoError);
    EXPECT_THROW(percentileAbsError(a, a, std::nan("")), IoError);
}

TEST(ErrorHeatmap, RampStopsAreExact) {
    // scale 4: error e maps to t = 4e; stops at t = 0, 0.25, 0.5, 0.75, 1 are
    // black, blue, red, yellow, white; e >= 0.25 saturates to white.
    const ImageF a = makeGrey(7, 1, 0.0f);
    ImageF b = makeGrey(7, 1, 0.0f);
    const float errors[7] = {0.0f, 0.0625f, 0.125f, 0.1875f, 0.25f, 1.0f, 0.09375f};
    for (uint32_t x = 0; x < 7; ++x)
        setPixel(b, x, 0, {0.0f, errors[x], 0.0f, 1.0f});
    const ImageF map = errorHeatmap(a, b, 4.0f);
    ASSERT_EQ(map.width, 7u);
    const auto expectRgb = [&](uint32_t x, float r, float g, float bl, const char* what) {
        const RgbaF p = pixel(map, x, 0);
        EXPECT_EQ(p.r, r) << what;
        EXPECT_EQ(p.g, g) << what;
        EXPECT_EQ(p.b, bl) << what;
        EXPECT_EQ(p.a, 1.0f) << what << " (alpha)";
    };
    expectRgb(0, 0.0f, 0.0f, 0.0f, "zero error is black");
    expectRgb(1, 0.0f, 0.0f, 1.0f, "t = 0.25 is blue");
    expectRgb(2, 1.0f, 0.0f, 0.0f, "t = 0.5 is red");
    expectRgb(3, 1.0f, 1.0f, 0.0f, "t = 0.75 is yellow");
    expectRgb(4, 1.0f, 1.0f, 1.0f, "t = 1 is white");
    expectRgb(5, 1.0f, 1.0f, 1.0f, "errors beyond 1/scale clamp to white");
    expectRgb(6, 0.5f, 0.0f, 0.5f, "t = 0.375: halfway between blue and red");
}

TEST(ErrorHeatmap, RefusesNonPositiveScale) {
    const ImageF a = makeGrey(2, 2, 0.0f);
    EXPECT_THROW(errorHeatmap(a, a, 0.0f), IoError);
    EXPECT_THROW(errorHeatmap(a, a, -1.0f), IoError);
}

} // namespace
} // namespace eng::io
