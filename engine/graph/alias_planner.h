#pragma once
// Transient aliasing by lifetime: transients whose executed lifetimes do not overlap may share
// device memory. CPU only: the allocator hands in each object's VkMemoryRequirements and its
// first and last use (positions in execution order), and gets back memory blocks and an offset
// per object. The render graph then makes each object that reuses memory wait on the accesses of
// every other object placed over the same bytes (Graph::execute).

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace eng::rg {

struct AliasRequest {
    VkDeviceSize size = 0;      // VkMemoryRequirements::size
    VkDeviceSize alignment = 1; // VkMemoryRequirements::alignment (a power of two)
    uint32_t memoryTypeBits = 0;
    // Objects share a block only with objects of the same class. Images and buffers use different
    // classes, so bufferImageGranularity never has to be honoured between neighbours.
    uint32_t memoryClass = 0;
    uint32_t firstUse = 0, lastUse = 0; // inclusive, positions in execution order
};

struct AliasPlacement {
    uint32_t block = 0;
    VkDeviceSize offset = 0;
};

struct AliasBlock {
    VkDeviceSize size = 0;
    uint32_t memoryTypeBits = 0; // what every object in the block accepts
};

struct AliasPlan {
    std::vector<AliasPlacement> placements; // per request
    std::vector<AliasBlock> blocks;
    VkDeviceSize requestedBytes = 0; // sum of the requests' sizes: memory without aliasing
    VkDeviceSize allocatedBytes = 0; // sum of the blocks' sizes
};

// Largest objects first, each at the lowest aligned offset of the first compatible block where it
// overlaps no object alive at the same time; a new block (sized by that object) otherwise.
// Throws std::invalid_argument for a zero size, a non-power-of-two alignment, no memory type or
// lastUse < firstUse.
AliasPlan planAliasing(const std::vector<AliasRequest>& requests);

// Whether two placed requests share bytes of one block (and so must be ordered by a barrier).
bool sharesMemory(const AliasPlan& plan, const std::vector<AliasRequest>& requests, uint32_t a, uint32_t b);

} // namespace eng::rg
