// AGAA's samples generation path (issue 13) on lavapipe with the validation layer: one per-sample
// G-buffer pass, Algorithm 1 on its depth and shading normal, each aggregate averaged from its
// samples at the top of the lighting tile (shaders/glsl/agaa/lighting.comp AGAA_GBUFFER).
//  - the per-sample aggregation against a CPU aggregation written here, in double, from the
//    formulas (not from the shader's source): Toksvig vector, SGGX matrix, albedo, metallic;
//  - metal and dielectric samples never share an aggregate when c leaves room for both;
//  - a flat plane equals the per-sample reference, at pixel rate and at sample rate;
//  - reruns are bit-identical, with shadows, alpha-to-coverage and emissive;
//  - Kaplanyan curvature roughness: a flat surface keeps its roughness exactly, a sphere's bias
//    stays within the max footprint at every distance;
//  - coverage routing is refused by name on a device without mixed samples.

#include "agaa/aggregate/aggregate.h"
#include "agaa/methods.h"
#include "agaa_test_support.h"
#include "aggregate_export.h"
#include "engine/frame/readback.h"
#include "engine/scene/camera_framing.h"
#include "engine/scene/gltf_loader.h"
#include "engine/scene/model_builder.h"
#include "engine/vk/check.h"
#include "gpu_test_support.h"
#include "tests/support/curvature_scene.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace {

namespace vk = eng::vk;

constexpr uint32_t kRecordFloats = agaa::test::kExportRecordFloats;

using agaa::test::request;

// The scene without shadowed lights (the export variant has no shadow maps).
eng::scene::Scene unshadowed(eng::scene::Scene scene) {
    for (eng::scene::Light& l : scene.lights)
        l.castsShadows = false;
    return scene;
}

std::vector<float> renderExport(agaa::test::AggregateExportPass& exporter, agaa::FrameRenderer& renderer,
                                const agaa::RenderRequest& r, shared::AgaaConstants* constants = nullptr) {
    return agaa::test::renderAggregateExport(exporter, renderer, r, nullptr, constants);
}

// The filtered GGX alpha of a Toksvig length, from paper section 3.5.2 in double.
double toksvigAlpha(double length, double smax) {
    double len = std::clamp(length, 0.0, 1.0);
    double f = len / (len + smax * (1.0 - len));
    return std::sqrt(2.0 / (f * smax + 2.0));
}

// The Toksvig length that encodes GGX alpha as normal variance (DESIGN section 4): with the
// Blinn-Phong exponent s = 2/alpha^2 - 2, the length whose Toksvig factor gives s from smax.
double toksvigLengthOf(double alpha, double smax, double alphaMin, double alphaMax) {
    double a = std::clamp(alpha, alphaMin, alphaMax);
    double s = std::clamp(2.0 / (a * a) - 2.0, 0.0, smax);
    return s * smax / (smax - s + s * smax);
}

struct CpuAggregate {
    uint32_t k = 0, coloured = 0; // samples in its statistics and its colour (off-layer ones in neither)
    double m0[3] = {}, m1[3] = {}, albedo[3] = {}, metallic = 0.0;
    bool metal = false, dielectric = false;
};

// Issue 13: the per-sample aggregation kernel against a CPU aggregation of the same samples.
TEST(AgaaSamplesGpu, AggregationMatchesAnIndependentCpuAggregation) {
    auto device = agaa::test::makeValidatedDevice();
    agaa::test::AggregateExportPass exporter(*device);
    struct Case {
        const char* scene;
        const char* ndf;
        uint32_t n, c;
    };
    const Case cases[] = {{"furball", "toksvig", 8, 2}, {"metal", "sggx", 8, 2},
                          {"metal", "toksvig", 8, 3},   {"foliage", "toksvig", 16, 2},
                          {"railings", "sggx", 4, 4},   {"furball", "toksvig", 8, 1},
                          {"railings", "sggx", 16, 1}};
    const uint32_t size = 64, pixels = size * size;
    for (const Case& k : cases) {
        eng::scene::Scene scene = unshadowed(eng::scene::loadTestScene(k.scene));
        agaa::FrameRenderer renderer(*device, scene);
        agaa::RenderRequest r = request("agaa-samples", k.n, k.c, size);
        r.settings.agaa.ndf = agaa::namedValue("ndf", k.ndf, agaa::kAggregateNdfNames);
        shared::AgaaConstants constants{};
        const std::vector<float> e = renderExport(exporter, renderer, r, &constants);
        const bool sggx = std::string(k.ndf) == "sggx";
        const double smax = constants.toksvig.x, alphaMin = constants.toksvig.y,
                     alphaMax = constants.toksvig.z;
        uint32_t compared = 0, mismatches = 0, multi = 0, mixedModels = 0, sharedModels = 0, offLayers = 0;
        double worstMean = 0.0, worstRoughness = 0.0;
        for (uint32_t p = 0; p < pixels; ++p) {
            CpuAggregate agg[4];
            uint32_t present = 0, offLayer = 0;
            bool metalSamples = false, dielectricSamples = false;
            for (uint32_t s = 0; s < k.n; ++s) {
                const float* rec = &e[(size_t(p) * k.n + s) * kRecordFloats];
                if (rec[12] != 1.0f) continue; // sky
                const uint32_t id = uint32_t(rec[11]);
                // c = 1: id 1 is a sample off the aggregate's layer; it gives aggregate 0 nothing
                // (the resolve lights it with its own diffuse colour, lighting.glsl offLayerRadiance;
                // the lighting reference test checks that).
                const bool off = k.c == 1 && id == 1;
                const uint32_t a = off ? 0 : id;
                ASSERT_LT(a, k.c) << k.scene << ": aggregate id out of range";
                const double N[3] = {rec[0], rec[1], rec[2]};
                const double alpha = double(rec[3]) * rec[3];
                CpuAggregate& g = agg[a];
                offLayer += off ? 1 : 0;
                if (off) continue;
                g.coloured += 1;
                for (int i = 0; i < 3; ++i)
                    g.albedo[i] += rec[4 + i];
                g.metallic += rec[7];
                if (g.k == 0) ++present;
                g.k += 1;
                if (sggx) {
                    double ca = std::clamp(alpha, alphaMin, alphaMax), a2 = ca * ca;
                    for (int i = 0; i < 3; ++i)
                        g.m0[i] += (1.0 - a2) * N[i] * N[i] + a2;
                    g.m1[0] += (1.0 - a2) * N[0] * N[1];
                    g.m1[1] += (1.0 - a2) * N[0] * N[2];
                    g.m1[2] += (1.0 - a2) * N[1] * N[2];
                } else {
                    double len = toksvigLengthOf(alpha, smax, alphaMin, alphaMax);
                    for (int i = 0; i < 3; ++i)
                        g.m0[i] += N[i] * len;
                }
                const bool metal = rec[7] >= 0.5f;
                (metal ? g.metal : g.dielectric) = true;
                (metal ? metalSamples : dielectricSamples) = true;
            }
            multi += present >= 2 ? 1 : 0;
            offLayers += offLayer;
            if (metalSamples && dielectricSamples && k.c >= 2) {
                ++mixedModels;
                for (const CpuAggregate& g : agg)
                    sharedModels += g.metal && g.dielectric ? 1 : 0;
            }
            for (uint32_t a = 0; a < k.c; ++a) {
                const CpuAggregate& g = agg[a];
                if (g.k == 0) continue;
                const float* rec = &e[(size_t(pixels) * k.n + size_t(p) * k.c + a) * kRecordFloats];
                ++compared;
                bool bad = uint32_t(rec[10]) != g.k || rec[15] != 1.0f;
                const double gpu[10] = {rec[0], rec[1], rec[2], rec[3], rec[4],
                                        rec[5], rec[6], rec[7], rec[8], rec[9]};
                const double cpu[10] = {g.m0[0] / g.k,
                                        g.m0[1] / g.k,
                                        g.m0[2] / g.k,
                                        g.m1[0] / g.k,
                                        g.m1[1] / g.k,
                                        g.m1[2] / g.k,
                                        g.albedo[0] / g.coloured,
                                        g.albedo[1] / g.coloured,
                                        g.albedo[2] / g.coloured,
                                        g.metallic / g.coloured};
                for (int i = 0; i < 10; ++i) {
                    double d = std::abs(gpu[i] - cpu[i]);
                    worstMean = std::max(worstMean, d);
                    bad = bad || d > 1e-5; // float sums of at most 32 values of magnitude <= 1
                }
                if (!sggx) {
                    // The normalisation, from the GPU's own mean vector (the Toksvig mapping is
                    // steep near length 1: float rounding of the mean would dominate otherwise).
                    double len = std::sqrt(gpu[0] * gpu[0] + gpu[1] * gpu[1] + gpu[2] * gpu[2]);
                    double want = std::sqrt(toksvigAlpha(len, smax));
                    double d = std::abs(rec[11] - want) / want;
                    worstRoughness = std::max(worstRoughness, d);
                    bad = bad || d > 1e-3;
                    if (len > 1e-6)
                        for (int i = 0; i < 3; ++i)
                            bad = bad || std::abs(rec[12 + i] - gpu[i] / len) > 1e-4;
                }
                mismatches += bad ? 1 : 0;
            }
        }
        std::printf(
            "[ measured ] %s n=%u c=%u %s: %u aggregates compared (%u pixels with 2 or more, %u samples off "
            "their layer), worst mean %.2e, worst roughness %.2e; %u pixels mix metal and dielectric\n",
            k.scene, k.n, k.c, k.ndf, compared, multi, offLayers, worstMean, worstRoughness, mixedModels);
        EXPECT_GT(compared, pixels / 2) << k.scene;
        if (k.c == 1) {
            EXPECT_GT(offLayers, 0u) << k.scene << ": c = 1 with no sample off its aggregate's layer";
        } else {
            EXPECT_GT(multi, 0u) << k.scene << ": the frame must hold pixels with several aggregates";
        }
        EXPECT_EQ(mismatches, 0u) << k.scene << " " << k.ndf
                                  << ": aggregates differ from the CPU aggregation";
        EXPECT_EQ(sharedModels, 0u) << k.scene << ": a metal and a dielectric sample share an aggregate";
        if (std::string(k.scene) == "metal") {
            EXPECT_GT(mixedModels, 0u) << "the metal scene must have pixels that mix metal and dielectric";
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// On one flat quad the samples path equals per-sample shading, at pixel and at sample rate.
TEST(AgaaSamplesGpu, PlaneEqualsTheReference) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = eng::scene::loadTestScene("plane");
    agaa::FrameRenderer renderer(*device, scene);
    for (bool sampleRate : {false, true})
        for (auto [n, c] : {std::pair{4u, 1u}, std::pair{8u, 2u}, std::pair{32u, 2u}}) {
            agaa::RenderRequest ref = request("reference", n, 1, 64);
            ref.settings.sampleRateShading = sampleRate;
            agaa::RenderRequest ag = request("agaa-samples", n, c, 64);
            ag.settings.sampleRateShading = sampleRate;
            agaa::RenderResult a = renderer.render(ref);
            agaa::RenderResult b = renderer.render(ag);
            double worst = 0.0;
            uint32_t covered = 0;
            for (uint32_t p = 0; p < 64 * 64; ++p) {
                if (a.shadingEvents[p] == 0) continue;
                ++covered;
                for (int ch = 0; ch < 3; ++ch)
                    worst = std::max(
                        worst, double(std::abs(b.display.rgba[p * 4 + ch] - a.display.rgba[p * 4 + ch])));
            }
            EXPECT_GT(covered, 64u * 64u / 2);
            EXPECT_LE(worst, 1e-3) << "n=" << n << " c=" << c << " sample rate " << sampleRate;
            // At 64x64 a pixel of the plane is 6 cm wide, close to k = 10 cm: at n = 32 the samples'
            // spread alone can pass the seed threshold (Equation 1's position term), and the
            // plane is then lit as two aggregates of the same surface: still equal to the reference.
            if (n <= 8) {
                EXPECT_EQ(b.shadingEventsMax, 1u) << "n=" << n << ": a flat pixel is one aggregate";
            }
        }
    agaa::test::expectNoValidationErrors(*device);
}

// Bit-identical reruns, and the variants say which path ran and why.
TEST(AgaaSamplesGpu, RerunsAreBitIdenticalAndTheVariantsNameThePath) {
    auto device = agaa::test::makeValidatedDevice();
    // default: shadows; metal: SGGX; foliage: alpha-to-coverage; hard-emissive: per-sample emissive.
    for (const char* name : {"default", "metal", "foliage", "hard-emissive"}) {
        eng::scene::Scene scene = eng::scene::loadTestScene(name);
        agaa::FrameRenderer renderer(*device, scene);
        for (bool sampleRate : {false, true}) {
            agaa::RenderRequest r = request("agaa-samples", 8, 2, 64);
            r.settings.sampleRateShading = sampleRate;
            r.settings.effects.curvatureRoughness.enabled = sampleRate;
            agaa::RenderResult a = renderer.render(r);
            agaa::RenderResult b = renderer.render(r);
            EXPECT_EQ(a.hdr.rgba, b.hdr.rgba) << name;
            EXPECT_EQ(a.display.rgba, b.display.rgba) << name;
            for (float v : a.hdr.rgba)
                ASSERT_TRUE(std::isfinite(v)) << name;
            bool named = false;
            for (const agaa::VariantChoice& v : a.variants)
                named = named || (v.effect == "generation" && v.variant.rfind("samples", 0) == 0);
            EXPECT_TRUE(named) << name << ": the stats variants must name the samples path";
            // The per-sample G-buffer is the path's storage, and its bytes say so.
            EXPECT_GE(a.bytesPerPixelSplit["per-sample"], 8.0 * 20.0) << name;
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// The aggregates debug view on the samples path: the clustering of the G-buffer, one colour per
// aggregate, with the lit frame's aggregate counts.
TEST(AgaaSamplesGpu, DebugViewShowsTheLitFramesAggregates) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = eng::scene::loadTestScene("railings");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest lit = request("agaa-samples", 8, 4, 64);
    agaa::RenderRequest debug = lit;
    debug.settings.debug = "aggregates";
    const agaa::RenderResult a = renderer.render(lit);
    const agaa::RenderResult b = renderer.render(debug);
    EXPECT_EQ(a.shadingEvents, b.shadingEvents) << "the view must show the aggregates the frame lit";
    EXPECT_GT(b.shadingEventsMax, 1u);
    for (float v : b.display.rgba)
        ASSERT_TRUE(std::isfinite(v));
    agaa::test::expectNoValidationErrors(*device);
}

using agaa::test::curvatureScene;

// Kaplanyan curvature roughness in the fill pass (common/curvature_roughness.glsl).
TEST(AgaaSamplesGpu, CurvatureRoughnessKeepsFlatSurfacesAndBoundsTheSphereBias) {
    auto device = agaa::test::makeValidatedDevice();
    agaa::test::AggregateExportPass exporter(*device);
    const uint32_t size = 64, n = 8, c = 2;
    const double roughness = 0.2, alpha2 = std::pow(roughness, 4.0), maxFootprint = 0.3;
    {
        eng::scene::Scene scene = curvatureScene(false, 3.0f);
        agaa::FrameRenderer renderer(*device, scene);
        agaa::RenderRequest r = request("agaa-samples", n, c, size);
        const std::vector<float> off = renderExport(exporter, renderer, r);
        r.settings.effects.curvatureRoughness.enabled = true;
        const std::vector<float> on = renderExport(exporter, renderer, r);
        uint32_t samples = 0, changed = 0;
        for (uint32_t i = 0; i < size * size * n; ++i) {
            const size_t at = size_t(i) * kRecordFloats;
            if (on[at + 12] != 1.0f) continue;
            ++samples;
            changed += on[at + 3] != off[at + 3] ? 1 : 0; // the G-buffer's RGBA16F roughness, bit for bit
        }
        EXPECT_GT(samples, size * size * n / 2);
        EXPECT_EQ(changed, 0u) << "a flat surface's roughness must stay the material's exactly";
    }
    double previousMean = -1.0;
    for (float distance : {1.2f, 3.0f, 12.0f, 60.0f}) {
        eng::scene::Scene scene = curvatureScene(true, distance);
        agaa::FrameRenderer renderer(*device, scene);
        agaa::RenderRequest r = request("agaa-samples", n, c, size);
        r.settings.effects.curvatureRoughness.enabled = true;
        const std::vector<float> e = renderExport(exporter, renderer, r);
        uint32_t samples = 0, outside = 0;
        double biasSum = 0.0, worst = 0.0;
        for (uint32_t i = 0; i < size * size * n; ++i) {
            const float* rec = &e[size_t(i) * kRecordFloats];
            if (rec[12] != 1.0f) continue;
            ++samples;
            const double bias = std::pow(double(rec[3]), 4.0) - alpha2; // added to alpha^2
            biasSum += bias;
            worst = std::max(worst, bias);
            // Never smoother than the material, never more than the max footprint (RGBA16F rounding).
            outside += bias < -1e-4 || bias > maxFootprint + 1e-3 ? 1 : 0;
        }
        ASSERT_GT(samples, 0u) << "distance " << distance;
        const double mean = biasSum / samples;
        std::printf("[ measured ] sphere at %.1f m: %u samples, mean alpha^2 bias %.4f, max %.4f\n", distance,
                    samples, mean, worst);
        EXPECT_EQ(outside, 0u) << "distance " << distance << ": the bias must stay in [0, max footprint]";
        EXPECT_GT(mean, previousMean) << "a smaller sphere on screen is more curved per pixel";
        previousMean = mean;
    }
    EXPECT_GT(previousMean, 0.05) << "at 60 m the sphere's curvature must widen the lobe";
    agaa::test::expectNoValidationErrors(*device);
}

// Coverage routing needs mixed samples and the sample-mask override; lavapipe has neither, and
// the request names what is missing instead of running something else.
TEST(AgaaSamplesGpu, CoverageRoutingIsRefusedByName) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = eng::scene::loadTestScene("plane");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest r = request("agaa", 8, 2, 64);
    r.settings.agaa.generation = agaa::AggregateGeneration::Coverage;
    try {
        renderer.render(r);
        ADD_FAILURE() << "coverage routing must be refused on " << device->caps().deviceName;
    } catch (const vk::MissingCapability& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("coverage"), std::string::npos) << what;
        if (!device->caps().mixedSamples) {
            EXPECT_NE(what.find("mixed"), std::string::npos) << what;
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
