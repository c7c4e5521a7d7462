#pragma once
// Render passes built from declared attachments: a graphics pass names its colour and depth
// attachments in setup (Builder::color, Builder::depthStencil) with their load/store ops and clear
// values, and execute() begins dynamic rendering around the pass's callback with the layouts the
// graph transitioned them to. Passes therefore never spell an image layout, and the layout in the
// VkRenderingInfo cannot drift from the one the barriers produced.

#include "engine/graph/resources.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace eng::rg {

// How the render pass treats one attachment.
struct Attachment {
    VkAttachmentLoadOp load = VK_ATTACHMENT_LOAD_OP_CLEAR;
    VkAttachmentStoreOp store = VK_ATTACHMENT_STORE_OP_STORE;
    VkClearValue clear{}; // used when load is CLEAR
};

// What a pass declared, by resource index. Colour attachments keep declaration order, which is
// their location in the fragment shader.
struct RenderTargets {
    struct Target {
        uint32_t resource = kInvalidId;
        Attachment attachment;
    };
    std::vector<Target> colors;
    Target depth; // resource kInvalidId: none
    uint32_t width = 0, height = 0, layers = 0;

    bool empty() const { return colors.empty() && depth.resource == kInvalidId; }
};

// The VkRenderingInfo of one pass and the attachment infos it points at (hence not copyable).
// The depth attachment is also the stencil attachment when its format has a stencil aspect, so
// pipelines that declare a stencil format (and only those) match it.
struct Rendering {
    Rendering() = default;
    Rendering(const Rendering&) = delete;
    Rendering& operator=(const Rendering&) = delete;

    std::vector<VkRenderingAttachmentInfo> colors;
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    VkViewport viewport{};
    VkRect2D scissor{};
};

struct RenderingView {
    VkImageView view = VK_NULL_HANDLE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkFormat format = VK_FORMAT_UNDEFINED;
};

// Fills `out` for the whole render area (viewport depth range 0..1). colorViews follow
// targets.colors; depthView is ignored without a depth target.
void buildRendering(const RenderTargets& targets, const std::vector<RenderingView>& colorViews,
                    const RenderingView& depthView, Rendering& out);

} // namespace eng::rg
