// The AG-buffer's fixed-point accumulation (shared/agaa.h, shared/ag_buffer.h): no overflow at
// n = 32, c = 1 with the largest legal inputs, exact round trips, and the Toksvig encoding of
// roughness as normal variance.

#include "agaa/aggregate/agaa_constants.h"
#include "shared/ag_buffer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using namespace shared;

TEST(FixedPoint, NoOverflowAtThirtyTwoSamplesInOneAggregate) {
    // Worst case: every one of 32 samples in the single aggregate carries the largest value.
    constexpr uint64_t kSamples = kMaxSamples;
    uint64_t normalSum = kSamples * quantizeSigned(1.0f, kNormalScale);
    uint64_t unormSum = kSamples * quantizeUnit(1.0f, kUnormScale);
    EXPECT_EQ(quantizeSigned(1.0f, kNormalScale), kNormalScale);
    EXPECT_LE(normalSum, uint64_t(kNormalFieldMask)) << "the x sum must stay below the count bits";
    EXPECT_LT(unormSum, uint64_t(1) << 16) << "a 16-bit field must not carry into its neighbour";
    EXPECT_LT(kSamples, uint64_t(1) << (32 - kCountShift)) << "the count must fit its 6 bits";
    // The packed word w0 = count << 26 | sum(x) stays a valid 32-bit value.
    uint64_t w0 = (kSamples << kCountShift) + normalSum;
    EXPECT_LE(w0, uint64_t(std::numeric_limits<uint32_t>::max()));
    // And one step more would overflow: the bound is tight, not accidental.
    EXPECT_GT((kSamples + 2) * uint64_t(kNormalScale), uint64_t(kNormalFieldMask));
}

TEST(FixedPoint, QuantisationEdges) {
    EXPECT_EQ(quantizeUnit(0.0f, kUnormScale), 0u);
    EXPECT_EQ(quantizeUnit(1.0f, kUnormScale), kUnormScale);
    EXPECT_EQ(quantizeUnit(-3.0f, kUnormScale), 0u) << "negative clamps to 0";
    EXPECT_EQ(quantizeUnit(7.0f, kUnormScale), kUnormScale) << "above 1 clamps to the scale";
    EXPECT_EQ(quantizeUnit(std::nanf(""), kUnormScale), 0u) << "NaN must not reach the atomics";
    EXPECT_EQ(quantizeUnit(std::numeric_limits<float>::infinity(), kUnormScale), kUnormScale);
    EXPECT_EQ(quantizeUnit(std::numeric_limits<float>::denorm_min(), kUnormScale), 0u);
    EXPECT_EQ(quantizeSigned(-1.0f, kNormalScale), 0u);
    EXPECT_EQ(quantizeSigned(0.0f, kNormalScale), (kNormalScale + 1) / 2);
}

TEST(FixedPoint, MeanRoundTripWithinHalfAStep) {
    for (uint32_t k : {1u, 3u, 8u, 32u})
        for (float x : {-1.0f, -0.73f, 0.0f, 0.12345f, 0.999f, 1.0f}) {
            uint32_t sum = k * quantizeSigned(x, kNormalScale);
            // Half a step (1/scale in [-1, 1]) plus fp32 rounding of v * scale near 2^21 (ulp 0.25 steps).
            EXPECT_NEAR(meanSigned(sum, k, kNormalScale), x, 1.25 / kNormalScale) << "k=" << k << " x=" << x;
            float u = 0.5f * (x + 1.0f);
            EXPECT_NEAR(meanUnit(k * quantizeUnit(u, kUnormScale), k, kUnormScale), u,
                        0.5 / kUnormScale + 1e-6);
        }
}

TEST(Toksvig, SingleSampleRoughnessRoundTrips) {
    const float alphaMin = agaa::kMinGgxAlpha;
    const float smax = 2.0f / (alphaMin * alphaMin) - 2.0f;
    for (float roughness : {0.05f, 0.1f, 0.2f, 0.35f, 0.5f, 0.7f, 0.9f}) {
        float alpha = roughness * roughness;
        float len = toksvigLength(alpha, smax, alphaMin, agaa::kMaxGgxAlpha);
        ASSERT_GE(len, 0.0f);
        ASSERT_LE(len, 1.0f);
        // Through the 21-bit quantisation the aggregate would store.
        float stored = meanSigned(quantizeSigned(len, kNormalScale), 1, kNormalScale);
        float back = filteredAlpha(stored, smax);
        EXPECT_NEAR(std::sqrt(back), roughness, 0.02f)
            << "roughness " << roughness << " must survive the AG-buffer";
    }
}

TEST(Toksvig, GuardsAtTheEdges) {
    const float alphaMin = agaa::kMinGgxAlpha;
    const float smax = 2.0f / (alphaMin * alphaMin) - 2.0f;
    const float alphaMax = agaa::kMaxGgxAlpha;
    // Roughness 0 (mirror) clamps to alpha_min: length 1, filtered alpha alpha_min.
    EXPECT_FLOAT_EQ(toksvigLength(0.0f, smax, alphaMin, alphaMax), 1.0f);
    EXPECT_NEAR(filteredAlpha(1.0f, smax), alphaMin, 1e-6f);
    // Roughness 1 clamps to alpha_max: the sample keeps a direction (length > 0.3) and
    // decodes back to alpha_max.
    float roughest = toksvigLength(1.0f, smax, alphaMin, alphaMax);
    EXPECT_GT(roughest, 0.3f) << "a fully rough sample must still contribute its normal's direction";
    EXPECT_NEAR(filteredAlpha(roughest, smax), alphaMax, 1e-4f);
    EXPECT_FLOAT_EQ(toksvigLength(std::nanf(""), smax, alphaMin, alphaMax), 1.0f)
        << "NaN roughness -> alpha_min";
    EXPECT_FLOAT_EQ(filteredAlpha(0.0f, smax), 1.0f)
        << "|N| = 0 (cancelled normals) must give alpha 1, not NaN";
    // Quantisation can push |N| slightly above 1: clamped, finite.
    EXPECT_NEAR(filteredAlpha(1.0001f, smax), alphaMin, 1e-6f);
    EXPECT_TRUE(std::isfinite(filteredAlpha(-0.5f, smax)));
    EXPECT_TRUE(std::isfinite(filteredAlpha(std::numeric_limits<float>::denorm_min(), smax)));
    // Two opposite unit normals average to |N| = 0: fully rough, as Toksvig intends.
    EXPECT_FLOAT_EQ(filteredAlpha(0.5f * (1.0f + -1.0f), smax), 1.0f);
}

} // namespace
