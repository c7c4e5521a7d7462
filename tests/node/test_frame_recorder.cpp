// Issue 50: a host without our render graph records a technique's frame into its own command
// buffer (agaa/common/frame_recorder.h), submits it itself, and gets in its own colour image what
// the graph path (FrameInputWriter + HostTargetWriter + FrameRunner, as samples/embed_node.cpp)
// writes there, bit for bit, validation-clean, with two frame slots in flight.

#include "agaa/common/frame_recorder.h"
#include "agaa/methods.h"
#include "engine/frame/frame_runner.h"
#include "engine/frame/gpu_scene.h"
#include "engine/frame/readback.h"
#include "engine/scene/scenegen.h"
#include "engine/vk/check.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/node/host_programs.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

namespace agaa::test {
namespace {

namespace vk = eng::vk;
namespace rg = eng::rg;

constexpr uint32_t kSize = 64;
constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;

// A host's colour image: written by the frame (a blit), then copied out by the host itself.
vk::Image hostImage(vk::Device& device, const char* name) {
    return vk::createImage(
        device,
        {kColorFormat, kSize, kSize, 1, 1, VK_SAMPLE_COUNT_1_BIT,
         VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
         VK_IMAGE_VIEW_TYPE_2D},
        name);
}

HostTarget target(const vk::Image& image, std::optional<rg::Use> final) {
    return {{image.image, image.view, image.view, {kColorFormat, kSize, kSize}}, std::nullopt, final};
}

// The host's copy of its image, recorded after the frame left it in TRANSFER_SRC_OPTIMAL (the
// state it named) and made visible to the transfer stage by the recorder's own last barrier.
void copyOut(VkCommandBuffer cmd, const vk::Image& image, const vk::Buffer& buffer) {
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {kSize, kSize, 1};
    vkCmdCopyImageToBuffer(cmd, image.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.buffer, 1, &region);
}

std::vector<float> read(vk::Device& device, const vk::Buffer& buffer) {
    std::vector<float> out(size_t(kSize) * kSize * 4);
    vk::invalidateBuffer(device, buffer);
    std::memcpy(out.data(), buffer.mapped, out.size() * sizeof(float));
    return out;
}

size_t differentBits(const std::vector<float>& a, const std::vector<float>& b) {
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i)
        n += std::memcmp(&a[i], &b[i], sizeof(float)) != 0 ? 1 : 0;
    return n;
}

class Recorder : public ::testing::TestWithParam<const char*> {};

TEST_P(Recorder, TheHostsCommandBufferGetsTheGraphPathsImageBitForBit) {
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("railings");
    eng::frame::GpuScene gpuScene(*device, scene);
    std::unique_ptr<Technique> node = createTechnique(GetParam(), *device, gpuScene, MethodSettings{});
    eng::frame::ViewSettings view;
    view.width = view.height = kSize;
    eng::frame::ViewSettings turned = view;
    turned.exposure = 2.0f; // the second slot's frame differs, so a slot mix-up shows

    vk::Image graphPath = hostImage(*device, "host.graphPath");
    vk::Image slot0 = hostImage(*device, "host.slot0"), slot1 = hostImage(*device, "host.slot1");
    const auto buffer = [&](const char* name) {
        return eng::frame::createReadbackBuffer(*device, kSize, kSize, kColorFormat, name);
    };
    vk::Buffer expected = buffer("host.expected"), got0 = buffer("host.got0"), got1 = buffer("host.got1"),
               expected1 = buffer("host.expected1");

    // The graph path, once per view.
    {
        FrameInputWriter inputs(*device, gpuScene);
        HostTargetWriter writer(*device);
        eng::frame::FrameRunner runner(*device);
        for (const auto& [v, out] : {std::pair{&view, &expected}, std::pair{&turned, &expected1}}) {
            rg::Graph graph;
            const FrameInputs in = inputs.write(graph, *v, node->samples(), 0);
            const HostTargetVersions written =
                writer.write(graph, node->addPasses(graph, in), in,
                             {target(graphPath, rg::Use::TransferSrc), std::nullopt});
            graph.markOutput(written.color);
            runner.run(graph);
            device->submitAndWait([&](VkCommandBuffer cmd) { copyOut(cmd, graphPath, *out); });
        }
    }

    // The host's own command buffer: both slots recorded before either is submitted.
    FrameRecorder recorder(*device, gpuScene);
    device->submitAndWait([&](VkCommandBuffer cmd) {
        recorder.record(cmd, *node, view, {target(slot0, rg::Use::TransferSrc), std::nullopt}, 0);
        recorder.record(cmd, *node, turned, {target(slot1, rg::Use::TransferSrc), std::nullopt}, 1);
        copyOut(cmd, slot0, got0);
        copyOut(cmd, slot1, got1);
    });
    const std::vector<float> want = read(*device, expected), want1 = read(*device, expected1);
    ASSERT_GT(differentBits(want, want1), want.size() / 10) << "the two views must differ to test anything";
    EXPECT_EQ(differentBits(read(*device, got0), want), 0u) << "slot 0";
    EXPECT_EQ(differentBits(read(*device, got1), want1), 0u) << "slot 1, recorded after slot 0";
    EXPECT_THROW(recorder.record(VK_NULL_HANDLE, *node, view, {target(slot0, std::nullopt), std::nullopt},
                                 FrameRecorder::kMaxSlots),
                 std::out_of_range);
    expectNoValidationErrors(*device);
    for (vk::Image* i : {&graphPath, &slot0, &slot1})
        vk::destroyImage(*device, *i);
    for (vk::Buffer* b : {&expected, &expected1, &got0, &got1})
        vk::destroyBuffer(*device, *b);
}

INSTANTIATE_TEST_SUITE_P(Node, Recorder, ::testing::Values("agaa", "reference"));

// A host's content through its own command buffer: the technique created from the host's traits
// alone (samples/host_engine/host_content.h), its drawer and the stand-in environment handed to
// FrameRecorder::record, its own camera. Its image is what our scene's technique records, bit for
// bit.
TEST(RecorderHostContent, AHostsContentRecordsAsOurScenesDoesBitForBit) {
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("railings");
    eng::frame::GpuScene gpuScene(*device, scene);
    MethodSettings settings; // the one accumulation build the host has (32-bit atomics, no subgroups)
    settings.agaa.atomics = AggregateAtomics::Bits32;
    settings.agaa.subgroupReduction = SubgroupReduction::Off;
    std::unique_ptr<Technique> ours = createTechnique("agaa", *device, gpuScene, settings);
    HostMesh mesh = hostMesh(scene);
    const TechniqueContent content{hostTraits(mesh, scene.lights, "host:railings")};
    HostGeometry host(*device, std::move(mesh), embeddedHostPrograms());
    const eng::frame::GpuEnvironment standIn(*device, nullptr);
    const EnvironmentBindings environment = environmentBindings(standIn);
    std::unique_ptr<Technique> hosts = createTechnique("agaa", *device, content, settings);
    eng::frame::ViewSettings view;
    view.width = view.height = kSize;
    view.cameraOverride = scene.cameras.at(0); // the host's own camera (its traits list none)

    vk::Image oursImage = hostImage(*device, "host.ours"), hostsImage = hostImage(*device, "host.hosts");
    vk::Buffer oursOut =
        eng::frame::createReadbackBuffer(*device, kSize, kSize, kColorFormat, "host.oursOut");
    vk::Buffer hostsOut =
        eng::frame::createReadbackBuffer(*device, kSize, kSize, kColorFormat, "host.hostsOut");
    FrameRecorder ourRecorder(*device, gpuScene), hostRecorder(*device, content);
    device->submitAndWait([&](VkCommandBuffer cmd) {
        ourRecorder.record(cmd, *ours, view, {target(oursImage, rg::Use::TransferSrc), std::nullopt});
        hostRecorder.record(cmd, *hosts, view, {target(hostsImage, rg::Use::TransferSrc), std::nullopt}, 0,
                            {&host, &environment, nullptr});
        copyOut(cmd, oursImage, oursOut);
        copyOut(cmd, hostsImage, hostsOut);
    });
    const std::vector<float> want = read(*device, oursOut), got = read(*device, hostsOut);
    double mean = 0.0;
    for (float v : want)
        mean += v;
    ASSERT_GT(mean / double(want.size()), 0.01) << "the scene must be visible to test anything";
    EXPECT_EQ(differentBits(got, want), 0u);
    EXPECT_THROW(hostRecorder.record(VK_NULL_HANDLE, *hosts, view,
                                     {target(hostsImage, rg::Use::TransferSrc), std::nullopt}),
                 std::invalid_argument)
        << "a frame of the host's content without its drawer";
    expectNoValidationErrors(*device);
    for (vk::Image* i : {&oursImage, &hostsImage})
        vk::destroyImage(*device, *i);
    for (vk::Buffer* b : {&oursOut, &hostsOut})
        vk::destroyBuffer(*device, *b);
}

} // namespace
} // namespace agaa::test
