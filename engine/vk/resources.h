#pragma once
// Plain-data buffers and images with their memory (one allocation each: the
// frames here hold a few dozen resources, a sub-allocator would buy nothing).
// Creation and destruction only: layouts and barriers belong to engine/graph.

#include "engine/vk/device.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>

namespace eng::vk {

enum class MemoryUse {
    GpuOnly,  // device-local
    Upload,   // host-visible, written by the CPU (uniforms, vertices on unified memory)
    Readback, // host-visible + cached, read by the CPU
};

struct Buffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr; // non-null for Upload and Readback
    bool coherent = true;
};

struct ImageDesc {
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t width = 1;
    uint32_t height = 1;
    uint32_t layers = 1;
    uint32_t mipLevels = 1;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    VkImageUsageFlags usage = 0;
    VkImageViewType viewType = VK_IMAGE_VIEW_TYPE_2D_ARRAY; // 2D for material textures
    // A second format of the same texel size for sampledView (the image is then MUTABLE_FORMAT):
    // a target written as UNORM with a shader's exact sRGB encode and read through the sampler's
    // sRGB decode. The fixed-function encode is not reproducible across CPUs on lavapipe
    // (see sample_gbuffer.h). UNDEFINED: sampledView has `format`.
    VkFormat sampledFormat = VK_FORMAT_UNDEFINED;
};

struct Image {
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;        // all aspects, of desc.viewType
    VkImageView sampledView = VK_NULL_HANDLE; // depth aspect only for depth formats, of sampledFormat if set,
                                              // else == view
    ImageDesc desc;
    VkDeviceSize bytes = 0; // the allocation's size, for bytes-per-pixel reports
};

bool isDepthFormat(VkFormat format);
bool hasStencil(VkFormat format);
VkImageAspectFlags aspectOf(VkFormat format);
uint32_t bytesPerTexel(VkFormat format); // per sample

Buffer createBuffer(const Device&, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse,
                    const std::string& name);
void destroyBuffer(const Device&, Buffer&);
// Copies bytes into a mapped buffer at offset (flushes non-coherent memory).
void writeBuffer(const Device&, const Buffer&, std::span<const std::byte> bytes, VkDeviceSize offset = 0);
// Makes GPU writes to a Readback buffer visible to the host (invalidates non-coherent memory).
void invalidateBuffer(const Device&, const Buffer&);

Image createImage(const Device&, const ImageDesc&, const std::string& name);
// For memory the caller owns and may share (render-graph transient aliasing): the object without
// memory and its requirements, then bound at an offset of the caller's allocation (an image gets
// its views then). destroyImage/destroyBuffer leave such memory to its owner.
Image createUnboundImage(const Device&, const ImageDesc&, const std::string& name, VkMemoryRequirements& req);
void bindImage(const Device&, Image&, VkDeviceMemory memory, VkDeviceSize offset, const std::string& name);
Buffer createUnboundBuffer(const Device&, VkDeviceSize size, VkBufferUsageFlags usage,
                           const std::string& name, VkMemoryRequirements& req);
void bindBuffer(const Device&, Buffer&, VkDeviceMemory memory, VkDeviceSize offset);
// Device-local memory of one of typeBits, named; throws OutOfMemory as createImage does.
VkDeviceMemory allocateDeviceMemory(const Device&, VkDeviceSize size, uint32_t typeBits,
                                    const std::string& name);
// Whether an optimal-tiling 2D image of this format, usage and sample count can be created.
bool supportsImage(const Device&, VkFormat, VkImageUsageFlags, VkSampleCountFlagBits);
void destroyImage(const Device&, Image&);

VkSampler createSampler(const Device&, VkFilter filter, VkSamplerAddressMode address, float maxLod,
                        const std::string& name);

} // namespace eng::vk
