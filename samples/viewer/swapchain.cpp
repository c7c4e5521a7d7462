#include "samples/viewer/swapchain.h"

#include "engine/frame/readback.h"
#include "engine/graph/graph.h"
#include "engine/vk/check.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace agaa::viewer {
namespace rg = eng::rg;
namespace vk = eng::vk;

namespace {

struct FormatChoice {
    VkSurfaceFormatKHR surface{VK_FORMAT_UNDEFINED, VK_COLOR_SPACE_SRGB_NONLINEAR_KHR};
    VkFormat frame = VK_FORMAT_UNDEFINED;
};

bool hasFeature(VkPhysicalDevice physical, VkFormat format, VkFormatFeatureFlags features) {
    VkFormatProperties props;
    vkGetPhysicalDeviceFormatProperties(physical, format, &props);
    return (props.optimalTilingFeatures & features) == features;
}

// The frame arrives already sRGB-encoded. A UNORM swapchain takes those bytes as they are; an
// SRGB one gets an SRGB frame image, so the blit decodes and re-encodes and the bytes survive.
FormatChoice chooseFormat(VkPhysicalDevice physical, VkSurfaceKHR surface) {
    uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(physical, surface, &count, formats.data()));
    const std::pair<VkFormat, VkFormat> preferred[] = {
        {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM},
        {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM},
        {VK_FORMAT_B8G8R8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB},
        {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R8G8B8A8_SRGB},
    };
    for (const auto& [swapchainFormat, frameFormat] : preferred) {
        for (const VkSurfaceFormatKHR& f : formats) {
            if (f.format != swapchainFormat || f.colorSpace != VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) continue;
            if (!hasFeature(physical, swapchainFormat, VK_FORMAT_FEATURE_BLIT_DST_BIT)) continue;
            if (!hasFeature(physical, frameFormat, VK_FORMAT_FEATURE_BLIT_SRC_BIT)) continue;
            return {f, frameFormat};
        }
    }
    std::string offered;
    for (const VkSurfaceFormatKHR& f : formats)
        offered += (offered.empty() ? "" : ", ") + std::to_string(f.format);
    throw vk::MissingCapability(
        "the window surface offers no 8-bit RGBA/BGRA format with sRGB colour space that "
        "can be blitted to (VkFormat values offered: " +
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
    const FormatChoice choice = chooseFormat(device.physical(), surface);
    m_format = choice.surface.format;
    m_colorSpace = choice.surface.colorSpace;
    m_frameFormat = choice.frame;
    m_blitFilter =
        hasFeature(device.physical(), m_frameFormat, VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT)
            ? VK_FILTER_LINEAR
            : VK_FILTER_NEAREST;

    VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = device.queueFamily();
    VK_CHECK(vkCreateCommandPool(device.device(), &poolInfo, nullptr, &m_commandPool));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = m_commandPool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(device.device(), &alloc, &m_cmd));
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(device.device(), &fenceInfo, nullptr, &m_fence));
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VK_CHECK(vkCreateSemaphore(device.device(), &semaphoreInfo, nullptr, &m_imageAcquired));
    device.setName(VK_OBJECT_TYPE_COMMAND_POOL, m_commandPool, "viewer.commandPool");
    device.setName(VK_OBJECT_TYPE_FENCE, m_fence, "viewer.frameFence");
    device.setName(VK_OBJECT_TYPE_SEMAPHORE, m_imageAcquired, "viewer.imageAcquired");

    createSwapchain(windowSize);
}

Swapchain::~Swapchain() {
    const VkDevice dev = m_device.device();
    vkDeviceWaitIdle(dev);
    vk::destroyBuffer(m_device, m_upload);
    vk::destroyBuffer(m_device, m_readback);
    vk::destroyImage(m_device, m_frameImage);
    destroySwapchain();
    for (VkSemaphore s : m_renderFinished)
        vkDestroySemaphore(dev, s, nullptr);
    vkDestroySemaphore(dev, m_imageAcquired, nullptr);
    vkDestroyFence(dev, m_fence, nullptr);
    vkDestroyCommandPool(dev, m_commandPool, nullptr);
    vkDestroySurfaceKHR(m_device.instance(), m_surface, nullptr);
}

void Swapchain::createSwapchain(VkExtent2D windowSize) {
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(m_device.physical(), m_surface, &caps));
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT))
        throw vk::MissingCapability("swapchain images cannot be transfer destinations on this surface");
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
    info.imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | (m_canReadBack ? VK_IMAGE_USAGE_TRANSFER_SRC_BIT : 0);
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = alpha;
    info.presentMode = VK_PRESENT_MODE_FIFO_KHR; // always available; paces the loop to the display
    info.clipped = VK_TRUE;
    info.oldSwapchain = old;
    VK_CHECK(vkCreateSwapchainKHR(m_device.device(), &info, nullptr, &m_swapchain));
    if (old) vkDestroySwapchainKHR(m_device.device(), old, nullptr);
    m_extent = extent;
    m_device.setName(VK_OBJECT_TYPE_SWAPCHAIN_KHR, m_swapchain, "viewer.swapchain");

    uint32_t count = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(m_device.device(), m_swapchain, &count, nullptr));
    m_images.resize(count);
    VK_CHECK(vkGetSwapchainImagesKHR(m_device.device(), m_swapchain, &count, m_images.data()));
    // Only ever grown: a semaphore an earlier present still waits on is never destroyed early.
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    while (m_renderFinished.size() < count) {
        VkSemaphore s = VK_NULL_HANDLE;
        VK_CHECK(vkCreateSemaphore(m_device.device(), &semaphoreInfo, nullptr, &s));
        m_device.setName(VK_OBJECT_TYPE_SEMAPHORE, s,
                         "viewer.renderFinished" + std::to_string(m_renderFinished.size()));
        m_renderFinished.push_back(s);
    }
}

void Swapchain::destroySwapchain() {
    if (m_swapchain) vkDestroySwapchainKHR(m_device.device(), m_swapchain, nullptr);
    m_swapchain = VK_NULL_HANDLE;
    m_images.clear();
}

void Swapchain::recreate(VkExtent2D windowSize) {
    vkDeviceWaitIdle(m_device.device());
    createSwapchain(windowSize);
}

void Swapchain::ensureFrameResources(uint32_t width, uint32_t height) {
    // The previous present waited on its fence: nothing on the GPU still reads these.
    if (m_frameImage.image && m_frameImage.desc.width == width && m_frameImage.desc.height == height) return;
    vk::destroyImage(m_device, m_frameImage);
    vk::destroyBuffer(m_device, m_upload);
    vk::ImageDesc desc;
    desc.format = m_frameFormat;
    desc.width = width;
    desc.height = height;
    // SAMPLED only so that the view vk::createImage always makes is valid (a view needs one).
    desc.usage =
        VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    desc.viewType = VK_IMAGE_VIEW_TYPE_2D;
    m_frameImage = vk::createImage(m_device, desc, "viewer.frame");
    m_upload = vk::createBuffer(m_device, VkDeviceSize(width) * height * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                                vk::MemoryUse::Upload, "viewer.upload");
}

PresentResult Swapchain::present(const eng::io::ImageU8& frame, eng::io::ImageU8* screenshot) {
    if (!eng::io::isConsistent(frame) || frame.width == 0 || frame.height == 0)
        throw std::logic_error("viewer: present() of an empty or inconsistent frame");
    ensureFrameResources(frame.width, frame.height);
    vk::writeBuffer(m_device, m_upload, std::as_bytes(std::span(frame.rgba)));

    uint32_t index = 0;
    VkResult acquired = vkAcquireNextImageKHR(m_device.device(), m_swapchain, UINT64_MAX, m_imageAcquired,
                                              VK_NULL_HANDLE, &index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) return PresentResult::OutOfDate; // semaphore left unsignalled
    if (acquired != VK_SUCCESS && acquired != VK_SUBOPTIMAL_KHR)
        throw std::runtime_error("vkAcquireNextImageKHR failed (VkResult " + std::to_string(acquired) + ")");

    const bool readBack = screenshot && m_canReadBack;
    if (readBack && m_readback.size != VkDeviceSize(m_extent.width) * m_extent.height * 4) {
        vk::destroyBuffer(m_device, m_readback);
        m_readback =
            vk::createBuffer(m_device, VkDeviceSize(m_extent.width) * m_extent.height * 4,
                             VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryUse::Readback, "viewer.screenshot");
    }

    // The graph: host upload -> frame image -> (scaled blit) -> swapchain image -> present.
    rg::Graph graph;
    const rg::Buffer upload =
        graph.importBuffer("viewer.upload", {m_upload.buffer, m_upload.size}, std::nullopt, std::nullopt);
    rg::PhysicalTexture framePhysical{m_frameImage.image,
                                      m_frameImage.view,
                                      m_frameImage.sampledView,
                                      {m_frameFormat, frame.width, frame.height}};
    const rg::Texture frameImage =
        graph.importTexture("viewer.frame", framePhysical, std::nullopt, std::nullopt);
    // Contents of an acquired image are discarded (initial nullopt: UNDEFINED, and the first
    // barrier waits on ALL_COMMANDS, which chains with the acquire semaphore's wait below).
    rg::PhysicalTexture swapPhysical{
        m_images[index], VK_NULL_HANDLE, VK_NULL_HANDLE, {m_format, m_extent.width, m_extent.height}};
    const rg::Texture target =
        graph.importTexture("viewer.swapchain", swapPhysical, std::nullopt, rg::Use::Present);

    struct Copy {
        rg::Buffer source;
        rg::Texture target;
    };
    const Copy& copy = graph.addPass<Copy>(
        "viewer.upload", rg::PassKind::Transfer,
        [&](rg::Builder& b, Copy& d) {
            d.source = b.read(upload, rg::Use::TransferSrc);
            d.target = b.write(frameImage, rg::Use::TransferDst);
        },
        [](const rg::Context& ctx, const Copy& d) {
            const rg::PhysicalTexture& dst = ctx.texture(d.target);
            VkBufferImageCopy region{};
            region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.imageExtent = {dst.desc.width, dst.desc.height, 1};
            vkCmdCopyBufferToImage(ctx.cmd(), ctx.buffer(d.source).buffer, dst.image,
                                   VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        });
    struct Blit {
        rg::Texture source, target;
    };
    const VkFilter filter = m_blitFilter;
    const Blit& blit = graph.addPass<Blit>(
        "viewer.blit", rg::PassKind::Transfer,
        [&](rg::Builder& b, Blit& d) {
            d.source = b.read(copy.target, rg::Use::TransferSrc);
            d.target = b.write(target, rg::Use::TransferDst);
        },
        [filter](const rg::Context& ctx, const Blit& d) {
            const rg::PhysicalTexture& src = ctx.texture(d.source);
            const rg::PhysicalTexture& dst = ctx.texture(d.target);
            VkImageBlit region{};
            region.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            region.srcOffsets[1] = {int32_t(src.desc.width), int32_t(src.desc.height), 1};
            region.dstOffsets[1] = {int32_t(dst.desc.width), int32_t(dst.desc.height), 1};
            vkCmdBlitImage(ctx.cmd(), src.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst.image,
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region, filter);
        });
    if (readBack) eng::frame::addReadbackPass(graph, blit.target, m_readback, "viewer.screenshot");
    graph.compile();

    VK_CHECK(vkResetCommandBuffer(m_cmd, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(m_cmd, &begin));
    rg::Graph::ExecuteInfo execute;
    execute.cmd = m_cmd;
    execute.beginLabel = m_device.beginLabel();
    execute.endLabel = m_device.endLabel();
    graph.execute(execute);
    VK_CHECK(vkEndCommandBuffer(m_cmd));

    VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    wait.semaphore = m_imageAcquired;
    wait.stageMask = VK_PIPELINE_STAGE_2_TRANSFER_BIT; // the first write to the image is a blit
    VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
    signal.semaphore = m_renderFinished[index];
    signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT; // includes the graph's final transition
    VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    cmdInfo.commandBuffer = m_cmd;
    VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    submit.waitSemaphoreInfoCount = 1;
    submit.pWaitSemaphoreInfos = &wait;
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmdInfo;
    submit.signalSemaphoreInfoCount = 1;
    submit.pSignalSemaphoreInfos = &signal;
    VK_CHECK(vkQueueSubmit2(m_device.queue(), 1, &submit, m_fence));

    VkPresentInfoKHR presentInfo{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
    presentInfo.waitSemaphoreCount = 1;
    presentInfo.pWaitSemaphores = &m_renderFinished[index];
    presentInfo.swapchainCount = 1;
    presentInfo.pSwapchains = &m_swapchain;
    presentInfo.pImageIndices = &index;
    const VkResult presented = vkQueuePresentKHR(m_device.queue(), &presentInfo);
    VK_CHECK(vkWaitForFences(m_device.device(), 1, &m_fence, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(m_device.device(), 1, &m_fence));
    if (presented != VK_SUCCESS && presented != VK_SUBOPTIMAL_KHR && presented != VK_ERROR_OUT_OF_DATE_KHR)
        throw std::runtime_error("vkQueuePresentKHR failed (VkResult " + std::to_string(presented) + ")");

    if (readBack) {
        vk::invalidateBuffer(m_device, m_readback);
        *screenshot = eng::io::makeImageU8(m_extent.width, m_extent.height);
        std::memcpy(screenshot->rgba.data(), m_readback.mapped, screenshot->rgba.size());
        if (m_format == VK_FORMAT_B8G8R8A8_UNORM || m_format == VK_FORMAT_B8G8R8A8_SRGB)
            for (size_t i = 0; i < screenshot->rgba.size(); i += 4)
                std::swap(screenshot->rgba[i], screenshot->rgba[i + 2]);
    } else if (screenshot) {
        *screenshot = frame; // the surface cannot be read back: the frame as uploaded
    }

    if (acquired == VK_SUBOPTIMAL_KHR || presented != VK_SUCCESS) return PresentResult::PresentedOutOfDate;
    return PresentResult::Presented;
}

} // namespace agaa::viewer
