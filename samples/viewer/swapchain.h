#pragma once
// The window's swapchain (FIFO): surface, images and their views, acquire and present. Nothing
// else: the frame graph (view_renderer.h) writes the acquired image and places every barrier,
// including the final one to presentation (rg::Use::Present). The acquire signals a fence the
// CPU waits on, and the graph's submit is waited on before the present, so with one frame in
// flight no semaphore is needed: lavapipe renders on the CPU, more frames in flight buy nothing.

#include "engine/graph/resources.h"
#include "engine/vk/device.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace agaa::viewer {

enum class PresentResult {
    Presented,
    // Shown, but the swapchain no longer matches the surface: recreate() before the next frame.
    PresentedOutOfDate,
    // Not shown (the surface changed under it): recreate().
    OutOfDate,
};

struct AcquiredImage {
    uint32_t index = 0;
    eng::rg::PhysicalTexture texture; // import with initial nullopt and final Use::Present
};

class Swapchain {
  public:
    // Takes ownership of `surface` (destroyed with the swapchain, before the device's instance).
    // Throws eng::vk::MissingCapability when the queue cannot present to it or the surface offers
    // no 8-bit sRGB format the display blit can write (the blit does the sRGB encode).
    Swapchain(eng::vk::Device& device, VkSurfaceKHR surface, VkExtent2D windowSize);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // Waits for the GPU and rebuilds the swapchain for the window's new framebuffer size.
    void recreate(VkExtent2D windowSize);
    // Waits until an image is free; nullopt when the swapchain is out of date (recreate()).
    std::optional<AcquiredImage> acquire();
    // Presents an image the caller's submit has finished writing (it waited on its fence).
    PresentResult present(uint32_t index);

    VkExtent2D extent() const { return m_extent; }
    VkFormat format() const { return m_format; }
    uint32_t imageCount() const { return uint32_t(m_images.size()); }
    uint32_t minImageCount() const { return m_minImageCount; }
    bool canReadBack() const { return m_canReadBack; } // TRANSFER_SRC: screenshots
    // Increments on every recreate(): framebuffers made for older image views are stale.
    uint32_t generation() const { return m_generation; }

  private:
    void createSwapchain(VkExtent2D windowSize);
    void destroyViews();

    eng::vk::Device& m_device;
    VkSurfaceKHR m_surface = VK_NULL_HANDLE;
    VkSwapchainKHR m_swapchain = VK_NULL_HANDLE;
    VkFormat m_format = VK_FORMAT_UNDEFINED;
    VkColorSpaceKHR m_colorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    bool m_canReadBack = false;
    VkExtent2D m_extent{0, 0};
    uint32_t m_minImageCount = 2;
    uint32_t m_generation = 0;
    std::vector<VkImage> m_images;
    std::vector<VkImageView> m_views;
    VkFence m_acquired = VK_NULL_HANDLE;
};

} // namespace agaa::viewer
