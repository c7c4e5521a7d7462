// The shared shader math on lavapipe (validation on) over edge inputs, against double-precision
// twins (shader_math_cases.cpp): finite everywhere, within each case's stated tolerance.

#include "engine/frame/frame_runner.h"
#include "engine/graph/graph.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/reflection.h"
#include "engine/vk/resources.h"
#include "gpu_test_support.h"
#include "shader_math_cases.h"
#include "shaders/tests/shader_math_comp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <span>

namespace {

namespace vk = eng::vk;
namespace rg = eng::rg;
using agaa::hard::MathCase;
using agaa::hard::MathResult;

// One dispatch of shader_math.comp over `cases`; the graph owns the barriers.
std::vector<MathResult> runKernel(vk::Device& device, const std::vector<MathCase>& cases) {
    const VkDeviceSize inBytes = cases.size() * sizeof(MathCase),
                       outBytes = cases.size() * sizeof(MathResult);
    vk::Buffer in = vk::createBuffer(device, inBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                     vk::MemoryUse::Upload, "test.mathCases");
    vk::Buffer out = vk::createBuffer(device, outBytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                      vk::MemoryUse::Readback, "test.mathResults");
    vk::writeBuffer(device, in, std::as_bytes(std::span(cases)));
    vk::LayoutDesc desc;
    desc.pushBindings = vk::reflectBindings({{kTestsShaderMathComp, VK_SHADER_STAGE_COMPUTE_BIT}});
    desc.pushConstantBytes = sizeof(uint32_t);
    vk::PipelineLayout layout = vk::createPipelineLayout(device, desc, "test.shaderMath.layout");
    VkPipeline pipeline =
        vk::createComputePipeline(device, kTestsShaderMathComp, layout.layout, {}, "test.shaderMath");
    {
        rg::Graph graph;
        rg::Buffer input =
            graph.importBuffer("test.mathCases", {in.buffer, in.size}, std::nullopt, std::nullopt);
        rg::Buffer output =
            graph.importBuffer("test.mathResults", {out.buffer, out.size}, std::nullopt, std::nullopt);
        struct Data {
            rg::Buffer in, out;
        };
        const uint32_t count = uint32_t(cases.size());
        graph.addCompute<Data>(
            "test.shaderMath",
            [&](rg::Builder& b, Data& d) {
                d.in = b.read(input, rg::Use::StorageReadCompute);
                d.out = b.write(output, rg::Use::StorageWriteCompute);
                b.sideEffect(); // the host reads the results
            },
            [&, count](const rg::Context& ctx, const Data& d) {
                VkCommandBuffer cmd = ctx.cmd();
                VkDescriptorBufferInfo bi[2] = {{ctx.buffer(d.in).buffer, 0, VK_WHOLE_SIZE},
                                                {ctx.buffer(d.out).buffer, 0, VK_WHOLE_SIZE}};
                VkWriteDescriptorSet w[2] = {};
                for (uint32_t i = 0; i < 2; ++i) {
                    w[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
                    w[i].dstBinding = i;
                    w[i].descriptorCount = 1;
                    w[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                    w[i].pBufferInfo = &bi[i];
                }
                vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
                device.pushDescriptorSet()(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout.layout, 0, 2, w);
                vkCmdPushConstants(cmd, layout.layout, VK_SHADER_STAGE_ALL, 0, sizeof(count), &count);
                vkCmdDispatch(cmd, (count + 63) / 64, 1, 1);
            });
        graph.compile();
        eng::frame::FrameRunner runner(device);
        runner.run(graph);
    }
    vk::invalidateBuffer(device, out);
    std::vector<MathResult> results(cases.size());
    std::memcpy(results.data(), out.mapped, outBytes);
    vkDestroyPipeline(device.device(), pipeline, nullptr);
    vk::destroyPipelineLayout(device, layout);
    vk::destroyBuffer(device, in);
    vk::destroyBuffer(device, out);
    return results;
}

TEST(HardShaderMath, EdgeInputsAreFiniteAndMatchTheDoubleTwins) {
    auto device = agaa::test::makeValidatedDevice();
    const std::vector<agaa::hard::EdgeCase> cases = agaa::hard::shaderMathCases();
    std::vector<MathCase> inputs;
    for (const auto& c : cases)
        inputs.push_back(c.input);
    const std::vector<MathResult> results = runKernel(*device, inputs);
    uint32_t failures = 0;
    for (size_t i = 0; i < cases.size(); ++i) {
        for (int k = 0; k < 4; ++k) {
            // Every output slot the kernel writes must be finite, whatever the case checks.
            EXPECT_TRUE(std::isfinite(results[i].r0[k]) && std::isfinite(results[i].r1[k]))
                << cases[i].name
                << ": a result component is NaN or Inf (guards: " << ::testing::PrintToString(cases[i].guards)
                << ")";
        }
        const std::string why = cases[i].check(results[i]);
        failures += !why.empty();
        EXPECT_TRUE(why.empty()) << cases[i].name << " [guards " << ::testing::PrintToString(cases[i].guards)
                                 << "]: " << why;
    }
    std::printf("[ measured ] %zu shader-math edge cases, %u failed\n", cases.size(), failures);
    agaa::test::expectNoValidationErrors(*device);
}

} // namespace
