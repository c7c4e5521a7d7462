// AGAA's cost-saving paths (issue 12) on lavapipe with the validation layer. Each is either exact
// (the compacted lighting list against the per-pixel schedule; 64-bit and subgroup-reduced
// atomics against 32-bit ones, the AG-buffer word for word) or a different approximation whose
// own invariant is checked here (per-fragment routing counts every visible sample once; the
// plane distance keeps a flat surface in one aggregate), with its error against the reference
// printed for the README.

#include "agaa/aggregate/aggregate.h"
#include "engine/frame/readback.h"
#include "engine/io/metrics.h"
#include "engine/io/tone_map.h"
#include "gpu_test_support.h"
#include "shared/ag_buffer.h"
#include "tools/harness/frame_renderer.h"
#include "tools/scenes/adversarial_scenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <vector>

namespace {

namespace vk = eng::vk;

agaa::RenderRequest agaaRequest(uint32_t n, uint32_t c, uint32_t size) {
    agaa::RenderRequest r;
    r.method = "agaa-accumulate"; // the accumulation kernel's paths
    r.settings.samples = n;
    r.settings.aggregates = c;
    r.view.width = r.view.height = size;
    return r;
}

struct Case {
    const char* scene;
    uint32_t n, c;
};

// The compacted schedule lights the same aggregates with the same values and the same code
// (agaa/lighting.comp shadeAggregate); only the invocation that does it differs. Any difference in
// the image is a bug in the list's bookkeeping (a lost, doubled or misrouted entry).
TEST(AgaaPathsGpu, CompactedLightingEqualsThePerPixelScheduleBitForBit) {
    auto device = agaa::test::makeValidatedDevice();
    // default: shadows + point lights; metal: SGGX; foliage: alpha-to-coverage; hard-emissive:
    // the per-sample emissive resolve; c = 4 needs up to 3 rounds of the list in a busy tile.
    const Case cases[] = {{"default", 8, 2}, {"metal", 8, 2},    {"foliage", 8, 4},
                          {"furball", 8, 3}, {"furball", 32, 2}, {"hard-emissive", 8, 2}};
    for (const Case& k : cases) {
        eng::scene::Scene scene = eng::scene::loadTestScene(k.scene);
        agaa::FrameRenderer renderer(*device, scene);
        // Both generation paths: on a GPU, auto runs the samples path with the compacted list.
        for (const char* path : {"agaa-accumulate", "agaa-samples"}) {
            agaa::RenderRequest compact = agaaRequest(k.n, k.c, 64);
            compact.method = path;
            compact.settings.agaa.shading = agaa::AggregateShading::Compact;
            agaa::RenderRequest registers = compact;
            registers.settings.agaa.shading = agaa::AggregateShading::Registers;
            agaa::RenderResult a = renderer.render(compact);
            agaa::RenderResult b = renderer.render(registers);
            uint64_t extra = 0; // entries that went through the list: events beyond one per pixel
            for (uint32_t e : a.shadingEvents)
                extra += e > 1 ? e - 1 : 0;
            EXPECT_GT(extra, 0u) << k.scene << " " << path << ": the list must have held entries";
            EXPECT_EQ(a.hdr.rgba, b.hdr.rgba) << k.scene << " " << path << " n=" << k.n << " c=" << k.c;
            EXPECT_EQ(a.display.rgba, b.display.rgba)
                << k.scene << " " << path << " n=" << k.n << " c=" << k.c;
            EXPECT_EQ(a.shadingEvents, b.shadingEvents) << k.scene << " " << path;
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// The AG-buffer words after generation with the given atomics settings.
std::vector<uint32_t> agBufferWords(vk::Device& device, agaa::FrameRenderer& renderer, agaa::RenderRequest r,
                                    uint32_t pixels) {
    const VkDeviceSize bytes = VkDeviceSize(pixels) * r.settings.aggregates * shared::kAggregateWords * 4;
    vk::Buffer host = vk::createBuffer(device, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                       vk::MemoryUse::Readback, "test.agBuffer");
    r.extraPasses = [&](eng::rg::Graph& graph, agaa::Technique& tech, const agaa::FrameInputs&) {
        auto& aggregate = dynamic_cast<agaa::AggregateAA&>(tech);
        eng::frame::addBufferReadbackPass(graph, aggregate.resources().agBuffer, host, "test.agBuffer");
    };
    renderer.render(r);
    std::vector<uint32_t> words(bytes / 4);
    std::memcpy(words.data(), host.mapped, bytes);
    vk::destroyBuffer(device, host);
    return words;
}

// 64-bit adds of two words equal two 32-bit adds because no field carries out of its word
// (shared/agaa.h); subgroup pre-reduction sums integers before adding them. Integer sums do not
// depend on their order, so all three AG-buffers must be equal word for word.
TEST(AgaaPathsGpu, WideAtomicsAndSubgroupReductionLeaveTheAgBufferUnchanged) {
    auto device = agaa::test::makeValidatedDevice();
    // Each path runs where the device offers it (lavapipe offers both; CI runs both).
    const eng::vk::Capabilities& caps = device->caps();
    const bool int64 = caps.bufferInt64Atomics;
    const bool subgroups = (caps.subgroupStages & VK_SHADER_STAGE_FRAGMENT_BIT) != 0 &&
                           (caps.subgroupOperations & VK_SUBGROUP_FEATURE_ARITHMETIC_BIT) != 0 &&
                           (caps.subgroupOperations & VK_SUBGROUP_FEATURE_BALLOT_BIT) != 0;
    if (!int64 && !subgroups)
        GTEST_SKIP() << caps.deviceName << " offers neither shaderBufferInt64Atomics nor fragment subgroups";
    const Case cases[] = {{"furball", 8, 2}, {"foliage", 8, 4}, {"metal", 16, 2}, {"hard-zfight", 8, 2}};
    const uint32_t size = 48;
    for (const Case& k : cases) {
        eng::scene::Scene scene = eng::scene::loadTestScene(k.scene);
        agaa::FrameRenderer renderer(*device, scene);
        agaa::RenderRequest base = agaaRequest(k.n, k.c, size);
        base.settings.agaa.atomics = agaa::AggregateAtomics::Bits32;
        base.settings.agaa.subgroupReduction = agaa::SubgroupReduction::Off;
        agaa::RenderRequest wide = base, reduced = base, both = base;
        wide.settings.agaa.atomics = agaa::AggregateAtomics::Bits64;
        reduced.settings.agaa.subgroupReduction = agaa::SubgroupReduction::On;
        both.settings.agaa.atomics = agaa::AggregateAtomics::Bits64;
        both.settings.agaa.subgroupReduction = agaa::SubgroupReduction::On;
        std::vector<uint32_t> narrow = agBufferWords(*device, renderer, base, size * size);
        EXPECT_TRUE(std::any_of(narrow.begin(), narrow.end(), [](uint32_t w) { return w != 0; }))
            << k.scene << ": the AG-buffer must hold accumulated samples";
        if (int64) {
            EXPECT_EQ(agBufferWords(*device, renderer, wide, size * size), narrow)
                << k.scene << ": 64-bit atomics";
        }
        if (subgroups) {
            EXPECT_EQ(agBufferWords(*device, renderer, reduced, size * size), narrow)
                << k.scene << ": subgroup reduction";
        }
        if (int64 && subgroups) {
            EXPECT_EQ(agBufferWords(*device, renderer, both, size * size), narrow) << k.scene << ": both";
        }
    }
    agaa::test::expectNoValidationErrors(*device);
}

// Samples accumulated per pixel (summed over its aggregates), for a Toksvig-layout AG-buffer.
std::vector<uint32_t> accumulatedPerPixel(const std::vector<uint32_t>& words, uint32_t c) {
    std::vector<uint32_t> perPixel(words.size() / (c * shared::kAggregateWords), 0u);
    for (size_t p = 0; p < perPixel.size(); ++p)
        for (uint32_t a = 0; a < c; ++a) {
            const uint32_t* w = &words[(p * c + a) * shared::kAggregateWords];
            perPixel[p] += shared::aggregateSampleCount(shared::kNdfToksvig, w[0], w[4]);
        }
    return perPixel;
}

double displayError(const agaa::RenderResult& a, const agaa::RenderResult& reference) {
    return eng::io::rmse(eng::io::srgbEncoded(a.display), eng::io::srgbEncoded(reference.display));
}

// Algorithm 2's routing sends a whole fragment to one aggregate: the split of a pixel's samples
// between its aggregates changes, but the stencil still admits every visible sample exactly once,
// so each pixel's total equals the per-sample routing's (which equals the metadata's: the replay
// test in test_agaa_gpu.cpp).
TEST(AgaaPathsGpu, FragmentRoutingCountsEveryVisibleSampleOnce) {
    auto device = agaa::test::makeValidatedDevice();
    const uint32_t size = 64;
    for (const char* name : {"furball", "foliage", "railings"}) { // Toksvig layout under auto
        eng::scene::Scene scene = eng::scene::loadTestScene(name);
        agaa::FrameRenderer renderer(*device, scene);
        agaa::RenderRequest samples = agaaRequest(8, 2, size);
        samples.settings.agaa.ndf = agaa::AggregateNdf::Toksvig;
        agaa::RenderRequest fragments = samples;
        fragments.settings.agaa.routing = agaa::AggregateRouting::Fragment;
        std::vector<uint32_t> bySample = agBufferWords(*device, renderer, samples, size * size);
        std::vector<uint32_t> byFragment = agBufferWords(*device, renderer, fragments, size * size);
        EXPECT_EQ(accumulatedPerPixel(byFragment, 2), accumulatedPerPixel(bySample, 2)) << name;
        EXPECT_NE(byFragment, bySample) << name << ": some fragment must straddle two aggregates";

        agaa::RenderResult reference = renderer.render([&] {
            agaa::RenderRequest r = agaaRequest(8, 1, size);
            r.method = "reference";
            return r;
        }());
        double perSample = displayError(renderer.render(samples), reference);
        double perFragment = displayError(renderer.render(fragments), reference);
        std::printf("[ measured ] %-9s AGAA (8,2) display RMSE vs reference: per-sample routing %.5f, "
                    "per-fragment routing %.5f\n",
                    name, perSample, perFragment);
        EXPECT_LT(perFragment, 2.0 * perSample)
            << name << ": Algorithm 2's routing is an approximation, not a failure";
    }
    agaa::test::expectNoValidationErrors(*device);
}

// The default scene's ground, seen at grazing angles near the horizon, spreads a pixel's samples
// over more than k in depth; Equation 1 then splits a flat floor into two aggregates and lights
// it twice. The plane distance keeps those samples together.
TEST(AgaaPathsGpu, PlaneDistanceLightsAFlatFloorOnce) {
    auto device = agaa::test::makeValidatedDevice();
    eng::scene::Scene scene = eng::scene::loadTestScene("default");
    agaa::FrameRenderer renderer(*device, scene);
    agaa::RenderRequest position = agaaRequest(8, 2, 96);
    position.settings.agaa.distance = agaa::AggregateDistance::Position; // the default is the plane distance
    agaa::RenderRequest plane = position;
    plane.settings.agaa.distance = agaa::AggregateDistance::Plane;
    agaa::RenderRequest reference = agaaRequest(8, 1, 96);
    reference.method = "reference";
    agaa::RenderResult ref = renderer.render(reference);
    agaa::RenderResult a = renderer.render(position);
    agaa::RenderResult b = renderer.render(plane);
    std::printf(
        "[ measured ] default AGAA (8,2): events/px %.4f (Equation 1) vs %.4f (plane); display RMSE vs "
        "reference %.5f vs %.5f\n",
        a.shadingEventsMean, b.shadingEventsMean, displayError(a, ref), displayError(b, ref));
    EXPECT_LT(b.shadingEventsMean, a.shadingEventsMean)
        << "the plane distance must merge the floor's samples";

    // A flat quad seen edge-on-ish: every covered pixel is one aggregate under the plane distance.
    eng::scene::Scene grazing = eng::scene::loadTestScene("hard-grazing");
    agaa::FrameRenderer grazingRenderer(*device, grazing);
    agaa::RenderResult g = grazingRenderer.render(plane);
    agaa::RenderResult gp = grazingRenderer.render(position);
    std::printf("[ measured ] hard-grazing AGAA (8,2): events/px %.4f (Equation 1) vs %.4f (plane)\n",
                gp.shadingEventsMean, g.shadingEventsMean);
    EXPECT_LE(g.shadingEventsMean, gp.shadingEventsMean);
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
