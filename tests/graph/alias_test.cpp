// Transient aliasing by lifetime: the CPU alias planner (engine/graph/alias_planner.h) and the
// barriers execute() records when an allocator places transients over the same memory, checked
// on the mock command recorder. No device.

#include "engine/graph/alias_planner.h"
#include "graph_test_support.h"

#include <stdexcept>

namespace eng::rg::test {
namespace {

AliasRequest request(VkDeviceSize size, uint32_t first, uint32_t last, VkDeviceSize alignment = 1,
                     uint32_t typeBits = 0x3, uint32_t memoryClass = 0) {
    AliasRequest r;
    r.size = size;
    r.alignment = alignment;
    r.memoryTypeBits = typeBits;
    r.memoryClass = memoryClass;
    r.firstUse = first;
    r.lastUse = last;
    return r;
}

TEST(AliasPlanner, TransientsAliveAtDifferentTimesShareABlock) {
    // a lives in passes 0..1, b in 2..3: disjoint, so b reuses a's bytes; c (1..2) overlaps both.
    const std::vector<AliasRequest> requests = {request(1000, 0, 1), request(800, 2, 3), request(500, 1, 2)};
    const AliasPlan plan = planAliasing(requests);
    ASSERT_EQ(plan.placements.size(), 3u);
    EXPECT_EQ(plan.placements[0].block, plan.placements[1].block) << "disjoint lifetimes share memory";
    EXPECT_EQ(plan.placements[1].offset, 0u);
    EXPECT_TRUE(sharesMemory(plan, requests, 0, 1));
    EXPECT_FALSE(sharesMemory(plan, requests, 0, 2)) << "c is alive together with a";
    EXPECT_FALSE(sharesMemory(plan, requests, 1, 2)) << "and together with b";
    EXPECT_EQ(plan.requestedBytes, 2300u);
    EXPECT_EQ(plan.allocatedBytes, 1500u) << "c does not fit beside a in a's 1000-byte block";
    ASSERT_EQ(plan.blocks.size(), 2u);
    EXPECT_EQ(plan.blocks[plan.placements[0].block].size, 1000u);
}

TEST(AliasPlanner, PacksBesideLiveObjectsAtAlignedOffsets) {
    // e (1024 bytes) lives only in pass 5, so its block is free during passes 0..1, where f, g and
    // h (alignment 256) are alive together: f at 0, g at the first multiple of 256 after f's end,
    // and h no longer fits (1024 + 200 > 1024) and opens a block of its own.
    const std::vector<AliasRequest> requests = {request(1024, 5, 5), request(300, 0, 1, 256),
                                                request(300, 0, 1, 256), request(200, 0, 1, 256)};
    const AliasPlan plan = planAliasing(requests);
    EXPECT_EQ(plan.placements[1].block, plan.placements[0].block);
    EXPECT_EQ(plan.placements[1].offset, 0u);
    EXPECT_EQ(plan.placements[2].block, plan.placements[0].block);
    EXPECT_EQ(plan.placements[2].offset, 512u) << "after f's 300 bytes, aligned up to 256";
    EXPECT_NE(plan.placements[3].block, plan.placements[0].block);
    EXPECT_EQ(plan.allocatedBytes, 1224u);
    EXPECT_EQ(plan.requestedBytes, 1824u);
    for (uint32_t i = 0; i < requests.size(); ++i) {
        for (uint32_t j = 0; j < requests.size(); ++j) {
            const bool together =
                requests[i].firstUse <= requests[j].lastUse && requests[j].firstUse <= requests[i].lastUse;
            if (i != j && together) {
                EXPECT_FALSE(sharesMemory(plan, requests, i, j))
                    << i << " and " << j << " are alive together";
            }
        }
    }
}

TEST(AliasPlanner, NeverMixesClassesOrIncompatibleMemoryTypes) {
    const std::vector<AliasRequest> requests = {request(100, 0, 0, 1, 0x1, 0), request(100, 1, 1, 1, 0x2, 0),
                                                request(100, 2, 2, 1, 0x1, 1), request(100, 3, 3, 1, 0x3, 0)};
    const AliasPlan plan = planAliasing(requests);
    EXPECT_FALSE(sharesMemory(plan, requests, 0, 1)) << "memory types 0x1 and 0x2 have nothing in common";
    EXPECT_FALSE(sharesMemory(plan, requests, 0, 2)) << "images and buffers are different classes";
    EXPECT_TRUE(sharesMemory(plan, requests, 0, 3)) << "0x3 accepts the block's type 0x1";
    EXPECT_EQ(plan.blocks[plan.placements[0].block].memoryTypeBits, 0x1u);
    EXPECT_EQ(plan.allocatedBytes, 300u);
}

TEST(AliasPlanner, RefusesMalformedRequestsWithAMessage) {
    const auto message = [](AliasRequest r) {
        try {
            planAliasing({request(64, 0, 0), r});
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string();
    };
    EXPECT_NE(message(request(0, 0, 0)).find("request 1 has size 0"), std::string::npos);
    EXPECT_NE(message(request(64, 0, 0, 3)).find("alignment 3, not a power of two"), std::string::npos);
    EXPECT_NE(message(request(64, 0, 0, 1, 0)).find("accepts no memory type"), std::string::npos);
    EXPECT_NE(message(request(64, 2, 1)).find("ends (1) before it starts (2)"), std::string::npos);
}

// Places transients with the real planner from made-up requirements (size: 4 bytes a texel),
// as TransientPool does with VkMemoryRequirements.
class AliasingAllocator final : public Allocator {
  public:
    std::vector<TransientAllocation>
    acquireTransients(const std::vector<TransientRequest>& requests) override {
        ++calls;
        seen = requests;
        std::vector<AliasRequest> alias;
        for (const TransientRequest& r : requests)
            alias.push_back(request(r.isImage ? VkDeviceSize(r.textureDesc.width) * r.textureDesc.height * 4
                                              : r.bufferDesc.size,
                                    r.firstUse, r.lastUse, 1, 0x1, r.isImage ? 1 : 0));
        plan = planAliasing(alias);
        std::vector<TransientAllocation> out(requests.size());
        for (size_t i = 0; i < requests.size(); ++i) {
            out[i].memory = plan.placements[i].block;
            out[i].offset = plan.placements[i].offset;
            out[i].size = alias[i].size;
            if (requests[i].isImage) {
                out[i].texture.image = fakeHandle<VkImage>(0x2000 + 2 * i);
                out[i].texture.view = fakeHandle<VkImageView>(0x2001 + 2 * i);
                out[i].texture.desc = requests[i].textureDesc;
            } else {
                out[i].buffer.buffer = fakeHandle<VkBuffer>(0x2000 + 2 * i);
                out[i].buffer.size = requests[i].bufferDesc.size;
            }
        }
        return out;
    }
    PhysicalTexture acquireTexture(const std::string&, const TextureDesc&, VkImageUsageFlags) override {
        ADD_FAILURE() << "the graph acquires all transients in one acquireTransients() call";
        return {};
    }
    PhysicalBuffer acquireBuffer(const std::string&, const BufferDesc&, VkBufferUsageFlags) override {
        ADD_FAILURE() << "the graph acquires all transients in one acquireTransients() call";
        return {};
    }
    void release(const PhysicalTexture&) override { ++released; }
    void release(const PhysicalBuffer&) override { ++released; }
    uint32_t calls = 0, released = 0;
    std::vector<TransientRequest> seen;
    AliasPlan plan;
};

TEST(GraphAliasing, ALaterTransientOnTheSameMemoryWaitsOnTheEarlierOnesAccesses) {
    // first (passes 0..1) and third (2..3) have disjoint lifetimes and share memory; second
    // (1..2) overlaps both and gets its own.
    Graph graph;
    Texture out = graph.importTexture("out", fakeTexture(), std::nullopt, std::nullopt);
    Texture first, second, third;
    graph.addCompute<NoData>(
        "p0",
        [&](Builder& b, NoData&) {
            first = b.write(b.create("first", colorDesc()), Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.addGraphics<NoData>(
        "p1",
        [&](Builder& b, NoData&) {
            b.read(first, Use::SampledFragment);
            second = b.color(b.create("second", colorDesc()));
        },
        nullptr);
    graph.addCompute<NoData>(
        "p2",
        [&](Builder& b, NoData&) {
            b.read(second, Use::SampledCompute);
            third = b.write(b.create("third", colorDesc()), Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.addCompute<NoData>(
        "p3",
        [&](Builder& b, NoData&) {
            b.read(third, Use::SampledCompute);
            out = b.write(out, Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.compile();
    AliasingAllocator allocator;
    MockRecorder recorder(fakeHandle<VkCommandBuffer>(0x5));
    Graph::ExecuteInfo info;
    info.cmd = fakeHandle<VkCommandBuffer>(0x5);
    info.allocator = &allocator;
    info.recorder = &recorder;
    graph.execute(info);

    ASSERT_EQ(allocator.calls, 1u);
    ASSERT_EQ(allocator.seen.size(), 3u);
    EXPECT_EQ(allocator.seen[0].name, "first");
    EXPECT_EQ(allocator.seen[0].firstUse, 0u) << "lifetimes are positions in execution order";
    EXPECT_EQ(allocator.seen[0].lastUse, 1u);
    EXPECT_EQ(allocator.seen[1].firstUse, 1u);
    EXPECT_EQ(allocator.seen[1].lastUse, 2u);
    EXPECT_EQ(allocator.seen[2].firstUse, 2u);
    EXPECT_EQ(allocator.seen[2].lastUse, 3u);
    ASSERT_EQ(allocator.plan.placements[0].block, allocator.plan.placements[2].block)
        << "the planner put first and third on the same bytes";
    ASSERT_EQ(allocator.plan.placements[2].offset, 0u);
    ASSERT_NE(allocator.plan.placements[1].block, allocator.plan.placements[0].block);

    // Recorded barriers, in pass order: p0 [first], p1 [first, second], p2 [second, third], p3 [third, out].
    ASSERT_EQ(recorder.barriers.size(), 4u);
    const auto find = [&](size_t call, VkImage image) -> const VkImageMemoryBarrier2* {
        for (const VkImageMemoryBarrier2& barrier : recorder.barriers[call])
            if (barrier.image == image) return &barrier;
        return nullptr;
    };
    const VkImage firstImage = fakeHandle<VkImage>(0x2000), thirdImage = fakeHandle<VkImage>(0x2004);
    const VkImageMemoryBarrier2* thirdStart = find(2, thirdImage);
    ASSERT_NE(thirdStart, nullptr);
    EXPECT_EQ(thirdStart->oldLayout, VK_IMAGE_LAYOUT_UNDEFINED) << "a new user discards the bytes' contents";
    EXPECT_EQ(thirdStart->newLayout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_NE(thirdStart->srcStageMask & VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0u)
        << "waits on first's compute write";
    EXPECT_NE(thirdStart->srcStageMask & VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, 0u)
        << "and on first's fragment-shader read (write after read on the same bytes)";
    EXPECT_NE(thirdStart->srcAccessMask & VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, 0u)
        << "first's write is made available before third overwrites the bytes";
    EXPECT_EQ(thirdStart->srcAccessMask & VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, 0u)
        << "reads need no availability";

    // And the other way round for the next execution: first's start waits on third's accesses.
    const VkImageMemoryBarrier2* firstStart = find(0, firstImage);
    ASSERT_NE(firstStart, nullptr);
    EXPECT_NE(firstStart->srcStageMask & VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, 0u);
    EXPECT_NE(firstStart->srcAccessMask & VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, 0u);

    // second shares with nobody: its start is exactly what compile() baked.
    const VkImageMemoryBarrier2* secondStart = find(1, fakeHandle<VkImage>(0x2002));
    ASSERT_NE(secondStart, nullptr);
    const Barrier baked = onlyBarrierBefore(graph, "p1", graph.resourceIndex(second));
    EXPECT_EQ(secondStart->srcStageMask, baked.srcStage);
    EXPECT_EQ(secondStart->srcAccessMask, baked.srcAccess);

    graph.releaseTransients();
    EXPECT_EQ(allocator.released, 3u);
}

TEST(GraphAliasing, WithoutSharedMemoryTheBakedBarriersAreRecordedUnchanged) {
    Graph graph;
    Texture out = graph.importTexture("out", fakeTexture(), std::nullopt, std::nullopt);
    Texture a;
    graph.addCompute<NoData>(
        "p0",
        [&](Builder& b, NoData&) { a = b.write(b.create("a", colorDesc()), Use::StorageImageWriteCompute); },
        nullptr);
    graph.addCompute<NoData>(
        "p1",
        [&](Builder& b, NoData&) {
            b.read(a, Use::SampledCompute);
            out = b.write(out, Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.compile();
    FakeAllocator allocator; // the default acquireTransients(): memory of its own for each
    MockRecorder recorder(fakeHandle<VkCommandBuffer>(0x6));
    Graph::ExecuteInfo info;
    info.cmd = fakeHandle<VkCommandBuffer>(0x6);
    info.allocator = &allocator;
    info.recorder = &recorder;
    graph.execute(info);
    const Barrier baked = onlyBarrierBefore(graph, "p0", graph.resourceIndex(a));
    ASSERT_EQ(recorder.barriers.size(), 2u);
    ASSERT_EQ(recorder.barriers[0].size(), 1u);
    EXPECT_EQ(recorder.barriers[0][0].srcStageMask, baked.srcStage);
    EXPECT_EQ(recorder.barriers[0][0].srcAccessMask, baked.srcAccess);
}

} // namespace
} // namespace eng::rg::test
