#include "engine/frame/uniform_ring.h"

#include <stdexcept>

namespace eng::frame {

UniformRing::UniformRing(const vk::Device& device, VkDeviceSize bytes, std::string name,
                         VkBufferUsageFlags usage)
    : m_device(device), m_bytes(bytes), m_name(std::move(name)), m_usage(usage) {}

UniformRing::~UniformRing() {
    // The GPU may still read the last frames' slots: the owner's destructor waits, but a ring can
    // also go with a constructor that threw after creating it.
    if (!m_buffers.empty()) vkDeviceWaitIdle(m_device.device());
    for (vk::Buffer& b : m_buffers)
        if (b.buffer) vk::destroyBuffer(m_device, b);
}

rg::Buffer UniformRing::write(rg::Graph& graph, uint32_t slot, std::span<const std::byte> bytes) {
    if (slot >= kMaxSlots)
        throw std::out_of_range(m_name + ": frame slot " + std::to_string(slot) + " is out of range (0.." +
                                std::to_string(kMaxSlots - 1) +
                                "; FrameInputs::frameSlot = frame in flight x views per frame + view)");
    if (bytes.size() > m_bytes)
        throw std::logic_error(m_name + ": " + std::to_string(bytes.size()) + " bytes do not fit a " +
                               std::to_string(m_bytes) + "-byte slot");
    const std::string name = m_name + "[" + std::to_string(slot) + "]";
    for (uint32_t r = 0; r < graph.resourceCount(); ++r)
        if (graph.resourceName(r) == name)
            throw std::logic_error(m_name + ": frame slot " + std::to_string(slot) +
                                   " is already used by this graph; each view recorded before the graph "
                                   "executes needs its own FrameInputs::frameSlot");
    if (slot >= m_buffers.size()) m_buffers.resize(slot + 1);
    vk::Buffer& buffer = m_buffers[slot];
    if (!buffer.buffer) buffer = vk::createBuffer(m_device, m_bytes, m_usage, vk::MemoryUse::Upload, name);
    vk::writeBuffer(m_device, buffer, bytes);
    // Host-written before submission (the submit makes host writes visible): no prior GPU use to
    // wait for within this graph.
    return graph.importBuffer(name, {buffer.buffer, buffer.size}, std::nullopt, std::nullopt);
}

} // namespace eng::frame
