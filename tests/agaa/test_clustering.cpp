// Algorithm 1 on synthetic sample sets (CPU reference; the GPU runs the same source and is
// compared with it in test_agaa_gpu.cpp), and the figure 5 metadata packing.

#include "agaa/aggregate/clustering.h"
#include "agaa_test_support.h"
#include "shared/clustering.h"

#include <gtest/gtest.h>

#include <random>

namespace {

using agaa::PixelSamples;
using agaa::test::depthAt;
using agaa::test::kernelConstants;

// theta = 0: the normal points at the camera; theta index 255 = 90 degrees away from it.
constexpr uint8_t kFacing = 0;
constexpr uint8_t kPerpendicular = 255;

TEST(Clustering, OnePlaneIsOneAggregate) {
    for (uint32_t n : {4u, 8u, 16u, 32u}) {
        auto k = kernelConstants(n, 4);
        PixelSamples p;
        // A plane facing the camera 0.5 m away: a 64-pixel view puts the pixel's samples at most
        // 6 mm apart, (6 mm / k)^2 = 0.004 < t, so one seed. (Pixel footprints beyond sqrt(t) k =
        // 2.2 cm split even flat pixels: see agaa/aggregate/README.md on choosing t.)
        for (uint32_t s = 0; s < n; ++s)
            p.depth[s] = depthAt(0.5f, k.frame);
        auto r = agaa::clusterPixel(31, 31, p, k.frame, k.agaa);
        EXPECT_EQ(r.count, 1u) << "n=" << n << ": a flat pixel is lit once";
        for (uint32_t s = 0; s < n; ++s)
            EXPECT_EQ(r.ids[s], 0u);
    }
}

TEST(Clustering, TwoPlanesAtNinetyDegreesSplitAlongTheEdge) {
    for (uint32_t n : {4u, 8u, 16u, 32u}) {
        auto k = kernelConstants(n, 2);
        PixelSamples p;
        // Left of x = 0.5 a plane facing the camera, right of it a plane turned by 90 degrees
        // (a convex edge), both at the same distance.
        for (uint32_t s = 0; s < n; ++s) {
            p.depth[s] = depthAt(0.5f, k.frame);
            p.theta[s] = k.frame.samplePositions[s].x < 0.5f ? kFacing : kPerpendicular;
        }
        auto r = agaa::clusterPixel(31, 31, p, k.frame, k.agaa);
        ASSERT_EQ(r.count, 2u) << "n=" << n << ": two orientations, two aggregates";
        for (uint32_t s = 0; s < n; ++s) {
            bool left = k.frame.samplePositions[s].x < 0.5f;
            bool sameAsFirstLeft = true;
            for (uint32_t o = 0; o < n; ++o) {
                if ((k.frame.samplePositions[o].x < 0.5f) != left) continue;
                sameAsFirstLeft = r.ids[o] == r.ids[s];
                if (!sameAsFirstLeft) break;
            }
            EXPECT_TRUE(sameAsFirstLeft)
                << "n=" << n << " sample " << s << ": one side split across aggregates";
        }
        // And the two sides differ.
        uint32_t leftId = 99, rightId = 99;
        for (uint32_t s = 0; s < n; ++s) {
            if (k.frame.samplePositions[s].x < 0.5f)
                leftId = r.ids[s];
            else
                rightId = r.ids[s];
        }
        EXPECT_NE(leftId, rightId) << "n=" << n;
    }
}

TEST(Clustering, SkyOnlyPixelHasNoAggregate) {
    auto k = kernelConstants(8, 2);
    PixelSamples p; // depth 0 everywhere: the far plane
    auto r = agaa::clusterPixel(3, 5, p, k.frame, k.agaa);
    EXPECT_EQ(r.count, 0u);
    EXPECT_EQ(r.words[0], 0u) << "sky samples keep id 0: nothing else in the metadata bits";
}

TEST(Clustering, SkySamplesAreExcludedFromTheAggregates) {
    auto k = kernelConstants(8, 2);
    PixelSamples p;
    for (uint32_t s = 0; s < 4; ++s)
        p.depth[s] = depthAt(1.0f, k.frame); // half covered, one plane
    auto r = agaa::clusterPixel(10, 10, p, k.frame, k.agaa);
    EXPECT_EQ(r.count, 1u) << "sky samples must not create a second aggregate";
}

TEST(Clustering, ThresholdStopsSeedsOnNearlyEqualSamples) {
    auto k = kernelConstants(8, 4);
    PixelSamples p;
    // Two planes 1 mm apart in depth: within t of each other, so one aggregate.
    for (uint32_t s = 0; s < 8; ++s)
        p.depth[s] = depthAt(s < 4 ? 0.5f : 0.501f, k.frame);
    EXPECT_EQ(agaa::clusterPixel(31, 31, p, k.frame, k.agaa).count, 1u);
    // 30 cm apart (d = 9 >> t): two.
    for (uint32_t s = 0; s < 8; ++s)
        p.depth[s] = depthAt(s < 4 ? 0.5f : 0.8f, k.frame);
    EXPECT_EQ(agaa::clusterPixel(31, 31, p, k.frame, k.agaa).count, 2u);
}

TEST(Clustering, FourSeparateSurfacesGiveFourAggregatesWithCFour) {
    auto k = kernelConstants(16, 4);
    PixelSamples p;
    for (uint32_t s = 0; s < 16; ++s)
        p.depth[s] = depthAt(1.0f + 0.5f * float(s % 4), k.frame);
    auto r = agaa::clusterPixel(31, 31, p, k.frame, k.agaa);
    EXPECT_EQ(r.count, 4u);
    for (uint32_t s = 4; s < 16; ++s)
        EXPECT_EQ(r.ids[s], r.ids[s % 4]) << "same depth, same aggregate";
}

// c = 1 (shared/clustering.h splitLayers): a pixel over two surfaces far apart keeps the larger
// one as its aggregate and flags the other's samples kOffLayer (their coverage only).
TEST(ClusteringLayers, OneAggregateKeepsTheLargerOfTwoLayers) {
    for (uint32_t n : {4u, 8u, 16u, 32u}) {
        auto k = kernelConstants(n, 1);
        for (uint32_t front : {1u, n / 4, n / 2 + 1, n - 1}) { // samples on the near plane
            PixelSamples p;
            for (uint32_t s = 0; s < n; ++s)
                p.depth[s] = depthAt(s < front ? 0.5f : 0.9f, k.frame); // 40 cm apart: d = 16 >> t
            auto r = agaa::clusterPixel(31, 31, p, k.frame, k.agaa);
            EXPECT_EQ(r.count, 1u) << "n=" << n << ": c = 1 is one aggregate";
            const bool nearKept = front > n - front;
            for (uint32_t s = 0; s < n; ++s)
                EXPECT_EQ(r.ids[s], (s < front) == nearKept ? 0u : shared::kOffLayer)
                    << "n=" << n << " front=" << front << " s=" << s;
        }
    }
}

// Equal layers: seed 0's (the sample farthest from the mean, the lowest index among equals) stays.
TEST(ClusteringLayers, EqualLayersKeepSeedZerosLayer) {
    auto k = kernelConstants(8, 1);
    PixelSamples p;
    for (uint32_t s = 0; s < 8; ++s)
        p.depth[s] = depthAt(s % 2 ? 0.9f : 0.5f, k.frame);
    auto r = agaa::clusterPixel(31, 31, p, k.frame, k.agaa);
    uint32_t on = 0;
    for (uint32_t s = 0; s < 8; ++s)
        on += r.ids[s] == 0u;
    EXPECT_EQ(on, 4u) << "four samples on the aggregate's layer, four off it";
    for (uint32_t s = 2; s < 8; ++s)
        EXPECT_EQ(r.ids[s], r.ids[s % 2]) << "one layer, one flag";
}

// The layer distance ignores normals and distances along one surface: a face-on pixel whose
// samples lie farther apart than sqrt(t) k (which splits it at c >= 2), a convex edge at 90
// degrees, and a plane at grazing incidence stay one layer at c = 1.
TEST(ClusteringLayers, OneSurfaceIsOneLayerWhateverItsNormalsAndFootprint) {
    for (uint32_t n : {8u, 16u}) {
        auto k = kernelConstants(n, 1);
        PixelSamples p;
        for (uint32_t s = 0; s < n; ++s) {
            p.depth[s] = depthAt(0.5f, k.frame);
            p.theta[s] = k.frame.samplePositions[s].x < 0.5f ? kFacing : kPerpendicular;
        }
        auto r = agaa::clusterPixel(31, 31, p, k.frame, k.agaa);
        for (uint32_t s = 0; s < n; ++s)
            EXPECT_EQ(r.ids[s], 0u) << "n=" << n << ": an edge between two orientations is one layer";
        // Scaled positions 10 k apart on one face-on plane (Equation 1's d = 100 >> t).
        float px[32], py[32], pz[32], nx[32], ny[32], nz[32];
        uint32_t model[32] = {}, ids[32] = {};
        bool valid[32] = {};
        for (uint32_t s = 0; s < n; ++s) {
            px[s] = 10.0f * float(s % 4);
            py[s] = 10.0f * float(s / 4);
            pz[s] = -50.0f;
            nx[s] = ny[s] = 0.0f;
            nz[s] = 1.0f;
            valid[s] = true;
        }
        EXPECT_EQ(shared::clusterSamples(n, 1, shared::kDistancePosition, 0.05f, px, py, pz, nx, ny, nz,
                                         model, valid, ids),
                  1u);
        for (uint32_t s = 0; s < n; ++s)
            EXPECT_EQ(ids[s], 0u) << "n=" << n << ": a wide face-on footprint is one layer";
        EXPECT_EQ(shared::clusterSamples(n, 2, shared::kDistancePosition, 0.05f, px, py, pz, nx, ny, nz,
                                         model, valid, ids),
                  2u)
            << "while Equation 1 splits it at c = 2";
    }
}

TEST(MetadataPacking, RoundTripForEveryRateAndAggregateCount) {
    std::mt19937 rng(7);
    for (uint32_t n : {4u, 8u, 16u, 32u}) {
        for (uint32_t c : {1u, 2u, 3u, 4u}) {
            uint32_t b = shared::metadataBits(c);
            EXPECT_EQ(b, c <= 2 ? 1u : 2u) << "b = ceil(log2 c), and c = 1's layer bit";
            EXPECT_EQ(shared::metadataWords(n, c), (n * b + 31) / 32);
            for (int trial = 0; trial < 50; ++trial) {
                uint32_t ids[shared::kMaxSamples] = {};
                for (uint32_t s = 0; s < n; ++s)
                    ids[s] = rng() % std::max(c, 2u); // c = 1: 0 on the layer, kOffLayer off it
                uint32_t words[4] = {};
                for (uint32_t w = 0; w < shared::metadataWords(n, c); ++w)
                    words[w] = shared::packMetadataWord(w, n, c, ids);
                for (uint32_t s = 0; s < n; ++s) {
                    uint32_t word = b == 0 ? 0u : words[(s * b) / 32];
                    ASSERT_EQ(shared::unpackMetadata(word, s, c), ids[s])
                        << "n=" << n << " c=" << c << " s=" << s;
                }
                // Figure 5: nothing but the ids in the used bits, zeros above n * b.
                if (b > 0 && n * b < 32) {
                    EXPECT_EQ(words[0] >> (n * b), 0u) << "n=" << n << " c=" << c;
                }
            }
        }
    }
}

TEST(MetadataPacking, Figure5Example) {
    // 8x MSAA, 4 aggregates: two bits per coverage sample, sample s in bits [2s, 2s+2).
    uint32_t ids[shared::kMaxSamples] = {0, 1, 2, 3, 3, 2, 1, 0};
    EXPECT_EQ(shared::packMetadataWord(0, 8, 4, ids), 0b0001101111100100u);
}

} // namespace

// The plane distance (AggregateDistance::Plane): samples of one plane are 0 apart however far
// apart they lie on it, where Equation 1 grows with their separation.
TEST(ClusteringDistance, PlaneDistanceIsZeroAlongOnePlane) {
    // A plane through the origin with unit normal (0, 0.6, 0.8); two points on it 3 k apart.
    const float nx = 0.0f, ny = 0.6f, nz = 0.8f;
    const float ax = 1.0f, ay = 0.8f, az = -0.6f, bx = -2.0f, by = -0.8f, bz = 0.6f;
    EXPECT_NEAR(shared::aggregatePlaneDistance(ax, ay, az, nx, ny, nz, bx, by, bz, nx, ny, nz), 0.0f, 1e-6f);
    EXPECT_GT(shared::aggregateDistance(ax, ay, az, nx, ny, nz, bx, by, bz, nx, ny, nz), 9.0f);
    EXPECT_EQ(shared::clusterDistance(shared::kDistancePlane, ax, ay, az, nx, ny, nz, bx, by, bz, nx, ny, nz),
              shared::aggregatePlaneDistance(ax, ay, az, nx, ny, nz, bx, by, bz, nx, ny, nz));
    EXPECT_EQ(
        shared::clusterDistance(shared::kDistancePosition, ax, ay, az, nx, ny, nz, bx, by, bz, nx, ny, nz),
        shared::aggregateDistance(ax, ay, az, nx, ny, nz, bx, by, bz, nx, ny, nz));
}

TEST(ClusteringDistance, PlaneDistanceIsTheSquaredOffsetBetweenParallelPlanesAndSymmetric) {
    // Two parallel planes h = 0.5 k apart along their normal, the points also 2 k apart sideways.
    const float nx = 0.0f, ny = 0.0f, nz = 1.0f;
    float d = shared::aggregatePlaneDistance(0.0f, 0.0f, 0.5f, nx, ny, nz, 2.0f, 0.0f, 0.0f, nx, ny, nz);
    EXPECT_FLOAT_EQ(d, 0.25f) << "(h / k)^2 from both tangent planes";
    // Different normals: the mean of the two one-sided distances plus Equation 1's normal term.
    const float mx = 0.0f, my = 0.6f, mz = 0.8f;
    float ab = shared::aggregatePlaneDistance(0.0f, 0.0f, 0.5f, nx, ny, nz, 1.0f, 1.0f, 0.0f, mx, my, mz);
    float ba = shared::aggregatePlaneDistance(1.0f, 1.0f, 0.0f, mx, my, mz, 0.0f, 0.0f, 0.5f, nx, ny, nz);
    EXPECT_FLOAT_EQ(ab, ba);
    const float da = 0.5f, db = -0.6f + 0.8f * 0.5f; // (a - b).n_a, (a - b).n_b with a - b = (-1, -1, 0.5)
    EXPECT_NEAR(ab, 0.5f * (da * da + db * db) + (1.0f - 0.8f) * (1.0f - 0.8f), 1e-6f);
}
