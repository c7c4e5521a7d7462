// A host built against the installed package (tests/package): renders one small frame of a
// built-in scene with one method by name, under the validation layer, and reads the HDR target
// back through its own pass. Exit 0 only for a validation-clean, finite, non-blank frame.
//
//   consumer METHOD SCENE SIZE

#include <agaa/agaa.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <span>
#include <string>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: consumer METHOD SCENE SIZE\n");
        return 2;
    }
    const std::string method = argv[1];
    const std::string sceneName = argv[2];
    const int sizeArg = std::atoi(argv[3]);
    if (sizeArg < 1 || sizeArg > 1024) {
        std::fprintf(stderr, "consumer: SIZE '%s' is not an integer in 1..1024\n", argv[3]);
        return 2;
    }
    const auto size = static_cast<uint32_t>(sizeArg);
    try {
        namespace vk = eng::vk;
        vk::DeviceOptions options;
        options.validation = true;
        vk::Device device(options);
        eng::scene::Scene scene = eng::scene::loadBuiltin(sceneName);
        eng::frame::GpuScene gpuScene(device, scene);

        agaa::MethodSettings settings; // n = 8, c = 2
        std::unique_ptr<agaa::Technique> technique =
            agaa::createTechnique(method, device, gpuScene, settings);
        eng::frame::ViewSettings view;
        view.width = view.height = size;
        shared::FrameConstants constants =
            eng::frame::makeFrameConstants(scene, view, eng::frame::makeSamplePattern(technique->samples()));
        auto lights = eng::frame::makeGpuLights(scene, constants.view);
        vk::Buffer frameBuffer =
            vk::createBuffer(device, sizeof constants, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                             vk::MemoryUse::Upload, "host.frame");
        vk::Buffer lightBuffer =
            vk::createBuffer(device, lights.size() * sizeof(shared::GpuLight),
                             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Upload, "host.lights");
        vk::writeBuffer(device, frameBuffer, std::as_bytes(std::span(&constants, 1)));
        vk::writeBuffer(device, lightBuffer, std::as_bytes(std::span(lights)));

        eng::rg::Graph graph;
        agaa::FrameInputs inputs;
        inputs.constants = &constants;
        inputs.width = inputs.height = size;
        inputs.frameConstants = graph.importBuffer("host.frame", {frameBuffer.buffer, frameBuffer.size},
                                                   std::nullopt, std::nullopt);
        inputs.lights = graph.importBuffer("host.lights", {lightBuffer.buffer, lightBuffer.size},
                                           std::nullopt, std::nullopt);
        agaa::FrameTargets targets = technique->addPasses(graph, inputs);
        vk::Buffer hostImage =
            eng::frame::createReadbackBuffer(device, size, size, VK_FORMAT_R32G32B32A32_SFLOAT, "host.image");
        eng::frame::addReadbackPass(graph, targets.hdr, hostImage, "host.post");
        eng::frame::FrameRunner runner(device);
        runner.run(graph);

        vk::invalidateBuffer(device, hostImage);
        const float* px = static_cast<const float*>(hostImage.mapped);
        double minimum = 1e30, maximum = -1e30, sum = 0.0;
        bool finite = true;
        for (uint32_t i = 0; i < size * size * 4; ++i) {
            if (i % 4 == 3) continue;
            finite &= std::isfinite(px[i]);
            minimum = std::min(minimum, double(px[i]));
            maximum = std::max(maximum, double(px[i]));
            sum += px[i];
        }
        const double mean = sum / (3.0 * size * size);
        // Non-blank: some light reached the frame and the pixels differ (not one flat clear colour).
        const bool blank = !(maximum > 0.0) || maximum - minimum < 1e-3;
        const uint32_t errors = device.validationErrors();
        std::printf(
            "consumer: %s on %s at %ux%u: mean radiance %.4f, range [%.4f, %.4f], %s, %s, %u validation "
            "error(s)\n",
            method.c_str(), sceneName.c_str(), size, size, mean, minimum, maximum,
            finite ? "finite" : "NOT FINITE", blank ? "BLANK" : "not blank", errors);
        vkDeviceWaitIdle(device.device());
        vk::destroyBuffer(device, hostImage);
        vk::destroyBuffer(device, frameBuffer);
        vk::destroyBuffer(device, lightBuffer);
        return finite && !blank && errors == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "consumer: %s\n", e.what());
        return 1;
    }
}
