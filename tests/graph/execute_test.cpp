// execute()'s recording, on a mock command recorder (engine/graph/recorder.h), without a device:
// per executed pass, in compiled order, the debug label, one pipeline barrier holding exactly the
// pass's compiled barriers translated field for field onto the physical objects (transients from
// the allocator, imports as handed in; whole images and buffers, no queue-family transfer), the
// timestamps around the pass's own commands, and the final-state barriers last; culled passes
// record nothing.

#include "graph_test_support.h"

#include <map>

namespace eng::rg::test {
namespace {

std::vector<std::string>* gTrace = nullptr; // the label callbacks are plain function pointers

void beginLabel(VkCommandBuffer, const VkDebugUtilsLabelEXT* label) {
    gTrace->push_back(std::string("label+ ") + label->pLabelName);
}
void endLabel(VkCommandBuffer) {
    gTrace->push_back("label-");
}

TEST(GraphExecute, RecordsTheCompiledBarriersLabelsAndTimestampsInOrder) {
    Graph graph;
    const PhysicalTexture targetImage = fakeTexture(VK_FORMAT_R16G16B16A16_SFLOAT, 0x100);
    Texture target = graph.importTexture("target", targetImage, std::nullopt, Use::TransferSrc);
    Texture color;
    Buffer counts;
    MockRecorder* recorderPtr = nullptr;
    auto run = [&](const char* name) {
        return [&, name](const Context& ctx, const NoData&) {
            EXPECT_EQ(ctx.cmd(), fakeHandle<VkCommandBuffer>(0x55)) << name;
            recorderPtr->trace.push_back(std::string("run ") + name);
        };
    };
    graph.addPass<NoData>(
        "raster", PassKind::Graphics,
        [&](Builder& b, NoData&) {
            color = b.write(b.create("color", colorDesc()), Use::ColorAttachment);
            counts = b.write(b.create("counts", bufferDesc()), Use::StorageReadWriteFragment);
        },
        run("raster"));
    graph.addPass<NoData>(
        "unused", PassKind::Compute,
        [&](Builder& b, NoData&) { b.write(b.create("scratch", bufferDesc()), Use::StorageWriteCompute); },
        run("unused"));
    graph.addPass<NoData>(
        "resolve", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(color, Use::SampledCompute);
            b.read(counts, Use::StorageReadCompute);
            target = b.write(target, Use::StorageImageWriteCompute);
        },
        run("resolve"));
    graph.compile();

    FakeAllocator allocator;
    MockRecorder recorder(fakeHandle<VkCommandBuffer>(0x55));
    recorderPtr = &recorder;
    gTrace = &recorder.trace;
    Graph::ExecuteInfo info;
    info.cmd = fakeHandle<VkCommandBuffer>(0x55);
    info.allocator = &allocator;
    info.queryPool = fakeHandle<VkQueryPool>(0x77);
    info.firstQuery = 4;
    info.beginLabel = beginLabel;
    info.endLabel = endLabel;
    info.recorder = &recorder;
    graph.execute(info);
    gTrace = nullptr;

    EXPECT_EQ(trace(recorder.trace), "label+ raster,barrier 1i1b,timestamp 4,run raster,timestamp 5,label-,"
                                     "label+ resolve,barrier 2i1b,timestamp 6,run resolve,timestamp 7,label-,"
                                     "label+ rg.finalState,barrier 1i0b,label-")
        << "order of execute()'s commands (the culled pass records nothing)";
    EXPECT_EQ(allocator.acquiredNames(), "color,counts") << "transients of executed passes only";

    // Physical objects: transients from the allocator, the import as handed in.
    std::map<uint32_t, VkImage> images = {{graph.resourceIndex(target), targetImage.image}};
    std::map<uint32_t, VkBuffer> buffers;
    std::vector<const std::vector<Barrier>*> compiledBarriers;
    for (const CompiledPass& p : graph.compiled().order)
        if (!p.barriers.empty()) compiledBarriers.push_back(&p.barriers);
    compiledBarriers.push_back(&graph.compiled().finalBarriers);
    ASSERT_EQ(recorder.barriers.size(), compiledBarriers.size());
    // The allocator handed out 0x1000 (image), 0x1001 (view) for color, then 0x1002 for counts.
    images[graph.resourceIndex(color)] = fakeHandle<VkImage>(0x1000);
    buffers[graph.resourceIndex(counts)] = fakeHandle<VkBuffer>(0x1002);
    for (size_t call = 0; call < compiledBarriers.size(); ++call) {
        size_t img = 0, buf = 0;
        for (const Barrier& b : *compiledBarriers[call]) {
            if (b.isImage) {
                ASSERT_LT(img, recorder.barriers[call].size());
                const VkImageMemoryBarrier2& r = recorder.barriers[call][img++];
                EXPECT_EQ(r.sType, VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2);
                EXPECT_EQ(r.image, images.at(b.resource)) << graph.resourceName(b.resource);
                EXPECT_EQ(r.srcStageMask, b.srcStage);
                EXPECT_EQ(r.srcAccessMask, b.srcAccess);
                EXPECT_EQ(r.dstStageMask, b.dstStage);
                EXPECT_EQ(r.dstAccessMask, b.dstAccess);
                EXPECT_EQ(r.oldLayout, b.oldLayout);
                EXPECT_EQ(r.newLayout, b.newLayout);
                EXPECT_EQ(r.srcQueueFamilyIndex, VK_QUEUE_FAMILY_IGNORED);
                EXPECT_EQ(r.dstQueueFamilyIndex, VK_QUEUE_FAMILY_IGNORED);
                EXPECT_EQ(r.subresourceRange.aspectMask, b.aspect);
                EXPECT_EQ(r.subresourceRange.baseMipLevel, 0u);
                EXPECT_EQ(r.subresourceRange.levelCount, VK_REMAINING_MIP_LEVELS);
                EXPECT_EQ(r.subresourceRange.baseArrayLayer, 0u);
                EXPECT_EQ(r.subresourceRange.layerCount, VK_REMAINING_ARRAY_LAYERS);
            } else {
                ASSERT_LT(buf, recorder.bufferBarriers[call].size());
                const VkBufferMemoryBarrier2& r = recorder.bufferBarriers[call][buf++];
                EXPECT_EQ(r.sType, VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2);
                EXPECT_EQ(r.buffer, buffers.at(b.resource)) << graph.resourceName(b.resource);
                EXPECT_EQ(r.srcStageMask, b.srcStage);
                EXPECT_EQ(r.srcAccessMask, b.srcAccess);
                EXPECT_EQ(r.dstStageMask, b.dstStage);
                EXPECT_EQ(r.dstAccessMask, b.dstAccess);
                EXPECT_EQ(r.offset, 0u);
                EXPECT_EQ(r.size, VK_WHOLE_SIZE);
                EXPECT_EQ(r.srcQueueFamilyIndex, VK_QUEUE_FAMILY_IGNORED);
                EXPECT_EQ(r.dstQueueFamilyIndex, VK_QUEUE_FAMILY_IGNORED);
            }
        }
    }
    // And what those barriers mean, written out by hand for the two that matter: the colour
    // target turns from attachment into a sampled image for the compute pass, and the import is
    // left in its requested final state.
    const VkImageMemoryBarrier2* sampled = nullptr;
    for (const VkImageMemoryBarrier2& r : recorder.barriers[1])
        if (r.image == fakeHandle<VkImage>(0x1000)) sampled = &r;
    ASSERT_NE(sampled, nullptr) << "no barrier on the colour target before resolve";
    EXPECT_EQ(sampled->oldLayout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(sampled->newLayout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(sampled->srcStageMask, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(sampled->srcAccessMask, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(sampled->dstStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_NE(sampled->dstAccessMask & VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, 0u);
    ASSERT_EQ(recorder.barriers.back().size(), 1u);
    const VkImageMemoryBarrier2& final = recorder.barriers.back()[0];
    EXPECT_EQ(final.image, targetImage.image);
    EXPECT_EQ(final.oldLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(final.newLayout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    EXPECT_EQ(final.srcStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(final.srcAccessMask, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
    EXPECT_EQ(final.dstStageMask, VK_PIPELINE_STAGE_2_TRANSFER_BIT);
    EXPECT_EQ(final.dstAccessMask, VK_ACCESS_2_TRANSFER_READ_BIT);
}

TEST(GraphExecute, WithoutTimestampsOrLabelsRecordsOnlyBarriersAndPasses) {
    Graph graph;
    Buffer sink = graph.importBuffer("sink", fakeBuffer(), Use::StorageReadWriteCompute, std::nullopt);
    MockRecorder recorder(fakeHandle<VkCommandBuffer>(0x9));
    graph.addPass<NoData>(
        "only", PassKind::Compute,
        [&](Builder& b, NoData&) { sink = b.write(sink, Use::StorageReadWriteCompute); },
        [&](const Context&, const NoData&) { recorder.trace.push_back("run only"); });
    graph.compile();
    Graph::ExecuteInfo info;
    info.cmd = fakeHandle<VkCommandBuffer>(0x9);
    info.recorder = &recorder;
    graph.execute(info);
    // The import's previous use was a compute read-write: the pass waits for it (write after write).
    EXPECT_EQ(trace(recorder.trace), "barrier 0i1b,run only");
    ASSERT_EQ(recorder.bufferBarriers.size(), 1u);
    EXPECT_EQ(recorder.bufferBarriers[0][0].buffer, fakeBuffer().buffer);
}

} // namespace
} // namespace eng::rg::test
