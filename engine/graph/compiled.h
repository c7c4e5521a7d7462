#pragma once
// The output of Graph::compile(): plain data that execute() turns into commands, and that tests
// and the dumps read without a device.

#include "engine/graph/resources.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace eng::rg {

// One sync2 barrier on one resource. Buffers keep oldLayout == newLayout == UNDEFINED and aspect 0.
struct Barrier {
    uint32_t resource = kInvalidId; // resource index (Graph::resourceIndex), not a handle version
    bool isImage = false;
    VkPipelineStageFlags2 srcStage = VK_PIPELINE_STAGE_2_NONE, dstStage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 srcAccess = VK_ACCESS_2_NONE, dstAccess = VK_ACCESS_2_NONE;
    VkImageLayout oldLayout = VK_IMAGE_LAYOUT_UNDEFINED, newLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageAspectFlags aspect = 0;
};

// Barriers are recorded before the pass, all in one vkCmdPipelineBarrier2.
struct CompiledPass {
    uint32_t pass = kInvalidId; // declaration index
    std::vector<Barrier> barriers;
};

struct CompiledGraph {
    std::vector<CompiledPass> order;    // execution order
    std::vector<uint32_t> culled;       // declaration indices, ascending
    std::vector<Barrier> finalBarriers; // imported resources with a requested final state
    // Per resource index. firstUse/lastUse are declaration indices of the first and last
    // executed pass touching the resource, kInvalidId when no executed pass does (then a
    // transient is not realised).
    std::vector<uint32_t> firstUse, lastUse;
    std::vector<VkImageUsageFlags> imageUsage;   // 0 for buffers
    std::vector<VkBufferUsageFlags> bufferUsage; // 0 for textures
};

} // namespace eng::rg
