// Render passes built from declared attachments, and the host-read final state, recorded through
// the mock command recorder: execute() begins dynamic rendering around a graphics pass's callback
// with the views, layouts, load/store ops and clear values the setup declared, sets the full-area
// viewport and scissor, and ends it after the callback; a readback buffer gets a transfer -> host
// barrier after the last pass. No device.

#include "graph_test_support.h"

namespace eng::rg::test {
namespace {

TextureDesc depthDesc(VkFormat format) {
    TextureDesc desc = colorDesc(format);
    desc.layers = 2;
    desc.samples = VK_SAMPLE_COUNT_4_BIT;
    return desc;
}

TextureDesc layered(VkFormat format) {
    TextureDesc desc = depthDesc(format);
    desc.format = format;
    return desc;
}

struct Targets {
    Texture depth, normal, albedo;
};

TEST(GraphRenderPass, BeginsRenderingWithTheDeclaredAttachmentsAroundTheCallback) {
    Graph graph;
    Texture out = graph.importTexture("out", fakeTexture(), std::nullopt, std::nullopt);
    MockRecorder recorder(fakeHandle<VkCommandBuffer>(0x55));
    const Targets& targets = graph.addGraphics<Targets>(
        "gbuffer",
        [&](Builder& b, Targets& d) {
            Attachment clearDepth;
            clearDepth.clear.depthStencil = {0.0f, 7};
            d.depth = b.depthStencil(b.create("depth", depthDesc(VK_FORMAT_D32_SFLOAT_S8_UINT)),
                                     Use::DepthStencilWrite, clearDepth);
            Attachment clearNormal;
            clearNormal.clear.color = {{0.5f, 0.25f, 0.0f, 1.0f}};
            d.normal = b.color(b.create("normal", layered(VK_FORMAT_R8G8_UNORM)), clearNormal);
            Attachment dontStore;
            dontStore.store = VK_ATTACHMENT_STORE_OP_DONT_CARE;
            d.albedo = b.color(b.create("albedo", layered(VK_FORMAT_R8G8B8A8_UNORM)), dontStore);
        },
        [&](const Context&, const Targets&) { recorder.trace.push_back("run gbuffer"); });
    graph.addCompute<NoData>(
        "light",
        [&](Builder& b, NoData&) {
            b.read(targets.depth, Use::SampledCompute);
            b.read(targets.normal, Use::SampledCompute);
            b.read(targets.albedo, Use::SampledCompute);
            out = b.write(out, Use::StorageImageWriteCompute);
        },
        [&](const Context&, const NoData&) { recorder.trace.push_back("run light"); });
    graph.compile();
    FakeAllocator allocator;
    Graph::ExecuteInfo info;
    info.cmd = fakeHandle<VkCommandBuffer>(0x55);
    info.allocator = &allocator;
    info.recorder = &recorder;
    graph.execute(info);

    EXPECT_EQ(trace(recorder.trace),
              "barrier 3i0b,beginRendering 2cds,viewport,run gbuffer,endRendering,barrier 4i0b,run light")
        << "the render pass encloses the callback, after the barriers; the compute pass has none";
    ASSERT_EQ(recorder.renderings.size(), 1u);
    const MockRecorder::RecordedRendering& r = recorder.renderings[0];
    EXPECT_EQ(r.info.renderArea.offset.x, 0);
    EXPECT_EQ(r.info.renderArea.offset.y, 0);
    EXPECT_EQ(r.info.renderArea.extent.width, 64u) << "the attachments' size is the render area";
    EXPECT_EQ(r.info.renderArea.extent.height, 32u);
    EXPECT_EQ(r.info.layerCount, 2u) << "layered attachments render all their layers";
    // FakeAllocator hands out image, view pairs in acquisition order: depth, normal, albedo.
    ASSERT_EQ(r.colors.size(), 2u);
    EXPECT_EQ(r.colors[0].imageView, fakeHandle<VkImageView>(0x1003)) << "location 0 is the first color()";
    EXPECT_EQ(r.colors[1].imageView, fakeHandle<VkImageView>(0x1005));
    for (const VkRenderingAttachmentInfo& c : r.colors) {
        EXPECT_EQ(c.sType, VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO);
        EXPECT_EQ(c.imageLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL)
            << "the layout the graph's barrier produced";
        EXPECT_EQ(c.loadOp, VK_ATTACHMENT_LOAD_OP_CLEAR) << "CLEAR is the default load";
    }
    EXPECT_EQ(r.colors[0].storeOp, VK_ATTACHMENT_STORE_OP_STORE);
    EXPECT_EQ(r.colors[1].storeOp, VK_ATTACHMENT_STORE_OP_DONT_CARE) << "declared store op";
    EXPECT_EQ(r.colors[0].clearValue.color.float32[0], 0.5f) << "declared clear value";
    EXPECT_EQ(r.colors[0].clearValue.color.float32[1], 0.25f);
    ASSERT_TRUE(r.hasDepth);
    EXPECT_EQ(r.depth.imageView, fakeHandle<VkImageView>(0x1001));
    EXPECT_EQ(r.depth.imageLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(r.depth.clearValue.depthStencil.depth, 0.0f);
    EXPECT_EQ(r.depth.clearValue.depthStencil.stencil, 7u);
    ASSERT_TRUE(r.hasStencil) << "D32S8 has a stencil aspect: it is the stencil attachment too";
    EXPECT_EQ(r.stencil.imageView, r.depth.imageView);
    ASSERT_EQ(recorder.viewports.size(), 1u);
    EXPECT_EQ(recorder.viewports[0].width, 64.0f);
    EXPECT_EQ(recorder.viewports[0].height, 32.0f);
    EXPECT_EQ(recorder.viewports[0].minDepth, 0.0f);
    EXPECT_EQ(recorder.viewports[0].maxDepth, 1.0f);
    EXPECT_EQ(recorder.scissors[0].extent.width, 64u);
    EXPECT_EQ(recorder.scissors[0].extent.height, 32u);
    // The barriers before the pass bring every attachment from UNDEFINED into its attachment layout.
    ASSERT_FALSE(recorder.barriers.empty());
    for (const VkImageMemoryBarrier2& barrier : recorder.barriers[0]) {
        EXPECT_EQ(barrier.oldLayout, VK_IMAGE_LAYOUT_UNDEFINED);
        EXPECT_TRUE(barrier.newLayout == VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL ||
                    barrier.newLayout == VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    }
}

TEST(GraphRenderPass, DepthWithoutStencilAspectIsNotTheStencilAttachment) {
    Graph graph;
    Texture map;
    MockRecorder recorder(fakeHandle<VkCommandBuffer>(0x1));
    graph.addGraphics<NoData>(
        "shadow",
        [&](Builder& b, NoData&) {
            map = b.depthStencil(b.create("map", colorDesc(VK_FORMAT_D32_SFLOAT)), Use::DepthStencilWrite);
        },
        nullptr);
    graph.markOutput(map);
    graph.compile();
    FakeAllocator allocator;
    Graph::ExecuteInfo info;
    info.cmd = fakeHandle<VkCommandBuffer>(0x1);
    info.allocator = &allocator;
    info.recorder = &recorder;
    graph.execute(info);
    EXPECT_EQ(trace(recorder.trace), "barrier 1i0b,beginRendering 0cd,viewport,endRendering")
        << "a pass without a callback still gets its (clearing) render pass";
}

TEST(GraphRenderPass, LoadedAttachmentsKeepTheirProducerAndTheLayoutOfTheirUse) {
    Graph graph;
    Texture depth, color;
    MockRecorder recorder(fakeHandle<VkCommandBuffer>(0x2));
    graph.addGraphics<NoData>(
        "prepass",
        [&](Builder& b, NoData&) {
            depth = b.depthStencil(b.create("depth", colorDesc(VK_FORMAT_D24_UNORM_S8_UINT)),
                                   Use::DepthStencilWrite);
        },
        nullptr);
    graph.addGraphics<NoData>(
        "equal",
        [&](Builder& b, NoData&) {
            Attachment load;
            load.load = VK_ATTACHMENT_LOAD_OP_LOAD;
            depth = b.depthStencil(depth, Use::DepthStencilRead, load);
            color = b.color(b.create("color", colorDesc()));
        },
        nullptr);
    graph.addGraphics<NoData>(
        "overlay",
        [&](Builder& b, NoData&) {
            Attachment load;
            load.load = VK_ATTACHMENT_LOAD_OP_LOAD;
            b.depthStencil(depth, Use::DepthReadOnly, load);
            b.read(depth, Use::SampledFragment);
            color = b.color(color, load);
        },
        nullptr);
    graph.markOutput(color);
    graph.compile();
    EXPECT_EQ(trace(graph.executedPassNames()), "prepass,equal,overlay")
        << "LOAD depends on the previous contents, so their producers are not culled";
    FakeAllocator allocator;
    Graph::ExecuteInfo info;
    info.cmd = fakeHandle<VkCommandBuffer>(0x2);
    info.allocator = &allocator;
    info.recorder = &recorder;
    graph.execute(info);
    ASSERT_EQ(recorder.renderings.size(), 3u);
    EXPECT_EQ(recorder.renderings[1].depth.loadOp, VK_ATTACHMENT_LOAD_OP_LOAD);
    EXPECT_EQ(recorder.renderings[1].depth.imageLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(recorder.renderings[2].depth.imageLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL)
        << "depth test plus sampling in one pass: the read-only depth layout";
    EXPECT_EQ(recorder.renderings[2].colors[0].loadOp, VK_ATTACHMENT_LOAD_OP_LOAD);
}

template <class Setup> std::string setupError(Setup setup, PassKind kind = PassKind::Graphics) {
    Graph graph;
    try {
        graph.addPass<NoData>("bad", kind, setup, nullptr);
    } catch (const std::logic_error& error) {
        return error.what();
    }
    return "";
}

TEST(GraphRenderPass, RefusesAttachmentsThatCannotFormOneRenderPass) {
    EXPECT_NE(setupError([](Builder& b, NoData&) { b.color(b.create("c", colorDesc())); }, PassKind::Compute)
                  .find("only graphics passes have attachments"),
              std::string::npos);
    EXPECT_NE(setupError([](Builder& b, NoData&) {
                  b.color(b.create("c", colorDesc()));
                  TextureDesc other = colorDesc();
                  other.width = 65;
                  b.color(b.create("d", other));
              }).find("differs from the render area 64x32x1"),
              std::string::npos);
    EXPECT_NE(setupError([](Builder& b, NoData&) {
                  b.color(b.create("c", colorDesc(VK_FORMAT_D32_SFLOAT)));
              }).find("a depth format; use depthStencil()"),
              std::string::npos);
    EXPECT_NE(setupError([](Builder& b, NoData&) {
                  b.depthStencil(b.create("c", colorDesc()), Use::DepthStencilWrite);
              }).find("not a depth format"),
              std::string::npos);
    EXPECT_NE(setupError([](Builder& b, NoData&) {
                  b.depthStencil(b.create("z", colorDesc(VK_FORMAT_D32_SFLOAT)), Use::SampledFragment);
              }).find("DepthStencilWrite, DepthStencilRead or DepthReadOnly"),
              std::string::npos);
    EXPECT_NE(setupError([](Builder& b, NoData&) {
                  b.depthStencil(b.create("z", colorDesc(VK_FORMAT_D32_SFLOAT)), Use::DepthStencilWrite);
                  b.depthStencil(b.create("z2", colorDesc(VK_FORMAT_D32_SFLOAT)), Use::DepthStencilWrite);
              }).find("already has depth attachment 'z'"),
              std::string::npos);
    EXPECT_NE(setupError([](Builder& b, NoData&) {
                  b.depthStencil(b.create("z", colorDesc(VK_FORMAT_D32_SFLOAT)), Use::DepthReadOnly);
              }).find("its load op must be LOAD"),
              std::string::npos)
        << "a read-only depth attachment cannot clear what it tests against";
}

TEST(GraphHostRead, ReadbackGetsATransferToHostBarrierAfterTheLastPass) {
    Graph graph;
    Texture image = graph.importTexture("image", fakeTexture(), Use::StorageImageWriteCompute, std::nullopt);
    Buffer host = graph.importBuffer("host", fakeBuffer(0x300), std::nullopt, Use::HostRead);
    VkImageLayout copyLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    graph.addPass<NoData>(
        "readback", PassKind::Transfer,
        [&](Builder& b, NoData&) {
            b.read(image, Use::TransferSrc);
            host = b.write(host, Use::TransferDst);
            b.sideEffect();
        },
        [&](const Context& ctx, const NoData&) { copyLayout = ctx.layout(image); });
    graph.compile();
    const std::vector<Barrier>& finals = graph.compiled().finalBarriers;
    ASSERT_EQ(finals.size(), 1u) << "only the host buffer has a final state";
    EXPECT_FALSE(finals[0].isImage);
    EXPECT_EQ(finals[0].resource, graph.resourceIndex(host));
    EXPECT_EQ(finals[0].srcStage, VK_PIPELINE_STAGE_2_TRANSFER_BIT);
    EXPECT_EQ(finals[0].srcAccess, VK_ACCESS_2_TRANSFER_WRITE_BIT) << "the copy's writes made available";
    EXPECT_EQ(finals[0].dstStage, VK_PIPELINE_STAGE_2_HOST_BIT);
    EXPECT_EQ(finals[0].dstAccess, VK_ACCESS_2_HOST_READ_BIT) << "and visible to host reads";

    MockRecorder recorder(fakeHandle<VkCommandBuffer>(0x3));
    Graph::ExecuteInfo info;
    info.cmd = fakeHandle<VkCommandBuffer>(0x3);
    info.recorder = &recorder;
    graph.execute(info);
    EXPECT_EQ(trace(recorder.trace), "barrier 1i1b,barrier 0i1b") << "the pass's barriers, then the host's";
    ASSERT_EQ(recorder.bufferBarriers.back().size(), 1u);
    const VkBufferMemoryBarrier2& recorded = recorder.bufferBarriers.back()[0];
    EXPECT_EQ(recorded.buffer, fakeBuffer(0x300).buffer);
    EXPECT_EQ(recorded.dstStageMask, VK_PIPELINE_STAGE_2_HOST_BIT);
    EXPECT_EQ(recorded.dstAccessMask, VK_ACCESS_2_HOST_READ_BIT);
    EXPECT_EQ(copyLayout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL) << "Context::layout names the copy's layout";
}

TEST(GraphHostRead, IsAFinalStateNotAPassUse) {
    Graph graph;
    Buffer host = graph.importBuffer("host", fakeBuffer(), std::nullopt, std::nullopt);
    try {
        graph.addPass<NoData>(
            "bad", PassKind::Transfer, [&](Builder& b, NoData&) { b.read(host, Use::HostRead); }, nullptr);
        FAIL() << "HostRead inside a pass was accepted";
    } catch (const std::logic_error& error) {
        EXPECT_NE(std::string(error.what()).find("not available in a transfer pass"), std::string::npos)
            << error.what();
    }
    EXPECT_THROW(graph.importTexture("t", fakeTexture(), std::nullopt, Use::HostRead), std::logic_error)
        << "HostRead is for buffers";
}

} // namespace
} // namespace eng::rg::test
