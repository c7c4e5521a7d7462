// Issue 18: one node records several views or frames before any executes. Each must equal the
// same view rendered alone, bit for bit: before the per-frame ring, AGAA's constants and the
// shadow fit were one buffer rewritten by every addPasses, so an earlier view silently rendered
// with a later view's constants (7,818 of 36,864 values differed, 0 validation errors).

#include "agaa/common/frame_inputs.h"
#include "agaa/methods.h"
#include "engine/frame/frame_runner.h"
#include "engine/frame/uniform_ring.h"
#include "engine/scene/scenegen.h"
#include "engine/vk/check.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/node/node_test_support.h"

#include <algorithm>
#include <array>
#include <memory>

namespace agaa::test {
namespace {

namespace vk = eng::vk;
namespace rg = eng::rg;

constexpr uint32_t kSize = 64;

// View i of the railings (its sun casts shadows, so the shadow fit follows each camera): an
// orbit of 20 degrees per view and a different exposure, so every per-frame constant differs.
eng::frame::ViewSettings orbitView(const eng::scene::Scene& scene, uint32_t i) {
    eng::frame::ViewSettings v;
    v.width = v.height = kSize;
    v.viewOverride = eng::frame::orbitView(scene.cameras.at(0).view,
                                           0.5f * (scene.bounds.min + scene.bounds.max), 20.0f * float(i));
    v.exposure = 1.0f + 0.25f * float(i);
    return v;
}

bool ran(const rg::Graph& graph, const std::string& pass) {
    const std::vector<std::string> names = graph.executedPassNames();
    return std::count(names.begin(), names.end(), pass) > 0;
}

std::vector<float> renderAlone(vk::Device& device, Technique& technique, const eng::frame::GpuScene& gpuScene,
                               const eng::frame::ViewSettings& view) {
    HostView host(device, gpuScene.scene(), view, technique.samples());
    rg::Graph graph;
    host.record(graph, technique, 0, "solo");
    eng::frame::FrameRunner runner(device);
    runner.run(graph);
    return host.read();
}

class TwoViews : public ::testing::TestWithParam<const char*> {};

TEST_P(TwoViews, OneGraphEqualsEachSoloRenderBitForBit) {
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("railings");
    eng::frame::GpuScene gpuScene(*device, scene);
    MethodSettings settings; // n = 8, c = 2
    std::unique_ptr<Technique> node = createTechnique(GetParam(), *device, gpuScene, settings);
    const eng::frame::ViewSettings viewA = orbitView(scene, 0), viewB = orbitView(scene, 1);
    const std::vector<float> soloA = renderAlone(*device, *node, gpuScene, viewA);
    const std::vector<float> soloB = renderAlone(*device, *node, gpuScene, viewB);
    ASSERT_GT(countDifferentBits(soloA, soloB), soloA.size() / 10)
        << "the two views must differ to test anything";

    HostView a(*device, scene, viewA, node->samples()), b(*device, scene, viewB, node->samples());
    rg::Graph graph;
    a.record(graph, *node, 0, "viewA");
    b.record(graph, *node, 1, "viewB");
    eng::frame::FrameRunner runner(*device);
    runner.run(graph);
    EXPECT_TRUE(ran(graph, std::string(GetParam()) + ".shadow") || ran(graph, "agaa.shadow"))
        << "the shadow pass's per-view constants are part of what this test guards";
    EXPECT_EQ(countDifferentBits(a.read(), soloA), 0u) << "view A recorded before view B, then both executed";
    EXPECT_EQ(countDifferentBits(b.read(), soloB), 0u) << "view B recorded after view A in the same graph";
    expectNoValidationErrors(*device);
}

INSTANTIATE_TEST_SUITE_P(Node, TwoViews, ::testing::Values("agaa", "reference"));

// The host-side FrameInputWriter keeps each slot's frame constants and lights apart too, and
// takes a host's own camera: the scene camera handed in as a host camera renders the same frame.
TEST(NodeFrameInputWriter, HostCamerasInTwoSlotsOfOneGraphEqualTheirSoloRenders) {
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("railings");
    eng::frame::GpuScene gpuScene(*device, scene);
    std::unique_ptr<Technique> node = createTechnique("agaa", *device, gpuScene, MethodSettings{});
    std::array<eng::frame::ViewSettings, 2> views = {orbitView(scene, 0), orbitView(scene, 1)};
    std::array<std::vector<float>, 2> solo;
    for (uint32_t v = 0; v < 2; ++v)
        solo[v] = renderAlone(*device, *node, gpuScene, views[v]);
    agaa::FrameInputWriter writer(*device, gpuScene);
    std::array<vk::Buffer, 2> display;
    rg::Graph graph;
    for (uint32_t v = 0; v < 2; ++v) {
        views[v].cameraOverride = scene.cameras.at(0); // the host's camera: view replaced by the orbit
        const FrameInputs in = writer.write(graph, views[v], node->samples(), v);
        display[v] = eng::frame::createReadbackBuffer(*device, kSize, kSize, VK_FORMAT_R32G32B32A32_SFLOAT,
                                                      "test.display");
        eng::frame::addReadbackPass(graph, node->addPasses(graph, in).display, display[v],
                                    "view" + std::to_string(v) + ".readback");
    }
    eng::frame::FrameRunner(*device).run(graph);
    for (uint32_t v = 0; v < 2; ++v) {
        vk::invalidateBuffer(*device, display[v]);
        const auto* got = static_cast<const float*>(display[v].mapped);
        const std::vector<float> displayOnly(got, got + size_t(kSize) * kSize * 4);
        const std::vector<float> want(solo[v].begin() + solo[v].size() / 2, solo[v].end());
        EXPECT_EQ(countDifferentBits(displayOnly, want), 0u) << "view " << v;
        vk::destroyBuffer(*device, display[v]);
    }
    eng::frame::ViewSettings bad = views[0];
    bad.cameraOverride->yfov = 0.0f;
    rg::Graph refused;
    EXPECT_THROW(writer.write(refused, bad, node->samples(), 0), std::invalid_argument)
        << "a host camera with yfov 0 would make a NaN projection";
    expectNoValidationErrors(*device);
}

TEST(NodeFrameSlots, AreRefusedWhenReusedInOneGraphOrOutOfRange) {
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("railings");
    eng::frame::GpuScene gpuScene(*device, scene);
    std::unique_ptr<Technique> node = createTechnique("agaa", *device, gpuScene, MethodSettings{});
    HostView a(*device, scene, orbitView(scene, 0), node->samples());
    HostView b(*device, scene, orbitView(scene, 1), node->samples());
    {
        rg::Graph graph;
        a.record(graph, *node, 2, "viewA");
        // Both views in slot 2 would read one buffer holding view B's constants.
        EXPECT_THROW(b.record(graph, *node, 2, "viewB"), std::logic_error);
    }
    {
        rg::Graph graph;
        EXPECT_THROW(a.record(graph, *node, eng::frame::UniformRing::kMaxSlots, "viewA"), std::out_of_range);
    }
    expectNoValidationErrors(*device);
}

// Three frames recorded into three command buffers and submitted back to back without waiting,
// as an engine with three frames in flight runs; sync validation watches the queue.
TEST(NodeFramesInFlight, ThreeSubmittedWithoutWaitingEqualEachSoloFrame) {
    constexpr uint32_t kFrames = 3;
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("railings");
    eng::frame::GpuScene gpuScene(*device, scene);
    std::unique_ptr<Technique> node = createTechnique("agaa", *device, gpuScene, MethodSettings{});
    std::array<std::vector<float>, kFrames> solo;
    for (uint32_t f = 0; f < kFrames; ++f)
        solo[f] = renderAlone(*device, *node, gpuScene, orbitView(scene, f));

    std::array<std::unique_ptr<HostView>, kFrames> hosts;
    std::array<rg::Graph, kFrames> graphs;
    eng::frame::TransientPool pool(*device); // each graph in flight holds its own transients
    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.queueFamilyIndex = device->queueFamily();
    VkCommandPool commandPool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateCommandPool(device->device(), &poolInfo, nullptr, &commandPool));
    std::array<VkCommandBuffer, kFrames> cmds{};
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = commandPool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = kFrames;
    VK_CHECK(vkAllocateCommandBuffers(device->device(), &alloc, cmds.data()));
    std::array<VkFence, kFrames> fences{};
    for (uint32_t f = 0; f < kFrames; ++f) {
        VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
        VK_CHECK(vkCreateFence(device->device(), &fenceInfo, nullptr, &fences[f]));
        hosts[f] = std::make_unique<HostView>(*device, scene, orbitView(scene, f), node->samples());
        // Frame f in flight uses ring slot f; all three are recorded before any is submitted.
        hosts[f]->record(graphs[f], *node, f, "frame" + std::to_string(f));
        graphs[f].compile();
        VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VK_CHECK(vkBeginCommandBuffer(cmds[f], &begin));
        rg::Graph::ExecuteInfo info;
        info.cmd = cmds[f];
        info.allocator = &pool;
        graphs[f].execute(info);
        VK_CHECK(vkEndCommandBuffer(cmds[f]));
    }
    for (uint32_t f = 0; f < kFrames; ++f) {
        VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
        cmdInfo.commandBuffer = cmds[f];
        VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
        submit.commandBufferInfoCount = 1;
        submit.pCommandBufferInfos = &cmdInfo;
        VK_CHECK(vkQueueSubmit2(device->queue(), 1, &submit, fences[f]));
    }
    VK_CHECK(vkWaitForFences(device->device(), kFrames, fences.data(), VK_TRUE, UINT64_MAX));
    for (uint32_t f = 0; f < kFrames; ++f) {
        graphs[f].releaseTransients();
        EXPECT_TRUE(ran(graphs[f], "agaa.shadow")) << "frame " << f << ": the shadow fit is per frame";
        EXPECT_EQ(countDifferentBits(hosts[f]->read(), solo[f]), 0u)
            << "frame " << f << " of " << kFrames << " in flight against the same frame rendered alone";
    }
    for (VkFence fence : fences)
        vkDestroyFence(device->device(), fence, nullptr);
    vkDestroyCommandPool(device->device(), commandPool, nullptr);
    expectNoValidationErrors(*device);
}

} // namespace
} // namespace agaa::test
