#include "engine/frame/transient_pool.h"

#include <algorithm>

namespace eng::frame {
namespace {

vk::ImageDesc imageDesc(const rg::TextureDesc& desc, VkImageUsageFlags usage) {
    vk::ImageDesc d{desc.format, desc.width, desc.height, desc.layers, 1, desc.samples, usage};
    d.sampledFormat = desc.sampledFormat;
    // Single-sample single-layer targets are plain 2D images to shaders (image2D, sampler2D);
    // layered or multisampled ones are arrays, so emulated and native rates share one shader.
    d.viewType = desc.layers == 1 && desc.samples == VK_SAMPLE_COUNT_1_BIT ? VK_IMAGE_VIEW_TYPE_2D
                                                                           : VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    return d;
}

bool sameTexture(const rg::TextureDesc& a, const rg::TextureDesc& b) {
    return a.format == b.format && a.width == b.width && a.height == b.height && a.layers == b.layers &&
           a.samples == b.samples && a.sampledFormat == b.sampledFormat;
}

// Same objects and the same lifetimes, hence the same placement is valid; names may differ.
bool sameKey(const std::vector<rg::TransientRequest>& a, const std::vector<rg::TransientRequest>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        const rg::TransientRequest& x = a[i];
        const rg::TransientRequest& y = b[i];
        if (x.isImage != y.isImage || x.firstUse != y.firstUse || x.lastUse != y.lastUse) return false;
        if (x.isImage && (!sameTexture(x.textureDesc, y.textureDesc) || x.imageUsage != y.imageUsage))
            return false;
        if (!x.isImage && (x.bufferDesc.size != y.bufferDesc.size || x.bufferUsage != y.bufferUsage))
            return false;
    }
    return true;
}

} // namespace

TransientPool::~TransientPool() {
    destroyAll();
}

void TransientPool::destroySet(Set& set) {
    for (Object& object : set.objects) {
        if (object.isImage)
            vk::destroyImage(m_device, object.image);
        else
            vk::destroyBuffer(m_device, object.buffer);
    }
    for (VkDeviceMemory block : set.blocks)
        vkFreeMemory(m_device.device(), block, nullptr);
    set.objects.clear();
    set.blocks.clear();
}

void TransientPool::destroyAll() {
    for (auto& set : m_sets)
        destroySet(*set);
    m_sets.clear();
    for (Standalone& s : m_standalone) {
        if (s.object.isImage)
            vk::destroyImage(m_device, s.object.image);
        else
            vk::destroyBuffer(m_device, s.object.buffer);
    }
    m_standalone.clear();
}

void TransientPool::clearUsage() {
    m_bytesByName.clear();
    m_requestedBytes = 0;
    m_allocatedBytes = 0;
}

VkDeviceSize TransientPool::heldBytes() const {
    VkDeviceSize bytes = 0;
    for (const auto& set : m_sets)
        bytes += set->plan.allocatedBytes;
    for (const Standalone& s : m_standalone)
        bytes += s.object.bytes;
    return bytes;
}

void TransientPool::evict() {
    // Only released sets go: their last submission has completed (release() comes after the
    // caller's wait), so no command buffer still refers to them.
    const auto stale = [&](uint64_t lastUsed) { return m_acquisitions - lastUsed > kEvictAfter; };
    for (auto& set : m_sets)
        if (set->outstanding == 0 && stale(set->lastUsed)) destroySet(*set);
    std::erase_if(m_sets, [](const std::unique_ptr<Set>& set) { return set->objects.empty(); });
    for (Standalone& s : m_standalone) {
        if (s.object.inUse || !stale(s.lastUsed)) continue;
        if (s.object.isImage)
            vk::destroyImage(m_device, s.object.image);
        else
            vk::destroyBuffer(m_device, s.object.buffer);
    }
    std::erase_if(m_standalone,
                  [](const Standalone& s) { return !s.object.image.image && !s.object.buffer.buffer; });
}

std::unique_ptr<TransientPool::Set>
TransientPool::createSet(const std::vector<rg::TransientRequest>& requests) {
    auto set = std::make_unique<Set>();
    set->key = requests;
    std::vector<rg::AliasRequest> alias(requests.size());
    try {
        for (size_t i = 0; i < requests.size(); ++i) {
            const rg::TransientRequest& request = requests[i];
            VkMemoryRequirements req{};
            Object object;
            object.isImage = request.isImage;
            if (request.isImage) {
                object.image = vk::createUnboundImage(
                    m_device, imageDesc(request.textureDesc, request.imageUsage), request.name, req);
                object.bytes = req.size;
            } else {
                object.buffer = vk::createUnboundBuffer(m_device, request.bufferDesc.size,
                                                        request.bufferUsage, request.name, req);
                object.bytes = request.bufferDesc.size;
            }
            set->objects.push_back(object);
            alias[i].size = req.size;
            alias[i].alignment = req.alignment;
            alias[i].memoryTypeBits = req.memoryTypeBits;
            // Without aliasing every object is a class of its own, so none shares a block.
            alias[i].memoryClass = m_aliasing ? (request.isImage ? 1u : 0u) : static_cast<uint32_t>(i);
            alias[i].firstUse = request.firstUse;
            alias[i].lastUse = request.lastUse;
        }
        set->plan = rg::planAliasing(alias);
        // A block is named by the transients it holds, so an allocation failure names them.
        std::vector<std::string> blockNames(set->plan.blocks.size());
        for (size_t i = 0; i < requests.size(); ++i) {
            std::string& name = blockNames[set->plan.placements[i].block];
            name += (name.empty() ? "" : " + ") + requests[i].name;
        }
        for (size_t b = 0; b < set->plan.blocks.size(); ++b)
            set->blocks.push_back(vk::allocateDeviceMemory(
                m_device, set->plan.blocks[b].size, set->plan.blocks[b].memoryTypeBits, blockNames[b]));
        for (size_t i = 0; i < requests.size(); ++i) {
            const rg::AliasPlacement& placement = set->plan.placements[i];
            Object& object = set->objects[i];
            if (object.isImage)
                vk::bindImage(m_device, object.image, set->blocks[placement.block], placement.offset,
                              requests[i].name);
            else
                vk::bindBuffer(m_device, object.buffer, set->blocks[placement.block], placement.offset);
        }
    } catch (...) {
        destroySet(*set);
        throw;
    }
    return set;
}

std::vector<rg::TransientAllocation>
TransientPool::acquireTransients(const std::vector<rg::TransientRequest>& requests) {
    ++m_acquisitions;
    evict();
    Set* found = nullptr;
    for (auto& set : m_sets)
        if (set->outstanding == 0 && sameKey(set->key, requests)) {
            found = set.get();
            break;
        }
    if (!found) {
        m_sets.push_back(createSet(requests));
        found = m_sets.back().get();
    }
    found->lastUsed = m_acquisitions;
    std::vector<rg::TransientAllocation> allocations(requests.size());
    for (size_t i = 0; i < requests.size(); ++i) {
        Object& object = found->objects[i];
        const rg::TransientRequest& request = requests[i];
        const rg::AliasPlacement& placement = found->plan.placements[i];
        rg::TransientAllocation& out = allocations[i];
        out.memory = placement.block;
        out.offset = placement.offset;
        if (object.isImage) {
            m_device.setName(VK_OBJECT_TYPE_IMAGE, object.image.image, request.name);
            out.texture = {object.image.image, object.image.view, object.image.sampledView,
                           request.textureDesc};
            out.size = object.image.bytes;
        } else {
            m_device.setName(VK_OBJECT_TYPE_BUFFER, object.buffer.buffer, request.name);
            out.buffer = {object.buffer.buffer, request.bufferDesc.size};
            // The bytes the buffer may touch: its requirement, at least its size.
            out.size = std::max(object.bytes, request.bufferDesc.size);
        }
        object.inUse = true;
        m_bytesByName[request.name] = object.bytes;
    }
    found->outstanding = static_cast<uint32_t>(requests.size());
    m_requestedBytes += found->plan.requestedBytes;
    m_allocatedBytes += found->plan.allocatedBytes;
    return allocations;
}

rg::PhysicalTexture TransientPool::acquireTexture(const std::string& name, const rg::TextureDesc& desc,
                                                  VkImageUsageFlags usage) {
    Standalone* found = nullptr;
    for (Standalone& s : m_standalone) {
        const vk::ImageDesc& d = s.object.image.desc;
        if (s.object.isImage && !s.object.inUse && d.format == desc.format && d.width == desc.width &&
            d.height == desc.height && d.layers == desc.layers && d.samples == desc.samples &&
            d.sampledFormat == desc.sampledFormat && d.usage == usage) {
            found = &s;
            break;
        }
    }
    if (!found) {
        Standalone s;
        s.object.isImage = true;
        s.object.image = vk::createImage(m_device, imageDesc(desc, usage), name);
        s.object.bytes = s.object.image.bytes;
        m_standalone.push_back(s);
        found = &m_standalone.back();
    } else {
        m_device.setName(VK_OBJECT_TYPE_IMAGE, found->object.image.image, name);
    }
    found->object.inUse = true;
    found->lastUsed = m_acquisitions;
    m_bytesByName[name] = found->object.bytes;
    return {found->object.image.image, found->object.image.view, found->object.image.sampledView, desc};
}

rg::PhysicalBuffer TransientPool::acquireBuffer(const std::string& name, const rg::BufferDesc& desc,
                                                VkBufferUsageFlags usage) {
    Standalone* found = nullptr;
    for (Standalone& s : m_standalone) {
        if (!s.object.isImage && !s.object.inUse && s.object.buffer.size == desc.size && s.usage == usage) {
            found = &s;
            break;
        }
    }
    if (!found) {
        Standalone s;
        s.object.buffer = vk::createBuffer(m_device, desc.size, usage, vk::MemoryUse::GpuOnly, name);
        s.object.bytes = desc.size;
        s.usage = usage;
        m_standalone.push_back(s);
        found = &m_standalone.back();
    } else {
        m_device.setName(VK_OBJECT_TYPE_BUFFER, found->object.buffer.buffer, name);
    }
    found->object.inUse = true;
    found->lastUsed = m_acquisitions;
    m_bytesByName[name] = found->object.bytes;
    return {found->object.buffer.buffer, desc.size};
}

bool TransientPool::releaseObject(VkImage image, VkBuffer buffer) {
    for (auto& set : m_sets)
        for (Object& object : set->objects) {
            const bool match = object.isImage ? object.image.image == image : object.buffer.buffer == buffer;
            if (!match || !object.inUse) continue;
            object.inUse = false;
            --set->outstanding;
            return true;
        }
    for (Standalone& s : m_standalone) {
        const bool match =
            s.object.isImage ? s.object.image.image == image : s.object.buffer.buffer == buffer;
        if (!match || !s.object.inUse) continue;
        s.object.inUse = false;
        return true;
    }
    return false;
}

void TransientPool::release(const rg::PhysicalTexture& texture) {
    releaseObject(texture.image, VK_NULL_HANDLE);
}

void TransientPool::release(const rg::PhysicalBuffer& buffer) {
    releaseObject(VK_NULL_HANDLE, buffer.buffer);
}

} // namespace eng::frame
