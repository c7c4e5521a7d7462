#pragma once
// A VkRenderPass for third-party code that needs one (Dear ImGui 1.86's Vulkan backend takes a
// render pass at init and records inside it), derived from the graph's Use table so that the
// pass never spells an image layout: the attachment enters and leaves in the layout of the Use
// the graph pass declares, and the graph's own barriers do every transition around it.

#include "engine/graph/use.h"

#include <vulkan/vulkan.h>

namespace eng::rg {

enum class AttachmentLoad {
    Load,     // draw on top of what earlier passes wrote (declare the use with readWrite())
    Clear,    // clear to the begin info's clear value
    DontCare, // every pixel is overwritten
};

// One colour attachment of `format` in one subpass. `use` must be Use::ColorAttachment (the one
// Use with an attachment layout for colour); the external dependencies carry that Use's stage
// and access, which the graph's barrier before the pass and after it chain with. Throws
// std::logic_error for any other use.
VkRenderPass createLegacyRenderPass(VkDevice device, VkFormat format, Use use, AttachmentLoad load);

// Ends the render pass's life; the caller waits until no command buffer uses it.
void destroyLegacyRenderPass(VkDevice device, VkRenderPass renderPass);

} // namespace eng::rg
