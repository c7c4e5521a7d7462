#pragma once
// The window's swapchain (FIFO) and the per-frame present: the CPU's sRGB-encoded frame is
// uploaded, copied into an RGBA8 image and blitted (scaled) into the acquired swapchain image by
// a small render graph, so every barrier, including the final transition to PRESENT_SRC_KHR,
// comes from engine/graph. One frame in flight: the viewer renders with FrameRenderer, which
// already waits for the GPU, so more would buy nothing on lavapipe.

#include "engine/io/image.h"
#include "engine/vk/device.h"
#include "engine/vk/resources.h"

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

namespace agaa::viewer {

enum class PresentResult {
    Presented,
    // Shown, but the swapchain no longer matches the surface: recreate() before the next frame.
    PresentedOutOfDate,
    // Not shown (the surface changed under it): recreate() and present the frame again.
    OutOfDate,
};

class Swapchain {
  public:
    // Takes ownership of `surface` (destroyed with the swapchain, before the device's instance).
    // Throws eng::vk::MissingCapability when the queue cannot present to it or the surface
    // offers no format the viewer can blit into.
    Swapchain(eng::vk::Device& device, VkSurfaceKHR surface, VkExtent2D windowSize);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // Waits for the GPU and rebuilds the swapchain for the window's new framebuffer size.
    void recreate(VkExtent2D windowSize);

    // Shows `frame` (sRGB-encoded RGBA8, any size) stretched over the whole window, and waits
    // for the copy to finish. With `screenshot` set, also reads the presented swapchain image
    // back into it (RGBA8; the uploaded frame where the surface forbids TRANSFER_SRC).
    PresentResult present(const eng::io::ImageU8& frame, eng::io::ImageU8* screenshot = nullptr);

    VkExtent2D extent() const { return m_extent; }
    VkFormat format() const { return m_format; }

  private:
    void createSwapchain(VkExtent2D windowSize);
    void destroySwapchain();
    void ensureFrameResources(uint32_t width, uint32_t height);

    eng::vk::Device& m_device;
    VkSurfaceKHR m_surface = VK_NULL_HANDLE;
    VkSwapchainKHR m_swapchain = VK_NULL_HANDLE;
    VkFormat m_format = VK_FORMAT_UNDEFINED;
    VkColorSpaceKHR m_colorSpace = VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
    VkFormat m_frameFormat =
        VK_FORMAT_R8G8B8A8_UNORM; // same encoding as m_format, so the blit keeps sRGB bytes
    VkFilter m_blitFilter = VK_FILTER_LINEAR;
    bool m_canReadBack = false; // swapchain images support TRANSFER_SRC
    VkExtent2D m_extent{0, 0};
    std::vector<VkImage> m_images;
    // Per swapchain image: the semaphore vkQueuePresentKHR waits on. Per image, not per frame,
    // because the presentation engine may still hold it when the next frame is submitted.
    std::vector<VkSemaphore> m_renderFinished;
    VkSemaphore m_imageAcquired = VK_NULL_HANDLE; // reusable: the fence wait retires its wait
    VkCommandPool m_commandPool = VK_NULL_HANDLE;
    VkCommandBuffer m_cmd = VK_NULL_HANDLE;
    VkFence m_fence = VK_NULL_HANDLE;

    // The frame on its way to the swapchain: host upload buffer and the RGBA8 image the blit reads.
    eng::vk::Buffer m_upload;
    eng::vk::Image m_frameImage;
    eng::vk::Buffer m_readback;
};

} // namespace agaa::viewer
