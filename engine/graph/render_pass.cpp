#include "engine/graph/render_pass.h"

namespace eng::rg {
namespace {

VkRenderingAttachmentInfo attachmentInfo(const Attachment& attachment, const RenderingView& view) {
    VkRenderingAttachmentInfo info{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    info.imageView = view.view;
    info.imageLayout = view.layout;
    info.loadOp = attachment.load;
    info.storeOp = attachment.store;
    info.clearValue = attachment.clear;
    return info;
}

} // namespace

void buildRendering(const RenderTargets& targets, const std::vector<RenderingView>& colorViews,
                    const RenderingView& depthView, Rendering& out) {
    out.colors.clear();
    for (size_t i = 0; i < targets.colors.size(); ++i)
        out.colors.push_back(attachmentInfo(targets.colors[i].attachment, colorViews.at(i)));
    out.info = VkRenderingInfo{VK_STRUCTURE_TYPE_RENDERING_INFO};
    out.info.renderArea = {{0, 0}, {targets.width, targets.height}};
    out.info.layerCount = targets.layers;
    out.info.colorAttachmentCount = static_cast<uint32_t>(out.colors.size());
    out.info.pColorAttachments = out.colors.empty() ? nullptr : out.colors.data();
    if (targets.depth.resource != kInvalidId) {
        out.depth = attachmentInfo(targets.depth.attachment, depthView);
        out.info.pDepthAttachment = &out.depth;
        if (imageAspect(depthView.format) & VK_IMAGE_ASPECT_STENCIL_BIT)
            out.info.pStencilAttachment = &out.depth;
    }
    out.viewport = {0.0f, 0.0f, float(targets.width), float(targets.height), 0.0f, 1.0f};
    out.scissor = out.info.renderArea;
}

} // namespace eng::rg
