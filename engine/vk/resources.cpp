#include "engine/vk/resources.h"

#include "engine/vk/check.h"

#include <cstring>
#include <stdexcept>
#include <string>

namespace eng::vk {

bool isDepthFormat(VkFormat f) {
    switch (f) {
    case VK_FORMAT_D16_UNORM:
    case VK_FORMAT_X8_D24_UNORM_PACK32:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_D16_UNORM_S8_UINT:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
        return true;
    default:
        return false;
    }
}

bool hasStencil(VkFormat f) {
    return f == VK_FORMAT_D16_UNORM_S8_UINT || f == VK_FORMAT_D24_UNORM_S8_UINT ||
           f == VK_FORMAT_D32_SFLOAT_S8_UINT || f == VK_FORMAT_S8_UINT;
}

VkImageAspectFlags aspectOf(VkFormat f) {
    if (!isDepthFormat(f)) return VK_IMAGE_ASPECT_COLOR_BIT;
    return VK_IMAGE_ASPECT_DEPTH_BIT | (hasStencil(f) ? VK_IMAGE_ASPECT_STENCIL_BIT : 0);
}

uint32_t bytesPerTexel(VkFormat f) {
    switch (f) {
    case VK_FORMAT_R8_UNORM:
    case VK_FORMAT_R8_UINT:
    case VK_FORMAT_S8_UINT:
        return 1;
    case VK_FORMAT_R8G8_UNORM:
    case VK_FORMAT_R8G8_UINT:
    case VK_FORMAT_R16_UINT:
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_D16_UNORM:
        return 2;
    case VK_FORMAT_D16_UNORM_S8_UINT:
        return 3;
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
    case VK_FORMAT_R16G16_SNORM:
    case VK_FORMAT_R16G16_UNORM:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_X8_D24_UNORM_PACK32:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
        return 4;
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
        return 5;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R16G16B16A16_UNORM:
    case VK_FORMAT_R32G32_UINT:
    case VK_FORMAT_R32G32_SFLOAT:
        return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_UINT:
        return 16;
    default:
        return 0;
    }
}

namespace {
// An allocation that ran out of memory is the caller's to report (STYLE.md, Errors): thrown with
// the resource's name and size, after the half-made object is destroyed.
[[noreturn]] void throwAllocationFailure(VkResult r, const std::string& name, VkDeviceSize bytes) {
    if (r == VK_ERROR_OUT_OF_DEVICE_MEMORY || r == VK_ERROR_OUT_OF_HOST_MEMORY)
        throw OutOfMemory("cannot allocate " + std::to_string(bytes) + " bytes for '" + name + "' (" +
                          resultName(r) + ")");
    checkFailed("vkAllocateMemory", __FILE__, __LINE__, r);
}
} // namespace

Buffer createBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUse use,
                    const std::string& name) {
    Buffer b;
    b.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size > 0 ? size : 4; // a zero-sized buffer is invalid; callers may have nothing to store
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(device.device(), &info, nullptr, &b.buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device.device(), b.buffer, &req);

    VkMemoryPropertyFlags required = 0, preferred = 0;
    switch (use) {
    case MemoryUse::GpuOnly:
        preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        break;
    case MemoryUse::Upload:
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
        preferred = VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        break;
    case MemoryUse::Readback:
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
        preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        break;
    }
    uint32_t type = device.findMemoryType(req.memoryTypeBits, required, preferred);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = type;
    if (VkResult r = device.allocateMemory(alloc, &b.memory); r != VK_SUCCESS) {
        vkDestroyBuffer(device.device(), b.buffer, nullptr);
        throwAllocationFailure(r, name, alloc.allocationSize);
    }
    VK_CHECK(vkBindBufferMemory(device.device(), b.buffer, b.memory, 0));
    if (use != MemoryUse::GpuOnly) {
        VK_CHECK(vkMapMemory(device.device(), b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped));
        VkPhysicalDeviceMemoryProperties props;
        vkGetPhysicalDeviceMemoryProperties(device.physical(), &props);
        b.coherent = (props.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_COHERENT_BIT) != 0;
    }
    device.setName(VK_OBJECT_TYPE_BUFFER, b.buffer, name);
    device.setName(VK_OBJECT_TYPE_DEVICE_MEMORY, b.memory, name + ".memory");
    device.trackResource(+1);
    return b;
}

void destroyBuffer(const Device& device, Buffer& b) {
    if (b.buffer) device.trackResource(-1);
    if (b.buffer) vkDestroyBuffer(device.device(), b.buffer, nullptr);
    if (b.memory) vkFreeMemory(device.device(), b.memory, nullptr);
    b = Buffer{};
}

void writeBuffer(const Device& device, const Buffer& b, std::span<const std::byte> bytes,
                 VkDeviceSize offset) {
    if (!b.mapped || offset + bytes.size() > b.size)
        throw std::logic_error("writeBuffer: buffer not mapped or write past its end");
    std::memcpy(static_cast<std::byte*>(b.mapped) + offset, bytes.data(), bytes.size());
    if (!b.coherent) {
        VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
        range.memory = b.memory;
        range.size = VK_WHOLE_SIZE;
        VK_CHECK(vkFlushMappedMemoryRanges(device.device(), 1, &range));
    }
}

void invalidateBuffer(const Device& device, const Buffer& b) {
    if (b.coherent || !b.mapped) return;
    VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
    range.memory = b.memory;
    range.size = VK_WHOLE_SIZE;
    VK_CHECK(vkInvalidateMappedMemoryRanges(device.device(), 1, &range));
}

namespace {

bool hasSampledFormat(const ImageDesc& desc) {
    return desc.sampledFormat != VK_FORMAT_UNDEFINED && desc.sampledFormat != desc.format;
}

VkImage createImageObject(const Device& device, const ImageDesc& desc) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    // The two formats must be of one compatibility class; equal texel sizes of colour formats is
    // the part the views' validation would report only as a VUID.
    const VkFormat formats[2] = {desc.format, desc.sampledFormat};
    VkImageFormatListCreateInfo formatList{VK_STRUCTURE_TYPE_IMAGE_FORMAT_LIST_CREATE_INFO};
    if (hasSampledFormat(desc)) {
        if (isDepthFormat(desc.format) || isDepthFormat(desc.sampledFormat) ||
            bytesPerTexel(desc.format) == 0 ||
            bytesPerTexel(desc.format) != bytesPerTexel(desc.sampledFormat))
            throw std::invalid_argument(
                "image sampledFormat (VkFormat " + std::to_string(desc.sampledFormat) +
                ") is not a colour format of the texel size of its format (VkFormat " +
                std::to_string(desc.format) + ")");
        info.flags |= VK_IMAGE_CREATE_MUTABLE_FORMAT_BIT;
        // The list keeps lossless compression on drivers that disable it for arbitrary views.
        formatList.viewFormatCount = 2;
        formatList.pViewFormats = formats;
        info.pNext = &formatList;
    }
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.width, desc.height, 1};
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = desc.layers;
    info.samples = desc.samples;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    // initialLayout stays zero (UNDEFINED): every transition is the render graph's.
    VkImage image = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImage(device.device(), &info, nullptr, &image));
    return image;
}

void createViews(const Device& device, Image& img, const std::string& name) {
    const ImageDesc& desc = img.desc;
    device.setName(VK_OBJECT_TYPE_IMAGE, img.image, name);
    // Copy-only images (transfer usage alone) cannot have views.
    constexpr VkImageUsageFlags kViewUsage =
        VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT |
        VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    if (!(desc.usage & kViewUsage)) return;
    // 2D_ARRAY views by default, so shaders use one sampler type whether or not the
    // sample rate is emulated with layers.
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = img.image;
    view.viewType = desc.viewType;
    view.format = desc.format;
    view.subresourceRange = {aspectOf(desc.format), 0, desc.mipLevels, 0, desc.layers};
    VK_CHECK(vkCreateImageView(device.device(), &view, nullptr, &img.view));
    img.sampledView = img.view;
    if (isDepthFormat(desc.format) && hasStencil(desc.format) && (desc.usage & VK_IMAGE_USAGE_SAMPLED_BIT)) {
        view.subresourceRange.aspectMask = VK_IMAGE_ASPECT_DEPTH_BIT;
        VK_CHECK(vkCreateImageView(device.device(), &view, nullptr, &img.sampledView));
    }
    if (hasSampledFormat(desc) && (desc.usage & VK_IMAGE_USAGE_SAMPLED_BIT)) {
        // Sampling only: an sRGB view may not inherit the image's storage usage.
        VkImageViewUsageCreateInfo usage{VK_STRUCTURE_TYPE_IMAGE_VIEW_USAGE_CREATE_INFO};
        usage.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
        view.pNext = &usage;
        view.format = desc.sampledFormat;
        VK_CHECK(vkCreateImageView(device.device(), &view, nullptr, &img.sampledView));
        device.setName(VK_OBJECT_TYPE_IMAGE_VIEW, img.sampledView, name + ".sampledView");
    }
    device.setName(VK_OBJECT_TYPE_IMAGE_VIEW, img.view, name + ".view");
}

} // namespace

Image createImage(const Device& device, const ImageDesc& desc, const std::string& name) {
    Image img;
    img.desc = desc;
    img.image = createImageObject(device, desc);
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device.device(), img.image, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = device.findMemoryType(req.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (VkResult r = device.allocateMemory(alloc, &img.memory); r != VK_SUCCESS) {
        vkDestroyImage(device.device(), img.image, nullptr);
        throwAllocationFailure(r, name, alloc.allocationSize);
    }
    VK_CHECK(vkBindImageMemory(device.device(), img.image, img.memory, 0));
    img.bytes = req.size;
    createViews(device, img, name);
    device.setName(VK_OBJECT_TYPE_DEVICE_MEMORY, img.memory, name + ".memory");
    device.trackResource(+1);
    return img;
}

Image createUnboundImage(const Device& device, const ImageDesc& desc, const std::string& name,
                         VkMemoryRequirements& req) {
    Image img;
    img.desc = desc;
    img.image = createImageObject(device, desc);
    vkGetImageMemoryRequirements(device.device(), img.image, &req);
    img.bytes = req.size;
    device.setName(VK_OBJECT_TYPE_IMAGE, img.image, name);
    device.trackResource(+1);
    return img;
}

void bindImage(const Device& device, Image& img, VkDeviceMemory memory, VkDeviceSize offset,
               const std::string& name) {
    VK_CHECK(vkBindImageMemory(device.device(), img.image, memory, offset));
    createViews(device, img, name);
}

Buffer createUnboundBuffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage,
                           const std::string& name, VkMemoryRequirements& req) {
    Buffer b;
    b.size = size;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(device.device(), &info, nullptr, &b.buffer));
    vkGetBufferMemoryRequirements(device.device(), b.buffer, &req);
    device.setName(VK_OBJECT_TYPE_BUFFER, b.buffer, name);
    device.trackResource(+1);
    return b;
}

void bindBuffer(const Device& device, Buffer& b, VkDeviceMemory memory, VkDeviceSize offset) {
    VK_CHECK(vkBindBufferMemory(device.device(), b.buffer, memory, offset));
}

VkDeviceMemory allocateDeviceMemory(const Device& device, VkDeviceSize size, uint32_t typeBits,
                                    const std::string& name) {
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = size;
    alloc.memoryTypeIndex = device.findMemoryType(typeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    if (VkResult r = device.allocateMemory(alloc, &memory); r != VK_SUCCESS)
        throwAllocationFailure(r, name, size);
    device.setName(VK_OBJECT_TYPE_DEVICE_MEMORY, memory, name);
    return memory;
}

bool supportsImage(const Device& device, VkFormat format, VkImageUsageFlags usage,
                   VkSampleCountFlagBits samples) {
    VkImageFormatProperties props;
    VkResult r = vkGetPhysicalDeviceImageFormatProperties(device.physical(), format, VK_IMAGE_TYPE_2D,
                                                          VK_IMAGE_TILING_OPTIMAL, usage, 0, &props);
    return r == VK_SUCCESS && (props.sampleCounts & samples) != 0;
}

void destroyImage(const Device& device, Image& img) {
    if (img.sampledView && img.sampledView != img.view)
        vkDestroyImageView(device.device(), img.sampledView, nullptr);
    if (img.view) vkDestroyImageView(device.device(), img.view, nullptr);
    if (img.image) device.trackResource(-1);
    if (img.image) vkDestroyImage(device.device(), img.image, nullptr);
    if (img.memory) vkFreeMemory(device.device(), img.memory, nullptr);
    img = Image{};
}

VkSampler createSampler(const Device& device, VkFilter filter, VkSamplerAddressMode address, float maxLod,
                        const std::string& name) {
    VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    info.magFilter = filter;
    info.minFilter = filter;
    info.mipmapMode =
        filter == VK_FILTER_LINEAR ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    info.addressModeU = info.addressModeV = info.addressModeW = address;
    info.maxLod = maxLod;
    VkSampler sampler = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSampler(device.device(), &info, nullptr, &sampler));
    device.setName(VK_OBJECT_TYPE_SAMPLER, sampler, name);
    return sampler;
}

} // namespace eng::vk
