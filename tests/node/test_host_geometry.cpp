// Issue 50, the geometry and material contract from a host's side (agaa/common/raster_pass.h): a
// drawer with its own vertex format (interleaved position and normal, 16-bit indices with a base
// vertex per draw), its own buffers, its own material (a constant per draw, in its own push
// constant) and its own shaders (samples/host_engine/shaders), which include only the module's
// raster includes (shaders/glsl/raster/). It draws the built-in scene's triangles; the methods'
// images must match what this project's own drawer makes of the same scene within display RMSE
// 1e-4 (the bound), validation-clean.

#include "agaa/common/raster_pass.h"
#include "agaa/common/shadow_map.h"
#include "agaa/methods.h"
#include "engine/frame/frame_constants.h"
#include "engine/frame/sample_pattern.h"
#include "engine/scene/scenegen.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/resources.h"
#include "tests/gpu/gpu_test_support.h"
#include "tests/node/host_programs.h"
#include "tests/node/node_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <iostream>
#include <memory>
#include <ostream>
#include <span>
#include <stdexcept>
#include <vector>

namespace agaa::test {
namespace {

namespace vk = eng::vk;

// The display image (HostView::read's second half).
std::vector<float> render(vk::Device& device, const eng::frame::GpuScene& scene, Technique& technique,
                          GeometryDrawer* geometry, const HostShadowMaps* shadowMaps = nullptr,
                          const EnvironmentBindings* environment = nullptr) {
    const std::vector<float> both = renderFrame(device, scene, technique, geometry, shadowMaps, environment);
    return {both.begin() + std::ptrdiff_t(both.size() / 2), both.end()};
}

double displayRmse(const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        if (i % 4 == 3) continue; // alpha
        const double d = double(a[i]) - double(b[i]);
        sum += d * d;
        ++n;
    }
    return std::sqrt(sum / double(n));
}

struct Case {
    const char* method;
    AggregateGeneration generation = AggregateGeneration::Auto;
    bool sampleRate = false; // MethodSettings::sampleRateShading: the host's sample-rate builds
};
void PrintTo(const Case& c, std::ostream* os) {
    *os << c.method << (c.generation == AggregateGeneration::Accumulate ? " accumulate" : "")
        << (c.sampleRate ? " at sample rate" : "");
}

class HostGeometryCase : public ::testing::TestWithParam<Case> {};

TEST_P(HostGeometryCase, AHostsOwnVerticesAndMaterialShadersMatchTheScenesOwnDrawer) {
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("railings");
    // What this host's constant material can stand for: no textures, masks or vertex colours.
    ASSERT_TRUE(scene.textures.empty());
    for (const eng::scene::Material& m : scene.materials)
        ASSERT_EQ(m.alphaMode, eng::scene::AlphaMode::Opaque);
    eng::frame::GpuScene gpuScene(*device, scene);
    MethodSettings settings;
    // The accumulate path in the one build this host has (RasterPass::defines empty).
    settings.agaa.generation = GetParam().generation;
    settings.agaa.atomics = AggregateAtomics::Bits32;
    settings.agaa.subgroupReduction = SubgroupReduction::Off;
    settings.sampleRateShading = GetParam().sampleRate;
    std::unique_ptr<Technique> technique = createTechnique(GetParam().method, *device, gpuScene, settings);
    ASSERT_FALSE(effectiveFeatures(sceneTraits(scene), settings.effects).vertexColors);
    const std::vector<float> own = render(*device, gpuScene, *technique, nullptr);
    // The host's technique knows no GpuScene: the host's traits, its drawer, and its environment,
    // the stand-in of content without one (railings has none).
    HostMesh mesh = hostMesh(scene);
    const SceneTraits traits = hostTraits(mesh, scene.lights, "host:railings");
    HostGeometry host(*device, std::move(mesh), embeddedHostPrograms());
    ASSERT_FALSE(traits.features.hasEnvironment());
    const eng::frame::GpuEnvironment standIn(*device, nullptr);
    const EnvironmentBindings environment = environmentBindings(standIn);
    std::unique_ptr<Technique> hostsTechnique =
        createTechnique(GetParam().method, *device, TechniqueContent{traits}, settings);
    const std::vector<float> hosts = render(*device, gpuScene, *hostsTechnique, &host, nullptr, &environment);
    double mean = 0.0;
    for (float v : own)
        mean += v;
    ASSERT_GT(mean / double(own.size()), 0.01) << "the scene must be visible to test anything";
    const double rmse = displayRmse(hosts, own);
    std::cout << GetParam().method << ": display RMSE " << rmse << " against the scene's drawer, "
              << countDifferentBits(hosts, own) << " of " << own.size() << " values differ\n";
    EXPECT_LE(rmse, 1e-4);
    expectNoValidationErrors(*device);
}

INSTANTIATE_TEST_SUITE_P(Node, HostGeometryCase,
                         ::testing::Values(Case{"reference"}, Case{"noaa"}, Case{"simple-complex"},
                                           Case{"sbaa"}, Case{"streaming"},
                                           Case{"sbaa", AggregateGeneration::Auto, true},
                                           Case{"streaming", AggregateGeneration::Auto, true}, Case{"agaa"},
                                           Case{"agaa", AggregateGeneration::Accumulate}),
                         [](const auto& info) {
                             std::string name = info.param.method;
                             std::replace(name.begin(), name.end(), '-', '_');
                             return name +
                                    (info.param.generation == AggregateGeneration::Accumulate ? "_accumulate"
                                                                                              : "") +
                                    (info.param.sampleRate ? "_sample_rate" : "");
                         });

// A technique created from a host's traits alone has no scene to fall back on: a frame without
// the host's drawer or environment is refused naming the missing input.
TEST(HostContent, AFrameWithoutTheHostsDrawerOrEnvironmentIsRefusedByName) {
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("railings");
    eng::frame::GpuScene gpuScene(*device, scene);
    HostGeometry host(*device, hostMesh(scene), embeddedHostPrograms());
    std::unique_ptr<Technique> technique =
        createTechnique("reference", *device, TechniqueContent{sceneTraits(scene)}, MethodSettings{});
    auto refusal = [&](GeometryDrawer* geometry) -> std::string {
        try {
            render(*device, gpuScene, *technique, geometry);
        } catch (const std::invalid_argument& e) {
            return e.what();
        }
        return "(accepted)";
    };
    EXPECT_NE(refusal(nullptr).find("FrameInputs::geometry"), std::string::npos) << refusal(nullptr);
    EXPECT_NE(refusal(&host).find("FrameInputs::environment"), std::string::npos) << refusal(&host);
    expectNoValidationErrors(*device);
}

// FrameInputs::shadowMaps: the host draws its own shadow map (its own geometry, pipelines and
// rendering, into its own image, with the module's fit from ShadowMapPass::makeConstants) and the
// method reads it in place of drawing one: the image equals the method's own, and no shadow pass of
// the module ran. Maps that are not what the lighting reads are refused by name.
TEST(HostShadowMaps, AHostsOwnShadowMapsReplaceTheModulesBitForBit) {
    auto device = makeValidatedDevice();
    const eng::scene::Scene scene = eng::scene::loadBuiltin("railings");
    eng::frame::GpuScene gpuScene(*device, scene);
    const MethodSettings settings;
    std::unique_ptr<Technique> technique = createTechnique("reference", *device, gpuScene, settings);
    const eng::scene::SceneFeatures features = effectiveFeatures(sceneTraits(scene), settings.effects);
    ASSERT_FALSE(features.shadowedLights.empty());
    HostGeometry host(*device, hostMesh(scene), embeddedHostPrograms());
    const std::vector<float> own = render(*device, gpuScene, *technique, &host);
    ASSERT_EQ(host.shadowMapsDrawn, 1);

    // The host's map and constants, for the frame renderFrame draws.
    const uint32_t size = settings.effects.shadowMapSize;
    const uint32_t layers = std::max<uint32_t>(2, uint32_t(features.shadowedLights.size()));
    vk::Image map = vk::createImage(*device,
                                    {ShadowMapPass::kFormat, size, size, layers, 1, VK_SAMPLE_COUNT_1_BIT,
                                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                     VK_IMAGE_VIEW_TYPE_2D_ARRAY},
                                    "host.shadowMap");
    const shared::FrameConstants frame = eng::frame::makeFrameConstants(
        scene, frameView(), eng::frame::makeSamplePattern(technique->samples()));
    const shared::ShadowConstants constants =
        ShadowMapPass::makeConstants(sceneTraits(scene), features.shadowedLights, size, &frame);
    vk::Buffer constantsBuffer =
        vk::createBuffer(*device, sizeof constants, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, vk::MemoryUse::Upload,
                         "host.shadowConstants");
    vk::writeBuffer(*device, constantsBuffer, std::as_bytes(std::span(&constants, 1)));

    // The host's own rendering of it, through the module's description of the pass.
    const ShadowMapPass module(*device, gpuScene, features, settings.effects, "host");
    const RasterPass& pass = module.rasterPass();
    host.prepare(pass);
    const VkImageLayout drawn = eng::rg::useInfo(eng::rg::Use::DepthStencilWrite).layout;
    device->submitAndWait([&](VkCommandBuffer cmd) {
        VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        barrier.dstStageMask =
            VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
        barrier.dstAccessMask =
            VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
        barrier.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        barrier.newLayout = drawn;
        barrier.image = map.image;
        barrier.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, layers};
        VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dependency.imageMemoryBarrierCount = 1;
        dependency.pImageMemoryBarriers = &barrier;
        vkCmdPipelineBarrier2(cmd, &dependency);
        VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        depth.imageView = map.view;
        depth.imageLayout = drawn;
        depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {1.0f, 0}; // nothing occludes
        VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
        rendering.renderArea = {{0, 0}, {size, size}};
        rendering.layerCount = layers;
        rendering.pDepthAttachment = &depth;
        vkCmdBeginRendering(cmd, &rendering);
        const VkViewport viewport{0.0f, 0.0f, float(size), float(size), 0.0f, 1.0f};
        const VkRect2D scissor{{0, 0}, {size, size}};
        vkCmdSetViewport(cmd, 0, 1, &viewport);
        vkCmdSetScissor(cmd, 0, 1, &scissor);
        host.recordDraws(cmd, pass, [&](VkCommandBuffer c, VkPipelineLayout layout) {
            eng::vk::PushDescriptors()
                .uniform(0, constantsBuffer.buffer)
                .push(*device, c, VK_PIPELINE_BIND_POINT_GRAPHICS, layout);
        });
        vkCmdEndRendering(cmd);
    });
    ASSERT_EQ(host.shadowMapsDrawn, 2);

    const HostShadowMaps maps{{map.image,
                               map.view,
                               map.sampledView,
                               {ShadowMapPass::kFormat, size, size, layers, VK_SAMPLE_COUNT_1_BIT}},
                              {constantsBuffer.buffer, constantsBuffer.size},
                              eng::rg::Use::DepthStencilWrite};
    const std::vector<float> hosts = render(*device, gpuScene, *technique, &host, &maps);
    EXPECT_EQ(host.shadowMapsDrawn, 2) << "the module drew a shadow map of its own";
    EXPECT_EQ(countDifferentBits(hosts, own), 0u);

    HostShadowMaps single = maps;
    single.map.desc.layers = 1;
    try {
        render(*device, gpuScene, *technique, &host, &single);
        ADD_FAILURE() << "a one-layer map was taken";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("FrameInputs::shadowMaps: map.desc.layers"), std::string::npos)
            << e.what();
    }
    expectNoValidationErrors(*device);
    vk::destroyImage(*device, map);
    vk::destroyBuffer(*device, constantsBuffer);
}

} // namespace
} // namespace agaa::test
