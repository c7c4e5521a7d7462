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
    // Image layouts come from the render graph's Use table (engine/graph/use.h), the one place
    // that decides them: sampled images are in the layout of a Sampled* use, storage images in
    // that of a StorageImage* use.
    PushDescriptors& sampled(uint32_t binding, VkSampler sampler, VkImageView view);
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
