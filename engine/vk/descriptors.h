#pragma once
// Collects the descriptors of one dispatch or draw and pushes them (VK_KHR_push_descriptor):
// passes bind per-frame resources without descriptor pools.

#include "engine/vk/device.h"

#include <vulkan/vulkan.h>

#include <vector>

namespace eng::vk {

class PushDescriptors {
  public:
    PushDescriptors& uniform(uint32_t binding, VkBuffer buffer);
    PushDescriptors& storage(uint32_t binding, VkBuffer buffer);
    PushDescriptors& sampled(uint32_t binding, VkSampler sampler, VkImageView view,
                             VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    PushDescriptors& storageImage(uint32_t binding, VkImageView view);
    void push(const Device& device, VkCommandBuffer cmd, VkPipelineBindPoint bindPoint,
              VkPipelineLayout layout);

  private:
    struct Entry {
        uint32_t binding;
        VkDescriptorType type;
        VkDescriptorBufferInfo buffer;
        VkDescriptorImageInfo image;
    };
    std::vector<Entry> m_entries;
};

} // namespace eng::vk
