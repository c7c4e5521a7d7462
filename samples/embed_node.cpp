// Embedding AGAA in a host engine. The host owns the Vulkan instance, device and queue, its
// colour and depth images and its render graph; the node adds its passes, writes the
// anti-aliased frame into the host's colour image and its depth into the host's depth image (so
// the host can keep drawing after it), and the graph records every barrier in between.
//   embed_node [SCENE]   renders a builtin scene (default: railings) at 64x64 and prints the
//                        passes that ran; exit status 1 on a validation error.
#include <agaa/agaa.h>

#include <cstdio>

int main(int argc, char** argv) {
    namespace vk = eng::vk;
    constexpr uint32_t kSize = 64;
    // The host's Vulkan, validated; its device enables what vk::DeviceSetup lists (lavapipe's
    // queue family 0 does graphics, compute and timestamps).
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* debugUtils = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkApplicationInfo app{
        VK_STRUCTURE_TYPE_APPLICATION_INFO, nullptr, "host", 0, "host", 0, VK_API_VERSION_1_3};
    VkInstanceCreateInfo ici{
        VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, nullptr, 0, &app, 1, &layer, 1, &debugUtils};
    vk::HostDevice host;
    VK_CHECK(vkCreateInstance(&ici, nullptr, &host.instance));
    uint32_t one = 1;
    vkEnumeratePhysicalDevices(host.instance, &one, &host.physical);
    const vk::DeviceSetup setup(host.physical, false);
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO, nullptr, 0, 0, 1, &priority};
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, nullptr, 0, 1, &qci};
    setup.fill(dci);
    VK_CHECK(vkCreateDevice(host.physical, &dci, nullptr, &host.device));
    vkGetDeviceQueue(host.device, 0, 0, &host.queue);
    host.enabledFeatures = dci.pNext;
    host.enabledExtensions = setup.extensions();
    host.debugUtils = host.validation = true;
    bool ok = false;
    {
        vk::Device device(host); // wraps the host's handles, owns none of them
        const eng::scene::Scene scene = eng::scene::loadBuiltin(argc > 1 ? argv[1] : "railings");
        eng::frame::GpuScene gpuScene(device, scene);
        agaa::AggregateAA node(device, gpuScene, agaa::AggregateSettings{}); // once: it owns pipelines
        agaa::HostTargetWriter writer(device);
        agaa::FrameInputWriter frame(device, gpuScene);
        // The host's targets: its own images (made here with the engine's allocation helper).
        const auto image = [&](VkFormat format, const char* name) {
            const VkImageUsageFlags use = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
            return vk::createImage(
                device, {format, kSize, kSize, 1, 1, VK_SAMPLE_COUNT_1_BIT, use, VK_IMAGE_VIEW_TYPE_2D},
                name);
        };
        vk::Image color = image(VK_FORMAT_R8G8B8A8_SRGB, "host.color"),
                  depth = image(VK_FORMAT_D32_SFLOAT, "host.depth");
        // Each image as the graph sees it, with its state before the frame and after (nullopt:
        // undefined before, its last use after; a host passes the Use it left the image in).
        const auto target = [](const vk::Image& i) {
            return agaa::HostTarget{{i.image, i.view, i.view, {i.desc.format, kSize, kSize}}, {}, {}};
        };
        // One frame: the host's camera (the scene's camera 0) in frame slot 0, as this host waits for
        // each frame; with F frames in flight and V views per frame, slot = frame * V + view.
        eng::rg::Graph graph;
        const agaa::FrameInputs in = frame.write(graph, {.width = kSize, .height = kSize}, node.samples(), 0);
        const agaa::HostTargetVersions out =
            writer.write(graph, node.addPasses(graph, in), in, {target(color), target(depth)});
        graph.markOutput(out.color); // the host's later passes would read it; here it is the result
        eng::frame::FrameRunner(device).run(graph);
        for (const std::string& pass : graph.executedPassNames())
            std::printf("%s ", pass.c_str());
        std::printf("\n%u validation errors\n", device.validationErrors());
        ok = device.validationErrors() == 0;
        vk::destroyImage(device, color);
        vk::destroyImage(device, depth);
    }
    vkDestroyDevice(host.device, nullptr);
    vkDestroyInstance(host.instance, nullptr);
    return ok ? 0 : 1;
}
