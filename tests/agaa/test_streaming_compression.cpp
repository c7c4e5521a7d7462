// Streaming G-buffer compression's CPU reference (agaa/streaming/streaming_compression.cpp;
// Kerzner and Salvi 2014, section 3): the merge test's three conditions at their edges, what a
// merge keeps, occluder fusion, the two eviction rules and their tie-break, the resolve weights,
// the recorded fragments' primitive order and the guards of the plane derivatives.

#include "agaa/streaming/streaming_compression.h"
#include "shared/streaming.h"

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace {

using agaa::StreamingOutcome;
using agaa::StreamingSurface;

// Named tolerances of these tests.
constexpr float kStep = 1.0e-4f;   // metres: how far past an interval edge a depth is moved
constexpr float kAngleStep = 0.1f; // degrees: how far past the normal threshold a normal is turned
constexpr float kExact = 1.0e-6f;  // an average of two floats, against the value expected
const float kCos45 = std::cos(45.0f * 3.14159265358979f / 180.0f);

glm::vec3 tilted(float degrees) {
    const float a = degrees * 3.14159265358979f / 180.0f;
    return {std::sin(a), 0.0f, std::cos(a)};
}

StreamingSurface fragment(uint32_t coverage, float z, glm::vec3 normal = {0, 0, 1}, float slope = 0.0f) {
    StreamingSurface f;
    f.coverage = f.depthTested = coverage;
    f.zView = z;
    f.dzdx = slope;
    f.dzdy = -slope;
    f.normal = normal;
    return f;
}

TEST(StreamingCompression, MergesOnlyFragmentsWithDisjointCoverage) {
    agaa::StreamingCompressor c(3, kCos45);
    EXPECT_EQ(c.add(fragment(0x0Fu, 1.0f)), StreamingOutcome::Inserted);
    EXPECT_EQ(c.add(fragment(0x18u, 1.0f)), StreamingOutcome::Inserted) << "sample 3 in both: no merge";
    EXPECT_EQ(c.add(fragment(0xE0u, 1.0f)), StreamingOutcome::Merged) << "disjoint, same plane: merged";
    ASSERT_EQ(c.surfaces().size(), 2u);
    EXPECT_EQ(c.surfaces()[0].coverage, 0xEFu) << "merged into the first surface that passes";
    EXPECT_EQ(c.surfaces()[0].depthTested, 0xEFu) << "depth-tested coverage ORed too";
}

TEST(StreamingCompression, DepthRangesMustOverlapAtTheirEdges) {
    // Ranges z +- (|dz/dx| + |dz/dy| + kDepthCompareRelative z): slope 0.01 each way at z = 1.
    const float slope = 0.01f;
    const StreamingSurface a = fragment(0x01u, 1.0f, {0, 0, 1}, slope);
    const float reach = agaa::streamingZMax(a) - a.zView; // a's half range
    for (float d : {-kStep, +kStep}) {
        // b's half range is reach * (z_b / z_a) to first order; solve z_b - half_b = zMax(a).
        const float zb = (agaa::streamingZMax(a) + 2.0f * slope) / (1.0f - 1.0e-4f) + d;
        const StreamingSurface b = fragment(0x02u, zb, {0, 0, 1}, slope);
        EXPECT_EQ(agaa::streamingCanMerge(a, b, kCos45), d < 0.0f)
            << "zMin(b) - zMax(a) = " << agaa::streamingZMin(b) - agaa::streamingZMax(a) << ", reach "
            << reach;
    }
}

TEST(StreamingCompression, NormalsWithinThePapersPiOverFourOrTheCodesCosine) {
    const StreamingSurface a = fragment(0x01u, 1.0f);
    EXPECT_TRUE(agaa::streamingCanMerge(a, fragment(0x02u, 1.0f, tilted(45.0f - kAngleStep)), kCos45));
    EXPECT_FALSE(agaa::streamingCanMerge(a, fragment(0x02u, 1.0f, tilted(45.0f + kAngleStep)), kCos45));
    // The public code's 0.78539816 as the cosine: acos = 38.24 degrees.
    const float code = agaa::kStreamingPublicCodeNormalCos;
    const float codeDegrees = std::acos(code) * 180.0f / 3.14159265358979f;
    EXPECT_NEAR(codeDegrees, 38.24f, 0.01f);
    EXPECT_TRUE(agaa::streamingCanMerge(a, fragment(0x02u, 1.0f, tilted(codeDegrees - kAngleStep)), code));
    EXPECT_FALSE(agaa::streamingCanMerge(a, fragment(0x02u, 1.0f, tilted(codeDegrees + kAngleStep)), code));
    EXPECT_TRUE(agaa::streamingCanMerge(a, fragment(0x02u, 1.0f, tilted(40.0f)), kCos45))
        << "40 degrees: the paper's threshold merges what the code's refuses";
    EXPECT_FALSE(agaa::streamingCanMerge(a, fragment(0x02u, 1.0f, tilted(40.0f)), code));
}

TEST(StreamingCompression, AMergeAveragesAndKeepsTheMinimumDepth) {
    StreamingSurface a = fragment(0x01u, 2.0f, tilted(10.0f), 0.02f),
                     b = fragment(0x06u, 1.9f, tilted(-10.0f), 0.04f);
    a.albedo = {0.2f, 0.4f, 0.6f};
    b.albedo = {0.4f, 0.0f, 0.2f};
    a.metallic = 1.0f;
    a.roughness = 0.2f;
    b.roughness = 0.6f;
    b.emissive = {2.0f, 0.0f, 4.0f};
    const StreamingSurface m = agaa::streamingMerge(a, b);
    EXPECT_EQ(m.coverage, 0x07u);
    EXPECT_EQ(m.zView, 1.9f) << "the minimum zView";
    EXPECT_NEAR(m.dzdx, 0.03f, kExact);
    EXPECT_NEAR(m.dzdy, -0.03f, kExact);
    EXPECT_NEAR(m.normal.x, 0.0f, kExact) << "normals averaged (and renormalised)";
    EXPECT_NEAR(m.normal.z, 1.0f, kExact);
    EXPECT_NEAR(m.albedo.r, 0.3f, kExact);
    EXPECT_NEAR(m.albedo.g, 0.2f, kExact);
    EXPECT_NEAR(m.metallic, 0.5f, kExact);
    EXPECT_NEAR(m.roughness, 0.4f, kExact);
    EXPECT_NEAR(m.emissive.b, 2.0f, kExact);
}

TEST(StreamingCompression, OpposingNormalsKeepTheSurfacesNormal) {
    // The kMinNormalLength guard of the average: n + (-n) = 0 cannot be normalised.
    const StreamingSurface m =
        agaa::streamingMerge(fragment(0x01u, 1.0f, {0, 0, 1}), fragment(0x02u, 1.0f, {0, 0, -1}));
    EXPECT_EQ(m.normal, glm::vec3(0, 0, 1));
}

TEST(StreamingCompression, OccluderFusionRemovesSamplesOnlyBehindDisjointRanges) {
    agaa::StreamingCompressor c(3, kCos45);
    c.add(fragment(0x0Fu, 2.0f));                // far
    c.add(fragment(0x03u, 1.0f, tilted(60.0f))); // near, another plane: covers samples 0, 1
    ASSERT_EQ(c.surfaces().size(), 2u);
    EXPECT_EQ(c.surfaces()[1].depthTested, 0x0Cu) << "the far surface loses the near one's samples";
    EXPECT_EQ(c.surfaces()[1].coverage, 0x0Fu) << "its raster coverage stays";
    agaa::StreamingCompressor p(3, kCos45);
    p.add(fragment(0x0Fu, 1.0f, {0, 0, 1}, 0.1f));
    p.add(fragment(0x03u, 0.95f, tilted(60.0f), 0.1f)); // inter-penetrating: ranges overlap
    EXPECT_EQ(p.surfaces()[1].depthTested, 0x0Fu) << "overlapping ranges: nothing removed";
}

TEST(StreamingCompression, AFourthSurfaceDropsOneCoveredAndBehind) {
    agaa::StreamingCompressor c(3, kCos45);
    c.add(fragment(0x03u, 1.0f, tilted(0.0f)));
    c.add(fragment(0x0Cu, 1.2f, tilted(60.0f)));
    c.add(fragment(0x30u, 1.4f, tilted(-60.0f)));
    // Behind all three, covered by their samples: dropped though it has more samples than any.
    StreamingSurface hidden = fragment(0x3Fu, 3.0f, tilted(30.0f));
    EXPECT_EQ(c.add(hidden), StreamingOutcome::DroppedCovered);
    ASSERT_EQ(c.surfaces().size(), 3u);
    EXPECT_EQ(c.surfaces()[2].zView, 1.4f);
    // An arrival in front that covers the farthest stored surface: that one goes.
    StreamingSurface front = fragment(0x30u | 0xC0u, 0.5f, tilted(80.0f));
    EXPECT_EQ(c.add(front), StreamingOutcome::DroppedCovered);
    ASSERT_EQ(c.surfaces().size(), 3u);
    EXPECT_EQ(c.surfaces()[0].zView, 0.5f);
    EXPECT_EQ(c.surfaces()[2].zView, 1.2f) << "the surface at 1.4 was covered by the arrival and dropped";
}

TEST(StreamingCompression, ElseTheFewestDepthTestedSamplesTiesTheFarther) {
    agaa::StreamingCompressor c(3, kCos45);
    c.add(fragment(0x07u, 1.0f, tilted(0.0f)));   // 3 samples
    c.add(fragment(0x08u, 1.2f, tilted(60.0f)));  // 1 sample
    c.add(fragment(0x30u, 1.4f, tilted(-60.0f))); // 2 samples
    EXPECT_EQ(c.add(fragment(0xC0u, 1.6f, tilted(30.0f))), StreamingOutcome::DroppedFewest);
    ASSERT_EQ(c.surfaces().size(), 3u);
    for (const StreamingSurface& s : c.surfaces())
        EXPECT_NE(s.coverage, 0x08u) << "the one-sample surface goes";
    // Now 3, 2, 2 samples and an arrival with 2: a tie among three; the farthest (the arrival) goes.
    EXPECT_EQ(c.add(fragment(0x300u, 1.8f, tilted(-30.0f))), StreamingOutcome::DroppedFewest);
    EXPECT_EQ(c.surfaces()[2].zView, 1.6f);
    // A tie between stored ones, the arrival nearer: the farther stored one goes.
    EXPECT_EQ(c.add(fragment(0xC00u, 1.1f, tilted(50.0f))), StreamingOutcome::DroppedFewest);
    EXPECT_EQ(c.surfaces()[2].zView, 1.4f);
}

TEST(StreamingCompression, ResolveWeightsGiveTheRestToTheSky) {
    agaa::StreamingPixel p;
    p.surfaces = {fragment(0x07u, 1.0f), fragment(0x18u, 2.0f)};
    std::vector<float> w = agaa::streamingResolveWeights(p, 8);
    ASSERT_EQ(w.size(), 3u);
    EXPECT_FLOAT_EQ(w[0], 3.0f / 8.0f);
    EXPECT_FLOAT_EQ(w[1], 2.0f / 8.0f);
    EXPECT_FLOAT_EQ(w[2], 3.0f / 8.0f) << "the sky: the samples no surface owns";
    // Inter-penetrating surfaces own overlapping samples: their counts are the denominator.
    p.surfaces = {fragment(0xFFu, 1.0f), fragment(0x0Fu, 1.0f)};
    w = agaa::streamingResolveWeights(p, 8);
    EXPECT_FLOAT_EQ(w[0], 8.0f / 12.0f);
    EXPECT_FLOAT_EQ(w[2], 0.0f);
}

shared::FrameConstants frameFor(uint32_t n) {
    shared::FrameConstants f{};
    f.counts = {n, 4, n / 4, 0};
    f.extent = {16.0f, 16.0f, 1.0f / 16.0f, 1.0f / 16.0f};
    f.depthParams = {0.1f, 100.0f, 1.0f, 0.0f};
    f.projParams = {1.5f, -1.5f, 0.0f, 0.0f};
    for (uint32_t s = 0; s < n; ++s)
        f.samplePositions[s] = {(float(s) + 0.5f) / float(n), 0.5f, 0.0f, 0.0f};
    return f;
}

TEST(StreamingCompression, RecordedFragmentsAreReplayedInPrimitiveOrder) {
    const shared::FrameConstants frame = frameFor(8);
    std::vector<agaa::StreamingSample> samples(8);
    const float ids[8] = {9, 9, 3, 3, 0, 7, 7, 3}; // 0 with depth 0: sky
    for (int s = 0; s < 8; ++s) {
        samples[s][0] = {s == 4 ? 0.0f : 0.5f, 0.0f, 0.0f, ids[s]};
        samples[s][1] = {ids[s] / 10.0f, 0, 0, 0};
    }
    const std::vector<StreamingSurface> f = agaa::recordedFragments(frame, samples.data(), 8, 8);
    ASSERT_EQ(f.size(), 3u);
    EXPECT_EQ(f[0].coverage, 0x8Cu) << "primitive 3 first";
    EXPECT_EQ(f[1].coverage, 0x60u);
    EXPECT_EQ(f[2].coverage, 0x03u);
    EXPECT_NEAR(f[0].albedo.r, 0.3f, kExact) << "the fragment's first sample's material";
    EXPECT_EQ(f[0].dzdx, 0.0f) << "octahedral (0, 0) is the view axis: a face-on plane";
}

TEST(StreamingCompression, GrazingPlanesGetBoundedDerivativesAndCentreDepth) {
    // A normal perpendicular to the ray would divide by N.D = 0: kStreamingMinFacing floors it, so
    // the slope is t |N.x| dD/dx / kStreamingMinFacing; the centre depth extrapolated from the
    // sample stays within kStreamingCentreDepthRange of it.
    shared::FrameConstants frame = frameFor(4);
    frame.extent = {2.0f, 2.0f, 0.5f, 0.5f};
    frame.samplePositions[0] = {0.0f, 0.0f, 0.0f, 0.0f}; // pixel (1, 1) + 0: ndc (0, 0), D = (0, 0, -1)
    std::vector<agaa::StreamingSample> samples(4);
    samples[0][0] = {0.001f, 0.5f, 0.5f, 1.0f}; // t = 50 m; octahedral (0.5, 0.5): normal (0.707, 0.707, 0)
    std::vector<StreamingSurface> f = agaa::recordedFragments(frame, samples.data(), 1, 1);
    ASSERT_EQ(f.size(), 1u);
    const float t = 0.1f * 100.0f / (0.001f * 99.9f + 0.1f);
    const float slope = t * std::sqrt(0.5f) * (2.0f * 0.5f / 1.5f) / shared::kStreamingMinFacing;
    EXPECT_NEAR(std::abs(f[0].dzdx), slope, 1.0e-4f * slope);
    EXPECT_GE(f[0].zView, t / shared::kStreamingCentreDepthRange) << "the centre depth stays in range";
    EXPECT_LE(f[0].zView, t * shared::kStreamingCentreDepthRange);
    // Far enough away the slope passes the largest half float: clamped to kStreamingMaxDerivative.
    frame.depthParams = {0.1f, 1.0e6f, 1.0f, 0.0f};
    samples[0][0].x = 1.0e-9f; // t ~ 1e6 m
    f = agaa::recordedFragments(frame, samples.data(), 1, 1);
    ASSERT_EQ(f.size(), 1u);
    EXPECT_EQ(std::abs(f[0].dzdx), shared::kStreamingMaxDerivative);
    const std::array<uint32_t, 9> r = agaa::streamingRecord(f[0]);
    EXPECT_TRUE(std::isfinite(glm::unpackHalf2x16(r[shared::kStreamingWordDepthDerivatives]).x))
        << "the half-float record holds no infinity";
}

} // namespace
