// Culling (Filament reference counting), execution order as trace strings (vuk style), and
// which transients get realised.

#include "graph_test_support.h"

namespace eng::rg::test {
namespace {

struct Frame {
    Texture depth, hdr, unusedA, unusedB;
    Buffer clusters;
};

// prepass -> cluster -> lighting -> imported hdr, with a two-pass dead branch declared in the
// middle so that culling has to look past declaration order.
void buildFrame(Graph& graph, Frame& frame) {
    frame.hdr = graph.importTexture("hdr", fakeTexture(), std::nullopt, Use::SampledFragment);
    graph.addPass<NoData>(
        "prepass", PassKind::Graphics,
        [&](Builder& b, NoData&) {
            TextureDesc desc = colorDesc(VK_FORMAT_D32_SFLOAT);
            frame.depth = b.write(b.create("depth", desc), Use::DepthStencilWrite);
        },
        nullptr);
    graph.addPass<NoData>(
        "debugA", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(frame.depth, Use::SampledCompute);
            frame.unusedA = b.write(b.create("debugA.out", colorDesc()), Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.addPass<NoData>(
        "cluster", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(frame.depth, Use::SampledCompute);
            frame.clusters = b.write(b.create("clusters", bufferDesc()), Use::StorageWriteCompute);
        },
        nullptr);
    graph.addPass<NoData>(
        "debugB", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(frame.unusedA, Use::SampledCompute);
            frame.unusedB = b.write(b.create("debugB.out", colorDesc()), Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.addPass<NoData>(
        "lighting", PassKind::Graphics,
        [&](Builder& b, NoData&) {
            b.read(frame.depth, Use::DepthReadOnly);
            b.read(frame.clusters, Use::StorageReadFragment);
            frame.hdr = b.write(frame.hdr, Use::ColorAttachment);
        },
        nullptr);
}

TEST(GraphCulling, UnusedChainIsCulledAndOrderSkipsIt) {
    Graph graph;
    Frame frame;
    buildFrame(graph, frame);
    graph.compile();
    EXPECT_EQ(trace(graph.culledPassNames()), "debugA,debugB")
        << "a chain whose last output nobody reads must be culled entirely, including its head";
    EXPECT_EQ(trace(graph.executedPassNames()), "prepass,cluster,lighting")
        << "execution order is declaration order minus culled passes";
    EXPECT_TRUE(graph.compiled().order.size() + graph.compiled().culled.size() == graph.passCount())
        << "every pass is either executed or culled";
}

TEST(GraphCulling, PassWritingOnlyAnUnreadTransientIsCulled) {
    Graph graph;
    graph.addPass<NoData>(
        "orphan", PassKind::Compute,
        [&](Builder& b, NoData&) { b.write(b.create("scratch", bufferDesc()), Use::StorageWriteCompute); },
        nullptr);
    graph.compile();
    EXPECT_EQ(trace(graph.culledPassNames()), "orphan") << "a write nobody reads has no observable effect";
    EXPECT_EQ(trace(graph.executedPassNames()), "");
}

TEST(GraphCulling, SideEffectPassIsKeptWithItsProducers) {
    Graph graph;
    Buffer stats;
    graph.addPass<NoData>(
        "produce", PassKind::Compute,
        [&](Builder& b, NoData&) {
            stats = b.write(b.create("stats", bufferDesc()), Use::StorageWriteCompute);
        },
        nullptr);
    graph.addPass<NoData>(
        "printStats", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(stats, Use::StorageReadCompute);
            b.sideEffect();
        },
        nullptr);
    graph.compile();
    EXPECT_EQ(trace(graph.executedPassNames()), "produce,printStats")
        << "sideEffect() keeps a pass that writes nothing, and its reads keep the producer alive";
    EXPECT_TRUE(graph.culledPassNames().empty());
}

TEST(GraphCulling, PassFeedingImportedOutputIsKept) {
    Graph graph;
    Buffer readback = graph.importBuffer("readback", fakeBuffer(), std::nullopt, std::nullopt);
    Buffer histogram;
    graph.addPass<NoData>(
        "histogram", PassKind::Compute,
        [&](Builder& b, NoData&) {
            histogram = b.write(b.create("histogram", bufferDesc()), Use::StorageWriteCompute);
        },
        nullptr);
    graph.addPass<NoData>(
        "copyOut", PassKind::Transfer,
        [&](Builder& b, NoData&) {
            b.read(histogram, Use::TransferSrc);
            b.write(readback, Use::TransferDst);
        },
        nullptr);
    graph.compile();
    EXPECT_EQ(trace(graph.executedPassNames()), "histogram,copyOut")
        << "writing an imported resource is observable outside the graph";
}

TEST(GraphCulling, MarkOutputKeepsTransientProducer) {
    Graph graph;
    Texture ao;
    graph.addPass<NoData>(
        "ao", PassKind::Compute,
        [&](Builder& b, NoData&) {
            ao = b.write(b.create("ao", colorDesc()), Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.markOutput(ao);
    graph.compile();
    EXPECT_EQ(trace(graph.executedPassNames()), "ao") << "markOutput() must keep the producing pass";
}

TEST(GraphCulling, ReadModifyWriteKeepsPreviousProducer) {
    // write() with a read-modify-write use depends on the old contents, exactly like readWrite().
    Graph graph;
    Buffer out = graph.importBuffer("out", fakeBuffer(), std::nullopt, std::nullopt);
    Buffer counter;
    graph.addPass<NoData>(
        "clear", PassKind::Transfer,
        [&](Builder& b, NoData&) { counter = b.write(b.create("counter", bufferDesc(4)), Use::TransferDst); },
        nullptr);
    graph.addPass<NoData>(
        "count", PassKind::Compute,
        [&](Builder& b, NoData&) { counter = b.write(counter, Use::StorageReadWriteCompute); }, nullptr);
    graph.addPass<NoData>(
        "emit", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(counter, Use::StorageReadCompute);
            b.write(out, Use::StorageWriteCompute);
        },
        nullptr);
    graph.compile();
    EXPECT_EQ(trace(graph.executedPassNames()), "clear,count,emit")
        << "atomics on a cleared counter need the clear; culling it would leave garbage";
}

TEST(GraphCulling, CulledPassesTransientsAreNotRealised) {
    Graph graph;
    Frame frame;
    buildFrame(graph, frame);
    graph.compile();
    const CompiledGraph& compiled = graph.compiled();
    EXPECT_EQ(compiled.firstUse[graph.resourceIndex(frame.unusedA)], kInvalidId)
        << "a transient touched only by culled passes has no lifetime";
    EXPECT_EQ(compiled.firstUse[graph.resourceIndex(frame.depth)], 0u)
        << "depth is first used by prepass (#0)";
    EXPECT_EQ(compiled.lastUse[graph.resourceIndex(frame.depth)], 4u)
        << "depth is last used by lighting (#4)";

    FakeAllocator allocator;
    graph.realiseTransients(allocator);
    EXPECT_EQ(allocator.acquiredNames(), "depth,clusters")
        << "only transients of executed passes are acquired; imports never are";
    graph.realiseTransients(allocator);
    EXPECT_EQ(allocator.requests().size(), 2u) << "realising again reuses the objects acquired before";
    graph.releaseTransients();
    EXPECT_EQ(allocator.released(), 2u) << "every acquired transient goes back to the allocator";
    graph.releaseTransients();
    EXPECT_EQ(allocator.released(), 2u) << "releasing twice must not double-free";
}

TEST(GraphCulling, UsageFlagsReachTheAllocator) {
    Graph graph;
    Texture out = graph.importTexture("out", fakeTexture(), std::nullopt, std::nullopt);
    Texture color;
    graph.addPass<NoData>(
        "draw", PassKind::Graphics,
        [&](Builder& b, NoData&) { color = b.write(b.create("color", colorDesc()), Use::ColorAttachment); },
        nullptr);
    graph.addPass<NoData>(
        "blur", PassKind::Compute,
        [&](Builder& b, NoData&) {
            b.read(color, Use::SampledCompute);
            b.write(out, Use::StorageImageWriteCompute);
        },
        nullptr);
    graph.compile();
    FakeAllocator allocator;
    graph.realiseTransients(allocator);
    const FakeAllocator::Request* request = allocator.find("color");
    ASSERT_NE(request, nullptr) << "the colour target is used, so it must be acquired";
    EXPECT_EQ(request->imageUsage,
              VkImageUsageFlags(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT))
        << "the image is created with exactly the usages its passes declared";
}

TEST(GraphOrder, RecompileAfterAddingPassesExtendsOrder) {
    Graph graph;
    Buffer out = graph.importBuffer("out", fakeBuffer(), std::nullopt, std::nullopt);
    graph.addPass<NoData>(
        "first", PassKind::Compute,
        [&](Builder& b, NoData&) { out = b.write(out, Use::StorageWriteCompute); }, nullptr);
    graph.compile();
    EXPECT_EQ(trace(graph.executedPassNames()), "first");
    graph.addPass<NoData>(
        "second", PassKind::Compute,
        [&](Builder& b, NoData&) { out = b.write(out, Use::StorageReadWriteCompute); }, nullptr);
    EXPECT_FALSE(graph.isCompiled()) << "adding a pass invalidates the compiled graph";
    graph.compile();
    EXPECT_EQ(trace(graph.executedPassNames()), "first,second");
}

TEST(GraphOrder, PassDataSurvivesLaterPasses) {
    Graph graph;
    struct Data {
        Buffer written;
    };
    Buffer out = graph.importBuffer("out", fakeBuffer(), std::nullopt, std::nullopt);
    const Data& first = graph.addPass<Data>(
        "first", PassKind::Compute,
        [&](Builder& b, Data& d) { d.written = out = b.write(out, Use::StorageWriteCompute); }, nullptr);
    const Buffer expected = first.written;
    for (int i = 0; i < 32; ++i)
        graph.addPass<NoData>(
            "more" + std::to_string(i), PassKind::Compute,
            [&](Builder& b, NoData&) { out = b.write(out, Use::StorageReadWriteCompute); }, nullptr);
    EXPECT_EQ(first.written, expected) << "the Data reference returned by addPass must stay valid";
    EXPECT_TRUE(expected.valid());
}

} // namespace
} // namespace eng::rg::test
