#include "engine/vk/descriptors.h"

#include "engine/graph/use.h"

namespace eng::vk {

PushDescriptors& PushDescriptors::uniform(uint32_t binding, VkBuffer buffer) {
    m_entries.push_back({binding, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, {buffer, 0, VK_WHOLE_SIZE}, {}});
    return *this;
}

PushDescriptors& PushDescriptors::storage(uint32_t binding, VkBuffer buffer) {
    m_entries.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, {buffer, 0, VK_WHOLE_SIZE}, {}});
    return *this;
}

PushDescriptors& PushDescriptors::sampled(uint32_t binding, VkSampler sampler, VkImageView view) {
    const VkImageLayout layout = rg::useInfo(rg::Use::SampledCompute).layout;
    m_entries.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {}, {sampler, view, layout}});
    return *this;
}

PushDescriptors& PushDescriptors::storageImage(uint32_t binding, VkImageView view) {
    const VkImageLayout layout = rg::useInfo(rg::Use::StorageImageReadWriteCompute).layout;
    m_entries.push_back({binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, {}, {VK_NULL_HANDLE, view, layout}});
    return *this;
}

void PushDescriptors::push(const Device& device, VkCommandBuffer cmd, VkPipelineBindPoint bindPoint,
                           VkPipelineLayout layout) {
    std::vector<VkWriteDescriptorSet> writes;
    writes.reserve(m_entries.size());
    for (const Entry& e : m_entries) {
        VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
        w.dstBinding = e.binding;
        w.descriptorCount = 1;
        w.descriptorType = e.type;
        bool isBuffer =
            e.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || e.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        if (isBuffer)
            w.pBufferInfo = &e.buffer;
        else
            w.pImageInfo = &e.image;
        writes.push_back(w);
    }
    device.pushDescriptorSet()(cmd, bindPoint, layout, 0, uint32_t(writes.size()), writes.data());
}

} // namespace eng::vk
