#pragma once
// Dear ImGui (1.86, Debian libimgui-dev) on top of the presented frame: the context, the GLFW
// input backend and the Vulkan backend. The backend needs a VkRenderPass, made from the graph's
// Use table (engine/graph/legacy_render_pass.h), and records inside a graph pass that declares
// the swapchain image as a colour attachment, so the graph places every barrier around it.

#include "engine/graph/graph.h"
#include "engine/vk/device.h"
#include "samples/viewer/swapchain.h"

#include <vulkan/vulkan.h>

#include <map>

struct GLFWwindow;

namespace agaa::viewer {

class UiOverlay {
  public:
    // Installs ImGui's GLFW callbacks after the window's own (it chains to them).
    UiOverlay(eng::vk::Device& device, GLFWwindow* window, const Swapchain& swapchain);
    ~UiOverlay();
    UiOverlay(const UiOverlay&) = delete;
    UiOverlay& operator=(const UiOverlay&) = delete;

    // Between these two the caller issues ImGui widgets.
    void beginFrame();
    void endFrame();
    // "viewer.ui": draws the frame's ImGui draw data over `target` (loadOp LOAD).
    eng::rg::Texture addPass(eng::rg::Graph& graph, eng::rg::Texture target);
    // Framebuffers of the old image views are dropped (the swapchain waited for the GPU).
    void swapchainRecreated(const Swapchain& swapchain);

    bool wantsMouse() const;
    bool wantsKeyboard() const;

  private:
    VkFramebuffer framebuffer(VkImageView view, uint32_t width, uint32_t height);

    eng::vk::Device& m_device;
    VkRenderPass m_renderPass = VK_NULL_HANDLE;
    VkDescriptorPool m_descriptorPool = VK_NULL_HANDLE;
    std::map<VkImageView, VkFramebuffer> m_framebuffers;
    uint32_t m_generation = 0;
};

} // namespace agaa::viewer
