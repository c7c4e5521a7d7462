#include "engine/graph/use.h"

#include "engine/graph/resources.h"

#include <array>

namespace eng::rg {
namespace {

constexpr VkPipelineStageFlags2 kFragmentTests =
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
constexpr VkAccessFlags2 kDepthReadWrite =
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
constexpr VkAccessFlags2 kStorageReadWrite =
    VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;

UseInfo image(VkPipelineStageFlags2 stage, VkAccessFlags2 access, VkImageLayout layout,
              VkImageUsageFlags usage) {
    UseInfo info;
    info.stage = stage;
    info.access = access;
    info.layout = layout;
    info.imageUsage = usage;
    info.target = UseTarget::Image;
    return info;
}

UseInfo buffer(VkPipelineStageFlags2 stage, VkAccessFlags2 access, VkBufferUsageFlags usage) {
    UseInfo info;
    info.stage = stage;
    info.access = access;
    info.bufferUsage = usage;
    info.target = UseTarget::Buffer;
    return info;
}

// A switch rather than a table literal so that adding a Use without its mapping is a
// -Wswitch warning instead of a silently zeroed entry.
UseInfo describe(Use use) {
    UseInfo info;
    switch (use) {
    case Use::ColorAttachment:
        // READ as well: loadOp LOAD and blending read the attachment.
        info = image(VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                     VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                     VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT);
        info.writes = true;
        break;
    case Use::DepthStencilWrite:
        info = image(kFragmentTests, kDepthReadWrite, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
        info.writes = true;
        break;
    case Use::DepthStencilRead:
        info = image(kFragmentTests, kDepthReadWrite, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
        info.writes = true;
        info.readsPrevious = true;
        break;
    case Use::DepthReadOnly:
        info = image(kFragmentTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                     VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT);
        break;
    case Use::SampledFragment:
        info = image(VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_USAGE_SAMPLED_BIT);
        break;
    case Use::SampledCompute:
        info = image(VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                     VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_IMAGE_USAGE_SAMPLED_BIT);
        break;
    case Use::StorageImageReadCompute:
        info = image(VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                     VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_USAGE_STORAGE_BIT);
        break;
    case Use::StorageImageWriteCompute:
        info = image(VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                     VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_USAGE_STORAGE_BIT);
        info.writes = true;
        break;
    case Use::StorageImageReadWriteCompute:
        info = image(VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kStorageReadWrite, VK_IMAGE_LAYOUT_GENERAL,
                     VK_IMAGE_USAGE_STORAGE_BIT);
        info.writes = true;
        info.readsPrevious = true;
        break;
    case Use::StorageImageReadWriteFragment:
        info = image(VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, kStorageReadWrite, VK_IMAGE_LAYOUT_GENERAL,
                     VK_IMAGE_USAGE_STORAGE_BIT);
        info.writes = true;
        info.readsPrevious = true;
        break;
    case Use::StorageReadCompute:
        info = buffer(VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        break;
    case Use::StorageWriteCompute:
        info = buffer(VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        info.writes = true;
        break;
    case Use::StorageReadWriteCompute:
        info = buffer(VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, kStorageReadWrite,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        info.writes = true;
        info.readsPrevious = true;
        break;
    case Use::StorageReadFragment:
        info = buffer(VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        break;
    case Use::StorageReadWriteFragment:
        info = buffer(VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, kStorageReadWrite,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        info.writes = true;
        info.readsPrevious = true;
        break;
    case Use::StorageReadVertex:
        info = buffer(VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT,
                      VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
        break;
    case Use::UniformRead:
        info = buffer(VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                          VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                      VK_ACCESS_2_UNIFORM_READ_BIT, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
        break;
    case Use::IndirectRead:
        // DRAW_INDIRECT also covers vkCmdDispatchIndirect.
        info = buffer(VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
                      VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
        break;
    case Use::TransferSrc:
        info.stage = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
        info.access = VK_ACCESS_2_TRANSFER_READ_BIT;
        info.layout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        info.imageUsage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
        info.bufferUsage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
        break;
    case Use::TransferDst:
        info.stage = VK_PIPELINE_STAGE_2_TRANSFER_BIT;
        info.access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
        info.layout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT;
        info.bufferUsage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
        info.writes = true;
        break;
    case Use::HostRead:
        info = buffer(VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT, 0);
        break;
    case Use::Present:
        info = image(VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, 0);
        break;
    }
    return info;
}

const std::array<UseInfo, kUseCount>& table() {
    static const std::array<UseInfo, kUseCount> kTable = [] {
        std::array<UseInfo, kUseCount> t{};
        for (uint32_t i = 0; i < kUseCount; ++i)
            t[i] = describe(static_cast<Use>(i));
        return t;
    }();
    return kTable;
}

} // namespace

const UseInfo& useInfo(Use use) {
    return table().at(static_cast<uint32_t>(use));
}

bool isWrite(Use use) {
    return useInfo(use).writes;
}

bool readsPrevious(Use use) {
    return useInfo(use).readsPrevious;
}

bool appliesTo(Use use, bool isImage) {
    const UseTarget target = useInfo(use).target;
    return target == UseTarget::Both || (target == UseTarget::Image) == isImage;
}

constexpr VkPipelineStageFlags2 kComputeQueueStages = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                                                      VK_PIPELINE_STAGE_2_TRANSFER_BIT |
                                                      VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT;

bool allowedIn(Use use, PassKind kind) {
    // The presentation engine and the host read these, not a pass.
    if (use == Use::Present || use == Use::HostRead) return false;
    switch (kind) {
    case PassKind::Graphics:
        return true;
    case PassKind::Transfer:
        return use == Use::TransferSrc || use == Use::TransferDst;
    case PassKind::Compute: {
        const VkPipelineStageFlags2 stage = useInfo(use).stage;
        // UniformRead lists graphics stages too, but a compute pass only reads it in COMPUTE.
        return use == Use::UniformRead || (stage & ~kComputeQueueStages) == 0;
    }
    }
    return false;
}

VkPipelineStageFlags2 stagesIn(Use use, PassKind kind) {
    const VkPipelineStageFlags2 stage = useInfo(use).stage;
    return kind == PassKind::Compute ? stage & kComputeQueueStages : stage;
}

std::string_view useName(Use use) {
    switch (use) {
    case Use::ColorAttachment:
        return "ColorAttachment";
    case Use::DepthStencilWrite:
        return "DepthStencilWrite";
    case Use::DepthStencilRead:
        return "DepthStencilRead";
    case Use::DepthReadOnly:
        return "DepthReadOnly";
    case Use::SampledFragment:
        return "SampledFragment";
    case Use::SampledCompute:
        return "SampledCompute";
    case Use::StorageImageReadCompute:
        return "StorageImageReadCompute";
    case Use::StorageImageWriteCompute:
        return "StorageImageWriteCompute";
    case Use::StorageImageReadWriteCompute:
        return "StorageImageReadWriteCompute";
    case Use::StorageImageReadWriteFragment:
        return "StorageImageReadWriteFragment";
    case Use::StorageReadCompute:
        return "StorageReadCompute";
    case Use::StorageWriteCompute:
        return "StorageWriteCompute";
    case Use::StorageReadWriteCompute:
        return "StorageReadWriteCompute";
    case Use::StorageReadFragment:
        return "StorageReadFragment";
    case Use::StorageReadWriteFragment:
        return "StorageReadWriteFragment";
    case Use::StorageReadVertex:
        return "StorageReadVertex";
    case Use::UniformRead:
        return "UniformRead";
    case Use::IndirectRead:
        return "IndirectRead";
    case Use::TransferSrc:
        return "TransferSrc";
    case Use::TransferDst:
        return "TransferDst";
    case Use::HostRead:
        return "HostRead";
    case Use::Present:
        return "Present";
    }
    return "?";
}

std::string_view passKindName(PassKind kind) {
    switch (kind) {
    case PassKind::Graphics:
        return "graphics";
    case PassKind::Compute:
        return "compute";
    case PassKind::Transfer:
        return "transfer";
    }
    return "?";
}

bool isDepthFormat(VkFormat format) {
    switch (format) {
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

VkImageAspectFlags imageAspect(VkFormat format) {
    switch (format) {
    case VK_FORMAT_D16_UNORM_S8_UINT:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_D32_SFLOAT_S8_UINT:
        return VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    case VK_FORMAT_S8_UINT:
        return VK_IMAGE_ASPECT_STENCIL_BIT;
    default:
        return isDepthFormat(format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
    }
}

} // namespace eng::rg
