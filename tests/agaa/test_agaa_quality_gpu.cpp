// AGAA must never look worse than no AA (issue 14), measured on every built-in and every hard-*
// scene: display RMSE (the technique's tone-mapped resolve, sRGB-encoded) against the per-sample
// reference at the same n, and the linear mean radiance against the reference's. The table it
// prints is the README's quality table (AGAA_QUALITY_SIZE re-runs it at another size,
// AGAA_QUALITY_NO_SHADOWS=1 without shadowed lights, AGAA_QUALITY_EXPOSURE=E at another exposure,
// AGAA_QUALITY_METAL_ROUGHNESS=R with every metal at roughness R, AGAA_QUALITY_REFERENCE_SAMPLES=N
// against the reference at n = N,
// AGAA_QUALITY_NDF=sggx|toksvig with one normal distribution: the measurements behind the README's causes).

#include "agaa_test_support.h"
#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"
#include "engine/scene/scenegen.h"
#include "gpu_test_support.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <span>
#include <string>
#include <vector>

namespace {

eng::io::ImageF encoded(const eng::io::ImageF& display) {
    eng::io::ImageF out = display;
    for (size_t i = 0; i < out.rgba.size(); ++i)
        if (i % 4 != 3) out.rgba[i] = eng::io::linearToSrgb(out.rgba[i]);
    return out;
}

// Mean linear radiance over the image (rgb averaged), the energy the resolve kept.
double meanRadiance(const eng::io::ImageF& hdr) {
    double sum = 0.0;
    for (size_t i = 0; i < hdr.rgba.size(); ++i)
        if (i % 4 != 3) sum += hdr.rgba[i];
    return sum / double(hdr.rgba.size() / 4 * 3);
}

agaa::RenderRequest request(const std::string& method, uint32_t n, uint32_t c, uint32_t size) {
    agaa::RenderRequest r = agaa::test::request(method, n, c, size);
    if (const char* e = std::getenv("AGAA_QUALITY_EXPOSURE")) r.view.exposure = float(std::atof(e));
    return r;
}

uint32_t qualitySize() {
    const char* env = std::getenv("AGAA_QUALITY_SIZE");
    return env ? uint32_t(std::clamp(std::atoi(env), 16, 512)) : 64;
}

std::vector<std::string> everyScene() {
    std::vector<std::string> scenes = eng::scene::sceneKinds();
    for (const std::string& h : eng::scene::hardSceneKinds())
        scenes.push_back(h);
    return scenes;
}

// Where AGAA is still worse than no AA (issue 14, open): measured at 64x64, n = 8, and listed so
// that the test guards every other scene and c, and notices when a gap closes (it then fails and
// asks for the entry to go). The README's quality table gives each with its numbers.
struct KnownGap {
    const char* scene;
    uint32_t c;
    const char* measured;
    const char* method = nullptr; // nullptr: both generation paths
};
// No display gap is left. The last, hard-mirror at c = 1 (1.13x samples path, 1.09x accumulate),
// was the off-layer samples' colour: c = 1 lights the larger of a pixel's two layers (shared/
// clustering.h splitLayers; before it hard-mirror 1.49x, hard-many-lights 1.35x), and the chrome
// wall's samples behind the plastic sphere's rim joined its albedo and metallic means, lit with
// the rim's grazing normals (a grey ring). They now resolve with their own diffuse colour under
// their own irradiance (lighting.glsl offLayerRadiance): 0.39x / 0.26x.
constexpr std::array<KnownGap, 0> kDisplayGaps{};
// The energy bound, at every c: within 10 % of the 8-sample reference's mean, with no slack (an
// allowance of no-AA's own distance once let c = 1's foliage pass at -13.7 %, no-AA being at
// -19 % there; it closed, -0.3 %, when the off-layer samples took their own irradiance).
// The reference reads each fragment's attributes at the centroid of its covered samples
// (reference/gbuffer_inputs.glsl). At the pixel centre, as before, a thin bar's normal was
// extrapolated outside the bar: the metal lattice's reference mean was 0.370 against 0.454 at
// sample rate, and that 18 % bias was the "+11.3 %" gap of metal c = 4 (now -2.3 %), and it hid
// the two metal gaps below (c = 1 measured -5.3 %, c = 2 +9.8 % against the biased reference).
// - spikes: the reference's mean (0.904) is one sample: a spike's flat cap that mirrors the sun
//   puts 3224 in one pixel, 94 % of the image's mean (0.118 without it, at the pixel centre);
//   the pixel-centre reference's mean went 0.12 to 0.30 with the size and n, and AGAA sees the
//   same 8 samples: its mean stays 0.19 to 0.26.
// - hard-light-inside: a light on the sphere's vertex puts the image's mean in the few samples of
//   one pixel, where AGAA and no-AA give the same radiance (+19 %, no-AA +18 %; -2.6 % at 128x128
//   and +1.5 % at 256x256 before the centroid).
// Metal, -24.1 % at c = 1 and -10.1 to -10.6 % at c = 2, closed in two steps (now -9.2 % and
// -4.5 to -4.7 %): c = 1's off-layer samples took a specular of their own (lighting.glsl
// offLayerLight; the bars behind the aggregate's layer were black: -14.2 %), and the aggregates'
// specular the microflake form where their normals spread (common/brdf.glsl specularFlake): the
// mean normal's horizon cut the sun's highlights on the bars' upper halves.
// Hard-mirror, -44 % at c = 2 (no-AA -60 %), closed when near mirrors took their samples' own view
// directions (lighting.glsl addLightFootprint: -0.1 %): the sun's peak on the flat chrome wall
// falls between pixel centres, and one view direction a pixel found it or missed it.
constexpr std::array<KnownGap, 6> kEnergyGaps{{
    {"spikes", 1, "-71.2 to -71.4 % mean radiance"},
    {"spikes", 2, "-68.8 to -68.9 % mean radiance"},
    {"spikes", 4, "-73.2 to -75.2 % mean radiance"},
    {"hard-light-inside", 1, "+19.0 to +19.4 % (no-AA +17.7 %)"},
    {"hard-light-inside", 2, "+19.0 to +19.4 % (no-AA +17.7 %)"},
    {"hard-light-inside", 4, "+19.0 to +19.4 % (no-AA +17.7 %)"},
}};

const KnownGap* knownGap(std::span<const KnownGap> gaps, const std::string& scene, uint32_t c,
                         const std::string& method) {
    for (const KnownGap& g : gaps)
        if (scene == g.scene && c == g.c && (!g.method || method == g.method)) return &g;
    return nullptr;
}

class QualityScene : public ::testing::TestWithParam<std::string> {};

// For both generation paths and c = 1, 2 and 4: AGAA(8, c)'s display error against the reference is at most
// no-AA's, and its linear mean radiance is within 10 % of the reference's (kEnergyGaps: where the
// 8-sample reference's mean is not converged).
TEST_P(QualityScene, AgaaIsNeverWorseThanNoAaAndKeepsTheEnergy) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = eng::scene::loadTestScene(GetParam());
    if (std::getenv("AGAA_QUALITY_NO_SHADOWS"))
        for (eng::scene::Light& l : scene.lights)
            l.castsShadows = false;
    if (const char* r = std::getenv("AGAA_QUALITY_METAL_ROUGHNESS"))
        for (eng::scene::Material& m : scene.materials)
            if (m.metallicFactor >= 0.5f) m.roughnessFactor = float(std::atof(r));
    const char* ndf = std::getenv("AGAA_QUALITY_NDF");
    agaa::FrameRenderer renderer(*device, scene);
    const uint32_t size = qualitySize(), n = 8;
    // AGAA_QUALITY_REFERENCE_SAMPLES=32: the reference at another n (AGAA stays at 8).
    const char* refSamples = std::getenv("AGAA_QUALITY_REFERENCE_SAMPLES");
    const bool measuredSetting = size == 64 && !std::getenv("AGAA_QUALITY_NO_SHADOWS") && !ndf &&
                                 !std::getenv("AGAA_QUALITY_EXPOSURE") &&
                                 !std::getenv("AGAA_QUALITY_METAL_ROUGHNESS") && !refSamples;
    const agaa::RenderResult ref =
        renderer.render(request("reference", refSamples ? uint32_t(std::atoi(refSamples)) : n, 1, size));
    const agaa::RenderResult noaa = renderer.render(request("noaa", 1, 1, size));
    const eng::io::ImageF refDisplay = encoded(ref.display);
    const double noaaError = eng::io::rmse(encoded(noaa.display), refDisplay);
    const double refMean = meanRadiance(ref.hdr), noaaMean = meanRadiance(noaa.hdr);
    std::printf(
        "[ measured ] %-18s reference mean %.4g, no-AA display RMSE %.4f, linear RMSE %.4g (mean %.4g)\n",
        GetParam().c_str(), refMean, noaaError, eng::io::rmse(noaa.hdr, ref.hdr), noaaMean);
    // Both generation paths, with the same known gaps (AGAA_QUALITY_METHOD: one method only).
    const char* only = std::getenv("AGAA_QUALITY_METHOD");
    std::vector<std::string> paths = {"agaa-samples", "agaa-accumulate"};
    if (only) paths = {only};
    for (const std::string& pathName : paths) {
        const char* path = pathName.c_str();
        for (uint32_t c : {1u, 2u, 4u}) {
            agaa::RenderRequest r = request(path, n, c, size);
            if (ndf) r.settings.ndf = ndf;
            const agaa::RenderResult ag = renderer.render(r);
            const double error = eng::io::rmse(encoded(ag.display), refDisplay);
            const double mean = meanRadiance(ag.hdr);
            std::printf("[ measured ] %-18s agaa (8, %u): display RMSE %.4f (%.2fx no-AA), linear RMSE %.4g, "
                        "mean %.4g "
                        "(%+.1f %%)\n",
                        GetParam().c_str(), c, error, noaaError > 0 ? error / noaaError : 0.0,
                        eng::io::rmse(ag.hdr, ref.hdr), mean,
                        refMean > 0 ? 100.0 * (mean - refMean) / refMean : 0.0);
            // A scene no-AA renders exactly (one surface per pixel) leaves AGAA the same slack.
            const bool displayOk = error <= std::max(noaaError, 1e-3);
            const bool energyOk = std::abs(mean - refMean) <= std::max(0.1 * refMean, 1e-3);
            if (!measuredSetting) continue; // a measurement run: print only
            const KnownGap* displayGap = knownGap(kDisplayGaps, GetParam(), c, pathName);
            const KnownGap* energyGap = knownGap(kEnergyGaps, GetParam(), c, pathName);
            if (displayGap) {
                EXPECT_FALSE(displayOk) << GetParam() << " " << path << " c=" << c
                                        << " is no longer worse than no AA (it measured "
                                        << displayGap->measured << "): remove it from kDisplayGaps";
            } else {
                EXPECT_TRUE(displayOk)
                    << GetParam() << " " << path << " c=" << c << ": AGAA worse than no AA";
            }
            if (energyGap) {
                EXPECT_FALSE(energyOk) << GetParam() << " " << path << " c=" << c
                                       << " now keeps the reference's energy (it measured "
                                       << energyGap->measured << "): remove it from kEnergyGaps";
            } else {
                EXPECT_TRUE(energyOk) << GetParam() << " " << path << " c=" << c
                                      << ": AGAA's mean radiance is not the reference's";
            }
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

INSTANTIATE_TEST_SUITE_P(Every, QualityScene, ::testing::ValuesIn(everyScene()), [](const auto& info) {
    std::string s = info.param;
    for (char& ch : s)
        if (ch == '-') ch = '_';
    return s;
});

} // namespace
