#pragma once
// Small builders for the push-descriptor writes a pass records in its execute callback
// (set 0 of every pipeline layout is a push-descriptor set, engine/vk/pipeline.h).

#include "engine/graph/graph.h"

#include <vulkan/vulkan.h>

namespace agaa {

inline VkDescriptorBufferInfo bufferInfo(const eng::rg::PhysicalBuffer& b) { return {b.buffer, 0, VK_WHOLE_SIZE}; }

// For texelFetch through a combined image sampler, in the layout the graph gives SampledCompute.
inline VkDescriptorImageInfo sampledImageInfo(VkSampler sampler, const eng::rg::PhysicalTexture& t) {
    return {sampler, t.sampledView, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
}

// For a storage image, in the layout the graph gives the StorageImage* uses.
inline VkDescriptorImageInfo storageImageInfo(const eng::rg::PhysicalTexture& t) {
    return {VK_NULL_HANDLE, t.view, VK_IMAGE_LAYOUT_GENERAL};
}

inline VkWriteDescriptorSet bufferWrite(uint32_t binding, VkDescriptorType type, const VkDescriptorBufferInfo* info) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pBufferInfo = info;
    return w;
}

inline VkWriteDescriptorSet imageWrite(uint32_t binding, VkDescriptorType type, const VkDescriptorImageInfo* info) {
    VkWriteDescriptorSet w{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    w.dstBinding = binding;
    w.descriptorCount = 1;
    w.descriptorType = type;
    w.pImageInfo = info;
    return w;
}

} // namespace agaa
