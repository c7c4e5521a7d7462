#pragma once
// How a pass touches a resource, and what that means for Vulkan: the sync2 stage and access of
// the access, the image layout it needs, and the usage flag the object must be created with.
// This table is the single source of truth for every barrier the graph generates.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string_view>

namespace eng::rg {

enum class PassKind { Graphics, Compute, Transfer };

enum class Use {
    // images
    ColorAttachment,   // COLOR_ATTACHMENT_OUTPUT, COLOR_ATTACHMENT_OPTIMAL
    DepthStencilWrite, // depth/stencil test + write
    // Depth test (EQUAL) without depth writes, but stencil may be written: synchronised as a
    // write so a following pass still waits for it.
    DepthStencilRead,
    DepthReadOnly, // depth test only, no writes at all: DEPTH_STENCIL_READ_ONLY_OPTIMAL
    SampledFragment,
    SampledCompute,
    StorageImageReadCompute,
    StorageImageWriteCompute,
    StorageImageReadWriteCompute,
    StorageImageReadWriteFragment,
    // buffers
    StorageReadCompute,
    StorageWriteCompute,
    StorageReadWriteCompute,
    StorageReadFragment,
    StorageReadWriteFragment, // fragment-shader SSBO atomics
    StorageReadVertex,
    UniformRead, // any shader stage reading a UBO (vertex | fragment | compute)
    IndirectRead,
    // both: copies, vkCmdFillBuffer and vkCmdClearColorImage. Stage TRANSFER, not CLEAR, because
    // lavapipe's synchronisation validation expects TRANSFER after vkCmdFillBuffer.
    TransferSrc,
    TransferDst,
    // Only as an imported buffer's final state: the host reads it after the submission's fence.
    // A fence wait makes the queue's work complete, not its writes visible to the host: that
    // takes a barrier to HOST / HOST_READ, which the graph records as the final-state barrier.
    // Never in a pass (the host is not a pipeline stage a pass can record in).
    HostRead,
    // Only as an imported swapchain image's final state: PRESENT_SRC_KHR, no stage and no access,
    // because vkQueuePresentKHR is ordered by the semaphore the submit signals. Never in a pass,
    // never as an initial state (import an acquired image with nullopt: the graph then waits on
    // ALL_COMMANDS, which chains with the acquire semaphore's wait).
    Present,
};

inline constexpr uint32_t kUseCount = static_cast<uint32_t>(Use::Present) + 1;

enum class UseTarget { Image, Buffer, Both };

struct UseInfo {
    VkPipelineStageFlags2 stage = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED; // images only
    VkImageUsageFlags imageUsage = 0;
    VkBufferUsageFlags bufferUsage = 0;
    UseTarget target = UseTarget::Both;
    bool writes = false;        // needs a new version and orders later accesses after it
    bool readsPrevious = false; // the pass depends on the contents of the version it replaces
};

const UseInfo& useInfo(Use use);

// Whether the use writes; DepthStencilRead counts as a write for synchronisation.
bool isWrite(Use use);
// Read-modify-write uses (storage read/write, DepthStencilRead): write() with one of these keeps
// the previous producer alive, as readWrite() does.
bool readsPrevious(Use use);
bool appliesTo(Use use, bool isImage);
// Graphics passes may use anything; compute passes no attachment/vertex/fragment uses;
// transfer passes only TransferSrc/TransferDst.
bool allowedIn(Use use, PassKind kind);

// The stages the use touches inside a pass of that kind: UniformRead in a compute pass is COMPUTE only.
VkPipelineStageFlags2 stagesIn(Use use, PassKind kind);

std::string_view useName(Use use);
std::string_view passKindName(PassKind kind);

// Access bits that are writes, so a barrier's srcAccess only names accesses that need availability.
inline constexpr VkAccessFlags2 kWriteAccessMask =
    VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;

} // namespace eng::rg
