// The transient pool on lavapipe with validation and synchronisation validation on: transients
// with disjoint lifetimes share device memory and keep their contents (the graph's aliasing
// barriers raise no validation message), and released sets unused for a while are freed, so
// repeated size changes keep the pool's memory bounded.

#include "engine/frame/frame_runner.h"
#include "engine/frame/readback.h"
#include "engine/frame/transient_pool.h"
#include "engine/graph/graph.h"
#include "engine/vk/resources.h"
#include "gpu_test_support.h"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace vk = eng::vk;
namespace rg = eng::rg;

constexpr VkFormat kFormat = VK_FORMAT_R32_UINT;

// Clears a new w x h texture to `value` in a transfer pass.
rg::Texture addClear(rg::Graph& graph, const std::string& name, uint32_t w, uint32_t h, uint32_t value) {
    struct Data {
        rg::Texture image;
    };
    return graph
        .addPass<Data>(
            name, rg::PassKind::Transfer,
            [&](rg::Builder& b, Data& d) {
                d.image =
                    b.write(b.create(name, {kFormat, w, h, 1, VK_SAMPLE_COUNT_1_BIT}), rg::Use::TransferDst);
            },
            [value](const rg::Context& ctx, const Data& d) {
                VkClearColorValue color{};
                color.uint32[0] = value;
                VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
                vkCmdClearColorImage(ctx.cmd(), ctx.texture(d.image).image, ctx.layout(d.image), &color, 1,
                                     &range);
            })
        .image;
}

std::vector<uint32_t> read(const vk::Device& device, const vk::Buffer& host, uint32_t count) {
    vk::invalidateBuffer(device, host);
    std::vector<uint32_t> values(count);
    std::memcpy(values.data(), host.mapped, count * 4);
    return values;
}

TEST(TransientPool, TransientsWithDisjointLifetimesShareMemoryAndKeepTheirContents) {
    auto device = agaa::test::makeValidatedDevice();
    constexpr uint32_t w = 32, h = 16;
    vk::Buffer firstHost = eng::frame::createReadbackBuffer(*device, w, h, kFormat, "test.first.host");
    vk::Buffer secondHost = eng::frame::createReadbackBuffer(*device, w, h, kFormat, "test.second.host");
    {
        eng::frame::FrameRunner runner(*device);
        for (int frame = 0; frame < 3; ++frame) { // reruns reuse the same aliased set
            rg::Graph graph;
            // first lives in passes 0..2, second in 3..4: the planner puts them on the same bytes.
            // first's last access is a colour attachment's load and store (pass 2), a stage that
            // second's own barrier (after its readback of the previous frame: TRANSFER) does not
            // wait on: the graph's aliasing wait orders second's clear after it. This layer's
            // synchronisation validation tracks each image on its own (checked: it stays silent
            // with the aliasing waits removed), so tests/graph/alias_test.cpp checks the waits;
            // this test checks the contents and that the waits themselves are valid.
            const rg::Texture first = addClear(graph, "test.first", w, h, 11u);
            eng::frame::addReadbackPass(graph, first, firstHost, "readback.first");
            graph.markOutput(graph.addGraphics<rg::Texture>(
                "test.first.attach",
                [&](rg::Builder& b, rg::Texture& d) {
                    rg::Attachment load;
                    load.load = VK_ATTACHMENT_LOAD_OP_LOAD;
                    d = b.color(first, load);
                },
                nullptr));
            eng::frame::addReadbackPass(graph, addClear(graph, "test.second", w, h, 22u), secondHost,
                                        "readback.second");
            runner.run(graph);
            ASSERT_EQ(graph.executedPassNames().size(), 5u);
            const eng::frame::TransientPool& pool = runner.pool();
            ASSERT_GT(pool.requestedBytes(), 0u);
            EXPECT_EQ(pool.allocatedBytes() * 2, pool.requestedBytes())
                << "two equal images alive at different times take one image's memory";
            for (uint32_t v : read(*device, firstHost, w * h))
                ASSERT_EQ(v, 11u) << "first was read back before second overwrote the shared bytes";
            for (uint32_t v : read(*device, secondHost, w * h))
                ASSERT_EQ(v, 22u);
        }
        EXPECT_EQ(runner.pool().heldBytes(), runner.pool().allocatedBytes()) << "one set, reused every frame";
    }
    vk::destroyBuffer(*device, firstHost);
    vk::destroyBuffer(*device, secondHost);
    agaa::test::expectNoValidationErrors(*device);
}

TEST(TransientPool, WithoutAliasingEveryTransientHasItsOwnMemory) {
    auto device = agaa::test::makeValidatedDevice();
    vk::Buffer hostA = eng::frame::createReadbackBuffer(*device, 8, 8, kFormat, "test.a.host");
    vk::Buffer hostB = eng::frame::createReadbackBuffer(*device, 8, 8, kFormat, "test.b.host");
    {
        eng::frame::FrameRunner runner(*device);
        runner.pool().setAliasing(false);
        rg::Graph graph;
        addClear(graph, "test.unused", 8, 8, 1u); // culled: not realised
        eng::frame::addReadbackPass(graph, addClear(graph, "test.a", 8, 8, 1u), hostA, "readback.a");
        eng::frame::addReadbackPass(graph, addClear(graph, "test.b", 8, 8, 2u), hostB, "readback.b");
        runner.run(graph);
        EXPECT_EQ(runner.pool().allocatedBytes(), runner.pool().requestedBytes());
        EXPECT_EQ(runner.pool().bytesByName().count("test.unused"), 0u)
            << "culled transients are not realised";
        EXPECT_EQ(read(*device, hostA, 64)[0], 1u);
        EXPECT_EQ(read(*device, hostB, 64)[0], 2u);
    }
    vk::destroyBuffer(*device, hostA);
    vk::destroyBuffer(*device, hostB);
    agaa::test::expectNoValidationErrors(*device);
}

TEST(TransientPool, RepeatedSizeChangesKeepMemoryBounded) {
    auto device = agaa::test::makeValidatedDevice();
    constexpr uint32_t kMax = 64;
    vk::Buffer host = eng::frame::createReadbackBuffer(*device, kMax, kMax, kFormat, "test.host");
    {
        eng::frame::FrameRunner runner(*device);
        const auto frame = [&](uint32_t size) {
            rg::Graph graph;
            eng::frame::addReadbackPass(graph, addClear(graph, "test.target", size, size, size), host,
                                        "readback.target");
            runner.run(graph);
            return runner.pool().allocatedBytes(); // this frame's set
        };
        // A window dragged through 40 sizes: without eviction the pool would hold all 40 sets.
        VkDeviceSize largest = 0, peak = 0, sum = 0;
        for (uint32_t i = 0; i < 40; ++i) {
            const VkDeviceSize bytes = frame(kMax - i);
            largest = std::max(largest, bytes);
            sum += bytes;
            peak = std::max(peak, runner.pool().heldBytes());
        }
        EXPECT_LE(peak, (eng::frame::TransientPool::kEvictAfter + 1) * largest)
            << "at most the sets of the last kEvictAfter frames, plus the current one, are held";
        EXPECT_LT(peak, sum / 2) << "most of the sizes seen were freed";
        // Then the size settles: after kEvictAfter more frames only its set is left.
        for (uint32_t i = 0; i <= eng::frame::TransientPool::kEvictAfter; ++i)
            frame(kMax);
        EXPECT_EQ(runner.pool().heldBytes(), runner.pool().allocatedBytes())
            << "only the current size is held";
        EXPECT_EQ(read(*device, host, 1)[0], kMax) << "the last frame's clear value";
    }
    vk::destroyBuffer(*device, host);
    agaa::test::expectNoValidationErrors(*device);
}

// The G-buffer's albedo is a UNORM target read through an sRGB view (sample_gbuffer.h): the
// sampled view must be of the second format, images of different sampled formats must never be
// handed out for each other, and a pair of formats of different sizes is refused by name.
TEST(TransientPool, ASampledFormatGivesTheSampledViewItsFormat) {
    auto device = agaa::test::makeValidatedDevice();
    {
        eng::frame::TransientPool pool(*device);
        constexpr VkImageUsageFlags kUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
        rg::TextureDesc srgb{VK_FORMAT_R8G8B8A8_UNORM, 8, 8, 2, VK_SAMPLE_COUNT_4_BIT,
                             VK_FORMAT_R8G8B8A8_SRGB};
        const rg::PhysicalTexture a = pool.acquireTexture("test.srgb", srgb, kUsage);
        EXPECT_NE(a.sampledView, a.view) << "the sampled view is a second view, of R8G8B8A8_SRGB";
        pool.release(a);
        rg::TextureDesc plain = srgb;
        plain.sampledFormat = VK_FORMAT_UNDEFINED;
        const rg::PhysicalTexture b = pool.acquireTexture("test.plain", plain, kUsage);
        EXPECT_NE(b.image, a.image) << "a released image with another sampled format was reused";
        EXPECT_EQ(b.sampledView, b.view);
        pool.release(b);
        const rg::PhysicalTexture c = pool.acquireTexture("test.srgb.again", srgb, kUsage);
        EXPECT_EQ(c.image, a.image) << "the same description reuses the released image";
        pool.release(c);

        rg::TextureDesc wrong = srgb;
        wrong.sampledFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
        try {
            pool.acquireTexture("test.wrong", wrong, kUsage);
            ADD_FAILURE() << "a sampled format of another texel size was accepted";
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("sampledFormat"), std::string::npos) << e.what();
        }
        pool.destroyAll();
    }
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
