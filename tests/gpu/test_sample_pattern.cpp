// The emulated sample positions (DESIGN section 3): distinct, inside the pixel,
// centred, and exactly what the rasteriser covers.

#include "engine/frame/sample_pattern.h"
#include "gpu_test_support.h"
#include "tools/harness/frame_renderer.h"

#include <gtest/gtest.h>

#include <set>

namespace {

using eng::frame::makeSamplePattern;

TEST(SamplePattern, PositionsAreDistinctInsideThePixelAndNRooks) {
    for (uint32_t n : {1u, 4u, 8u, 16u, 32u}) {
        auto p = makeSamplePattern(n);
        ASSERT_EQ(p.positions.size(), n) << "one position per sample";
        ASSERT_EQ(p.layers * p.samplesPerLayer, n) << "layers x hardware samples = n";
        std::set<float> xs, ys;
        glm::vec2 mean(0.0f);
        for (glm::vec2 q : p.positions) {
            EXPECT_GT(q.x, 0.0f) << "n=" << n << ": sample outside the pixel";
            EXPECT_LT(q.x, 1.0f) << "n=" << n;
            EXPECT_GT(q.y, 0.0f) << "n=" << n;
            EXPECT_LT(q.y, 1.0f) << "n=" << n;
            xs.insert(q.x);
            ys.insert(q.y);
            mean += q / float(n);
        }
        // n-rooks: every sample has its own column and row, so edges at any angle
        // produce n + 1 coverage levels and no two samples are duplicates.
        EXPECT_EQ(xs.size(), n) << "n=" << n << ": two samples share an x";
        EXPECT_EQ(ys.size(), n) << "n=" << n << ": two samples share a y";
        EXPECT_NEAR(mean.x, 0.5f, 1e-6f) << "n=" << n << ": pattern not centred";
        EXPECT_NEAR(mean.y, 0.5f, 1e-6f) << "n=" << n << ": pattern not centred";
    }
}

TEST(SamplePattern, UnsupportedCountsAreRefused) {
    for (uint32_t n : {0u, 2u, 3u, 6u, 12u, 64u})
        EXPECT_THROW(makeSamplePattern(n), std::invalid_argument) << n;
}

// Renders a rectangle whose right (or bottom) edge crosses one pixel at a known
// fraction f and counts the covered samples through the shading-event image: the
// count must equal the number of table positions on the covered side of f.
TEST(SamplePatternGpu, RasteriserCoversExactlyTheTablePositions) {
    auto device = agaa::test::makeValidatedDevice();
    constexpr uint32_t kSize = 16;
    constexpr uint32_t kColumn = 7;
    const float fractions[] = {0.1f + 1.0f / 128, 0.3f + 1.0f / 128, 0.5f + 1.0f / 256, 0.77f, 0.9f};
    for (bool vertical : {true, false}) {
        for (float f : fractions) {
            eng::scene::Scene scene = agaa::test::emptyScene("edge");
            eng::scene::Camera cam = scene.cameras[0];
            glm::mat4 proj = eng::frame::reversedZPerspective(cam.yfov, 1.0f, cam.znear, cam.zfar);
            // Pixel coordinate c + f -> NDC -> view space at depth 1 (z = -1).
            float ndc = 2.0f * (float(kColumn) + f) / float(kSize) - 1.0f;
            if (vertical) {
                float x = ndc / proj[0][0];
                agaa::test::addRectangle(scene, {-50.0f, -50.0f}, {x, 50.0f}, -1.0f, 0);
            } else {
                float y = ndc / proj[1][1]; // proj[1][1] < 0: pixel y grows downwards
                agaa::test::addRectangle(scene, {-50.0f, y}, {50.0f, 50.0f}, -1.0f, 0);
            }
            agaa::FrameRenderer renderer(*device, scene);
            for (uint32_t n : {1u, 4u, 8u, 16u, 32u}) {
                agaa::RenderRequest r;
                r.method = "reference";
                r.settings.samples = n;
                r.view.width = r.view.height = kSize;
                agaa::RenderResult out = renderer.render(r);
                auto pattern = makeSamplePattern(n);
                uint32_t expected = 0;
                for (glm::vec2 q : pattern.positions)
                    expected += (vertical ? q.x : q.y) < f ? 1u : 0u;
                uint32_t pixel = vertical ? 3 * kSize + kColumn : kColumn * kSize + 3;
                EXPECT_EQ(out.shadingEvents[pixel], expected)
                    << (vertical ? "vertical" : "horizontal") << " edge at fraction " << f << ", n=" << n;
                uint32_t inside = vertical ? 3 * kSize + kColumn - 2 : (kColumn - 2) * kSize + 3;
                EXPECT_EQ(out.shadingEvents[inside], n) << "a fully covered pixel has every sample, n=" << n;
            }
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
