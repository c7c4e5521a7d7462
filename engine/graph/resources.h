#pragma once
// Virtual resource handles, their descriptions, the physical objects they resolve to, and the
// allocator interface through which the device layer realises transients. Plain data only.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>
#include <vector>

namespace eng::rg {

inline constexpr uint32_t kInvalidId = ~0u;

// Handles are versioned (Filament): `id` names one version of a resource, and every write()
// returns the handle of a new version. Holding an old handle after a write is how the graph
// detects a pass reading or overwriting contents that no longer exist.
struct Texture {
    uint32_t id = kInvalidId;
    bool valid() const { return id != kInvalidId; }
    bool operator==(const Texture&) const = default;
};

struct Buffer {
    uint32_t id = kInvalidId;
    bool valid() const { return id != kInvalidId; }
    bool operator==(const Buffer&) const = default;
};

struct TextureDesc {
    VkFormat format = VK_FORMAT_UNDEFINED;
    uint32_t width = 1, height = 1, layers = 1;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    // A format of the same texel size that sampled reads see (PhysicalTexture::sampledView): a
    // UNORM colour target read as sRGB. UNDEFINED: they see `format`.
    VkFormat sampledFormat = VK_FORMAT_UNDEFINED;
};

struct BufferDesc {
    VkDeviceSize size = 0;
};

struct PhysicalTexture {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;        // all aspects; 2D, or 2D_ARRAY when layers > 1
    VkImageView sampledView = VK_NULL_HANDLE; // depth aspect only for depth formats, of sampledFormat if
                                              // set, else == view
    TextureDesc desc;
};

struct PhysicalBuffer {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
};

// One transient the graph needs for an execution, with its lifetime, so that an allocator can let
// transients that are never alive at the same time share memory.
struct TransientRequest {
    std::string name;
    bool isImage = false;
    TextureDesc textureDesc;
    BufferDesc bufferDesc;
    VkImageUsageFlags imageUsage = 0;
    VkBufferUsageFlags bufferUsage = 0;
    uint32_t firstUse = 0, lastUse = 0; // positions in execution order, inclusive
};

// Where the allocator put one transient. Two transients with the same `memory` whose
// [offset, offset + size) overlap share bytes: the graph orders the later user after the other's
// accesses. memory kInvalidId: memory of its own.
struct TransientAllocation {
    PhysicalTexture texture;
    PhysicalBuffer buffer;
    uint32_t memory = kInvalidId;
    VkDeviceSize offset = 0, size = 0;
};

// Implemented by the device layer; the graph only asks for objects with the usage flags that
// compile() accumulated, and hands them back in releaseTransients(). Creating an object must not
// record commands: the graph is the only place that transitions layouts.
class Allocator {
  public:
    virtual ~Allocator() = default;
    virtual PhysicalTexture acquireTexture(const std::string& name, const TextureDesc&,
                                           VkImageUsageFlags usage) = 0;
    virtual PhysicalBuffer acquireBuffer(const std::string& name, const BufferDesc&,
                                         VkBufferUsageFlags usage) = 0;
    // Every transient of one execution at once, in request order. The default acquires them one
    // by one, each with memory of its own.
    virtual std::vector<TransientAllocation> acquireTransients(const std::vector<TransientRequest>& requests);
    // Called by Graph::releaseTransients(); the caller has already waited for the GPU.
    virtual void release(const PhysicalTexture&) = 0;
    virtual void release(const PhysicalBuffer&) = 0;
};

// Aspect used for barriers and the `view` of a texture: DEPTH (|STENCIL) for depth formats,
// STENCIL for S8_UINT, COLOR otherwise.
VkImageAspectFlags imageAspect(VkFormat format);
bool isDepthFormat(VkFormat format);

} // namespace eng::rg
