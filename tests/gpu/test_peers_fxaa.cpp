// Peers 1 on lavapipe, validation on: FXAA 3.11 quality (Lottes 2009) on the no-AA
// image, against its CPU twin (agaa/fxaa/fxaa_reference.cpp) and its defining property:
// it changes only pixels at luma edges.

#include "agaa/fxaa/fxaa_reference.h"
#include "engine/io/metrics.h"
#include "gpu_test_support.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace {

agaa::RenderResult render(agaa::FrameRenderer& renderer, const std::string& method, uint32_t size) {
    agaa::RenderRequest r;
    r.method = method;
    r.view.width = r.view.height = size;
    return renderer.render(r);
}

bool pixelChanged(const eng::io::ImageF& a, const eng::io::ImageF& b, size_t i) {
    for (int c = 0; c < 3; ++c)
        if (a.rgba[i * 4 + c] != b.rgba[i * 4 + c]) return true;
    return false;
}

// A plane filling the whole view: smooth shading, no luma edge anywhere.
TEST(FxaaGpu, FlatImageIsBitUnchanged) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = agaa::test::emptyScene("flat");
    agaa::test::addRectangle(scene, {-50.0f, -50.0f}, {50.0f, 50.0f}, -1.0f, 0);
    agaa::FrameRenderer renderer(*device, scene);
    const uint32_t size = 64;
    agaa::RenderResult noaa = render(renderer, "noaa", size);
    agaa::RenderResult fxaa = render(renderer, "fxaa", size);
    agaa::FxaaSettings settings;
    uint32_t edges = 0;
    for (uint32_t y = 0; y < size; ++y)
        for (uint32_t x = 0; x < size; ++x)
            edges += agaa::fxaaIsEdgePixel(noaa.display, int(x), int(y), settings);
    ASSERT_EQ(edges, 0u) << "the test image must have no luma edge";
    EXPECT_EQ(fxaa.display.rgba, noaa.display.rgba) << "FXAA changed a pixel of an edge-free image";
    agaa::test::expectNoValidationErrors(*device);
}

// Every changed pixel lies within one pixel of a pixel that passes FXAA's local contrast
// test (computed on the CPU from the no-AA image); and FXAA does change edges.
TEST(FxaaGpu, ChangesOnlyPixelsNearLumaEdges) {
    auto device = agaa::test::makeValidatedDevice();
    const uint32_t size = 128;
    for (const char* name : {"railings", "foliage"}) {
        eng::scene::Scene scene = eng::scene::loadTestScene(name);
        agaa::FrameRenderer renderer(*device, scene);
        agaa::RenderResult noaa = render(renderer, "noaa", size);
        agaa::RenderResult fxaa = render(renderer, "fxaa", size);
        agaa::FxaaSettings settings;
        std::vector<uint8_t> edge(size_t(size) * size);
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x)
                edge[y * size + x] = agaa::fxaaIsEdgePixel(noaa.display, int(x), int(y), settings);
        uint32_t changed = 0, farFromEdges = 0, edgeCount = 0;
        for (uint32_t y = 0; y < size; ++y)
            for (uint32_t x = 0; x < size; ++x) {
                edgeCount += edge[y * size + x];
                if (!pixelChanged(noaa.display, fxaa.display, size_t(y) * size + x)) continue;
                ++changed;
                bool near = false;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        int xx = int(x) + dx, yy = int(y) + dy;
                        if (xx >= 0 && yy >= 0 && xx < int(size) && yy < int(size))
                            near |= edge[yy * size + xx] != 0;
                    }
                farFromEdges += near ? 0 : 1;
            }
        std::printf("fxaa %s %ux%u: %u edge pixels, %u changed\n", name, size, size, edgeCount, changed);
        EXPECT_GT(changed, 20u) << name << ": FXAA smooths the scene's edges";
        EXPECT_EQ(farFromEdges, 0u) << name << ": FXAA changed pixels away from any luma edge";
        EXPECT_EQ(fxaa.hdr.rgba, noaa.hdr.rgba) << "the HDR target is the no-AA one";
        EXPECT_EQ(fxaa.shadingEvents, noaa.shadingEvents) << "FXAA shades nothing";
    }
    agaa::test::expectNoValidationErrors(*device);
}

// GPU pass vs CPU twin on the same no-AA image. The arithmetic is the same, in the same order;
// the only latitude is fp32 contraction (FMA) in llvmpipe, so a value may differ in its last bits
// (the colour by at most kRounding), and a comparison whose two sides are within kDecisionRounding
// may go the other way. Every pixel is therefore one of: bit-exact; within rounding; or departing
// further where the twin reports a decision within rounding of its threshold (its decision
// margin, fxaa_reference.h). A pixel that departs further with every decision clear of its
// threshold is a real difference between pass and twin, and fails the test by name.
TEST(FxaaGpu, MatchesTheCpuTwin) {
    // Colour: values in [0, 1] through a handful of fp32 operations: a few ulps of 1 (1.2e-7).
    constexpr double kRounding = 1e-5;
    // Luma: sqrt of a weighted sum, a /12 low-pass and bilinear lerps before each comparison.
    constexpr float kDecisionRounding = 1e-5f;
    auto device = agaa::test::makeValidatedDevice();
    uint32_t total = 0, exact = 0, rounding = 0, flipped = 0, unexplained = 0;
    for (const char* name : {"railings", "foliage", "furball"}) {
        eng::scene::Scene scene = eng::scene::loadTestScene(name);
        agaa::FrameRenderer renderer(*device, scene);
        const uint32_t size = 128;
        agaa::RenderResult noaa = render(renderer, "noaa", size);
        agaa::RenderResult fxaa = render(renderer, "fxaa", size);
        std::vector<float> margins;
        eng::io::ImageF cpu = agaa::fxaaReference(noaa.display, agaa::FxaaSettings{}, &margins);
        for (size_t i = 0; i < size_t(size) * size; ++i) {
            double d = 0.0;
            for (int c = 0; c < 3; ++c)
                d = std::max(d, double(std::abs(cpu.rgba[i * 4 + c] - fxaa.display.rgba[i * 4 + c])));
            ++total;
            if (d == 0.0) {
                ++exact;
            } else if (d <= kRounding) {
                ++rounding;
            } else if (margins[i] <= kDecisionRounding) {
                ++flipped;
            } else {
                ++unexplained;
                ADD_FAILURE() << name << " pixel (" << i % size << ", " << i / size
                              << "): GPU FXAA departs by " << d << " from its CPU twin with every decision "
                              << margins[i] << " or more from its threshold";
            }
        }
    }
    std::printf(
        "fxaa GPU vs CPU: %u pixels: %u bit-exact, %u within rounding (<= %.0e), %u departing where a "
        "decision sat within %.0e of its threshold, %u unexplained\n",
        total, exact, rounding, kRounding, flipped, double(kDecisionRounding), unexplained);
    EXPECT_EQ(unexplained, 0u);
    // Decisions on their threshold are rare (a tie of two lumas or a luma on a threshold).
    EXPECT_LE(flipped, total / 1000) << "more than 0.1 % of the pixels took a decision on its threshold";
    agaa::test::expectNoValidationErrors(*device);
}

TEST(FxaaGpu, TwoRunsAreBitIdenticalAndFinite) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = eng::scene::loadTestScene("default");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderResult a = render(renderer, "fxaa", 64);
    agaa::RenderResult b = render(renderer, "fxaa", 64);
    EXPECT_TRUE(eng::io::allFinite(a.display) && eng::io::allFinite(a.hdr)) << "NaN/Inf out of FXAA";
    EXPECT_EQ(a.display.rgba, b.display.rgba) << "FXAA is a pure function of its input";
    EXPECT_EQ(a.samples, 1u);
    EXPECT_LE(a.shadingEventsMax, 1u) << "the no-AA shading: one event per pixel at most";
    agaa::test::expectNoValidationErrors(*device);
}

TEST(FxaaSettingsTest, OutOfRangeSettingsAreRefused) {
    agaa::FxaaSettings s;
    s.preset = 17;
    EXPECT_THROW(agaa::checkFxaaSettings(s), std::invalid_argument) << "unknown preset";
    s = {};
    s.edgeThresholdMin = 0.0f;
    EXPECT_THROW(agaa::checkFxaaSettings(s), std::invalid_argument)
        << "edgeThresholdMin 0 would divide by zero";
    s = {};
    s.subpix = NAN;
    EXPECT_THROW(agaa::checkFxaaSettings(s), std::invalid_argument) << "NaN setting";
    for (uint32_t p : {10u, 15u, 29u, 39u})
        EXPECT_NO_THROW(agaa::fxaaPresetSteps(p)) << p;
    EXPECT_EQ(agaa::fxaaPresetSteps(39).size(), 12u);
    EXPECT_EQ(agaa::fxaaPresetSteps(10).size(), 3u);
}

} // namespace
