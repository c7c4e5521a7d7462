#include "engine/frame/transient_pool.h"

namespace eng::frame {

TransientPool::~TransientPool() {
    destroyAll();
}

void TransientPool::destroyAll() {
    for (auto& t : m_textures)
        vk::destroyImage(m_device, t.image);
    for (auto& b : m_buffers)
        vk::destroyBuffer(m_device, b.buffer);
    m_textures.clear();
    m_buffers.clear();
}

rg::PhysicalTexture TransientPool::acquireTexture(const std::string& name, const rg::TextureDesc& desc,
                                                  VkImageUsageFlags usage) {
    TextureEntry* found = nullptr;
    for (auto& t : m_textures) {
        const vk::ImageDesc& d = t.image.desc;
        if (!t.inUse && d.format == desc.format && d.width == desc.width && d.height == desc.height &&
            d.layers == desc.layers && d.samples == desc.samples && d.usage == usage) { // same view type too
            found = &t;
            break;
        }
    }
    if (!found) {
        vk::ImageDesc d{desc.format, desc.width, desc.height, desc.layers, 1, desc.samples, usage};
        // Single-sample single-layer targets are plain 2D images to shaders (image2D, sampler2D);
        // layered or multisampled ones are arrays, so emulated and native rates share one shader.
        d.viewType = desc.layers == 1 && desc.samples == VK_SAMPLE_COUNT_1_BIT ? VK_IMAGE_VIEW_TYPE_2D
                                                                               : VK_IMAGE_VIEW_TYPE_2D_ARRAY;
        m_textures.push_back({vk::createImage(m_device, d, name), false});
        found = &m_textures.back();
    } else {
        m_device.setName(VK_OBJECT_TYPE_IMAGE, found->image.image, name);
    }
    found->inUse = true;
    m_bytesByName[name] = found->image.bytes;
    return {found->image.image, found->image.view, found->image.sampledView, desc};
}

rg::PhysicalBuffer TransientPool::acquireBuffer(const std::string& name, const rg::BufferDesc& desc,
                                                VkBufferUsageFlags usage) {
    BufferEntry* found = nullptr;
    for (auto& b : m_buffers) {
        if (!b.inUse && b.buffer.size == desc.size && b.usage == usage) {
            found = &b;
            break;
        }
    }
    if (!found) {
        m_buffers.push_back(
            {vk::createBuffer(m_device, desc.size, usage, vk::MemoryUse::GpuOnly, name), usage, false});
        found = &m_buffers.back();
    } else {
        m_device.setName(VK_OBJECT_TYPE_BUFFER, found->buffer.buffer, name);
    }
    found->inUse = true;
    m_bytesByName[name] = found->buffer.size;
    return {found->buffer.buffer, desc.size};
}

void TransientPool::release(const rg::PhysicalTexture& texture) {
    for (auto& t : m_textures)
        if (t.image.image == texture.image) t.inUse = false;
}

void TransientPool::release(const rg::PhysicalBuffer& buffer) {
    for (auto& b : m_buffers)
        if (b.buffer.buffer == buffer.buffer) b.inUse = false;
}

} // namespace eng::frame
