#include "engine/graph/legacy_render_pass.h"

#include <stdexcept>
#include <string>

namespace eng::rg {

VkRenderPass createLegacyRenderPass(VkDevice device, VkFormat format, Use use, AttachmentLoad load) {
    if (use != Use::ColorAttachment)
        throw std::logic_error("createLegacyRenderPass: use " + std::string(useName(use)) +
                               " is not a colour attachment use (allowed: ColorAttachment)");
    const UseInfo& info = useInfo(use);

    VkAttachmentDescription attachment{};
    attachment.format = format;
    attachment.samples = VK_SAMPLE_COUNT_1_BIT;
    attachment.loadOp = load == AttachmentLoad::Load    ? VK_ATTACHMENT_LOAD_OP_LOAD
                        : load == AttachmentLoad::Clear ? VK_ATTACHMENT_LOAD_OP_CLEAR
                                                        : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachment.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachment.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    // The graph has already moved the image into the use's layout and moves it on afterwards:
    // the render pass itself transitions nothing.
    attachment.initialLayout = info.layout;
    attachment.finalLayout = info.layout;

    VkAttachmentReference reference{0, info.layout};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &reference;

    // Explicit external dependencies instead of the implicit ones (which wait on nothing at the
    // start): the graph's barrier before the pass ends in the use's stage and access, and the
    // one after it starts there, so both chain through these.
    VkSubpassDependency dependencies[2]{};
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = VkPipelineStageFlags(info.stage);
    dependencies[0].dstStageMask = VkPipelineStageFlags(info.stage);
    dependencies[0].srcAccessMask = VkAccessFlags(info.access & kWriteAccessMask);
    dependencies[0].dstAccessMask = VkAccessFlags(info.access);
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask = VkPipelineStageFlags(info.stage);
    dependencies[1].dstStageMask = VkPipelineStageFlags(info.stage);
    dependencies[1].srcAccessMask = VkAccessFlags(info.access & kWriteAccessMask);
    dependencies[1].dstAccessMask = VkAccessFlags(info.access);

    VkRenderPassCreateInfo create{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    create.attachmentCount = 1;
    create.pAttachments = &attachment;
    create.subpassCount = 1;
    create.pSubpasses = &subpass;
    create.dependencyCount = 2;
    create.pDependencies = dependencies;
    VkRenderPass renderPass = VK_NULL_HANDLE;
    const VkResult result = vkCreateRenderPass(device, &create, nullptr, &renderPass);
    if (result != VK_SUCCESS)
        throw std::runtime_error("vkCreateRenderPass failed (VkResult " + std::to_string(result) + ")");
    return renderPass;
}

void destroyLegacyRenderPass(VkDevice device, VkRenderPass renderPass) {
    if (renderPass) vkDestroyRenderPass(device, renderPass, nullptr);
}

} // namespace eng::rg
