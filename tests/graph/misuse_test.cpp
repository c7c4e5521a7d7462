// Misuse is refused with std::logic_error naming the pass and the resource, never compiled into
// wrong barriers.

#include "graph_test_support.h"

#include <stdexcept>

namespace eng::rg::test {
namespace {

// Runs `body`, expects std::logic_error, and returns its message so the test can check that the
// message names the culprit.
template <class Body> std::string logicErrorOf(Body&& body) {
    try {
        body();
    } catch (const std::logic_error& error) {
        return error.what();
    }
    ADD_FAILURE() << "expected std::logic_error";
    return {};
}

TEST(GraphMisuse, ReadingInvalidHandleThrows) {
    Graph graph;
    const std::string message = logicErrorOf([&] {
        graph.addPass<NoData>(
            "blur", PassKind::Compute, [&](Builder& b, NoData&) { b.read(Texture{}, Use::SampledCompute); },
            nullptr);
    });
    EXPECT_NE(message.find("blur"), std::string::npos) << "the message names the pass: " << message;
    EXPECT_NE(message.find("invalid"), std::string::npos) << message;
}

TEST(GraphMisuse, ReadingHandleFromElsewhereThrows) {
    Graph graph;
    EXPECT_THROW(graph.addPass<NoData>(
                     "blur", PassKind::Compute,
                     [&](Builder& b, NoData&) { b.read(Buffer{42}, Use::StorageReadCompute); }, nullptr),
                 std::logic_error)
        << "a handle id this graph never issued";
}

TEST(GraphMisuse, ReadingNeverWrittenTransientThrows) {
    Graph graph;
    const std::string message = logicErrorOf([&] {
        graph.addPass<NoData>(
            "lighting", PassKind::Compute,
            [&](Builder& b, NoData&) { b.read(b.create("gbuffer", colorDesc()), Use::SampledCompute); },
            nullptr);
    });
    EXPECT_NE(message.find("gbuffer"), std::string::npos) << "the message names the resource: " << message;
}

TEST(GraphMisuse, WritingOldVersionThrows) {
    Graph graph;
    Texture original;
    graph.addPass<NoData>(
        "first", PassKind::Graphics,
        [&](Builder& b, NoData&) {
            original = b.create("color", colorDesc());
            b.write(original, Use::ColorAttachment);
        },
        nullptr);
    const std::string message = logicErrorOf([&] {
        graph.addPass<NoData>(
            "second", PassKind::Graphics,
            [&](Builder& b, NoData&) { b.write(original, Use::ColorAttachment); }, nullptr);
    });
    EXPECT_NE(message.find("old"), std::string::npos) << message;
    EXPECT_NE(message.find("first"), std::string::npos)
        << "the message names the pass that wrote since: " << message;
    EXPECT_THROW(graph.compile(), std::logic_error) << "a graph whose setup threw must not compile";
}

TEST(GraphMisuse, ReadingOldVersionThrows) {
    Graph graph;
    Buffer original, updated;
    graph.addPass<NoData>(
        "clear", PassKind::Transfer,
        [&](Builder& b, NoData&) { original = b.write(b.create("counter", bufferDesc()), Use::TransferDst); },
        nullptr);
    graph.addPass<NoData>(
        "count", PassKind::Compute,
        [&](Builder& b, NoData&) { updated = b.readWrite(original, Use::StorageReadWriteCompute); }, nullptr);
    EXPECT_NE(original, updated) << "write() returns a new version";
    EXPECT_THROW(graph.addPass<NoData>(
                     "stale", PassKind::Compute,
                     [&](Builder& b, NoData&) { b.read(original, Use::StorageReadCompute); }, nullptr),
                 std::logic_error)
        << "the contents of the old version no longer exist";
}

TEST(GraphMisuse, WrongKindOfUseThrows) {
    Graph graph;
    Buffer buffer;
    graph.addPass<NoData>(
        "fill", PassKind::Transfer,
        [&](Builder& b, NoData&) { buffer = b.write(b.create("data", bufferDesc()), Use::TransferDst); },
        nullptr);
    EXPECT_THROW(graph.addPass<NoData>(
                     "a", PassKind::Compute,
                     [&](Builder& b, NoData&) { b.read(buffer, Use::SampledCompute); }, nullptr),
                 std::logic_error)
        << "an image use on a buffer";
    Graph second;
    Buffer data;
    second.addPass<NoData>(
        "fill", PassKind::Transfer,
        [&](Builder& b, NoData&) { data = b.write(b.create("data", bufferDesc()), Use::TransferDst); },
        nullptr);
    EXPECT_THROW(second.addPass<NoData>(
                     "b", PassKind::Compute,
                     [&](Builder& b, NoData&) { b.read(Texture{data.id}, Use::SampledCompute); }, nullptr),
                 std::logic_error)
        << "a buffer handle passed as a texture";
}

TEST(GraphMisuse, ReadWithWritingUseThrows) {
    Graph graph;
    Texture depth;
    graph.addPass<NoData>(
        "prepass", PassKind::Graphics,
        [&](Builder& b, NoData&) {
            depth = b.write(b.create("depth", colorDesc(VK_FORMAT_D32_SFLOAT)), Use::DepthStencilWrite);
        },
        nullptr);
    EXPECT_THROW(graph.addPass<NoData>(
                     "decals", PassKind::Graphics,
                     [&](Builder& b, NoData&) { b.read(depth, Use::DepthStencilRead); }, nullptr),
                 std::logic_error)
        << "DepthStencilRead may write stencil, so read() would hide a write from later passes";
}

TEST(GraphMisuse, WriteWithReadOnlyUseThrows) {
    Graph graph;
    EXPECT_THROW(graph.addPass<NoData>(
                     "p", PassKind::Compute,
                     [&](Builder& b, NoData&) { b.write(b.create("x", colorDesc()), Use::SampledCompute); },
                     nullptr),
                 std::logic_error);
}

TEST(GraphMisuse, ConflictingLayoutsInOnePassThrow) {
    Graph graph;
    Texture color;
    graph.addPass<NoData>(
        "draw", PassKind::Graphics,
        [&](Builder& b, NoData&) { color = b.write(b.create("color", colorDesc()), Use::ColorAttachment); },
        nullptr);
    EXPECT_THROW(graph.addPass<NoData>(
                     "feedback", PassKind::Graphics,
                     [&](Builder& b, NoData&) {
                         b.read(color, Use::SampledFragment);
                         b.write(color, Use::ColorAttachment);
                     },
                     nullptr),
                 std::logic_error)
        << "sampling and rendering to one image in one pass is a feedback loop";
}

TEST(GraphMisuse, AttachmentUseInComputePassThrows) {
    Graph graph;
    EXPECT_THROW(graph.addPass<NoData>(
                     "notGraphics", PassKind::Compute,
                     [&](Builder& b, NoData&) { b.write(b.create("c", colorDesc()), Use::ColorAttachment); },
                     nullptr),
                 std::logic_error);
}

TEST(GraphMisuse, InvalidDescriptionsThrow) {
    Graph graph;
    EXPECT_THROW(graph.addPass<NoData>(
                     "p", PassKind::Compute,
                     [&](Builder& b, NoData&) { b.create("noFormat", TextureDesc{}); }, nullptr),
                 std::logic_error)
        << "VK_FORMAT_UNDEFINED cannot be realised";
    Graph second;
    EXPECT_THROW(
        second.addPass<NoData>(
            "p", PassKind::Compute, [&](Builder& b, NoData&) { b.create("empty", BufferDesc{}); }, nullptr),
        std::logic_error);
}

TEST(GraphMisuse, CompiledAndExecuteNeedCompile) {
    Graph graph;
    EXPECT_THROW(graph.compiled(), std::logic_error);
    EXPECT_THROW(graph.executedPassNames(), std::logic_error);
    graph.compile();
    EXPECT_THROW(graph.execute(Graph::ExecuteInfo{}), std::logic_error)
        << "execute without a command buffer is refused before any Vulkan call";
}

TEST(GraphMisuse, RecompileWhileRealisedThrows) {
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
    FakeAllocator allocator;
    graph.realiseTransients(allocator);
    EXPECT_NO_THROW(graph.compile()) << "compiling an unchanged graph again is a no-op";
    graph.addPass<NoData>(
        "blur", PassKind::Compute,
        [&](Builder& b, NoData&) { ao = b.write(ao, Use::StorageImageReadWriteCompute); }, nullptr);
    EXPECT_THROW(graph.compile(), std::logic_error)
        << "usage flags may change, so realised transients must be released first";
    graph.releaseTransients();
    EXPECT_NO_THROW(graph.compile());
}

} // namespace
} // namespace eng::rg::test
