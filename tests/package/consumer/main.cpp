// A host built against the installed package (tests/package): renders one small frame of a
// built-in scene with one method by name, under the validation layer, and reads the HDR target
// back through its own pass. Exit 0 only for a validation-clean, finite, non-blank frame.
//
// With HOST_SPIRV_DIR (the host's shaders, which the package test compiled against the installed
// GLSL alone), the frame is rendered a second time as a host with its own content renders it:
// the technique created from the host's traits alone (no GpuScene), the host's drawer with its own
// vertex layout, material and programs (samples/host_engine/host_content.h, built on installed headers
// only) and the stand-in environment. Exit 0 then also needs the two frames to agree.
//
//   consumer METHOD SCENE SIZE [HOST_SPIRV_DIR]

#include <agaa/agaa.h>

#include "tests/node/host_mesh.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace vk = eng::vk;

// One frame's HDR target, read back through the host's own pass.
std::vector<float> render(vk::Device& device, agaa::Technique& technique, const eng::scene::Scene& scene,
                          uint32_t size, agaa::GeometryDrawer* geometry,
                          const agaa::EnvironmentBindings* environment) {
    eng::frame::ViewSettings view;
    view.width = view.height = size;
    shared::FrameConstants constants =
        eng::frame::makeFrameConstants(scene, view, eng::frame::makeSamplePattern(technique.samples()));
    auto lights = eng::frame::makeGpuLights(scene, constants.view);
    vk::Buffer frameBuffer = vk::createBuffer(device, sizeof constants, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                              vk::MemoryUse::Upload, "host.frame");
    vk::Buffer lightBuffer =
        vk::createBuffer(device, lights.size() * sizeof(shared::GpuLight), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                         vk::MemoryUse::Upload, "host.lights");
    vk::writeBuffer(device, frameBuffer, std::as_bytes(std::span(&constants, 1)));
    vk::writeBuffer(device, lightBuffer, std::as_bytes(std::span(lights)));

    eng::rg::Graph graph;
    agaa::FrameInputs inputs;
    inputs.geometry = geometry;
    inputs.environment = environment;
    inputs.constants = &constants;
    inputs.width = inputs.height = size;
    inputs.frameConstants =
        graph.importBuffer("host.frame", {frameBuffer.buffer, frameBuffer.size}, std::nullopt, std::nullopt);
    inputs.lights =
        graph.importBuffer("host.lights", {lightBuffer.buffer, lightBuffer.size}, std::nullopt, std::nullopt);
    agaa::FrameTargets targets = technique.addPasses(graph, inputs);
    vk::Buffer hostImage =
        eng::frame::createReadbackBuffer(device, size, size, VK_FORMAT_R32G32B32A32_SFLOAT, "host.image");
    eng::frame::addReadbackPass(graph, targets.hdr, hostImage, "host.post");
    eng::frame::FrameRunner runner(device);
    runner.run(graph);

    vk::invalidateBuffer(device, hostImage);
    std::vector<float> hdr(size_t(size) * size * 4);
    std::memcpy(hdr.data(), hostImage.mapped, hdr.size() * sizeof(float));
    vkDeviceWaitIdle(device.device());
    vk::destroyBuffer(device, hostImage);
    vk::destroyBuffer(device, frameBuffer);
    vk::destroyBuffer(device, lightBuffer);
    return hdr;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 4 && argc != 5) {
        std::fprintf(stderr, "usage: consumer METHOD SCENE SIZE [HOST_SPIRV_DIR]\n");
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
        vk::DeviceOptions options;
        options.validation = true;
        vk::Device device(options);
        eng::scene::Scene scene = eng::scene::loadBuiltin(sceneName);
        eng::frame::GpuScene gpuScene(device, scene);

        // n = 8, c = 2; AGAA's accumulation kernel in the one build the host's shaders have.
        agaa::MethodSettings settings;
        settings.agaa.atomics = agaa::AggregateAtomics::Bits32;
        settings.agaa.subgroupReduction = agaa::SubgroupReduction::Off;
        std::unique_ptr<agaa::Technique> technique =
            agaa::createTechnique(method, device, gpuScene, settings);
        const std::vector<float> px = render(device, *technique, scene, size, nullptr, nullptr);

        double minimum = 1e30, maximum = -1e30, sum = 0.0;
        bool finite = true;
        for (size_t i = 0; i < px.size(); ++i) {
            if (i % 4 == 3) continue;
            finite &= std::isfinite(px[i]);
            minimum = std::min(minimum, double(px[i]));
            maximum = std::max(maximum, double(px[i]));
            sum += px[i];
        }
        const double mean = sum / (3.0 * size * size);
        // Non-blank: some light reached the frame and the pixels differ (not one flat clear colour).
        const bool blank = !(maximum > 0.0) || maximum - minimum < 1e-3;

        bool hostAgrees = true;
        if (argc == 5) {
            const std::string dir = argv[4];
            const host_engine::HostProgramFiles programs = host_engine::readHostPrograms(dir);
            agaa::test::HostMesh mesh = agaa::test::hostMesh(scene);
            const agaa::TechniqueContent content{
                agaa::test::hostTraits(mesh, scene.lights, "host:" + sceneName)};
            agaa::test::HostGeometry drawer(device, std::move(mesh), programs.programs());
            const eng::frame::GpuEnvironment standIn(device, nullptr);
            const agaa::EnvironmentBindings environment = agaa::environmentBindings(standIn);
            std::unique_ptr<agaa::Technique> hosts = agaa::createTechnique(method, device, content, settings);
            const std::vector<float> got = render(device, *hosts, scene, size, &drawer, &environment);
            size_t differ = 0;
            double squares = 0.0;
            for (size_t i = 0; i < px.size(); ++i) {
                differ += std::memcmp(&px[i], &got[i], sizeof(float)) != 0 ? 1 : 0;
                squares += (double(px[i]) - double(got[i])) * (double(px[i]) - double(got[i]));
            }
            const double rmse = std::sqrt(squares / double(px.size()));
            hostAgrees = rmse <= 1e-4;
            std::printf(
                "consumer: %s as a host's content (its traits, drawer, shaders, no GpuScene): HDR RMSE "
                "%.3g against the scene's, %zu of %zu values differ\n",
                method.c_str(), rmse, differ, px.size());
        }
        const uint32_t errors = device.validationErrors();
        std::printf(
            "consumer: %s on %s at %ux%u: mean radiance %.4f, range [%.4f, %.4f], %s, %s, %u validation "
            "error(s)\n",
            method.c_str(), sceneName.c_str(), size, size, mean, minimum, maximum,
            finite ? "finite" : "NOT FINITE", blank ? "BLANK" : "not blank", errors);
        return finite && !blank && hostAgrees && errors == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "consumer: %s\n", e.what());
        return 1;
    }
}
