#pragma once
// Realises the graph's transient resources on the device (eng::rg::Allocator).
//
// Aliasing: the transients of one execution are placed by rg::planAliasing() from their
// VkMemoryRequirements and lifetimes, so transients never alive at the same time share
// VkDeviceMemory blocks (the graph adds the barriers that order them).
//
// Reuse and eviction: a released set of transients is handed out again to an execution asking
// for the same descriptions, usages and lifetimes, so rendering the same frame repeatedly
// (benchmarks, the viewer) allocates nothing after the first frame. A set no execution has
// asked for during the last kEvictAfter acquisitions is freed, so changing sizes (a resizing
// window) keeps memory bounded instead of growing with every size seen.

#include "engine/graph/alias_planner.h"
#include "engine/graph/resources.h"
#include "engine/vk/device.h"
#include "engine/vk/resources.h"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace eng::frame {

class TransientPool final : public rg::Allocator {
  public:
    static constexpr uint32_t kEvictAfter = 8; // acquisitions a released set survives unused

    explicit TransientPool(const vk::Device& device) : m_device(device) {}
    ~TransientPool() override;
    TransientPool(const TransientPool&) = delete;
    TransientPool& operator=(const TransientPool&) = delete;

    std::vector<rg::TransientAllocation> acquireTransients(const std::vector<rg::TransientRequest>&) override;
    // Single objects with memory of their own, outside any set (the graph uses acquireTransients).
    rg::PhysicalTexture acquireTexture(const std::string& name, const rg::TextureDesc&,
                                       VkImageUsageFlags) override;
    rg::PhysicalBuffer acquireBuffer(const std::string& name, const rg::BufferDesc&,
                                     VkBufferUsageFlags) override;
    void release(const rg::PhysicalTexture&) override;
    void release(const rg::PhysicalBuffer&) override;

    // Off: every transient gets a block of its own (for comparisons; on by default).
    void setAliasing(bool enabled) { m_aliasing = enabled; }

    // Bytes of device memory behind each resource name acquired since the last clearUsage(),
    // from the real allocations (VkMemoryRequirements::size; a buffer's requested size).
    const std::map<std::string, VkDeviceSize>& bytesByName() const { return m_bytesByName; }
    // Since the last clearUsage(): the transients' memory requirements summed (what they would
    // take without aliasing) and the memory their blocks take.
    VkDeviceSize requestedBytes() const { return m_requestedBytes; }
    VkDeviceSize allocatedBytes() const { return m_allocatedBytes; }
    void clearUsage();
    // Device memory the pool holds now, in use or not.
    VkDeviceSize heldBytes() const;
    void destroyAll();

  private:
    struct Object {
        bool isImage = false;
        vk::Image image;
        vk::Buffer buffer;
        VkDeviceSize bytes = 0; // for bytesByName
        bool inUse = false;
    };
    struct Set {
        std::vector<rg::TransientRequest> key; // names excluded from the comparison
        std::vector<Object> objects;
        std::vector<VkDeviceMemory> blocks;
        rg::AliasPlan plan;
        uint32_t outstanding = 0; // objects handed out and not yet released
        uint64_t lastUsed = 0;    // m_acquisitions when last handed out
    };
    struct Standalone {
        Object object;
        VkBufferUsageFlags usage = 0;
        uint64_t lastUsed = 0;
    };

    std::unique_ptr<Set> createSet(const std::vector<rg::TransientRequest>& requests);
    void destroySet(Set& set);
    void evict();
    bool releaseObject(VkImage image, VkBuffer buffer);

    const vk::Device& m_device;
    std::vector<std::unique_ptr<Set>> m_sets;
    std::vector<Standalone> m_standalone;
    std::map<std::string, VkDeviceSize> m_bytesByName;
    VkDeviceSize m_requestedBytes = 0, m_allocatedBytes = 0;
    uint64_t m_acquisitions = 0;
    bool m_aliasing = true;
};

} // namespace eng::frame
