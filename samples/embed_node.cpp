// Embedding AGAA in a host engine's render graph: the host owns the graph, the frame
// constants and its own passes; the AGAA node adds its passes and hands back an HDR target
// that the host's next pass consumes. No window, no swapchain, no global state.
//
//   embed_node [--builtin NAME] [--size N]    prints what ran and the mean of the host's output
//
// The host pass here is a stand-in for a host's post-processing: it reads the AGAA HDR target
// with a transfer copy into a host-visible buffer, exactly as a compute or raster pass would
// declare a sampled read. The graph inserts every barrier between the two.

#include "agaa/aggregate/aggregate.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/frame_runner.h"
#include "engine/frame/gpu_scene.h"
#include "engine/frame/readback.h"
#include "engine/frame/sample_pattern.h"
#include "engine/scene/scene_error.h"
#include "engine/scene/scenegen.h"
#include "engine/vk/check.h"
#include "engine/vk/device.h"
#include "engine/vk/resources.h"

#include <cmath>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    std::string sceneName = "default";
    uint32_t size = 96;
    for (int i = 1; i + 1 < argc; i += 2) {
        std::string flag = argv[i];
        if (flag == "--builtin")
            sceneName = argv[i + 1];
        else if (flag == "--size")
            size = uint32_t(std::max(1, std::atoi(argv[i + 1])));
        else {
            std::fprintf(stderr, "embed_node: unknown argument '%s' (allowed: --builtin NAME, --size N)\n",
                         argv[i]);
            return 2;
        }
    }
    try {
        namespace vk = eng::vk;
        eng::vk::DeviceOptions options;
        options.validation = true; // a host would decide; the sample shows it validation-clean
        vk::Device device(options);
        eng::scene::Scene scene = eng::scene::loadBuiltin(sceneName);
        eng::frame::GpuScene gpuScene(device, scene);

        // The host's frame: its constants and lights in its own buffers.
        agaa::AggregateSettings settings; // n = 8, c = 2
        eng::frame::ViewSettings view;
        view.width = view.height = size;
        shared::FrameConstants constants =
            eng::frame::makeFrameConstants(scene, view, eng::frame::makeSamplePattern(settings.samples));
        auto lights = eng::frame::makeGpuLights(scene, constants.view);
        vk::Buffer frameBuffer =
            vk::createBuffer(device, sizeof constants, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                             vk::MemoryUse::Upload, "host.frame");
        vk::Buffer lightBuffer =
            vk::createBuffer(device, lights.size() * sizeof(shared::GpuLight),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload, "host.lights");
        vk::writeBuffer(device, frameBuffer, std::as_bytes(std::span(&constants, 1)));
        vk::writeBuffer(device, lightBuffer, std::as_bytes(std::span(lights)));

        // The AGAA node: created once (it owns its pipelines), added to each frame's graph.
        agaa::AggregateAA node(device, gpuScene, settings);

        eng::rg::Graph graph;
        agaa::FrameInputs inputs;
        inputs.scene = &gpuScene;
        inputs.constants = &constants;
        inputs.width = inputs.height = size;
        inputs.frameConstants = graph.importBuffer("host.frame", {frameBuffer.buffer, frameBuffer.size},
                                                   std::nullopt, std::nullopt);
        inputs.lights = graph.importBuffer("host.lights", {lightBuffer.buffer, lightBuffer.size},
                                           std::nullopt, std::nullopt);
        agaa::FrameTargets targets = node.addPasses(graph, inputs);

        // The host's own pass consumes the node's HDR output.
        vk::Buffer hostImage =
            eng::frame::createReadbackBuffer(device, size, size, VK_FORMAT_R32G32B32A32_SFLOAT, "host.image");
        eng::frame::addReadbackPass(graph, targets.hdr, hostImage, "host.post");

        eng::frame::FrameRunner runner(device);
        eng::frame::FrameTiming timing = runner.run(graph);
        std::printf("passes run:");
        for (const auto& p : timing.passes)
            std::printf(" %s (%.1f ms)", p.name.c_str(), p.gpuMs);
        std::printf("\npasses culled:");
        for (const auto& p : graph.culledPassNames())
            std::printf(" %s", p.c_str());
        vk::invalidateBuffer(device, hostImage);
        const float* px = static_cast<const float*>(hostImage.mapped);
        double mean = 0.0;
        bool finite = true;
        for (uint32_t i = 0; i < size * size; ++i) {
            mean += (px[4 * i] + px[4 * i + 1] + px[4 * i + 2]) / 3.0;
            finite &=
                std::isfinite(px[4 * i]) && std::isfinite(px[4 * i + 1]) && std::isfinite(px[4 * i + 2]);
        }
        std::printf("\nhost output: %ux%u, mean radiance %.4f, %s, %u validation error(s)\n", size, size,
                    mean / (size * size), finite ? "finite" : "NOT FINITE", device.validationErrors());
        vkDeviceWaitIdle(device.device());
        vk::destroyBuffer(device, hostImage);
        vk::destroyBuffer(device, frameBuffer);
        vk::destroyBuffer(device, lightBuffer);
        return finite && device.validationErrors() == 0 ? 0 : 1;
    } catch (const eng::scene::SceneError& e) {
        std::fprintf(stderr, "embed_node: %s\n", e.what());
        return 2;
    } catch (const eng::vk::MissingCapability& e) {
        std::fprintf(stderr, "embed_node: the device lacks a required capability: %s\n", e.what());
        return 3;
    }
}
