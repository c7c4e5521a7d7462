#pragma once
// Shared fixtures for the render-graph CPU tests: a fake allocator that records what the graph
// asks for, fake imported objects, and lookups into the compiled barriers. No device anywhere.

#include "engine/graph/graph.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace eng::rg::test {

// Non-dispatchable handles are opaque pointers on 64-bit targets; small integers are never
// dereferenced by compile() or realiseTransients().
template <class Handle> Handle fakeHandle(uintptr_t value) {
    return reinterpret_cast<Handle>(value);
}

class FakeAllocator final : public Allocator {
  public:
    struct Request {
        std::string name;
        bool isImage = false;
        VkImageUsageFlags imageUsage = 0;
        VkBufferUsageFlags bufferUsage = 0;
    };

    PhysicalTexture acquireTexture(const std::string& name, const TextureDesc& desc,
                                   VkImageUsageFlags usage) override {
        m_requests.push_back({name, true, usage, 0});
        PhysicalTexture texture;
        texture.image = fakeHandle<VkImage>(m_next++);
        texture.view = fakeHandle<VkImageView>(m_next++);
        texture.sampledView = texture.view;
        texture.desc = desc;
        return texture;
    }

    PhysicalBuffer acquireBuffer(const std::string& name, const BufferDesc& desc,
                                 VkBufferUsageFlags usage) override {
        m_requests.push_back({name, false, 0, usage});
        PhysicalBuffer buffer;
        buffer.buffer = fakeHandle<VkBuffer>(m_next++);
        buffer.size = desc.size;
        return buffer;
    }

    void release(const PhysicalTexture&) override { ++m_released; }
    void release(const PhysicalBuffer&) override { ++m_released; }

    const std::vector<Request>& requests() const { return m_requests; }
    uint32_t released() const { return m_released; }

    std::string acquiredNames() const {
        std::string names;
        for (const Request& request : m_requests)
            names += (names.empty() ? "" : ",") + request.name;
        return names;
    }

    const Request* find(const std::string& name) const {
        for (const Request& request : m_requests)
            if (request.name == name) return &request;
        return nullptr;
    }

  private:
    std::vector<Request> m_requests;
    uint32_t m_released = 0;
    uintptr_t m_next = 0x1000;
};

inline std::string trace(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& name : names)
        out += (out.empty() ? "" : ",") + name;
    return out;
}

inline TextureDesc colorDesc(VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT) {
    TextureDesc desc;
    desc.format = format;
    desc.width = 64;
    desc.height = 32;
    return desc;
}

inline BufferDesc bufferDesc(VkDeviceSize size = 256) {
    BufferDesc desc;
    desc.size = size;
    return desc;
}

inline PhysicalTexture fakeTexture(VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT, uintptr_t id = 0x100) {
    PhysicalTexture texture;
    texture.image = fakeHandle<VkImage>(id);
    texture.view = fakeHandle<VkImageView>(id + 1);
    texture.sampledView = texture.view;
    texture.desc = colorDesc(format);
    return texture;
}

inline PhysicalBuffer fakeBuffer(uintptr_t id = 0x200) {
    PhysicalBuffer buffer;
    buffer.buffer = fakeHandle<VkBuffer>(id);
    buffer.size = 256;
    return buffer;
}

// The barriers compiled before the pass named `pass` that touch `resource`; empty if the pass
// did not execute or needs none for it.
inline std::vector<Barrier> barriersBefore(const Graph& graph, const std::string& pass, uint32_t resource) {
    std::vector<Barrier> found;
    for (const CompiledPass& compiledPass : graph.compiled().order) {
        if (graph.passName(compiledPass.pass) != pass) continue;
        for (const Barrier& barrier : compiledPass.barriers)
            if (barrier.resource == resource) found.push_back(barrier);
    }
    return found;
}

// Exactly one barrier expected; fails the test (and returns an empty one) otherwise.
inline Barrier onlyBarrierBefore(const Graph& graph, const std::string& pass, uint32_t resource) {
    const std::vector<Barrier> found = barriersBefore(graph, pass, resource);
    EXPECT_EQ(found.size(), 1u) << "pass '" << pass << "' should have exactly one barrier on '"
                                << graph.resourceName(resource) << "'";
    return found.empty() ? Barrier{} : found.front();
}

// Records what execute() asks of the command recorder, in order, as a trace of short strings plus
// deep copies of the structures (which point at storage that ends with the call).
class MockRecorder final : public CommandRecorder {
  public:
    explicit MockRecorder(VkCommandBuffer expected) : m_expected(expected) {}
    void pipelineBarrier(VkCommandBuffer cmd, const VkDependencyInfo& d) override {
        EXPECT_EQ(cmd, m_expected) << "barrier recorded into another command buffer";
        EXPECT_EQ(d.memoryBarrierCount, 0u) << "the graph records per-resource barriers only";
        barriers.emplace_back(d.pImageMemoryBarriers, d.pImageMemoryBarriers + d.imageMemoryBarrierCount);
        bufferBarriers.emplace_back(d.pBufferMemoryBarriers,
                                    d.pBufferMemoryBarriers + d.bufferMemoryBarrierCount);
        trace.push_back("barrier " + std::to_string(d.imageMemoryBarrierCount) + "i" +
                        std::to_string(d.bufferMemoryBarrierCount) + "b");
    }
    void writeTimestamp(VkCommandBuffer cmd, VkPipelineStageFlags2 stage, VkQueryPool pool,
                        uint32_t query) override {
        EXPECT_EQ(cmd, m_expected);
        EXPECT_EQ(stage, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT)
            << "timestamps wait for everything before them";
        EXPECT_EQ(pool, fakeHandle<VkQueryPool>(0x77));
        trace.push_back("timestamp " + std::to_string(query));
    }
    void beginRendering(VkCommandBuffer cmd, const VkRenderingInfo& info) override {
        EXPECT_EQ(cmd, m_expected);
        // Deep copy: the graph's VkRenderingInfo points at storage that ends with the pass.
        RecordedRendering r;
        r.info = info;
        r.colors.assign(info.pColorAttachments, info.pColorAttachments + info.colorAttachmentCount);
        r.hasDepth = info.pDepthAttachment != nullptr;
        if (r.hasDepth) r.depth = *info.pDepthAttachment;
        r.hasStencil = info.pStencilAttachment != nullptr;
        if (r.hasStencil) r.stencil = *info.pStencilAttachment;
        renderings.push_back(r);
        trace.push_back("beginRendering " + std::to_string(info.colorAttachmentCount) + "c" +
                        (r.hasDepth ? "d" : "") + (r.hasStencil ? "s" : ""));
    }
    void setViewport(VkCommandBuffer cmd, const VkViewport& viewport, const VkRect2D& scissor) override {
        EXPECT_EQ(cmd, m_expected);
        viewports.push_back(viewport);
        scissors.push_back(scissor);
        trace.push_back("viewport");
    }
    void endRendering(VkCommandBuffer cmd) override {
        EXPECT_EQ(cmd, m_expected);
        trace.push_back("endRendering");
    }
    struct RecordedRendering {
        VkRenderingInfo info{};
        std::vector<VkRenderingAttachmentInfo> colors;
        VkRenderingAttachmentInfo depth{}, stencil{};
        bool hasDepth = false, hasStencil = false;
    };
    std::vector<std::string> trace;
    std::vector<RecordedRendering> renderings;
    std::vector<VkViewport> viewports;
    std::vector<VkRect2D> scissors;
    std::vector<std::vector<VkImageMemoryBarrier2>> barriers;
    std::vector<std::vector<VkBufferMemoryBarrier2>> bufferBarriers;

  private:
    VkCommandBuffer m_expected;
};

struct NoData {};

} // namespace eng::rg::test
