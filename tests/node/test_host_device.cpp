// Issue 18: a host with its own VkInstance, VkDevice and queue, and its own colour and depth
// images, renders a frame through the node. Nothing here is created by the library except what
// the node itself owns (pipelines, its ring, transients); the targets are plain Vulkan images.

#include "agaa/aggregate/aggregate.h"
#include "agaa/common/host_targets.h"
#include "agaa/methods.h"
#include "engine/frame/frame_runner.h"
#include "engine/scene/scenegen.h"
#include "engine/vk/check.h"
#include "engine/vk/device_setup.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/node/node_test_support.h"
#include "tests/support/aggregate_instrumentation.h"

#include <atomic>
#include <cmath>
#include <cstring>

namespace agaa::test {
namespace {

namespace vk = eng::vk;
namespace rg = eng::rg;

constexpr uint32_t kSize = 64;

// The host's messenger: counts what the validation layer says outside the wrapper's lifetime too
// (objects still alive at vkDestroyDevice).
VKAPI_ATTR VkBool32 VKAPI_CALL countErrors(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                           VkDebugUtilsMessageTypeFlagsEXT,
                                           const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    const char* id = data->pMessageIdName ? data->pMessageIdName : "";
    if (!std::strncmp(id, "VUID-", 5) || !std::strncmp(id, "UNASSIGNED-", 11) ||
        !std::strncmp(id, "SYNC-", 5)) {
        static_cast<std::atomic<uint32_t>*>(user)->fetch_add(1);
        std::fprintf(stderr, "[host validation] %s\n", data->pMessage);
    }
    return VK_FALSE;
}

// What an engine has before it meets the node: an instance with validation and sync validation,
// a device made from the features and extensions eng::vk::DeviceSetup lists, and a queue.
struct Host {
    VkInstance instance = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    VkQueue queue = VK_NULL_HANDLE;
    uint32_t family = 0;
    std::atomic<uint32_t> errors{0};

    Host() {
        const char* layer = "VK_LAYER_KHRONOS_validation";
        const char* ext = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
        VkValidationFeatureEnableEXT sync = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
        VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
        features.enabledValidationFeatureCount = 1;
        features.pEnabledValidationFeatures = &sync;
        VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
        app.apiVersion = VK_API_VERSION_1_3;
        VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
        info.pNext = &features;
        info.pApplicationInfo = &app;
        info.enabledLayerCount = 1;
        info.ppEnabledLayerNames = &layer;
        info.enabledExtensionCount = 1;
        info.ppEnabledExtensionNames = &ext;
        VK_CHECK(vkCreateInstance(&info, nullptr, &instance));
        VkDebugUtilsMessengerCreateInfoEXT m{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
        m.messageSeverity =
            VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
        m.messageType =
            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
        m.pfnUserCallback = &countErrors;
        m.pUserData = &errors;
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        VK_CHECK(create(instance, &m, nullptr, &messenger));
        uint32_t count = 1;
        vkEnumeratePhysicalDevices(instance, &count, &physical);
    }
    // `edit` may switch features off, as a host that forgot one would.
    void createDevice(const std::function<void(vk::FeatureChain&)>& edit = {}) {
        const vk::DeviceSetup setup(physical, false);
        enabled = setup.features();
        if (edit) edit(enabled);
        extensions = setup.extensions();
        float priority = 1.0f;
        VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
        queueInfo.queueFamilyIndex = family; // lavapipe: family 0 does graphics, compute, timestamps
        queueInfo.queueCount = 1;
        queueInfo.pQueuePriorities = &priority;
        VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
        info.pNext = enabled.head();
        info.queueCreateInfoCount = 1;
        info.pQueueCreateInfos = &queueInfo;
        info.enabledExtensionCount = uint32_t(extensions.size());
        info.ppEnabledExtensionNames = extensions.data();
        VK_CHECK(vkCreateDevice(physical, &info, nullptr, &device));
        vkGetDeviceQueue(device, family, 0, &queue);
    }
    vk::HostDevice handles() const {
        vk::HostDevice h;
        h.instance = instance;
        h.physical = physical;
        h.device = device;
        h.queue = queue;
        h.queueFamily = family;
        h.enabledFeatures = enabled.head();
        h.enabledExtensions = extensions;
        h.debugUtils = h.validation = true;
        return h;
    }
    ~Host() {
        if (device) vkDestroyDevice(device, nullptr);
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance, messenger, nullptr);
        vkDestroyInstance(instance, nullptr);
    }
    vk::FeatureChain enabled;
    std::vector<const char*> extensions;
};

// A plain Vulkan image of the host's, with one device-local allocation and a 2D view.
struct HostImage {
    VkDevice device;
    VkImage image = VK_NULL_HANDLE;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    rg::TextureDesc desc;
    HostImage(VkDevice d, VkPhysicalDevice physical, VkFormat format, VkImageUsageFlags usage,
              VkImageAspectFlags aspect)
        : device(d), desc{format, kSize, kSize, 1, VK_SAMPLE_COUNT_1_BIT} {
        VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
        info.imageType = VK_IMAGE_TYPE_2D;
        info.format = format;
        info.extent = {kSize, kSize, 1};
        info.mipLevels = info.arrayLayers = 1;
        info.samples = VK_SAMPLE_COUNT_1_BIT;
        info.usage = usage;
        VK_CHECK(vkCreateImage(device, &info, nullptr, &image));
        VkMemoryRequirements req;
        vkGetImageMemoryRequirements(device, image, &req);
        VkPhysicalDeviceMemoryProperties props;
        vkGetPhysicalDeviceMemoryProperties(physical, &props);
        VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
        alloc.allocationSize = req.size;
        while (!(req.memoryTypeBits & (1u << alloc.memoryTypeIndex)))
            ++alloc.memoryTypeIndex;
        VK_CHECK(vkAllocateMemory(device, &alloc, nullptr, &memory));
        VK_CHECK(vkBindImageMemory(device, image, memory, 0));
        VkImageViewCreateInfo v{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
        v.image = image;
        v.viewType = VK_IMAGE_VIEW_TYPE_2D;
        v.format = format;
        v.subresourceRange = {aspect, 0, 1, 0, 1};
        VK_CHECK(vkCreateImageView(device, &v, nullptr, &view));
    }
    ~HostImage() {
        vkDestroyImageView(device, view, nullptr);
        vkDestroyImage(device, image, nullptr);
        vkFreeMemory(device, memory, nullptr);
    }
    rg::PhysicalTexture physical() const { return {image, view, view, desc}; }
};

// Copies a single-sample image's `aspect` into a host buffer (the library's readback copies colour).
void addAspectReadback(rg::Graph& graph, rg::Texture texture, VkImageAspectFlags aspect,
                       const vk::Buffer& host, const std::string& name) {
    const rg::Buffer target =
        graph.importBuffer(name + ".host", {host.buffer, host.size}, std::nullopt, std::nullopt);
    struct Data {
        rg::Texture source;
        rg::Buffer target;
    };
    graph.addPass<Data>(
        name, rg::PassKind::Transfer,
        [&](rg::Builder& b, Data& d) {
            d.source = b.read(texture, rg::Use::TransferSrc);
            d.target = b.write(target, rg::Use::TransferDst);
            b.sideEffect();
        },
        [aspect](const rg::Context& ctx, const Data& d) {
            VkBufferImageCopy copy{};
            copy.imageSubresource = {aspect, 0, 0, 1};
            copy.imageExtent = {kSize, kSize, 1};
            vkCmdCopyImageToBuffer(ctx.cmd(), ctx.texture(d.source).image,
                                   rg::useInfo(rg::Use::TransferSrc).layout, ctx.buffer(d.target).buffer, 1,
                                   &copy);
        });
}

float srgbEncode(float x) {
    x = std::clamp(x, 0.0f, 1.0f);
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

TEST(NodeHostDevice, RendersIntoTheHostsOwnColourAndDepthTargets) {
    Host host;
    host.createDevice();
    {
        vk::Device device(host.handles());
        EXPECT_FALSE(device.ownsDevice());
        EXPECT_EQ(device.device(), host.device);
        const eng::scene::Scene scene = eng::scene::loadBuiltin("furball"); // covered and sky pixels
        eng::frame::GpuScene gpuScene(device, scene);
        AggregateSettings settings; // n = 8, c = 2
        settings.generation =
            AggregateGeneration::Accumulate; // its prepass depth can be read back per sample
        AggregateAA node(device, gpuScene, settings);
        agaa::test::ClusteringInputReadback clusteringInputs(device);
        HostTargetWriter writer(device);
        HostImage color(host.device, host.physical, VK_FORMAT_R8G8B8A8_SRGB,
                        VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                        VK_IMAGE_ASPECT_COLOR_BIT);
        HostImage depth(host.device, host.physical, VK_FORMAT_D32_SFLOAT,
                        VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                        VK_IMAGE_ASPECT_DEPTH_BIT);

        eng::frame::ViewSettings view;
        view.width = view.height = kSize;
        HostView frame(device, scene, view, settings.samples);
        vk::Buffer colorHost =
            eng::frame::createReadbackBuffer(device, kSize, kSize, VK_FORMAT_R8G8B8A8_SRGB, "test.color");
        vk::Buffer depthHost =
            eng::frame::createReadbackBuffer(device, kSize, kSize, VK_FORMAT_R32_SFLOAT, "test.depth");
        vk::Buffer samplesHost =
            vk::createBuffer(device, VkDeviceSize(kSize) * kSize * settings.samples * 8,
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Readback, "test.samples");
        {
            rg::Graph graph;
            FrameInputs in = frame.record(graph, node, 0, "host");
            clusteringInputs.add(graph, node, in, samplesHost);
            // Fresh images: contents undefined before; the host then reads both back as a transfer.
            HostTargets targets;
            targets.color = {color.physical(), std::nullopt, rg::Use::TransferSrc};
            targets.depth = HostTarget{depth.physical(), std::nullopt, rg::Use::TransferSrc};
            const HostTargetVersions written = writer.write(graph, frame.lastTargets, in, targets);
            addAspectReadback(graph, written.color, VK_IMAGE_ASPECT_COLOR_BIT, colorHost,
                              "test.readback.color");
            addAspectReadback(graph, written.depth, VK_IMAGE_ASPECT_DEPTH_BIT, depthHost,
                              "test.readback.depth");
            eng::frame::FrameRunner runner(device);
            runner.run(graph);
        }
        const std::vector<float> images = frame.read();
        const float* display = images.data() + size_t(kSize) * kSize * 4;
        vk::invalidateBuffer(device, colorHost);
        vk::invalidateBuffer(device, depthHost);
        vk::invalidateBuffer(device, samplesHost);
        const auto* bytes = static_cast<const uint8_t*>(colorHost.mapped);
        const auto* depths = static_cast<const float*>(depthHost.mapped);
        const auto* samples = static_cast<const uint32_t*>(samplesHost.mapped);
        uint32_t colourOff = 0, depthOff = 0, covered = 0;
        for (uint32_t p = 0; p < kSize * kSize; ++p) {
            for (int c = 0; c < 3; ++c) // the blit's sRGB encode rounds: within one step of 8 bits
                colourOff +=
                    std::abs(srgbEncode(display[4 * p + c]) * 255.0f - float(bytes[4 * p + c])) > 1.0f;
            float nearest = 0.0f; // reversed Z: the largest sample is the nearest
            for (uint32_t s = 0; s < settings.samples; ++s) {
                float d;
                std::memcpy(&d, &samples[2 * (p * settings.samples + s)], 4);
                nearest = std::max(nearest, d);
            }
            covered += nearest > 0.0f;
            depthOff += std::memcmp(&nearest, &depths[p], 4) != 0;
        }
        EXPECT_EQ(colourOff, 0u) << "host colour = the node's display, sRGB-encoded by the blit";
        EXPECT_EQ(depthOff, 0u) << "host depth = the nearest visibility sample, bit for bit";
        EXPECT_GT(covered, kSize * kSize / 10) << "the railings must cover part of the frame";
        EXPECT_LT(covered, kSize * kSize) << "and leave some sky, so depth 0 is tested too";
        for (vk::Buffer* b : {&colorHost, &depthHost, &samplesHost})
            vk::destroyBuffer(device, *b);
        expectNoValidationErrors(device);
    }
    vkDestroyDevice(host.device, nullptr); // the host's, after the wrapper and all made with it
    host.device = VK_NULL_HANDLE;
    EXPECT_EQ(host.errors.load(), 0u) << "validation errors on the host's instance";
}

// Every method hands back its depth, multisampled (n >= 4) or not (noaa), and the writer fills
// the host's targets validation-clean. A pixel whose resolved depth is 0 (sky) must have
// exactly the sky's radiance: no sample of it was covered.
class EveryMethod : public ::testing::TestWithParam<const char*> {};

TEST_P(EveryMethod, WritesTheHostsTargets) {
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("furball");
    eng::frame::GpuScene gpuScene(*device, scene);
    MethodSettings settings;
    settings.samples = 4;
    std::unique_ptr<Technique> node = createTechnique(GetParam(), *device, gpuScene, settings);
    HostTargetWriter writer(*device);
    const VkImageUsageFlags use =
        VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    vk::Image color = vk::createImage(*device,
                                      {VK_FORMAT_R16G16B16A16_SFLOAT, kSize, kSize, 1, 1,
                                       VK_SAMPLE_COUNT_1_BIT, use, VK_IMAGE_VIEW_TYPE_2D},
                                      "test.color");
    vk::Image depth = vk::createImage(
        *device,
        {VK_FORMAT_D32_SFLOAT_S8_UINT, kSize, kSize, 1, 1, VK_SAMPLE_COUNT_1_BIT, use, VK_IMAGE_VIEW_TYPE_2D},
        "test.depth");
    vk::Buffer depthHost =
        eng::frame::createReadbackBuffer(*device, kSize, kSize, VK_FORMAT_R32_SFLOAT, "test.depth.host");
    eng::frame::ViewSettings view;
    view.width = view.height = kSize;
    {
        HostView frame(*device, scene, view, node->samples());
        rg::Graph graph;
        const FrameInputs in = frame.record(graph, *node, 0, "host");
        HostTargets targets;
        targets.color = {{color.image, color.view, color.view, {color.desc.format, kSize, kSize}}, {}, {}};
        targets.depth = HostTarget{
            {depth.image, depth.view, depth.sampledView, {depth.desc.format, kSize, kSize}}, {}, {}};
        const HostTargetVersions out = writer.write(graph, frame.lastTargets, in, targets);
        graph.markOutput(out.color);
        addAspectReadback(graph, out.depth, VK_IMAGE_ASPECT_DEPTH_BIT, depthHost, "test.readback.depth");
        eng::frame::FrameRunner(*device).run(graph);
        const std::vector<float> images = frame.read();
        const float* hdr = images.data(); // not display: FXAA filters it across the sky's edges
        vk::invalidateBuffer(*device, depthHost);
        const auto* depths = static_cast<const float*>(depthHost.mapped);
        uint32_t covered = 0, outOfRange = 0, skyLit = 0, sky = 0;
        while (sky < kSize * kSize - 1 && depths[sky] != 0.0f)
            ++sky;
        for (uint32_t p = 0; p < kSize * kSize; ++p) {
            covered += depths[p] > 0.0f;
            outOfRange += !(depths[p] >= 0.0f && depths[p] <= 1.0f);
            // A pixel with no sample in front of the sky has exactly the sky's radiance.
            skyLit += depths[p] == 0.0f && (hdr[4 * p] != hdr[4 * sky] || hdr[4 * p + 2] != hdr[4 * sky + 2]);
        }
        EXPECT_EQ(outOfRange, 0u);
        EXPECT_GT(covered, kSize * kSize / 10);
        EXPECT_LT(covered, kSize * kSize);
        EXPECT_LE(skyLit, 0u) << "pixels the host depth calls sky but the node shaded";
    }
    vk::destroyBuffer(*device, depthHost);
    vk::destroyImage(*device, color);
    vk::destroyImage(*device, depth);
    expectNoValidationErrors(*device);
}

INSTANTIATE_TEST_SUITE_P(Node, EveryMethod,
                         ::testing::Values("noaa", "reference", "simple-complex", "sbaa", "fxaa", "agaa"));

TEST(NodeHostDevice, RefusesAHostDeviceWithoutARequiredFeatureNamingIt) {
    Host host;
    host.createDevice([](vk::FeatureChain& f) { f.v13.dynamicRendering = VK_FALSE; });
    try {
        vk::Device device(host.handles());
        ADD_FAILURE() << "a host device without dynamicRendering was accepted";
    } catch (const vk::MissingCapability& e) {
        EXPECT_NE(std::string(e.what()).find("dynamicRendering"), std::string::npos) << e.what();
    }
    EXPECT_EQ(host.errors.load(), 0u);
}

TEST(NodeHostDevice, RefusesAHostDeviceWithoutAFeatureTheRendererReliesOn) {
    Host host;
    host.createDevice([](vk::FeatureChain& f) { f.v12.scalarBlockLayout = VK_FALSE; });
    try {
        vk::Device device(host.handles());
        ADD_FAILURE() << "a host device without scalarBlockLayout (supported here) was accepted";
    } catch (const vk::MissingCapability& e) {
        EXPECT_NE(std::string(e.what()).find("scalarBlockLayout"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace agaa::test
