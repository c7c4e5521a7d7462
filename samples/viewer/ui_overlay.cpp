#include "samples/viewer/ui_overlay.h"

#include "engine/graph/legacy_render_pass.h"
#include "engine/vk/check.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace agaa::viewer {
namespace rg = eng::rg;

namespace {

void checkVk(VkResult result) {
    if (result != VK_SUCCESS)
        throw std::runtime_error("ImGui Vulkan backend: VkResult " + std::to_string(result));
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

} // namespace

UiOverlay::UiOverlay(eng::vk::Device& device, GLFWwindow* window, const Swapchain& swapchain)
    : m_device(device), m_generation(swapchain.generation()) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr; // the layout is fixed; no imgui.ini in the working directory
    ImGui::StyleColorsDark();
    // The swapchain is SRGB (the display blit encodes): ImGui's colours are sRGB values, so
    // decode them once and the framebuffer's encode gives back the intended colours.
    for (ImVec4& c : ImGui::GetStyle().Colors) {
        c.x = srgbToLinear(c.x);
        c.y = srgbToLinear(c.y);
        c.z = srgbToLinear(c.z);
    }
    if (!ImGui_ImplGlfw_InitForVulkan(window, true))
        throw std::runtime_error("ImGui GLFW backend init failed");

    m_renderPass = rg::createLegacyRenderPass(device.device(), swapchain.format(), rg::Use::ColorAttachment,
                                              rg::AttachmentLoad::Load);
    device.setName(VK_OBJECT_TYPE_RENDER_PASS, m_renderPass, "viewer.ui");
    // The backend allocates one combined image sampler (the font atlas).
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    poolInfo.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    poolInfo.maxSets = 4;
    poolInfo.poolSizeCount = 1;
    poolInfo.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(device.device(), &poolInfo, nullptr, &m_descriptorPool));

    ImGui_ImplVulkan_InitInfo init{};
    init.Instance = device.instance();
    init.PhysicalDevice = device.physical();
    init.Device = device.device();
    init.QueueFamily = device.queueFamily();
    init.Queue = device.queue();
    init.DescriptorPool = m_descriptorPool;
    init.Subpass = 0;
    init.MinImageCount = swapchain.minImageCount();
    init.ImageCount = std::max(swapchain.imageCount(), swapchain.minImageCount());
    init.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    init.CheckVkResultFn = &checkVk;
    if (!ImGui_ImplVulkan_Init(&init, m_renderPass))
        throw std::runtime_error("ImGui Vulkan backend init failed");
    // The font atlas upload is the backend's own one-off copy (with its own barriers, on an image
    // the graph never sees), before the first frame.
    device.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

UiOverlay::~UiOverlay() {
    vkDeviceWaitIdle(m_device.device());
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    for (const auto& [view, fb] : m_framebuffers)
        vkDestroyFramebuffer(m_device.device(), fb, nullptr);
    vkDestroyDescriptorPool(m_device.device(), m_descriptorPool, nullptr);
    rg::destroyLegacyRenderPass(m_device.device(), m_renderPass);
}

void UiOverlay::beginFrame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void UiOverlay::endFrame() {
    ImGui::Render();
}

void UiOverlay::swapchainRecreated(const Swapchain& swapchain) {
    if (swapchain.generation() == m_generation) return;
    for (const auto& [view, fb] : m_framebuffers)
        vkDestroyFramebuffer(m_device.device(), fb, nullptr);
    m_framebuffers.clear();
    m_generation = swapchain.generation();
    ImGui_ImplVulkan_SetMinImageCount(swapchain.minImageCount());
}

VkFramebuffer UiOverlay::framebuffer(VkImageView view, uint32_t width, uint32_t height) {
    auto it = m_framebuffers.find(view);
    if (it != m_framebuffers.end()) return it->second;
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = m_renderPass;
    info.attachmentCount = 1;
    info.pAttachments = &view;
    info.width = width;
    info.height = height;
    info.layers = 1;
    VkFramebuffer fb = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(m_device.device(), &info, nullptr, &fb));
    m_device.setName(VK_OBJECT_TYPE_FRAMEBUFFER, fb, "viewer.ui.framebuffer");
    return m_framebuffers.emplace(view, fb).first->second;
}

rg::Texture UiOverlay::addPass(rg::Graph& graph, rg::Texture target) {
    struct Data {
        rg::Texture target;
    };
    ImDrawData* drawData = ImGui::GetDrawData();
    const Data& data = graph.addGraphics<Data>(
        "viewer.ui",
        [&](rg::Builder& b, Data& d) { d.target = b.readWrite(target, rg::Use::ColorAttachment); },
        [this, drawData](const rg::Context& ctx, const Data& d) {
            const rg::PhysicalTexture& t = ctx.texture(d.target);
            VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
            begin.renderPass = m_renderPass;
            begin.framebuffer = framebuffer(t.view, t.desc.width, t.desc.height);
            begin.renderArea = {{0, 0}, {t.desc.width, t.desc.height}};
            vkCmdBeginRenderPass(ctx.cmd(), &begin, VK_SUBPASS_CONTENTS_INLINE);
            if (drawData) ImGui_ImplVulkan_RenderDrawData(drawData, ctx.cmd());
            vkCmdEndRenderPass(ctx.cmd());
        });
    return data.target;
}

bool UiOverlay::wantsMouse() const {
    return ImGui::GetIO().WantCaptureMouse;
}

bool UiOverlay::wantsKeyboard() const {
    return ImGui::GetIO().WantCaptureKeyboard;
}

} // namespace agaa::viewer
