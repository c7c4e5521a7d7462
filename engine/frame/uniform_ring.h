#pragma once
// Per-frame data that a node writes on the host while it records (addPasses): uniform constants,
// or a storage array such as the frame's lights; one buffer per frame slot. A host that records several views
// or frames before any executes gives each its own slot (FrameInputs::frameSlot = frame in flight x views per
// frame + view), so a later recording never overwrites constants an earlier, still unexecuted one reads
// (issue 18).
//
// Lifetimes: slot s's buffer is written by write() on the host and read by the GPU from the
// submission of the graph that imported it until that submission's fence signals. The host must
// not record slot s again before then. Buffers are created on first use of a slot and live as
// long as the ring (the node).
// Threads: not thread-safe; one ring is used by one recording thread at a time.

#include "engine/graph/graph.h"
#include "engine/vk/device.h"
#include "engine/vk/resources.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace eng::frame {

class UniformRing {
  public:
    // The most slots one ring hands out: 4 frames in flight x 4 views. A larger index is refused,
    // because it is far more likely a host's counter that never wraps than a real need.
    static constexpr uint32_t kMaxSlots = 16;

    // usage: UNIFORM_BUFFER for constants, STORAGE_BUFFER for arrays such as the frame's lights.
    UniformRing(const vk::Device& device, VkDeviceSize bytes, std::string name,
                VkBufferUsageFlags usage = VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
    ~UniformRing();
    UniformRing(const UniformRing&) = delete;
    UniformRing& operator=(const UniformRing&) = delete;

    // Copies `bytes` into slot `slot` and imports the slot's buffer into `graph` as
    // "<name>[slot]". Throws std::out_of_range for slot >= kMaxSlots, and std::logic_error when
    // `graph` already imports this slot (two views in one graph need two slots).
    rg::Buffer write(rg::Graph& graph, uint32_t slot, std::span<const std::byte> bytes);
    uint32_t slotsInUse() const { return uint32_t(m_buffers.size()); }

  private:
    const vk::Device& m_device;
    VkDeviceSize m_bytes;
    std::string m_name;
    VkBufferUsageFlags m_usage;
    std::vector<vk::Buffer> m_buffers; // [slot]; VK_NULL_HANDLE until first used
};

} // namespace eng::frame
