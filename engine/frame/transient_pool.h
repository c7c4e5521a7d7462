#pragma once
// Realises the graph's transient resources on the device (eng::rg::Allocator).
// Released objects are kept and handed out again to a request with the same
// description and usage, so rendering the same frame repeatedly (benchmarks,
// the viewer) allocates nothing after the first frame.

#include "engine/graph/resources.h"
#include "engine/vk/device.h"
#include "engine/vk/resources.h"

#include <map>
#include <string>
#include <vector>

namespace eng::frame {

class TransientPool final : public rg::Allocator {
  public:
    explicit TransientPool(const vk::Device& device) : m_device(device) {}
    ~TransientPool() override;
    TransientPool(const TransientPool&) = delete;
    TransientPool& operator=(const TransientPool&) = delete;

    rg::PhysicalTexture acquireTexture(const std::string& name, const rg::TextureDesc&,
                                       VkImageUsageFlags) override;
    rg::PhysicalBuffer acquireBuffer(const std::string& name, const rg::BufferDesc&,
                                     VkBufferUsageFlags) override;
    void release(const rg::PhysicalTexture&) override;
    void release(const rg::PhysicalBuffer&) override;

    // Bytes of device memory behind each resource name acquired since the last clearUsage(),
    // from the real allocations (VkMemoryRequirements::size).
    const std::map<std::string, VkDeviceSize>& bytesByName() const { return m_bytesByName; }
    void clearUsage() { m_bytesByName.clear(); }
    void destroyAll();

  private:
    struct TextureEntry {
        vk::Image image;
        bool inUse = false;
    };
    struct BufferEntry {
        vk::Buffer buffer;
        VkBufferUsageFlags usage = 0;
        bool inUse = false;
    };
    const vk::Device& m_device;
    std::vector<TextureEntry> m_textures;
    std::vector<BufferEntry> m_buffers;
    std::map<std::string, VkDeviceSize> m_bytesByName;
};

} // namespace eng::frame
