// The converged truth on lavapipe, validation on: tiles that stitch into the image one large
// frame would give, k = 1 as the sample-rate reference itself, and the disk cache.

#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"
#include "gpu_test_support.h"
#include "tools/harness/converged_truth.h"
#include "tools/scenes/adversarial_scenes.h"
#include "truth_request.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace {

agaa::RenderResult referenceAtSampleRate(agaa::FrameRenderer& renderer, uint32_t w, uint32_t h) {
    agaa::RenderRequest r = agaa::test::truthView(w, h);
    r.method = "reference";
    r.settings.samples = 32;
    r.settings.sampleRateShading = true;
    return renderer.render(r);
}

// Box-averages k x k blocks.
eng::io::ImageF downsample(const eng::io::ImageF& big, uint32_t k) {
    eng::io::ImageF out = eng::io::makeImage(big.width / k, big.height / k);
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x) {
            float sum[4] = {};
            for (uint32_t v = 0; v < k; ++v)
                for (uint32_t u = 0; u < k; ++u) {
                    const eng::io::RgbaF p = eng::io::pixel(big, k * x + u, k * y + v);
                    sum[0] += p.r, sum[1] += p.g, sum[2] += p.b;
                }
            const float inv = 1.0f / float(k * k);
            eng::io::setPixel(out, x, y, {sum[0] * inv, sum[1] * inv, sum[2] * inv, 1.0f});
        }
    return out;
}

// k = 1 is one frame of the reference at n = 32 with sample-rate shading: bit for bit.
TEST(ConvergedTruthGpu, OneTileIsTheSampleRateReference) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = eng::scene::loadTestScene("default");
    agaa::FrameRenderer renderer(*device, scene);
    const agaa::ConvergedTruth t =
        agaa::renderConvergedTruth(renderer, agaa::test::truthView(48, 32), {1, 32});
    const agaa::RenderResult ref = referenceAtSampleRate(renderer, 48, 32);
    EXPECT_EQ(t.display.rgba, ref.display.rgba);
    EXPECT_EQ(t.hdr.rgba, ref.hdr.rgba);
    EXPECT_TRUE(std::isinf(t.errorEstimate)) << "one tile has no second half: its error is unknown";
    agaa::test::expectNoValidationErrors(*device);
}

// The k^2 tiles are the pieces of one k-times-larger frame: the default scene (shadowed sun, a
// sky, tile light culling) tiled at k = 2 against one 2x frame box-filtered. The tiles'
// projections differ from the large frame's by rounding only, so a few edge samples may flip:
// measured 6.1e-4 (default) and 1.9e-4 (spikes), against truth error estimates of 7.7e-3 and 2.6e-2.
TEST(ConvergedTruthGpu, TilesStitchIntoTheLargeFrame) {
    auto device = agaa::test::makeValidatedDevice();
    for (const char* name : {"default", "spikes"}) {
        eng::scene::Scene scene = eng::scene::loadTestScene(name);
        agaa::FrameRenderer renderer(*device, scene);
        const agaa::ConvergedTruth t =
            agaa::renderConvergedTruth(renderer, agaa::test::truthView(40, 24), {2, 32});
        const agaa::RenderResult big = referenceAtSampleRate(renderer, 80, 48);
        const eng::io::ImageF whole = downsample(big.display, 2);
        const double err = eng::io::rmse(eng::io::srgbEncoded(t.display), eng::io::srgbEncoded(whole));
        EXPECT_LT(err, 1.5e-3) << name << ": tiled and whole frames differ by display RMSE " << err;
        EXPECT_GT(t.errorEstimate, 0.0) << name << ": the halves differ somewhere on an edge";
        EXPECT_LT(t.errorEstimate, 0.05) << name;
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Stored on the first render, read back on the second, and keyed by the exposure.
TEST(ConvergedTruthGpu, TheCacheServesTheSameTruthOnce) {
    auto device = agaa::test::makeValidatedDevice();
    const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) / "agaa_truth_cache_gpu";
    std::filesystem::remove_all(dir);
    const agaa::TruthCache cache(dir);
    eng::scene::Scene scene = eng::scene::loadTestScene("plane");
    agaa::FrameRenderer renderer(*device, scene);
    const agaa::ConvergedTruth first =
        agaa::renderConvergedTruth(renderer, agaa::test::truthView(16, 16), {2, 32}, &cache);
    EXPECT_FALSE(first.fromCache);
    const agaa::ConvergedTruth second =
        agaa::renderConvergedTruth(renderer, agaa::test::truthView(16, 16), {2, 32}, &cache);
    EXPECT_TRUE(second.fromCache);
    EXPECT_EQ(second.display.rgba, first.display.rgba);
    EXPECT_EQ(second.errorEstimate, first.errorEstimate);
    agaa::RenderRequest brighter = agaa::test::truthView(16, 16);
    brighter.view.exposure = 2.0f;
    EXPECT_NE(agaa::truthKey(scene, brighter, 2.0f, {2, 32}), first.key) << "exposure is part of the key";
    EXPECT_NE(agaa::truthKey(scene, agaa::test::truthView(16, 16), 1.0f, {4, 32}), first.key)
        << "k is part of the key";
    ASSERT_FALSE(scene.lights.empty());
    scene.lights.front().castsShadows = !scene.lights.front().castsShadows;
    EXPECT_NE(agaa::truthKey(scene, agaa::test::truthView(16, 16), 1.0f, {2, 32}), first.key)
        << "which lights cast shadows is part of the key";
    std::filesystem::remove_all(dir);
    agaa::test::expectNoValidationErrors(*device);
}

TEST(ConvergedTruthGpu, OtherMethodsRefuseATile) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = eng::scene::loadTestScene("plane");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest r = agaa::test::truthView(8, 8);
    r.method = "agaa";
    r.view.tile = {2, {8, 0}};
    EXPECT_THROW(renderer.render(r), std::invalid_argument);
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
