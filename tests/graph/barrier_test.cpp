// Barrier generation: every hazard class, layout transitions, aspects, imported initial/final
// states and usage accumulation, checked on the compiled data without a device.

#include "graph_test_support.h"

namespace eng::rg::test {
namespace {

constexpr VkPipelineStageFlags2 kFragmentTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;

// A compute pass that consumes `buffer` and writes an imported sink so it is never culled.
void addBufferConsumer(Graph& graph, const std::string& name, Buffer buffer, Use use, Buffer& sink) {
    graph.addPass<NoData>(
        name, PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(buffer, use);
            sink = b.write(sink, Use::StorageReadWriteCompute);
        },
        nullptr);
}

TEST(GraphBarriers, ReadAfterWriteStorageBuffer) {
    Graph graph;
    Buffer sink = graph.importBuffer("sink", fakeBuffer(), Use::StorageReadWriteCompute, std::nullopt);
    Buffer data;
    graph.addPass<NoData>(
        "produce", PassKind::Compute,
        [&](Builder& b, NoData&) {
            data = b.write(b.create("data", bufferDesc()), Use::StorageWriteCompute);
        },
        nullptr);
    addBufferConsumer(graph, "consume", data, Use::StorageReadCompute, sink);
    graph.compile();

    const Barrier barrier = onlyBarrierBefore(graph, "consume", graph.resourceIndex(data));
    EXPECT_FALSE(barrier.isImage) << "a buffer gets a buffer barrier";
    EXPECT_EQ(barrier.srcStage, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT) << "wait for the writing dispatch";
    EXPECT_EQ(barrier.dstStage, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT) << "before the reading dispatch";
    EXPECT_EQ(barrier.srcAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT) << "make the storage write available";
    EXPECT_EQ(barrier.dstAccess, VK_ACCESS_2_SHADER_STORAGE_READ_BIT) << "and visible to storage reads";
}

TEST(GraphBarriers, WriteAfterReadWaitsForEveryReader) {
    Graph graph;
    Buffer sink = graph.importBuffer("sink", fakeBuffer(), Use::StorageReadWriteCompute, std::nullopt);
    Buffer data;
    graph.addPass<NoData>(
        "produce", PassKind::Compute,
        [&](Builder& b, NoData&) {
            data = b.write(b.create("data", bufferDesc()), Use::StorageWriteCompute);
        },
        nullptr);
    graph.addPass<NoData>(
        "shade", PassKind::Graphics,
        [&](Builder& b, NoData&) {
            b.read(data, Use::StorageReadFragment);
            sink = b.write(sink, Use::StorageReadWriteFragment);
        },
        nullptr);
    addBufferConsumer(graph, "reduce", data, Use::StorageReadCompute, sink);
    graph.addPass<NoData>(
        "overwrite", PassKind::Compute,
        [&](Builder& b, NoData&) { data = b.write(data, Use::StorageWriteCompute); }, nullptr);
    addBufferConsumer(graph, "consume", data, Use::StorageReadCompute, sink);
    graph.compile();
    ASSERT_EQ(trace(graph.executedPassNames()), "produce,shade,reduce,overwrite,consume");

    const Barrier war = onlyBarrierBefore(graph, "overwrite", graph.resourceIndex(data));
    EXPECT_EQ(war.srcStage & VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT)
        << "the overwrite must wait for the fragment-shader reader";
    EXPECT_EQ(war.srcStage & VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT)
        << "and for the compute reader";
    EXPECT_EQ(war.srcAccess, VK_ACCESS_2_NONE) << "write-after-read needs only an execution dependency: the "
                                                  "readers' barriers made the write available";
    EXPECT_EQ(war.dstAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

TEST(GraphBarriers, WriteAfterWriteMakesFirstWriteAvailable) {
    Graph graph;
    Buffer out = graph.importBuffer("out", fakeBuffer(), std::nullopt, std::nullopt);
    graph.addPass<NoData>(
        "clear", PassKind::Transfer, [&](Builder& b, NoData&) { out = b.write(out, Use::TransferDst); },
        nullptr);
    graph.addPass<NoData>(
        "fill", PassKind::Compute, [&](Builder& b, NoData&) { out = b.write(out, Use::StorageWriteCompute); },
        nullptr);
    graph.compile();
    const Barrier waw = onlyBarrierBefore(graph, "fill", graph.resourceIndex(out));
    EXPECT_EQ(waw.srcStage, VK_PIPELINE_STAGE_2_TRANSFER_BIT);
    EXPECT_EQ(waw.srcAccess, VK_ACCESS_2_TRANSFER_WRITE_BIT)
        << "write-after-write with no reader between must flush the first write";
    EXPECT_EQ(waw.dstAccess, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

TEST(GraphBarriers, ColorAttachmentToSampledComputeChangesLayout) {
    Graph graph;
    Texture out = graph.importTexture("out", fakeTexture(), std::nullopt, std::nullopt);
    Texture color;
    graph.addPass<NoData>(
        "draw", PassKind::Graphics,
        [&](Builder& b, NoData&) { color = b.write(b.create("color", colorDesc()), Use::ColorAttachment); },
        nullptr);
    graph.addPass<NoData>(
        "post", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(color, Use::SampledCompute);
            out = b.write(out, Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.compile();

    const Barrier barrier = onlyBarrierBefore(graph, "post", graph.resourceIndex(color));
    EXPECT_TRUE(barrier.isImage);
    EXPECT_EQ(barrier.oldLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(barrier.newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
        << "sampling needs the read-only layout";
    EXPECT_EQ(barrier.srcStage, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(barrier.dstStage, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(barrier.srcAccess, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT)
        << "only write bits belong in srcAccess";
    EXPECT_EQ(barrier.dstAccess, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    EXPECT_EQ(barrier.aspect, VkImageAspectFlags(VK_IMAGE_ASPECT_COLOR_BIT));
}

TEST(GraphBarriers, FragmentAndComputeReadersAfterOneWriteAreBothCovered) {
    Graph graph;
    Texture out = graph.importTexture("out", fakeTexture(), std::nullopt, std::nullopt);
    Texture color;
    graph.addPass<NoData>(
        "draw", PassKind::Graphics,
        [&](Builder& b, NoData&) { color = b.write(b.create("color", colorDesc()), Use::ColorAttachment); },
        nullptr);
    for (const char* name : {"shade", "reduce", "shadeAgain"}) {
        const bool compute = std::string(name) == "reduce";
        graph.addPass<NoData>(
            name, compute ? PassKind::Compute : PassKind::Graphics,
            [&](Builder& b, NoData&) {
                b.read(color, compute ? Use::SampledCompute : Use::SampledFragment);
                out = b.write(out, compute ? Use::StorageImageReadWriteCompute
                                           : Use::StorageImageReadWriteFragment);
            },
            nullptr);
    }
    graph.compile();
    const uint32_t r = graph.resourceIndex(color);

    const Barrier first = onlyBarrierBefore(graph, "shade", r);
    EXPECT_EQ(first.oldLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(first.newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(first.dstStage, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);

    const Barrier second = onlyBarrierBefore(graph, "reduce", r);
    EXPECT_EQ(second.oldLayout, second.newLayout) << "the layout is already right; no second transition";
    EXPECT_EQ(second.dstStage, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT)
        << "the first barrier only made the write visible to the fragment stage";
    EXPECT_EQ(second.srcStage & VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT)
        << "the compute reader must depend on the writer";
    EXPECT_EQ(second.srcStage & VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
              VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT)
        << "and chain through the stage the layout transition completed before";
    EXPECT_EQ(second.srcAccess, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);

    EXPECT_TRUE(barriersBefore(graph, "shadeAgain", r).empty())
        << "a fragment read already covered since the last write needs no barrier";
}

TEST(GraphBarriers, TransientFirstUseStartsUndefined) {
    Graph graph;
    Texture out = graph.importTexture("out", fakeTexture(), std::nullopt, std::nullopt);
    Texture color;
    graph.addPass<NoData>(
        "draw", PassKind::Graphics,
        [&](Builder& b, NoData&) { color = b.write(b.create("color", colorDesc()), Use::ColorAttachment); },
        nullptr);
    graph.addPass<NoData>(
        "post", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(color, Use::SampledCompute);
            out = b.write(out, Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.compile();

    const Barrier barrier = onlyBarrierBefore(graph, "draw", graph.resourceIndex(color));
    EXPECT_EQ(barrier.oldLayout, VK_IMAGE_LAYOUT_UNDEFINED) << "a transient's old contents are discarded";
    EXPECT_EQ(barrier.newLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(barrier.dstStage, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(barrier.srcStage,
              VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT)
        << "re-executing the graph must wait for the previous execution's last accesses (the compute read, "
           "chained through the transition)";
    EXPECT_EQ(barrier.srcAccess, VK_ACCESS_2_NONE)
        << "contents are discarded, so nothing needs to be flushed";
}

TEST(GraphBarriers, DepthFormatsGetDepthAspects) {
    for (const auto& [format, aspect] :
         {std::pair{VK_FORMAT_D32_SFLOAT, VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT)},
          std::pair{VK_FORMAT_D24_UNORM_S8_UINT,
                    VkImageAspectFlags(VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT)}}) {
        Graph graph;
        Texture out = graph.importTexture("out", fakeTexture(), std::nullopt, std::nullopt);
        Texture depth;
        graph.addPass<NoData>(
            "prepass", PassKind::Graphics,
            [&](Builder& b, NoData&) {
                depth = b.write(b.create("depth", colorDesc(format)), Use::DepthStencilWrite);
            },
            nullptr);
        graph.addPass<NoData>(
            "lighting", PassKind::Graphics,
            [&](Builder& b, NoData&) {
                b.read(depth, Use::DepthReadOnly);
                b.read(depth, Use::SampledFragment);
                out = b.write(out, Use::ColorAttachment);
            },
            nullptr);
        graph.compile();
        const uint32_t r = graph.resourceIndex(depth);
        const Barrier write = onlyBarrierBefore(graph, "prepass", r);
        EXPECT_EQ(write.aspect, aspect)
            << "format " << format << ": barriers must name every aspect of the format";
        EXPECT_EQ(write.newLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL);
        const Barrier read = onlyBarrierBefore(graph, "lighting", r);
        EXPECT_EQ(read.aspect, aspect);
        EXPECT_EQ(read.newLayout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL)
            << "depth test plus sampling the same depth merge into the read-only depth layout";
        EXPECT_EQ(read.dstStage, kFragmentTests | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT)
            << "one merged barrier covers both uses in the pass";
        EXPECT_EQ(read.srcAccess, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    }
}

TEST(GraphBarriers, DepthStencilReadIsSynchronisedAsAWrite) {
    Graph graph;
    Texture out = graph.importTexture("out", fakeTexture(), std::nullopt, std::nullopt);
    Texture depth;
    graph.addPass<NoData>(
        "prepass", PassKind::Graphics,
        [&](Builder& b, NoData&) {
            depth =
                b.write(b.create("depth", colorDesc(VK_FORMAT_D24_UNORM_S8_UINT)), Use::DepthStencilWrite);
        },
        nullptr);
    graph.addPass<NoData>(
        "decals", PassKind::Graphics,
        [&](Builder& b, NoData&) {
            depth = b.readWrite(depth, Use::DepthStencilRead);
            out = b.write(out, Use::ColorAttachment);
        },
        nullptr);
    graph.addPass<NoData>(
        "fog", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(depth, Use::SampledCompute);
            out = b.write(out, Use::StorageImageReadWriteCompute);
        },
        nullptr);
    graph.compile();
    const uint32_t r = graph.resourceIndex(depth);
    const Barrier decals = onlyBarrierBefore(graph, "decals", r);
    EXPECT_EQ(decals.oldLayout, decals.newLayout) << "both uses live in DEPTH_STENCIL_ATTACHMENT_OPTIMAL";
    EXPECT_EQ(decals.srcAccess, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT)
        << "stencil writes after depth writes are write-after-write";
    const Barrier fog = onlyBarrierBefore(graph, "fog", r);
    EXPECT_EQ(fog.srcStage, kFragmentTests) << "fog must wait for the stencil writes of the decal pass";
    EXPECT_EQ(fog.srcAccess, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(fog.newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

TEST(GraphBarriers, TransferFillThenComputeReadUsesTransferStage) {
    Graph graph;
    Buffer sink = graph.importBuffer("sink", fakeBuffer(), std::nullopt, std::nullopt);
    Buffer counter;
    graph.addPass<NoData>(
        "clear", PassKind::Transfer,
        [&](Builder& b, NoData&) { counter = b.write(b.create("counter", bufferDesc(4)), Use::TransferDst); },
        nullptr);
    addBufferConsumer(graph, "count", counter, Use::StorageReadCompute, sink);
    graph.compile();
    const Barrier barrier = onlyBarrierBefore(graph, "count", graph.resourceIndex(counter));
    EXPECT_EQ(barrier.srcStage, VK_PIPELINE_STAGE_2_TRANSFER_BIT)
        << "vkCmdFillBuffer is a TRANSFER-stage write (lavapipe sync validation rejects CLEAR here)";
    EXPECT_EQ(barrier.srcStage & VK_PIPELINE_STAGE_2_CLEAR_BIT, 0u);
    EXPECT_EQ(barrier.srcAccess, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    EXPECT_EQ(barrier.dstStage, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
}

TEST(GraphBarriers, ImportedInitialAndFinalStates) {
    Graph graph;
    Texture target = graph.importTexture("target", fakeTexture(), std::nullopt, Use::TransferSrc);
    Texture history = graph.importTexture("history", fakeTexture(VK_FORMAT_R16G16B16A16_SFLOAT, 0x300),
                                          Use::SampledFragment, std::nullopt);
    graph.addPass<NoData>(
        "draw", PassKind::Graphics,
        [&](Builder& b, NoData&) { target = b.write(target, Use::ColorAttachment); }, nullptr);
    graph.addPass<NoData>(
        "accumulate", PassKind::Compute,
        [&](Builder& b, NoData&) { history = b.write(history, Use::StorageImageWriteCompute); }, nullptr);
    graph.compile();

    const Barrier undefinedStart = onlyBarrierBefore(graph, "draw", graph.resourceIndex(target));
    EXPECT_EQ(undefinedStart.oldLayout, VK_IMAGE_LAYOUT_UNDEFINED) << "initial nullopt: contents undefined";
    EXPECT_EQ(undefinedStart.srcStage, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT)
        << "unknown prior accesses: wait for everything submitted before";

    const Barrier historyStart = onlyBarrierBefore(graph, "accumulate", graph.resourceIndex(history));
    EXPECT_EQ(historyStart.oldLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)
        << "the declared initial use gives the old layout";
    EXPECT_EQ(historyStart.newLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(historyStart.srcStage, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT)
        << "write-after-read against the use before the graph";
    EXPECT_EQ(historyStart.srcAccess, VK_ACCESS_2_NONE);

    const std::vector<Barrier>& finals = graph.compiled().finalBarriers;
    ASSERT_EQ(finals.size(), 1u) << "only the import with a final use gets a final barrier";
    EXPECT_EQ(finals[0].resource, graph.resourceIndex(target));
    EXPECT_EQ(finals[0].oldLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(finals[0].newLayout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    EXPECT_EQ(finals[0].srcStage, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(finals[0].srcAccess, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(finals[0].dstStage, VK_PIPELINE_STAGE_2_TRANSFER_BIT);
    EXPECT_EQ(finals[0].dstAccess, VK_ACCESS_2_TRANSFER_READ_BIT);
}

TEST(GraphBarriers, SwapchainImageEndsInPresent) {
    // The viewer's per-frame copy: an acquired swapchain image (contents discarded) is written by
    // a copy and handed to vkQueuePresentKHR, which the submit's signal semaphore orders.
    Graph graph;
    Texture swapchain = graph.importTexture("swapchain", fakeTexture(), std::nullopt, Use::Present);
    graph.addPass<NoData>(
        "copy", PassKind::Transfer,
        [&](Builder& b, NoData&) { swapchain = b.write(swapchain, Use::TransferDst); }, nullptr);
    graph.compile();

    const Barrier acquire = onlyBarrierBefore(graph, "copy", graph.resourceIndex(swapchain));
    EXPECT_EQ(acquire.srcStage, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT)
        << "the transition must chain with the acquire semaphore's wait, whatever its stage";
    const std::vector<Barrier>& finals = graph.compiled().finalBarriers;
    ASSERT_EQ(finals.size(), 1u) << "the present transition is the import's final barrier";
    EXPECT_EQ(finals[0].oldLayout, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
    EXPECT_EQ(finals[0].newLayout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR) << "vkQueuePresentKHR needs PRESENT_SRC";
    EXPECT_EQ(finals[0].srcStage, VK_PIPELINE_STAGE_2_TRANSFER_BIT) << "after the copy";
    EXPECT_EQ(finals[0].srcAccess, VK_ACCESS_2_TRANSFER_WRITE_BIT)
        << "made available for the presentation engine";
    EXPECT_EQ(finals[0].dstStage, VK_PIPELINE_STAGE_2_NONE) << "the signal semaphore orders the present";
    EXPECT_EQ(finals[0].dstAccess, VK_ACCESS_2_NONE);
}

TEST(GraphBarriers, PresentIsRefusedInPassesAndAsInitialState) {
    Graph graph;
    Texture image = graph.importTexture("image", fakeTexture(), std::nullopt, std::nullopt);
    EXPECT_THROW(
        graph.addPass<NoData>(
            "bad", PassKind::Graphics, [&](Builder& b, NoData&) { b.read(image, Use::Present); }, nullptr),
        std::logic_error)
        << "no pass can present: the use has no stage, so no barrier could order it";
    Graph other;
    EXPECT_THROW(other.importTexture("swapchain", fakeTexture(), Use::Present, std::nullopt),
                 std::logic_error)
        << "an initial Present would give the first barrier no source stage to chain with the acquire";
}

TEST(GraphBarriers, UsageFlagsAccumulateOverUses) {
    Graph graph;
    Buffer readback = graph.importBuffer("readback", fakeBuffer(), std::nullopt, std::nullopt);
    Texture image;
    Buffer args;
    graph.addPass<NoData>(
        "draw", PassKind::Graphics,
        [&](Builder& b, NoData&) { image = b.write(b.create("image", colorDesc()), Use::ColorAttachment); },
        nullptr);
    graph.addPass<NoData>(
        "clearArgs", PassKind::Transfer,
        [&](Builder& b, NoData&) { args = b.write(b.create("args", bufferDesc()), Use::TransferDst); },
        nullptr);
    graph.addPass<NoData>(
        "build", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(image, Use::SampledCompute);
            args = b.readWrite(args, Use::StorageReadWriteCompute);
        },
        nullptr);
    graph.addPass<NoData>(
        "dispatch", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(args, Use::IndirectRead);
            b.read(args, Use::UniformRead);
            readback = b.write(readback, Use::StorageWriteCompute);
        },
        nullptr);
    graph.addPass<NoData>(
        "copy", PassKind::Transfer,
        [&](Builder& b, NoData&) {
            b.read(image, Use::TransferSrc);
            readback = b.write(readback, Use::TransferDst);
        },
        nullptr);
    graph.compile();
    const CompiledGraph& compiled = graph.compiled();
    EXPECT_EQ(compiled.imageUsage[graph.resourceIndex(image)],
              VkImageUsageFlags(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                VK_IMAGE_USAGE_TRANSFER_SRC_BIT))
        << "an image needs every usage any executed pass declared, and no more";
    EXPECT_EQ(compiled.bufferUsage[graph.resourceIndex(args)],
              VkBufferUsageFlags(VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT |
                                 VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT));
    const Barrier dispatch = onlyBarrierBefore(graph, "dispatch", graph.resourceIndex(args));
    EXPECT_EQ(dispatch.dstStage,
              VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT)
        << "UniformRead in a compute pass is a COMPUTE read only, merged with the indirect read";
    EXPECT_EQ(dispatch.dstAccess, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT);
}

} // namespace
} // namespace eng::rg::test
