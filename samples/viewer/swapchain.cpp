#include "samples/viewer/swapchain.h"

#include "engine/vk/check.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace agaa::viewer {
namespace vk = eng::vk;

namespace {

constexpr VkImageUsageFlags kRequiredUsage =
    VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;

bool hasFeature(VkPhysicalDevice physical, VkFormat format, VkFormatFeatureFlags features) {
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(physical, format, &props);
    return (props.optimalTilingFeatures & features) == features;
}

// An SRGB format, so the display blit from the linear RGBA32F display image does the sRGB
// encode in hardware (or lavapipe's copy code) and the UI blends in linear light.
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice physical, VkSurfaceKHR surface) {
    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()));
    for (VkFormat preferred : {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB})
        for (const VkSurfaceFormatKHR& f : formats)
            if (f.format == preferred && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR &&
                hasFeature(physical, preferred,
                           VK_FORMAT_FEATURE_BLIT_DST_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT))
                return f;
    std::string offered;
    for (const VkSurfaceFormatKHR& f : formats)
        offered += (offered.empty() ? "" : ", ") + std::to_string(f.format);
    throw vk::MissingCapability(
        "the window surface offers no B8G8R8A8_SRGB or R8G8B8A8_SRGB format "
        "(sRGB colour space, blit destination, blendable) (VkFormat values offered: " +
        (offered.empty() ? std::string("none") : offered) + ")");
}

} // namespace

Swapchain::Swapchain(vk::Device& device, VkSurfaceKHR surface, VkExtent2D windowSize)
    : m_device(device), m_surface(surface) {
    VkBool32 canPresent = VK_FALSE;
    VK_CHECK(
        vkGetPhysicalDeviceSurfaceSupportKHR(device.physical(), device.queueFamily(), surface, &canPresent));
    if (!canPresent) {
        vkDestroySurfaceKHR(device.instance(), surface, nullptr);
        throw vk::MissingCapability(device.caps().deviceName + ": its queue family " +
                                    std::to_string(device.queueFamily()) + " cannot present to this window");
    }
    try {
        const VkSurfaceFormatKHR choice = chooseFormat(device.physical(), surface);
        m_format = choice.format;
        m_colorSpace = choice.colorSpace;
    } catch (...) {
        vkDestroySurfaceKHR(device.instance(), surface, nullptr);
        throw;
    }
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(device.device(), &fenceInfo, nullptr, &m_acquired));
    device.setName(VK_OBJECT_TYPE_FENCE, m_acquired, "viewer.imageAcquired");
    createSwapchain(windowSize);
}

Swapchain::~Swapchain() {
    vkDeviceWaitIdle(m_device.device());
    destroyViews();
    if (m_swapchain) vkDestroySwapchainKHR(m_device.device(), m_swapchain, nullptr);
    vkDestroyFence(m_device.device(), m_acquired, nullptr);
    vkDestroySurfaceKHR(m_device.instance(), m_surface, nullptr);
}

void Swapchain::destroyViews() {
    for (VkImageView v : m_views)
        vkDestroyImageView(m_device.device(), v, nullptr);
    m_views.clear();
    m_images.clear();
}

void Swapchain::createSwapchain(VkExtent2D windowSize) {
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(m_device.physical(), m_surface, &caps));
    if ((caps.supportedUsageFlags & kRequiredUsage) != kRequiredUsage)
        throw vk::MissingCapability(
            "swapchain images cannot be transfer destinations and colour attachments on this surface");
    m_canReadBack = (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT) != 0;

    // currentExtent is 0xFFFFFFFF where the surface takes its size from the swapchain (Wayland).
    VkExtent2D extent = caps.currentExtent;
    if (extent.width == UINT32_MAX) {
        extent.width = std::clamp(windowSize.width, caps.minImageExtent.width, caps.maxImageExtent.width);
        extent.height = std::clamp(windowSize.height, caps.minImageExtent.height, caps.maxImageExtent.height);
    }
    if (extent.width == 0 || extent.height == 0)
        throw std::logic_error("viewer: swapchain requested for a minimised window");
    uint32_t imageCount = caps.minImageCount + 1;
    if (caps.maxImageCount > 0) imageCount = std::min(imageCount, caps.maxImageCount);
    m_minImageCount = std::max(2u, caps.minImageCount);
    VkCompositeAlphaFlagBitsKHR alpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
    if (!(caps.supportedCompositeAlpha & alpha))
        alpha = VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha & -caps.supportedCompositeAlpha);

    VkSwapchainKHR old = m_swapchain;
    VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
    info.surface = m_surface;
    info.minImageCount = imageCount;
    info.imageFormat = m_format;
    info.imageColorSpace = m_colorSpace;
    info.imageExtent = extent;
    info.imageArrayLayers = 1;
    info.imageUsage = kRequiredUsage | (m_canReadBack ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = alpha;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR; // always available; paces the loop to the display
    info.clipped = VK_TRUE;
    info.oldSwapchain = old;
    VK_CHECK(vkCreateSwapchainKHR(m_device.device(), &info, nullptr, &m_swapchain));
    destroyViews();
    if (old) vkDestroySwapchainKHR(m_device.device(), old, nullptr);
    m_extent = extent;
    ++m_generation;
    m_device.setName(VK_OBJECT_TYPE_SWAPCHAIN_KHR, m_swapchain, "viewer.swapchain");

    uint32_t count = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(m_device.device(), m_swapchain, &count, nullptr));
    m_images.resize(count);
    VK_CHECK(vkGetSwapchainImagesKHR(m_device.device(), m_swapchain, &count, m_images.data()));
    for (uint32_t i = 0; i < count; ++i) {
        VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        view.image = m_images[i];
        view.viewType = VK_IMAGE_VIEW_TYPE_2D;
        view.format = m_format;
        view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView v = VK_NULL_HANDLE;
        VK_CHECK(vkCreateImageView(m_device.device(), &view, nullptr, &v));
        m_device.setName(VK_OBJECT_TYPE_IMAGE_VIEW, v, "viewer.swapchain" + std::to_string(i));
        m_views.push_back(v);
    }
}

void Swapchain::recreate(VkExtent2D windowSize) {
    vkDeviceWaitIdle(m_device.device());
    createSwapchain(windowSize);
}

std::optional<AcquiredImage> Swapchain::acquire() {
    uint32_t index = 0;
    const VkResult acquired =
        vkAcquireNextImageKHR(m_device.device(), m_swapchain, UINT64_MAX, VK_NULL_HANDLE, m_acquired, &index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) return std::nullopt; // the fence is left unsignalled
    if (acquired != VK_SUCCESS && acquired != VK_SUBOPTIMAL_KHR)
        throw std::runtime_error("vkAcquireNextImageKHR failed (VkResult " + std::to_string(acquired) + ")");
    // The presentation engine is done with the image once the fence signals: the graph's first
    // barrier (from UNDEFINED, all commands) may then write it.
    VK_CHECK(vkWaitForFences(m_device.device(), 1, &m_acquired, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(m_device.device(), 1, &m_acquired));
    AcquiredImage image;
    image.index = index;
    image.texture.image = m_images[index];
    image.texture.view = m_views[index];
    image.texture.sampledView = m_views[index];
    image.texture.desc = {m_format, m_extent.width, m_extent.height};
    return image;
}

PresentResult Swapchain::present(uint32_t index) {
    VkPresentInfoKHR presentInfo{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    presentInfo.swapchainCount = 1;
    presentInfo.pSwapchains = &m_swapchain;
    presentInfo.pImageIndices = &index;
    const VkResult presented = vkQueuePresentKHR(m_device.queue(), &presentInfo);
    if (presented == VK_ERROR_OUT_OF_DATE_KHR) return PresentResult::OutOfDate;
    if (presented == VK_SUBOPTIMAL_KHR) return PresentResult::PresentedOutOfDate;
    if (presented != VK_SUCCESS)
        throw std::runtime_error("vkQueuePresentKHR failed (VkResult " + std::to_string(presented) + ")");
    return PresentResult::Presented;
}

} // namespace agaa::viewer
