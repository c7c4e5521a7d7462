// AGAA must never look worse than no AA (issue 14), measured on every built-in and every hard-*
// scene: display RMSE (the technique's tone-mapped resolve, sRGB-encoded) against the per-sample
// reference at the same n, and the linear mean radiance against the reference's. The table it
// prints is the README's quality table (AGAA_QUALITY_SIZE re-runs it at another size,
// AGAA_QUALITY_NO_SHADOWS=1 without shadowed lights, AGAA_QUALITY_EXPOSURE=E|auto at another exposure,
// AGAA_QUALITY_METAL_ROUGHNESS=R with every metal at roughness R, AGAA_QUALITY_REFERENCE_SAMPLES=N
// against the reference at n = N,
// AGAA_QUALITY_NDF=sggx|toksvig with one normal distribution; AGAA_QUALITY_DISTANCE=plane,
// AGAA_QUALITY_SEED_THRESHOLD=T, AGAA_QUALITY_SHADOW_FOOTPRINT=statistics|samples,
// AGAA_QUALITY_CURVATURE=1, AGAA_QUALITY_TOLERANCE=T and AGAA_QUALITY_ALIAS_LIMIT=L|none (the
// shading rate, on both paths) AGAA's
// other settings: the measurements behind docs/decisions).

#include "agaa/aggregate/agaa_constants.h"
#include "agaa_test_support.h"
#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/scenegen.h"
#include "gpu_test_support.h"
#include "tools/harness/converged_truth.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
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

// A glTF file gives no exposure: it is metered, the same for every method and the truth.
agaa::RenderRequest request(const eng::scene::Scene& scene, const std::string& method, uint32_t n, uint32_t c,
                            uint32_t size) {
    agaa::RenderRequest r = agaa::test::request(method, n, c, size);
    r.autoExposure = !scene.exposure.has_value();
    if (const char* e = std::getenv("AGAA_QUALITY_EXPOSURE")) {
        r.autoExposure = std::string(e) == "auto"; // metered, as --exposure auto
        if (!r.autoExposure) r.view.exposure = float(std::atof(e));
    }
    return r;
}

// The shared real scenes (../shared/scenes; never copied in), lit as agaa-render's default does.
struct RealScene {
    const char* name;
    const char* asset;
};
constexpr RealScene kRealScenes[] = {
    {"gltf-cubes", "Cubes/Cubes.glb"},
    {"gltf-mixed-lighting", "MixedLightingExample/MixedLightingExample.gltf"},
    {"gltf-dutch-ship", "dutch_ship_medium/dutch_ship_medium_1k.gltf"},
};

eng::scene::Scene loadScene(const std::string& name) {
    for (const RealScene& r : kRealScenes)
        if (name == r.name) {
            eng::scene::Scene scene =
                eng::scene::loadGltf(std::filesystem::path(AGAA_SHARED_SCENES_DIR) / r.asset);
            eng::scene::applyLighting(scene, eng::scene::LightingMode::Automatic);
            return scene;
        }
    return eng::scene::loadTestScene(name);
}

bool realSceneMissing(const std::string& name) {
    for (const RealScene& r : kRealScenes)
        if (name == r.name)
            return !std::filesystem::exists(std::filesystem::path(AGAA_SHARED_SCENES_DIR) / r.asset);
    return false;
}

uint32_t qualitySize() {
    const char* env = std::getenv("AGAA_QUALITY_SIZE");
    return env ? uint32_t(std::clamp(std::atoi(env), 16, 512)) : 64;
}

std::vector<std::string> everyScene() {
    std::vector<std::string> scenes = eng::scene::sceneKinds();
    for (const std::string& h : eng::scene::hardSceneKinds())
        scenes.push_back(h);
    for (const RealScene& r : kRealScenes)
        scenes.push_back(r.name);
    return scenes;
}

// Where AGAA misses a bound against the converged truth (64x64, n = 8, truth k = 4), listed so
// that the test guards every other scene and c, and notices when a gap closes (it then fails and
// asks for the entry to go). docs/truth.md gives each with its numbers and the reference's.
struct KnownGap {
    const char* scene;
    uint32_t c;
    const char* measured;
    const char* method = nullptr; // nullptr: both generation paths
};
// hard-far was one until the vertex transforms became camera-relative (FrameConstants::eye): 1e5 m
// from the origin fp32 had put every multi-sample method 5x further from the truth than no-AA
// (docs/truth.md). Today, issue 35's mirror V-grooves at c = 1 on the accumulate path
// (hard-mirror-vgroove: chrome at roughness 0, 400 grooves, sun along the view axis, fill sky;
// no-AA 0.0120, reference (8) 0.0035): 0.174. One aggregate holds both walls; its mean normal faces
// the camera and mirrors the sun, where each wall mirrors the sky. The samples path was 0.170 until
// the shading rate flagged the pixels above the alias limit whose aggregates' mean normal lies in a
// gap between their members' (kMeanNormalGap); it is now the reference's 0.0035. The accumulate
// path's default tolerance is never (a tolerance costs it 12 bytes of kept material per sample):
// with AGAA_QUALITY_TOLERANCE=100 it is 0.0035 (docs/decisions/shading-rate-estimate.md, step 6).
// (c = 2 and 4 on the samples path were 0.0209 until the float SGGX sums' rounding step,
// kSggxFloatRoundingStep, then 0.0037; 0.0048 since auto lights near mirrors with Toksvig's lobe,
// issue 49: docs/decisions/ndf-auto.md.)
constexpr std::array<KnownGap, 1> kDisplayGaps{{
    {"hard-mirror-vgroove", 1, "0.174 (no-AA 0.0120; samples path 0.0035)", "agaa-accumulate"},
}};
// The energy bound, at every c: within 10 % of the truth's mean, plus the truth's mean's own error
// (ConvergedTruth::meanErrorEstimate: +-16.6 % on spikes, 10.4 % on glints, 20.8 % on hard-mirror,
// 3.5 % on hard-light-inside, at most 1.6 % elsewhere). The gaps, each beside the reference (8)'s
// own distance from the truth:
// - foliage: -14.8 to -15.6 % (the truth's mean +-0.2 %), as the reference (8) (-15.6 %); no-AA
//   -30.9 %. Every method that evaluates alpha-tested materials once a pixel loses this much
//   coverage against the truth's per-sample materials.
// - glints: +23.7 to +35.5 % at c = 1 and 2 (the truth's mean +-10.4 %; reference (8) +56.2 %,
//   no-AA +19.7 %): glossy gold rods of 2.5 mm under point lights only, whose n = 8 samples alias
//   every highlight. c = 4 holds (+10.6 / +16.2 %) since auto lights near mirrors with Toksvig's
//   lobe (issue 49); with SGGX it was -29.9 to +55.9 %, and c = 1 and 2 +35.7 to +62.3 %.
// - hard-mirror: -37.7 to -38.6 % (the truth's mean +-20.8 %; reference (8) -38.4 %, no-AA
//   -75.5 %): the sun's mirror image on the chrome wall is narrower than a sample's spacing at n = 8.
// - hard-light-inside: +21.9 / +22.0 % (the truth's mean +-3.5 %; reference (8) +2.5 %, no-AA
//   +20.5 %): a light on the sphere's vertex puts the image's mean in the few samples of one pixel.
// - hard-mirror-vgroove c = 1, accumulate path: the sun mirrored, as its display.
// Spikes was listed (c = 2 accumulate +10.1 %, c = 4 -10.9 to -21.5 %) until the truth's mean had
// an error of its own: +-16.6 %, a handful of samples mirroring the sun carrying it. The 8-sample
// reference had listed spikes at c = 1 and 4 (-71 to -75 %): its own noise.
constexpr std::array<KnownGap, 12> kEnergyGaps{{
    {"foliage", 1, "-14.8 % (reference (8) -15.6 %)"},
    {"foliage", 2, "-15.6 % (reference (8) -15.6 %)"},
    {"foliage", 4, "-15.5 to -15.6 % (reference (8) -15.6 %)"},
    {"glints", 1, "+25.1 to +35.5 % (reference (8) +56.2 %)"},
    {"glints", 2, "+23.7 to +34.0 % (reference (8) +56.2 %)"},
    {"hard-mirror", 1, "-37.7 to -38.6 % (reference (8) -38.4 %)"},
    {"hard-mirror", 2, "-37.7 to -38.6 % (reference (8) -38.4 %)"},
    {"hard-mirror", 4, "-37.7 to -38.6 % (reference (8) -38.4 %)"},
    {"hard-light-inside", 1, "+21.9 to +22.0 % (no-AA +20.5 %)"},
    {"hard-light-inside", 2, "+21.9 to +22.0 % (no-AA +20.5 %)"},
    {"hard-light-inside", 4, "+21.9 to +22.0 % (no-AA +20.5 %)"},
    {"hard-mirror-vgroove", 1, "+245.5 % (no-AA +2.8 %): the sun mirrored, as its display",
     "agaa-accumulate"},
}};

const KnownGap* knownGap(std::span<const KnownGap> gaps, const std::string& scene, uint32_t c,
                         const std::string& method) {
    for (const KnownGap& g : gaps)
        if (scene == g.scene && c == g.c && (!g.method || method == g.method)) return &g;
    return nullptr;
}

class QualityScene : public ::testing::TestWithParam<std::string> {};

// The converged truth of a scene at the test's size (tools/harness/converged_truth.h): k = 4, 512
// samples a pixel; cached in the build folder, so a re-run of the suite pays for it once.
agaa::ConvergedTruth truthOf(agaa::FrameRenderer& renderer, const agaa::RenderRequest& view) {
    const agaa::TruthCache cache(agaa::truthCacheDir(AGAA_TEST_TRUTH_CACHE));
    return agaa::renderConvergedTruth(renderer, view, agaa::TruthSettings{}, &cache);
}

// For both generation paths and c = 1, 2 and 4, against the converged truth: AGAA(8, c)'s display
// error is at most no-AA's (decidedly worse only: by more than the truth's own error estimate),
// and its linear mean radiance is within 10 % of the truth's. The reference at the same n is
// printed beside it: the shading error at fixed visibility.
TEST_P(QualityScene, AgaaIsNeverWorseThanNoAaAndKeepsTheEnergy) {
    if (realSceneMissing(GetParam())) GTEST_SKIP() << GetParam() << " is missing (AGAA_SHARED_SCENES_DIR)";
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = loadScene(GetParam());
    if (std::getenv("AGAA_QUALITY_NO_SHADOWS"))
        for (eng::scene::Light& l : scene.lights)
            l.castsShadows = false;
    if (const char* r = std::getenv("AGAA_QUALITY_METAL_ROUGHNESS"))
        for (eng::scene::Material& m : scene.materials)
            if (m.metallicFactor >= 0.5f) m.roughnessFactor = float(std::atof(r));
    const char* ndf = std::getenv("AGAA_QUALITY_NDF");
    agaa::FrameRenderer renderer(*device, scene);
    const uint32_t size = qualitySize(), n = 8;
    const bool measuredSetting =
        size == 64 && !std::getenv("AGAA_QUALITY_NO_SHADOWS") && !ndf &&
        !std::getenv("AGAA_QUALITY_DISTANCE") && !std::getenv("AGAA_QUALITY_SEED_THRESHOLD") &&
        !std::getenv("AGAA_QUALITY_SHADOW_FOOTPRINT") && !std::getenv("AGAA_QUALITY_CURVATURE") &&
        !std::getenv("AGAA_QUALITY_EXPOSURE") && !std::getenv("AGAA_QUALITY_METAL_ROUGHNESS") &&
        !std::getenv("AGAA_QUALITY_TOLERANCE") && !std::getenv("AGAA_QUALITY_ALIAS_LIMIT");
    const agaa::ConvergedTruth truth = truthOf(renderer, request(scene, "reference", n, 1, size));
    const agaa::RenderResult ref = renderer.render(request(scene, "reference", n, 1, size));
    // The same reference with materials at sample rate: what of its error is the pixel-rate material.
    agaa::RenderRequest sampleRate = request(scene, "reference", n, 1, size);
    sampleRate.settings.sampleRateShading = true;
    const agaa::RenderResult refSampleRate = renderer.render(sampleRate);
    const agaa::RenderResult noaa = renderer.render(request(scene, "noaa", 1, 1, size));
    const eng::io::ImageF truthDisplay = encoded(truth.display);
    const double noaaError = eng::io::rmse(encoded(noaa.display), truthDisplay);
    const double refError = eng::io::rmse(encoded(ref.display), truthDisplay);
    const double truthMean = meanRadiance(truth.hdr), noaaMean = meanRadiance(noaa.hdr);
    auto percent = [&](double mean) { return truthMean > 0 ? 100.0 * (mean - truthMean) / truthMean : 0.0; };
    // The truth's mean is itself off by about meanErrorEstimate (its sub-pixel images' spread, in
    // luma), as a share of the mean: the energy bound's slack, as the truth's own display error is
    // the display bound's.
    const double truthMeanError =
        truth.meanLuminance > 0 ? 100.0 * truth.meanErrorEstimate / truth.meanLuminance : 0.0;
    std::printf(
        "[ measured ] %-18s truth mean %.4g (own error %.4f, the mean's own +-%.1f %%), reference (8) "
        "display RMSE %.4f (mean %+.1f %%), at sample rate %.4f (%+.1f %%), no-AA %.4f (mean %+.1f %%)\n",
        GetParam().c_str(), truthMean, truth.errorEstimate, truthMeanError, refError,
        percent(meanRadiance(ref.hdr)), eng::io::rmse(encoded(refSampleRate.display), truthDisplay),
        percent(meanRadiance(refSampleRate.hdr)), noaaError, percent(noaaMean));
    // Both generation paths, with the same known gaps (AGAA_QUALITY_METHOD: one method only).
    const char* only = std::getenv("AGAA_QUALITY_METHOD");
    std::vector<std::string> paths = {"agaa-samples", "agaa-accumulate"};
    if (only) paths = {only};
    for (const std::string& pathName : paths) {
        const char* path = pathName.c_str();
        for (uint32_t c : {1u, 2u, 4u}) {
            agaa::RenderRequest r = request(scene, path, n, c, size);
            if (ndf)
                r.settings.agaa.ndf = agaa::namedValue("AGAA_QUALITY_NDF", ndf, agaa::kAggregateNdfNames);
            if (const char* d = std::getenv("AGAA_QUALITY_DISTANCE"))
                r.settings.agaa.distance =
                    agaa::namedValue("AGAA_QUALITY_DISTANCE", d, agaa::kAggregateDistanceNames);
            if (const char* t = std::getenv("AGAA_QUALITY_SEED_THRESHOLD"))
                r.settings.seedThreshold = float(std::atof(t));
            if (const char* f = std::getenv("AGAA_QUALITY_SHADOW_FOOTPRINT"))
                r.settings.effects.shadowFootprint = std::string(f) == "samples"
                                                         ? agaa::EffectSettings::ShadowFootprint::Samples
                                                         : agaa::EffectSettings::ShadowFootprint::Statistics;
            if (std::getenv("AGAA_QUALITY_CURVATURE")) r.settings.effects.curvatureRoughness.enabled = true;
            if (const char* t = std::getenv("AGAA_QUALITY_TOLERANCE"))
                r.settings.agaa.tolerance = float(std::atof(t));
            if (const char* l = std::getenv("AGAA_QUALITY_ALIAS_LIMIT"))
                r.settings.agaa.aliasLimit =
                    std::string(l) == "none" ? agaa::kAliasLimitNone : float(std::atof(l));
            const agaa::RenderResult ag = renderer.render(r);
            const double error = eng::io::rmse(encoded(ag.display), truthDisplay);
            const double mean = meanRadiance(ag.hdr);
            std::printf("[ measured ] %-18s %s (8, %u): display RMSE %.4f (%.2fx no-AA, %.2fx reference), "
                        "mean %.4g (%+.1f %%)\n",
                        GetParam().c_str(), path, c, error, noaaError > 0 ? error / noaaError : 0.0,
                        refError > 0 ? error / refError : 0.0, mean,
                        truthMean > 0 ? 100.0 * (mean - truthMean) / truthMean : 0.0);
            // Worse only when decidedly so: each error may be off by the truth's own. A scene no-AA
            // renders exactly (one surface per pixel) leaves AGAA the same slack.
            const bool displayOk = error <= std::max(noaaError, 1e-3) + truth.errorEstimate;
            const bool energyOk = std::abs(mean - truthMean) <=
                                  std::max(0.1 * truthMean, 1e-3) + truthMean * truthMeanError / 100.0;
            if (!measuredSetting) continue; // a measurement run: print only
            const KnownGap* displayGap = knownGap(kDisplayGaps, GetParam(), c, pathName);
            const KnownGap* energyGap = knownGap(kEnergyGaps, GetParam(), c, pathName);
            if (displayGap && pathName == "agaa-accumulate") {
                // The accumulate path's default is never; its shading rate, once set, closes the gap
                // (docs/decisions/shading-rate-estimate.md, step 6).
                agaa::RenderRequest withRate = r;
                withRate.settings.agaa.tolerance = agaa::kDefaultTolerance;
                const double rateError =
                    eng::io::rmse(encoded(renderer.render(withRate).display), truthDisplay);
                std::printf("[ measured ] %-18s %s (8, %u) at tolerance %g: display RMSE %.4f\n",
                            GetParam().c_str(), path, c, double(agaa::kDefaultTolerance), rateError);
                EXPECT_LE(rateError, std::max(noaaError, 1e-3) + truth.errorEstimate)
                    << GetParam() << " " << path << " c=" << c << ": the shading rate must close the gap";
            }
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
                                       << " now keeps the truth's energy (it measured " << energyGap->measured
                                       << "): remove it from kEnergyGaps";
            } else {
                EXPECT_TRUE(energyOk)
                    << GetParam() << " " << path << " c=" << c << ": AGAA's mean radiance is not the truth's";
            }
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Issue 35's clause for the glossy thin-metal kind (glints: gold rods of 2.5 mm, roughness 0.02,
// point lights only): AGAA (8, 2) at its defaults has at most 1.25 times the reference (8)'s display
// error, and its linear mean lies within 10 % of the truth's, at exposure 1 (the scene's own) and
// at the exposure --exposure auto meters, where the issue found AGAA (8, 2) at 0.335 against the
// reference's 0.129. Each bound allows the truth's own error, as the suite's. At exposure 1 the
// mean is a known gap: +35.7 % against a truth uncertain by +-10.4 %, where the reference (8) is
// at +56.2 %. The accumulate path (no shading rate) is printed beside it.
TEST(QualityThinMetal, AgaaWithinAQuarterOfPerSampleShadingAtBothExposures) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadTestScene("glints");
    agaa::FrameRenderer renderer(*device, scene);
    const uint32_t size = 64, n = 8;
    for (bool metered : {false, true}) {
        auto at = [&](const char* method, uint32_t c) {
            agaa::RenderRequest r = agaa::test::request(method, n, c, size);
            r.autoExposure = metered;
            return r;
        };
        const agaa::ConvergedTruth truth = truthOf(renderer, at("reference", 1));
        const eng::io::ImageF truthDisplay = encoded(truth.display);
        const double truthMean = meanRadiance(truth.hdr);
        const double truthMeanShare = truth.meanErrorEstimate / truth.meanLuminance;
        const double refError =
            eng::io::rmse(encoded(renderer.render(at("reference", 1)).display), truthDisplay);
        for (const char* method : {"agaa-samples", "agaa-accumulate"}) {
            const agaa::RenderResult ag = renderer.render(at(method, 2));
            const double error = eng::io::rmse(encoded(ag.display), truthDisplay);
            const double mean = (meanRadiance(ag.hdr) - truthMean) / truthMean;
            std::printf(
                "[ measured ] glints %-10s %s (8, 2): display RMSE %.4f, %.2fx the reference (8)'s %.4f; "
                "mean %+.1f %% (the truth's own +-%.1f %%)\n",
                metered ? "metered" : "exposure 1", method, error, error / refError, refError, 100.0 * mean,
                100.0 * truthMeanShare);
            if (std::string(method) != "agaa-samples") continue; // printed: it has no shading rate
            EXPECT_LE(error, 1.25 * refError + truth.errorEstimate) << (metered ? "metered" : "exposure 1");
            if (metered) {
                EXPECT_LE(std::abs(mean), 0.1 + truthMeanShare) << "metered";
            } else {
                EXPECT_GT(std::abs(mean), 0.1 + truthMeanShare)
                    << "the energy gap at exposure 1 has closed: say so in the comment above";
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
