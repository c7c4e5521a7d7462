// Streaming G-buffer compression (Kerzner and Salvi 2014) on lavapipe, validation on: the GPU
// compression against its CPU reference (agaa/streaming/streaming_compression.cpp) on the same
// recorded fragments, the resolve against the CPU weights on an emissive-only scene (no lights:
// each surface's shade is its emissive), the lost coverage and memory the stats report, reruns,
// and the settings refused.

#include "agaa/streaming/streaming.h"
#include "agaa/streaming/streaming_compression.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/frame_runner.h"
#include "engine/frame/readback.h"
#include "engine/io/tone_map.h"
#include "engine/scene/scenegen.h"
#include "gpu_test_support.h"
#include "shared/streaming.h"
#include "tests/support/sample_inputs_export.h"
#include "tools/harness/frame_renderer.h"

#include <glm/gtc/packing.hpp>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace {

namespace vk = eng::vk;

// One frame of streaming compression's passes with the prepass exported, the compressed G-buffer, the lost
// samples and the display read back.
struct StreamingFrame {
    shared::FrameConstants constants{};
    std::vector<agaa::StreamingSample> samples;
    std::vector<uint32_t> surfaces, lost;
    std::vector<float> display; // RGBA
};

StreamingFrame renderStreaming(vk::Device& device, const eng::scene::Scene& scene,
                               const agaa::StreamingSettings& settings, uint32_t w, uint32_t h) {
    eng::frame::GpuScene gpuScene(device, scene);
    eng::frame::FrameRunner runner(device);
    agaa::StreamingCompression streaming(device, gpuScene, settings);
    agaa::test::SampleInputsExport fragmentExport = agaa::test::streamingFragments(device);
    const uint32_t n = settings.samples, S = settings.surfaces;
    eng::frame::ViewSettings view;
    view.width = w;
    view.height = h;
    StreamingFrame f;
    f.constants = eng::frame::makeFrameConstants(scene, view, eng::frame::makeSamplePattern(n));
    std::vector<shared::GpuLight> lights = eng::frame::makeGpuLights(scene, f.constants.view);
    vk::Buffer frameBuf = vk::createBuffer(device, sizeof(f.constants), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                           vk::MemoryUse::Upload, "test.frame");
    vk::Buffer lightBuf =
        vk::createBuffer(device, std::max<size_t>(1, lights.size()) * sizeof(shared::GpuLight),
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload, "test.lights");
    vk::Buffer exportBuf =
        vk::createBuffer(device, VkDeviceSize(w) * h * n * sizeof(agaa::StreamingSample),
                         VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Readback, "test.export");
    vk::Buffer surfacesHost =
        vk::createBuffer(device, VkDeviceSize(w) * h * S * shared::kStreamingSurfaceWords * 4,
                         VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback, "test.surfaces");
    vk::Buffer lostHost = eng::frame::createReadbackBuffer(device, w, h, VK_FORMAT_R32_UINT, "test.lost");
    vk::Buffer displayHost =
        eng::frame::createReadbackBuffer(device, w, h, VK_FORMAT_R32G32B32A32_SFLOAT, "test.display");
    vk::writeBuffer(device, frameBuf, std::as_bytes(std::span(&f.constants, 1)));
    vk::writeBuffer(device, lightBuf, std::as_bytes(std::span(lights)));
    {
        eng::rg::Graph graph;
        agaa::FrameInputs in;
        in.width = w;
        in.height = h;
        in.frameConstants =
            graph.importBuffer("frame", {frameBuf.buffer, frameBuf.size}, std::nullopt, std::nullopt);
        in.lights =
            graph.importBuffer("lights", {lightBuf.buffer, lightBuf.size}, std::nullopt, std::nullopt);
        eng::rg::Buffer target =
            graph.importBuffer("export", {exportBuf.buffer, exportBuf.size}, std::nullopt, std::nullopt);
        const agaa::SampleGBuffer g = streaming.addFragments(graph, in);
        const agaa::StreamingCompression::Surfaces s = streaming.addCompression(graph, in, g);
        const agaa::FrameTargets t = streaming.addLighting(graph, in, g, s);
        fragmentExport.add(
            graph, in,
            {{2, g.depth}, {3, g.normal}, {4, g.albedoMetal}, {5, g.emissiveRoughness}, {11, g.primitive}},
            14, target);
        eng::frame::addBufferReadbackPass(graph, s.surfaces, surfacesHost, "readback.surfaces");
        eng::frame::addReadbackPass(graph, s.lostSamples, lostHost, "readback.lost");
        eng::frame::addReadbackPass(graph, t.display, displayHost, "readback.display");
        runner.run(graph);
    }
    auto copy = [&](const vk::Buffer& b, auto& out, size_t count) {
        vk::invalidateBuffer(device, b);
        out.resize(count);
        std::memcpy(out.data(), b.mapped, count * sizeof(out[0]));
    };
    copy(exportBuf, f.samples, size_t(w) * h * n);
    copy(surfacesHost, f.surfaces, size_t(w) * h * S * shared::kStreamingSurfaceWords);
    copy(lostHost, f.lost, size_t(w) * h);
    copy(displayHost, f.display, size_t(w) * h * 4);
    for (vk::Buffer* b : {&frameBuf, &lightBuf, &exportBuf, &surfacesHost, &lostHost, &displayHost})
        vk::destroyBuffer(device, *b);
    return f;
}

float halfValue(uint32_t word, int which) {
    return glm::unpackHalf2x16(word)[which];
}

// An emissive-only scene: black, non-metallic materials that glow, no lights, no environment, a
// background quad covering the view and, in front, bars 0.3 px to 2 px wide in three colours:
// pixels with up to four primitives on different planes.
eng::scene::Scene emissiveBars() {
    eng::scene::Scene s = agaa::test::emptyScene("streaming-emissive-bars");
    s.lights.clear();
    s.materials.clear();
    const glm::vec3 glow[4] = {
        {0.2f, 0.3f, 0.4f}, {3.0f, 0.5f, 0.1f}, {0.1f, 2.0f, 0.3f}, {0.6f, 0.2f, 4.0f}};
    for (const glm::vec3& e : glow) {
        eng::scene::Material m;
        m.baseColorFactor = {0.0f, 0.0f, 0.0f, 1.0f};
        m.metallicFactor = 0.0f;
        m.roughnessFactor = 1.0f;
        m.emissiveFactor = e;
        m.doubleSided = true;
        s.materials.push_back(m);
    }
    agaa::test::addRectangle(s, {-50, -50}, {50, 50}, -10.0f, 0);
    // At z = -3 to -1, a 32 px frame with yfov 0.8 covers about 0.84 z wide: a pixel ~ 0.026 z.
    for (int i = 0; i < 24; ++i) {
        const float z = -1.0f - 0.25f * float(i % 3);
        const float x = -0.45f * -z + float(i) * 0.04f * -z;
        const float width = (0.008f + 0.003f * float(i % 5)) * -z;
        agaa::test::addRectangle(s, {x, -0.5f * -z}, {x + width, 0.5f * -z}, z, 1 + uint32_t(i % 3));
    }
    return s;
}

glm::vec2 snormPair(uint32_t word) {
    return glm::unpackSnorm2x16(word);
}

// Tolerances of the GPU-against-CPU comparison, each for what it covers.
constexpr float kZViewRelative = 1.0e-5f;     // fp32 depth -> view distance, contraction allowed
constexpr float kHalfRelative = 2.0e-3f;      // a half float (11-bit mantissa) after fp32 averaging
constexpr float kSnormStep = 3.0f / 32767.0f; // the octahedral normal's snorm16, after renormalising
constexpr float kNearThreshold = 1.0e-4f;     // a merge decision this close to its edge may round apart
constexpr float kResolveTolerance = 1.0e-4f;  // display: ACES of half emissives, fp32 sums

bool sameRecord(const uint32_t* gpu, const std::array<uint32_t, 9>& want) {
    bool same = gpu[shared::kStreamingWordCoverage] == want[shared::kStreamingWordCoverage] &&
                gpu[shared::kStreamingWordDepthTested] == want[shared::kStreamingWordDepthTested];
    const float zg = std::bit_cast<float>(gpu[shared::kStreamingWordZView]);
    const float zc = std::bit_cast<float>(want[shared::kStreamingWordZView]);
    same = same && std::abs(zg - zc) <= kZViewRelative * std::abs(zc);
    for (uint32_t word = shared::kStreamingWordAlbedoRg; word <= shared::kStreamingWordEmissiveBRoughness;
         ++word)
        for (int c = 0; c < 2; ++c) {
            const float a = halfValue(gpu[word], c), b = halfValue(want[word], c);
            same = same && std::abs(a - b) <= kHalfRelative * std::max(1.0f, std::abs(b));
        }
    for (int c = 0; c < 2; ++c) {
        const float a = halfValue(gpu[shared::kStreamingWordDepthDerivatives], c);
        const float b = halfValue(want[shared::kStreamingWordDepthDerivatives], c);
        same = same && std::abs(a - b) <= kHalfRelative * std::max(1.0e-2f, std::abs(b));
        const float na = snormPair(gpu[shared::kStreamingWordNormal])[c];
        const float nb = snormPair(want[shared::kStreamingWordNormal])[c];
        same = same && std::abs(na - nb) <= kSnormStep;
    }
    return same;
}

} // namespace

// The compression on the GPU equals its CPU reference on the exported fragments: every kept
// surface's coverage and depth-tested coverage bit for bit, zView, derivatives, normal and
// material to their storage precision, and the lost samples. Foliage at n = 8 with S = 2 and 3:
// many pixels merge, many have more surfaces than they keep. Pixels where a merge decision sits
// within 1e-4 of its threshold may differ by fp32 rounding; those are counted, not compared.
TEST(StreamingGpu, CompressionMatchesTheCpuReference) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("foliage");
    for (uint32_t S : {2u, 3u}) {
        agaa::StreamingSettings settings;
        settings.samples = 8;
        settings.surfaces = S;
        const float normalCos = std::cos(settings.normalAngleDegrees * 3.14159265358979f / 180.0f);
        const uint32_t w = 48, h = 48, n = settings.samples;
        const StreamingFrame f = renderStreaming(*device, scene, settings, w, h);
        uint32_t mismatches = 0, nearThreshold = 0, merged = 0, dropped = 0, full = 0;
        for (uint32_t y = 0; y < h; ++y)
            for (uint32_t x = 0; x < w; ++x) {
                const size_t p = size_t(y) * w + x;
                const agaa::StreamingSample* px = &f.samples[p * n];
                const agaa::StreamingPixel cpu =
                    agaa::compressPixel(f.constants, px, int(x), int(y), S, normalCos);
                agaa::StreamingCompressor replay(S, normalCos);
                for (const agaa::StreamingSurface& frag :
                     agaa::recordedFragments(f.constants, px, int(x), int(y))) {
                    const agaa::StreamingOutcome o = replay.add(frag);
                    merged += o == agaa::StreamingOutcome::Merged ? 1 : 0;
                    dropped += o == agaa::StreamingOutcome::DroppedCovered ||
                               o == agaa::StreamingOutcome::DroppedFewest;
                }
                full += cpu.surfaces.size() == S ? 1 : 0;
                bool same = f.lost[p] == cpu.lostSamples;
                for (uint32_t k = 0; k < S && same; ++k) {
                    const uint32_t* gpu = &f.surfaces[(p * S + k) * shared::kStreamingSurfaceWords];
                    if (k >= cpu.surfaces.size())
                        same = gpu[shared::kStreamingWordCoverage] == 0u;
                    else
                        same = sameRecord(gpu, agaa::streamingRecord(cpu.surfaces[k]));
                }
                if (same) continue;
                if (cpu.margin < kNearThreshold)
                    ++nearThreshold;
                else if (++mismatches <= 5)
                    ADD_FAILURE() << "S = " << S << ", pixel " << x << "," << y
                                  << ": GPU and CPU compressions differ (lost " << f.lost[p] << " vs "
                                  << cpu.lostSamples << ")";
            }
        std::printf("[ measured ] foliage S=%u: %u merges, %u drops, %u pixels full, %u near-threshold "
                    "disagreements\n",
                    S, merged, dropped, full, nearThreshold);
        EXPECT_GT(merged, 100u) << "foliage's tessellated leaves must merge, or the test proves little";
        EXPECT_GT(dropped, 10u) << "S = " << S << ": pixels with more surfaces than kept";
        EXPECT_EQ(mismatches, 0u);
        EXPECT_LE(nearThreshold, w * h / 200) << "too many near-threshold disagreements for rounding alone";
    }
    agaa::test::expectNoValidationErrors(*device);
}

// The resolve: with no light and no environment each surface's shade is its emissive, so where no
// coverage was lost the display is sum_k w_k ACES(e_k), w_k = popcount(depth-tested_k) / n from the
// CPU compression, e_k its (averaged) emissive as the half floats stored.
TEST(StreamingGpu, ResolveWeightsEachSurfaceByItsDepthTestedCoverage) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = emissiveBars();
    for (uint32_t S : {1u, 3u}) {
        agaa::StreamingSettings settings;
        settings.samples = 8;
        settings.surfaces = S;
        const float normalCos = std::cos(settings.normalAngleDegrees * 3.14159265358979f / 180.0f);
        const uint32_t w = 32, h = 32, n = settings.samples;
        const StreamingFrame f = renderStreaming(*device, scene, settings, w, h);
        float worst = 0.0f;
        uint32_t compared = 0, multi = 0, losing = 0;
        for (uint32_t p = 0; p < w * h; ++p) {
            const agaa::StreamingSample* px = &f.samples[size_t(p) * n];
            const agaa::StreamingPixel pixel =
                agaa::compressPixel(f.constants, px, int(p % w), int(p / w), S, normalCos);
            ASSERT_EQ(pixel.coveredSamples, n) << "the background covers the view";
            if (pixel.lostSamples > 0) {
                ++losing; // the sky takes those samples: not an emissive sum
                continue;
            }
            ++compared;
            multi += pixel.surfaces.size() > 1 ? 1 : 0;
            const std::vector<float> weights = agaa::streamingResolveWeights(pixel, n);
            for (int c = 0; c < 3; ++c) {
                float want = 0.0f;
                for (size_t k = 0; k < pixel.surfaces.size(); ++k) {
                    const std::array<uint32_t, 9> r = agaa::streamingRecord(pixel.surfaces[k]);
                    const float e = c < 2 ? halfValue(r[shared::kStreamingWordEmissiveRg], c)
                                          : halfValue(r[shared::kStreamingWordEmissiveBRoughness], 0);
                    want += weights[k] * eng::io::toneMapAces(e);
                }
                worst = std::max(worst, std::abs(f.display[size_t(p) * 4 + c] - want));
            }
        }
        std::printf("[ measured ] resolve S=%u: max |GPU - CPU| %.3g over %u pixels, %u with >1 surface, "
                    "%u losing coverage\n",
                    S, worst, compared, multi, losing);
        EXPECT_LT(worst, kResolveTolerance) << "S = " << S;
        if (S == 1) {
            EXPECT_GT(losing, 30u) << "one surface per pixel drops the bars' or the background's coverage";
            EXPECT_GT(compared, 50u) << "pixels of the background alone keep everything";
        } else {
            EXPECT_GT(compared, w * h / 2) << "three surfaces keep most pixels whole";
            EXPECT_GT(multi, 30u) << "S = " << S << ": the bars make pixels with several surfaces";
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Through the frame renderer: lost coverage shrinks as S grows, at most S shading events a pixel,
// the memory split into the compressed G-buffer (36 B a surface) and the recorded-fragment list,
// and reruns bit-identical.
TEST(StreamingGpu, LostCoverageMemoryShadingEventsAndReruns) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("furball");
    agaa::FrameRenderer renderer(*device, scene);
    double previous = 2.0;
    for (uint32_t S : {1u, 2u, 3u}) {
        agaa::RenderRequest r;
        r.method = "streaming";
        r.settings.samples = 8;
        r.settings.surfaces = S;
        r.view.width = r.view.height = 32;
        const agaa::RenderResult a = renderer.render(r);
        const agaa::RenderResult b = renderer.render(r);
        ASSERT_TRUE(a.lostCoverageFraction) << "streaming reports the coverage its drops leave to the sky";
        std::printf(
            "[ measured ] furball S=%u: lost %.4f of the samples in %llu pixels, events mean %.3f max "
            "%u, %.0f B/px surfaces + %.0f B/px fragment list\n",
            S, *a.lostCoverageFraction, static_cast<unsigned long long>(a.pixelsWithLostCoverage),
            a.shadingEventsMean, a.shadingEventsMax, a.bytesPerPixelSplit.at("per-aggregate"),
            a.bytesPerPixelSplit.at("fragment-list"));
        EXPECT_LE(a.shadingEventsMax, S) << "at most S shading events per pixel";
        EXPECT_LE(*a.lostCoverageFraction, previous) << "more surfaces lose less";
        if (S == 1) {
            EXPECT_GT(*a.lostCoverageFraction, 0.0) << "the furball has pixels with several surfaces";
        }
        previous = *a.lostCoverageFraction;
        EXPECT_EQ(a.bytesPerPixelSplit.at("per-aggregate"), double(S * shared::kStreamingSurfaceWords * 4))
            << "the compressed G-buffer: S records of 36 bytes";
        EXPECT_GT(a.bytesPerPixelSplit.at("fragment-list"), 0.0) << "the list the missing interlock costs";
        EXPECT_EQ(a.hdr.rgba, b.hdr.rgba) << "S = " << S << ": reruns differ";
        EXPECT_EQ(a.display.rgba, b.display.rgba) << "S = " << S << ": reruns differ";
        EXPECT_TRUE(eng::io::allFinite(a.hdr));
    }
    agaa::test::expectNoValidationErrors(*device);
}

// The normal threshold is a setting: the authors' code's cosine 0.78539816 (38.24 degrees) merges
// less than the paper's pi/4, so foliage's leaves keep more surfaces and the image changes.
TEST(StreamingGpu, TheNormalThresholdIsASetting) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("foliage");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest r;
    r.method = "streaming";
    r.settings.samples = 8;
    r.view.width = r.view.height = 48;
    const agaa::RenderResult paper = renderer.render(r);
    r.settings.streamingNormalAngle =
        std::acos(agaa::kStreamingPublicCodeNormalCos) * 180.0f / 3.14159265358979f;
    const agaa::RenderResult code = renderer.render(r);
    std::printf("[ measured ] foliage 48x48: events mean %.4f at 45 degrees, %.4f at %.2f degrees\n",
                paper.shadingEventsMean, code.shadingEventsMean, r.settings.streamingNormalAngle);
    EXPECT_NE(paper.display.rgba, code.display.rgba) << "the threshold changes which fragments merge";
    EXPECT_GT(code.shadingEventsMean, paper.shadingEventsMean) << "a stricter threshold merges less";
    agaa::test::expectNoValidationErrors(*device);
}

TEST(StreamingGpu, RefusesSettingsOutOfRange) {
    auto device = agaa::test::makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("plane");
    eng::frame::GpuScene gpuScene(*device, scene);
    struct Bad {
        uint32_t n, S;
        float degrees;
        const char* what;
    };
    for (const Bad& bad : {Bad{1u, 3u, 45.0f, "--samples 1"}, Bad{8u, 0u, 45.0f, "--surfaces 0"},
                           Bad{8u, 4u, 45.0f, "--surfaces 4"}, Bad{8u, 3u, 0.0f, "--streaming-normal-angle"},
                           Bad{8u, 3u, 91.0f, "--streaming-normal-angle"},
                           Bad{8u, 3u, std::nanf(""), "--streaming-normal-angle"}}) {
        agaa::StreamingSettings s;
        s.samples = bad.n;
        s.surfaces = bad.S;
        s.normalAngleDegrees = bad.degrees;
        try {
            agaa::StreamingCompression streaming(*device, gpuScene, s);
            ADD_FAILURE() << bad.what << " was accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find(bad.what), std::string::npos) << e.what();
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}
