// Goal P8 (issue 14): more geometry samples beat more shading samples. On the default scene at
// 160x90, AGAA (32, 2) against the converged truth (tools/harness/converged_truth.h, 512 samples a
// pixel) must be no decidedly worse than per-sample shading at n = 8: not by more than the
// truth's own error estimate. The test prints where AGAA's error goes, so that a gap is a measurement, not a
// guess:
//   - display RMSE (each method's own resolve, sRGB) and linear RMSE against the truth;
//   - the same split by the pixel's depth complexity (the surfaces AGAA (32, 4) with the
//     tangent-plane distance finds): pixels of one or two surfaces show what c = 2 costs where it
//     need not merge surfaces, pixels of three or more where it must;
//   - AGAA_P8_NO_SHADOWS=1: the same without shadowed lights (the aggregate's one footprint
//     lookup against every sample's own tap); AGAA_P8_SHADOW_STATISTICS=1 / AGAA_P8_SHADOW_SAMPLES=1
//     another shadow footprint, AGAA_P8_SHADOW_TAPS=T its tap count; AGAA_P8_NDF=sggx|toksvig one
//     normal distribution,
//     AGAA_P8_DIFFUSE=1 every material a rough dielectric (what is left is the diffuse's error).

#include "agaa_test_support.h"
#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"
#include "engine/scene/scenegen.h"
#include "gpu_test_support.h"
#include "tools/harness/converged_truth.h"
#include "tools/harness/frame_renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

constexpr uint32_t kWidth = 160, kHeight = 90;

agaa::RenderRequest request(const std::string& method, uint32_t n, uint32_t c) {
    agaa::RenderRequest r;
    r.method = method;
    r.settings.samples = n;
    r.settings.aggregates = c;
    if (const char* ndf = std::getenv("AGAA_P8_NDF"))
        r.settings.agaa.ndf = agaa::namedValue("AGAA_P8_NDF", ndf, agaa::kAggregateNdfNames);
    if (std::getenv("AGAA_P8_SHADOW_SAMPLES"))
        r.settings.effects.shadowFootprint = agaa::EffectSettings::ShadowFootprint::Samples;
    if (std::getenv("AGAA_P8_SHADOW_STATISTICS"))
        r.settings.effects.shadowFootprint = agaa::EffectSettings::ShadowFootprint::Statistics;
    if (const char* taps = std::getenv("AGAA_P8_SHADOW_TAPS"))
        r.settings.effects.shadowTaps = uint32_t(std::atoi(taps));
    r.view.width = kWidth;
    r.view.height = kHeight;
    return r;
}

// RMSE over the pixels where mask(pixel) holds (all channels but alpha).
template <class Mask> double maskedRmse(const eng::io::ImageF& a, const eng::io::ImageF& b, Mask mask) {
    double sum = 0.0;
    size_t count = 0;
    for (size_t p = 0; p < a.rgba.size() / 4; ++p) {
        if (!mask(p)) continue;
        for (size_t ch = 0; ch < 3; ++ch) {
            const double d = double(a.rgba[4 * p + ch]) - double(b.rgba[4 * p + ch]);
            sum += d * d;
        }
        count += 3;
    }
    return count ? std::sqrt(sum / double(count)) : 0.0;
}

TEST(GoalP8, MoreGeometrySamplesBeatMoreShadingSamples) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = eng::scene::loadBuiltin("default");
    if (std::getenv("AGAA_P8_NO_SHADOWS"))
        for (eng::scene::Light& l : scene.lights)
            l.castsShadows = false;
    if (std::getenv("AGAA_P8_DIFFUSE"))
        for (eng::scene::Material& m : scene.materials) {
            m.metallicFactor = 0.0f;
            m.roughnessFactor = 1.0f;
        }
    agaa::FrameRenderer renderer(*device, scene);
    const agaa::TruthCache cache(agaa::truthCacheDir(AGAA_TEST_TRUTH_CACHE));
    const agaa::ConvergedTruth truth =
        agaa::renderConvergedTruth(renderer, request("reference", 32, 1), agaa::TruthSettings{}, &cache);
    const eng::io::ImageF truthDisplay = eng::io::srgbEncoded(truth.display);
    std::printf("[ measured ] truth: %ux%u tiles at n=%u, own error estimate %.4f\n",
                truth.settings.supersampling, truth.settings.supersampling, truth.settings.samples,
                truth.errorEstimate);
    const agaa::RenderResult perSample = renderer.render(request("reference", 8, 1));
    const double perSampleError = eng::io::rmse(eng::io::srgbEncoded(perSample.display), truthDisplay);
    std::printf("[ measured ] per-sample (8): display RMSE %.4f, linear %.4g\n", perSampleError,
                eng::io::rmse(perSample.hdr, truth.hdr));

    // The pixel's depth complexity, as the clustering sees it with four aggregates and the
    // tangent-plane distance (a flat surface stays one aggregate): 1, 2, or 3+ surfaces.
    agaa::RenderRequest classify = request("agaa-accumulate", 32, 4);
    classify.settings.agaa.distance = agaa::AggregateDistance::Plane;
    const std::vector<uint32_t> surfaces = renderer.render(classify).shadingEvents;
    const eng::io::ImageF perSampleDisplay = eng::io::srgbEncoded(perSample.display);
    auto split = [&](const eng::io::ImageF& display) {
        std::string out;
        for (uint32_t k : {1u, 2u, 3u}) {
            size_t pixels = 0;
            auto in = [&](size_t p) { return k < 3 ? surfaces[p] == k : surfaces[p] >= 3; };
            for (size_t p = 0; p < surfaces.size(); ++p)
                pixels += in(p) ? 1 : 0;
            char line[160];
            std::snprintf(line, sizeof line, " | %u%s surfaces (%zu px): %.4f", k, k < 3 ? "" : "+", pixels,
                          maskedRmse(display, truthDisplay, in));
            out += line;
        }
        return out;
    };
    std::printf("[ measured ] per-sample (8) by depth complexity%s\n", split(perSampleDisplay).c_str());

    // Goal P8 at the defaults, on both generation paths: AGAA (32, c) no worse than per-sample (8),
    // within the truth's own error (docs/truth.md has the figures).
    const bool measuredSetting = !std::getenv("AGAA_P8_NDF") && !std::getenv("AGAA_P8_NO_SHADOWS") &&
                                 !std::getenv("AGAA_P8_DIFFUSE") && !std::getenv("AGAA_P8_SHADOW_SAMPLES") &&
                                 !std::getenv("AGAA_P8_SHADOW_STATISTICS") &&
                                 !std::getenv("AGAA_P8_SHADOW_TAPS");
    for (const char* method : {"agaa-accumulate", "agaa-samples"}) {
        for (uint32_t c : {2u, 4u}) {
            const agaa::RenderResult ag = renderer.render(request(method, 32, c));
            const eng::io::ImageF display = eng::io::srgbEncoded(ag.display);
            const double error = eng::io::rmse(display, truthDisplay);
            std::printf("[ measured ] %s (32, %u): display RMSE %.4f (%.2fx per-sample (8)), linear %.4g%s\n",
                        method, c, error, error / perSampleError, eng::io::rmse(ag.hdr, truth.hdr),
                        split(display).c_str());
            if (!measuredSetting) continue;
            EXPECT_LE(error, perSampleError + truth.errorEstimate)
                << method << " (32, " << c << "): goal P8 (per-sample (8) " << perSampleError
                << ", truth's own error " << truth.errorEstimate << ")";
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
